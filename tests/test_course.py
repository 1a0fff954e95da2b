"""trex course: a small course rendered at -q l on a LocalCluster of 2 worker processes.

The course: a lecture of two tiny subtitled chapters (written here: the project's chapters
take minutes at -ql), two scenes (the polygon scene on a polygon file, a tiny scene as a
png), exercises for 3 students, and a scene that breaks. One run renders it all (the
broken scene fails, the rest finish); a second run, of the same course without the broken
scene, renders nothing. The command runs as a user runs it, in a process of its own.
"""

import json
import os
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import av
import pytest
from click.testing import CliRunner

from trex.cli import main
from trex.course import tasks as course_tasks
from trex.course.manifest import record, reusable, write_manifest
from trex.course.run import sweep

REPO = Path(__file__).resolve().parent.parent
# one xdist worker runs them all: the course is rendered once, by the module's fixture
pytestmark = pytest.mark.xdist_group("course")

TINY = textwrap.dedent("""
    from manim import BLUE, Circle, Create, FadeOut, Scene, Square

    class Cues(Scene):
        def construct(self):
            self.next_section("Cues")
            square = Square(color=BLUE)
            self.play(Create(square), subcaption="a square", subcaption_duration=1.0,
                      run_time=1.0)
            self.wait(0.4)
            self.play(FadeOut(square), subcaption="gone", run_time=0.5)

    class MoreCues(Scene):
        def construct(self):
            self.next_section("More cues")
            self.play(Create(Circle()), subcaption="a circle", run_time=1.0)
            self.wait(0.4)
""")
BROKEN = textwrap.dedent("""
    from manim import Scene

    class Boom(Scene):
        def construct(self):
            raise RuntimeError("the scene broke")
""")
STAR = "[[0, 0], [4, 1], [8, 0], [7, 4], [8, 8], [4, 7], [0, 8], [1, 4]]"
COURSE = textwrap.dedent("""
    [course]
    title = "A small course"
    quality = "l"

    [[lecture]]
    chapters = ["tiny.py:Cues", "tiny.py:MoreCues"]

    [[scene]]
    scene = "polygon"
    polygons = ["star.json"]

    [[scene]]
    scene = "tiny.py:Cues"
    format = "png"

    [[slides]]
    scene = "lecture"
    chapters = ["tiny.py:Cues", "tiny.py:MoreCues"]

    [[exercises]]
    students = 3
    n = 1
    seed = 7
""")
BROKEN_ITEM = '\n[[scene]]\nscene = "broken.py:Boom"\nformat = "png"\n'


def trex(*args, timeout=400):
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(
        p for p in (str(REPO), os.environ.get("PYTHONPATH", "")) if p)}
    return subprocess.run([sys.executable, "-m", "trex", *args], capture_output=True,
                          text=True, env=env, cwd=REPO, timeout=timeout)


def in_process(*args):
    result = CliRunner().invoke(main, list(args))
    return result.exit_code, result.stdout, result.stderr


@pytest.fixture(scope="module")
def folder(tmp_path_factory) -> Path:
    folder = tmp_path_factory.mktemp("course")
    (folder / "tiny.py").write_text(TINY)
    (folder / "broken.py").write_text(BROKEN)
    (folder / "star.json").write_text(STAR)
    (folder / "course.toml").write_text(COURSE)
    (folder / "with-broken.toml").write_text(COURSE + BROKEN_ITEM)
    return folder


@pytest.fixture(scope="module")
def first(folder):
    """The course with its broken scene, rendered once on 2 workers."""
    result = trex("course", str(folder / "with-broken.toml"), "-o", str(folder / "out"),
                  "--workers", "2")
    return folder / "out", result


@pytest.fixture(scope="module")
def manifest(first):
    out, _ = first
    return {t["id"]: t for t in json.loads((out / "course.json").read_text())["tasks"]}


def test_a_failing_item_is_reported_while_the_others_finish(first, manifest):
    out, result = first
    assert result.returncode == 1, result.stderr
    failed = [line for line in result.stderr.splitlines() if line.startswith("error: ")]
    assert failed == ["error: scene-broken-Boom (scene 3): RuntimeError: the scene broke"]
    assert manifest["scene-broken-Boom"]["status"] == "failed"
    assert manifest["scene-broken-Boom"]["error"] == "RuntimeError: the scene broke"
    others = [t for t in manifest.values() if t["id"] != "scene-broken-Boom"]
    assert len(others) == 9 and {t["status"] for t in others} == {"done"}
    assert not (out / "scene-broken-Boom.png").exists()


def test_the_outputs_are_laid_out_and_listed(first, manifest):
    out, result = first
    assert sorted(manifest) == [
        "exercises/student-1", "exercises/student-2", "exercises/student-3", "lecture-1",
        "lecture-1/chapters/01-tiny-Cues", "lecture-1/chapters/02-tiny-MoreCues",
        "scene-broken-Boom", "scene-polygon-star", "scene-tiny-Cues", "slides-lecture"]
    for task in manifest.values():
        assert set(task) == {"id", "kind", "item", "files", "status", "video_seconds",
                             "wall_seconds", "worker", "fingerprint", "error"}
        assert all((out / name).is_file() for name in task["files"])
        assert len(task["fingerprint"]) == 64
    assert manifest["scene-polygon-star"]["files"] == ["scene-polygon-star.mp4"]
    assert manifest["scene-tiny-Cues"]["files"] == ["scene-tiny-Cues.png"]
    assert manifest["exercises/student-2"]["files"] == [
        "exercises/student-2/answers.md", "exercises/student-2/exercise-01.png"]
    workers = {t["worker"] for t in manifest.values() if t["status"] == "done"}
    assert workers <= {"0", "1"}
    assert "dashboard: http" in result.stderr
    assert "course: [####################] 10/10 tasks" in result.stderr
    # nothing half-written anywhere: no temporary name is left
    assert [p.relative_to(out).as_posix() for p in out.rglob(".*")] == [
        "slides-lecture/.trex-slides"]  # trex slides' own marker


def test_the_students_get_their_own_seeded_exercises(first):
    out, _ = first
    answers = [(out / f"exercises/student-{k}/answers.md").read_text() for k in (1, 2, 3)]
    assert len(set(answers)) == 3
    assert "seed 7" in answers[0] and "seed 9" in answers[2]


def test_the_lecture_is_joined_from_its_chapters(first, manifest):
    out, _ = first
    lecture = out / "lecture-1"
    entries = json.loads((lecture / "chapters.json").read_text())
    assert [e["file"] for e in entries] == ["chapters/01-tiny-Cues.mp4",
                                            "chapters/02-tiny-MoreCues.mp4"]

    def frames(path):
        with av.open(str(path)) as container:
            return container.streams.video[0].frames

    assert frames(lecture / "lecture.mp4") == sum(
        frames(lecture / e["file"]) for e in entries)
    assert "a circle" in (lecture / "lecture.srt").read_text()
    assert manifest["lecture-1"]["files"] == [f"lecture-1/{name}" for name in (
        "lecture.mp4", "lecture.srt", "chapters.json", "chapters.md", "teacher-notes.md")]
    assert manifest["lecture-1"]["video_seconds"] == pytest.approx(
        sum(manifest[f"lecture-1/{e['file'][:-4]}"]["video_seconds"] for e in entries))
    # the chapter's step marks say how it was made, as trex lecture's: trex slides reuses it
    marks = json.loads((lecture / "chapters" / "01-tiny-Cues.steps.json").read_text())
    assert marks["made_by"]["class"] == "Cues" and marks["made_by"]["quality"] == "l"


def test_the_lectures_slides_reuse_its_chapters(first, manifest):
    out, _ = first
    slides = manifest["slides-lecture"]
    assert slides["files"] == ["slides-lecture/index.html"]
    assert not any(t["id"].startswith("slides-lecture-chapters") for t in manifest.values())
    clips = sorted((out / "slides-lecture" / "clips").glob("*.mp4"))
    assert len(clips) >= 2  # a step at least per chapter
    assert (out / "slides-lecture" / "handout.pdf").is_file()
    assert slides["video_seconds"] > 0


def test_a_rerun_renders_nothing(first, folder):
    out, _ = first
    before = {p: p.stat().st_mtime_ns for p in out.rglob("*") if p.is_file()
              and p.name != "course.json"}
    result = trex("course", str(folder / "course.toml"), "-o", str(out))
    assert result.returncode == 0, result.stderr
    assert result.stdout.startswith("course: 0 done, 9 reused, 0 failed; 0.0 s of video in ")
    assert "dashboard" not in result.stderr  # no cluster was even started
    tasks = json.loads((out / "course.json").read_text())["tasks"]
    assert {t["status"] for t in tasks} == {"reused"} and len(tasks) == 9
    after = {p: p.stat().st_mtime_ns for p in before}
    assert after == before


def test_a_dry_run_lists_the_tasks_and_renders_nothing(folder, tmp_path):
    out = tmp_path / "none"
    code, stdout, stderr = in_process("course", str(folder / "course.toml"), "-o", str(out),
                                      "--dry-run")
    assert code == 0, stderr
    lines = stdout.splitlines()
    assert lines[0] == "lecture-1/chapters/01-tiny-Cues: chapter of lecture 1, to render"
    assert lines[2].startswith("lecture-1: join of lecture 1, to render (after ")
    assert lines[-1] == "course: 9 tasks, 9 to render, 0 reused (dry run: nothing rendered)"
    assert not out.exists()


# --- bad course files ---------------------------------------------------------------------------


BAD = {
    "unknown kind": ("[[video]]\nscene = 'gravity'\n", "[video]: unknown kind; known: course, "
                     "lecture, scene, slides, exercises"),
    "unknown field": ("[[scene]]\nscene = 'gravity'\npolygon = 'star.json'\n",
                      "scene 1, field polygon: unknown field; known: scene, polygons, format, "
                      "quality, panel"),
    "unknown scene": ("[[scene]]\nscene = 'nonesuch'\n",
                      "scene 1, field scene: unknown scene 'nonesuch'; known: "),
    "bad polygon": ("[[scene]]\nscene = 'polygon'\npolygons = ['counterexample', 'bow.json']\n",
                    "scene 1, field polygons[1]: "),
    "no students": ("[[exercises]]\nstudents = 0\n",
                    "exercises 1, field students: must be from 1 to 10000, not 0"),
    "a wrong type": ("[[exercises]]\nstudents = '3'\n",
                     "exercises 1, field students: must be a whole number, not '3'"),
    "bad quality": ("[course]\nquality = 'x'\n[[scene]]\nscene = 'gravity'\n",
                    "[course], field quality: 'x' is not one of l, m, h, k"),
    "not TOML": ("[[scene]\n", "the file: not TOML: "),
    "a rejected run": ("[[lecture]]\npolygon = 'triangle'\nchapters = ['polygon', 'scaling']\n",
                       "lecture 1, field polygon: triangle: "),
}


@pytest.mark.parametrize("case", sorted(BAD))
def test_a_bad_course_file_is_one_line_before_anything(case, tmp_path):
    text, said = BAD[case]
    (tmp_path / "bow.json").write_text("[[0, 0], [4, 4], [4, 0], [0, 4]]")
    course = tmp_path / "course.toml"
    course.write_text(text)
    out = tmp_path / "out"
    code, stdout, stderr = in_process("course", str(course), "-o", str(out))
    assert code == 2
    assert stdout == ""
    assert len(stderr.splitlines()) == 1
    assert stderr.startswith(f"error: {course}: {said}"), stderr
    assert not out.exists()


def test_an_output_that_is_a_file_is_refused(folder, tmp_path):
    out = tmp_path / "file"
    out.write_text("x")
    code, _, stderr = in_process("course", str(folder / "course.toml"), "-o", str(out))
    assert (code, stderr) == (2, f"error: {out}: exists and is not a directory\n")


def test_a_slides_folder_that_is_not_slides_is_refused(folder, tmp_path):
    out = tmp_path / "out"
    (out / "slides-lecture").mkdir(parents=True)
    (out / "slides-lecture" / "notes.txt").write_text("mine")
    code, _, stderr = in_process("course", str(folder / "course.toml"), "-o", str(out))
    assert code == 2
    assert stderr.startswith(f"error: slides 1: {out / 'slides-lecture'}: exists and is not "
                             "earlier slides")
    assert sorted(p.name for p in out.rglob("*")) == ["notes.txt", "slides-lecture"]


# --- the parts, without a cluster -------------------------------------------------------------------


def _task(files=("a.mp4",), settings=None, inputs=()):
    return course_tasks.Task("a", "scene", "scene 1", files, settings or {"x": 1}, inputs)


def test_a_fingerprint_covers_settings_input_bytes_code_and_dependencies(tmp_path):
    polygon = tmp_path / "p.json"
    polygon.write_text(STAR)
    base = _task(inputs=(str(polygon),))

    def fp(*tasks, code="c"):
        return course_tasks.fingerprinted(list(tasks), code)[-1].fingerprint

    first = fp(base)
    assert fp(base) == first
    assert fp(_task(settings={"x": 2}, inputs=(str(polygon),))) != first
    assert fp(base, code="d") != first
    polygon.write_text(STAR.replace("[1, 4]", "[2, 4]"))
    assert fp(base) != first
    dep = course_tasks.Task("b", "join", "lecture 1", ("b.mp4",), {}, deps=("a",))
    assert fp(base, dep) != fp(_task(settings={"x": 2}, inputs=(str(polygon),)), dep)


def test_reuse_needs_the_fingerprint_a_finished_status_and_every_file(tmp_path):
    task = course_tasks.fingerprinted([_task()], "c")[0]
    (tmp_path / "a.mp4").write_bytes(b"video")
    done = record(task, "done", files=("a.mp4",))
    assert reusable(task, {"a": done}, tmp_path) == done
    assert reusable(task, {"a": {**done, "fingerprint": "other"}}, tmp_path) is None
    assert reusable(task, {"a": {**done, "status": "failed"}}, tmp_path) is None
    (tmp_path / "a.mp4").unlink()
    assert reusable(task, {"a": done}, tmp_path) is None


def test_sweep_removes_only_what_a_stopped_task_left(tmp_path):
    task = _task(files=("scene-x.mp4", "exercises/student-1/answers.md"))
    (tmp_path / "exercises").mkdir()
    left = [tmp_path / ".scene-x.mp4.k2j3.render", tmp_path / "exercises/.student-1.9x.build"]
    for path in left:
        path.mkdir()
        (path / "half.mp4").write_bytes(b"half")
    kept = [tmp_path / ".other.mp4.k2j3.render", tmp_path / "scene-x.mp4",
            tmp_path / ".hidden"]
    for path in kept:
        path.write_text("mine")
    assert sweep([task], tmp_path) == 2
    assert not any(p.exists() for p in left) and all(p.exists() for p in kept)


def test_the_manifest_is_written_whole(tmp_path):
    task = course_tasks.fingerprinted([_task()], "c")[0]
    write_manifest(tmp_path, "T", [record(task, "failed", error="boom")])
    data = json.loads((tmp_path / "course.json").read_text())
    assert data["title"] == "T" and data["tasks"][0]["error"] == "boom"
    assert [p.name for p in tmp_path.iterdir()] == ["course.json"]


# --- a worker killed mid-task ------------------------------------------------------------------------

SLOW = textwrap.dedent("""
    import os
    import time
    from pathlib import Path

    from manim import Circle, Create, Scene, Square

    STARTED = Path(__file__).with_name("started")

    class Slow(Scene):
        def construct(self):
            self.play(Create(Square()), run_time=0.5)
            if not STARTED.exists():  # the first try: say where, then wait to be killed
                STARTED.write_text(str(os.getpid()))
                time.sleep(120)
            self.play(Create(Circle()), run_time=0.5)
""")


def test_a_worker_killed_mid_task_has_its_task_run_again(tmp_path):
    (tmp_path / "slow.py").write_text(SLOW)
    (tmp_path / "course.toml").write_text("[[scene]]\nscene = 'slow.py:Slow'\n")
    out = tmp_path / "out"
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(
        p for p in (str(REPO), os.environ.get("PYTHONPATH", "")) if p)}
    process = subprocess.Popen([sys.executable, "-m", "trex", "course",
                                str(tmp_path / "course.toml"), "-o", str(out), "--workers", "2"],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                               env=env, cwd=REPO)
    try:
        started = tmp_path / "started"
        deadline = time.monotonic() + 300
        while not started.exists() or not started.read_text():
            assert process.poll() is None, process.communicate()
            assert time.monotonic() < deadline, "the task never started"
            time.sleep(0.2)
        time.sleep(0.5)  # mid-task: its first frames are written, beside the output
        assert [p.name for p in out.glob(".*.render")]
        os.kill(int(started.read_text()), signal.SIGKILL)
        _, stderr = process.communicate(timeout=300)
    finally:
        process.kill()
    assert process.returncode == 0, stderr
    task, = json.loads((out / "course.json").read_text())["tasks"]
    assert (task["id"], task["status"], task["files"]) == (
        "scene-slow-Slow", "done", ["scene-slow-Slow.mp4"])
    with av.open(str(out / "scene-slow-Slow.mp4")) as container:
        assert container.streams.video[0].frames == 16  # both plays (8 frames each at -ql)
    assert sorted(p.name for p in out.iterdir()) == ["course.json", "scene-slow-Slow.mp4"]


def test_a_scheduler_that_cannot_be_reached_is_one_line_and_leaves_nothing(folder, tmp_path):
    out = tmp_path / "out"
    # in a process of its own, bounded: Dask tries for 10 s (trex.course.run.CONNECT_TIMEOUT)
    result = trex("course", str(folder / "course.toml"), "-o", str(out), "--scheduler",
                  "tcp://127.0.0.1:1", timeout=120)
    assert result.returncode == 2 and result.stdout == ""
    assert result.stderr.startswith("error: tcp://127.0.0.1:1: Timed out trying to connect")
    assert len(result.stderr.splitlines()) == 1
    assert not out.exists()


@pytest.mark.parametrize(("address", "said"), [
    ("nonsense://127.0.0.1:8786", "unknown scheme 'nonsense'; known: tcp, tls, ws, wss, ucx "
     "(tcp://HOST:8786)"),
    ("inproc://x", "unknown scheme 'inproc'; known: "),  # this process's own: no use here
    ("127.0.0.1", "needs a host and a port from 1 to 65535 (tcp://HOST:8786)"),
    ("tcp://127.0.0.1:port", "needs a host and a port from 1 to 65535"),
    ("tcp://127.0.0.1:99999", "needs a host and a port from 1 to 65535"),
    ("tcp://:8786", "needs a host and a port from 1 to 65535"),
])
def test_a_bad_scheduler_address_is_one_line_before_anything(folder, tmp_path, address, said):
    out = tmp_path / "out"
    code, stdout, stderr = in_process("course", str(folder / "course.toml"), "-o", str(out),
                                      "--scheduler", address)
    assert (code, stdout) == (2, "")
    assert stderr.startswith(f"error: --scheduler {address}: {said}"), stderr
    assert len(stderr.splitlines()) == 1
    assert not out.exists()


@pytest.mark.parametrize("answer", [b"HTTP/1.0 200 OK\r\n\r\nhello", b""])
def test_a_port_that_is_no_scheduler_is_one_line_and_leaves_nothing(folder, tmp_path, answer):
    """Something listens there (a web server; or a service that says nothing): one line,
    exit 2, within a bounded time, nothing written."""
    import socket
    import threading

    server = socket.create_server(("127.0.0.1", 0))
    port = server.getsockname()[1]
    accepted = []

    def serve():
        while True:
            try:
                conn, _ = server.accept()
            except OSError:  # closed: the test is over
                return
            accepted.append(conn)
            if answer:
                conn.sendall(answer)

    threading.Thread(target=serve, daemon=True).start()
    out = tmp_path / "out"
    try:
        result = trex("course", str(folder / "course.toml"), "-o", str(out), "--scheduler",
                      f"tcp://127.0.0.1:{port}", timeout=120)
    finally:
        server.close()
        for conn in accepted:
            conn.close()
    assert accepted  # it did connect
    assert (result.returncode, result.stdout) == (2, ""), result.stderr
    assert result.stderr.startswith(f"error: tcp://127.0.0.1:{port}: "), result.stderr
    assert len(result.stderr.splitlines()) == 1, result.stderr
    assert not out.exists()


# --- a cluster of its own: a dask scheduler and workers started as a user starts them ----------------

DASK = Path(sys.executable).with_name("dask")
EXTERNAL = textwrap.dedent("""
    [course]
    title = "On a cluster"
    quality = "l"

    [[scene]]
    scene = "tiny.py:Cues"

    [[exercises]]
    students = 1
    n = 1
    seed = 7
""")


def _group_alive(pgid: int) -> list[int]:
    """The processes of process group ``pgid`` still running (zombies are dead)."""
    alive = []
    for stat in Path("/proc").glob("[0-9]*/stat"):
        try:
            fields = stat.read_text().rpartition(")")[2].split()
        except OSError:  # gone meanwhile
            continue
        if int(fields[2]) == pgid and fields[0] != "Z":
            alive.append(int(stat.parent.name))
    return alive


def _stop(process: subprocess.Popen) -> None:
    """SIGTERM to the process's whole group (a worker's nanny spawns its worker), then
    SIGKILL to what is left after 30 s."""
    for sig, wait in ((signal.SIGTERM, 30), (signal.SIGKILL, 10)):
        try:
            os.killpg(process.pid, sig)
        except ProcessLookupError:
            break
        deadline = time.monotonic() + wait
        while _group_alive(process.pid) and time.monotonic() < deadline:
            time.sleep(0.2)
        if not _group_alive(process.pid):
            break
    process.wait(timeout=10)


class _Dask:
    """Dask's own commands started as a user starts them, each a process group of its own,
    seeing this checkout's code (their output in ``logs/``)."""

    def __init__(self, folder: Path) -> None:
        self.folder, self.logs = folder, folder / "logs"
        self.logs.mkdir()
        self.env = {**os.environ, "PYTHONPATH": os.pathsep.join(
            p for p in (str(REPO), os.environ.get("PYTHONPATH", "")) if p)}
        self.started: list[subprocess.Popen] = []

    def start(self, name: str, *args: str) -> subprocess.Popen:
        with open(self.logs / f"{name}.log", "w") as log:
            self.started.append(subprocess.Popen(
                [str(DASK), *args], stdout=log, stderr=subprocess.STDOUT, env=self.env,
                cwd=self.folder, start_new_session=True))
        return self.started[-1]

    def scheduler(self) -> str:
        """``dask scheduler`` on 127.0.0.1, on a port of its choosing: its address."""
        info = self.folder / "scheduler.json"
        process = self.start("scheduler", "scheduler", "--host", "127.0.0.1", "--port", "0",
                             "--dashboard-address", "127.0.0.1:0", "--scheduler-file",
                             str(info), "--idle-timeout", "600s")  # (if left, it stops)
        deadline = time.monotonic() + 120
        while not info.exists() or not info.read_text().strip():
            assert process.poll() is None, (self.logs / "scheduler.log").read_text()
            assert time.monotonic() < deadline, "the scheduler never wrote its address"
            time.sleep(0.2)
        time.sleep(0.2)  # (the file is written whole, but give it its closing brace)
        address = json.loads(info.read_text())["address"]
        assert address.startswith("tcp://127.0.0.1:")
        return address

    def workers(self, address: str, n: int) -> subprocess.Popen:
        """``dask worker ADDRESS --nworkers N --nthreads 1``, named ext-0 …, joined."""
        from distributed import Client

        process = self.start("workers", "worker", address, "--nworkers", str(n),
                             "--nthreads", "1", "--name", "ext", "--host", "127.0.0.1",
                             "--no-dashboard", "--local-directory",
                             str(self.folder / "dask-worker-space"), "--death-timeout", "60s")
        with Client(address, timeout="30s") as client:
            client.wait_for_workers(n, timeout=180)
        # what the check at the end looks for: the worker command and a process per worker
        assert len(_group_alive(process.pid)) >= n + 1
        return process

    def stop(self) -> None:
        """Stop everything started, and check that no process of it is left."""
        for process in reversed(self.started):
            _stop(process)
        left = {p.pid: _group_alive(p.pid) for p in self.started}
        assert not any(left.values()), f"processes of the cluster left running: {left}"


@pytest.fixture
def dask_commands(tmp_path):
    """A :class:`_Dask`; what it started is stopped afterwards and checked gone."""
    if not DASK.exists():
        pytest.skip(f"no dask command beside {sys.executable} (distributed's CLI)")
    if not Path("/proc/self/stat").exists():
        pytest.skip("needs /proc to check that no process of the cluster is left")
    dask = _Dask(tmp_path)
    try:
        yield dask
    finally:
        dask.stop()


@pytest.fixture
def cluster(dask_commands):
    """A scheduler on 127.0.0.1 and 2 single-threaded workers, as separate processes."""
    address = dask_commands.scheduler()
    dask_commands.workers(address, 2)
    return address, dask_commands.started


def test_a_course_runs_on_a_cluster_started_apart(cluster, tmp_path):
    address, _ = cluster
    (tmp_path / "tiny.py").write_text(TINY)
    (tmp_path / "course.toml").write_text(EXTERNAL)
    out = tmp_path / "out"
    result = trex("course", str(tmp_path / "course.toml"), "-o", str(out), "--scheduler",
                  address, timeout=600)
    assert result.returncode == 0, result.stderr
    assert result.stdout.startswith("course: 2 done, 0 reused, 0 failed; ")
    assert "dashboard: http://127.0.0.1:" in result.stderr
    tasks = {t["id"]: t for t in json.loads((out / "course.json").read_text())["tasks"]}
    assert sorted(tasks) == ["exercises/student-1", "scene-tiny-Cues"]
    assert {t["status"] for t in tasks.values()} == {"done"}
    assert {t["worker"] for t in tasks.values()} <= {"ext-0", "ext-1"}  # the cluster's own
    assert tasks["scene-tiny-Cues"]["files"] == ["scene-tiny-Cues.mp4", "scene-tiny-Cues.srt"]
    assert sorted(p.relative_to(out).as_posix() for p in out.rglob("*")) == [
        "course.json", "exercises", "exercises/student-1", "exercises/student-1/answers.md",
        "exercises/student-1/exercise-01.png", "scene-tiny-Cues.mp4", "scene-tiny-Cues.srt"]
    # the same files as the commands make on this machine
    sheet = tmp_path / "sheet"
    made = trex("exercises", "--n", "1", "--seed", "7", "-o", str(sheet))
    assert made.returncode == 0, made.stderr
    for name in ("answers.md", "exercise-01.png"):
        assert (out / "exercises/student-1" / name).read_bytes() == (sheet / name).read_bytes()
    here = tmp_path / "here.mp4"
    made = trex("render", str(tmp_path / "tiny.py:Cues"), "-q", "l", "-o", str(here))
    assert made.returncode == 0, made.stderr
    assert _frame_sums(out / "scene-tiny-Cues.mp4") == _frame_sums(here)
    assert (out / "scene-tiny-Cues.srt").read_text() == here.with_suffix(".srt").read_text()
    # and again on the same cluster: nothing to render
    again = trex("course", str(tmp_path / "course.toml"), "-o", str(out), "--scheduler",
                 address, timeout=600)
    assert again.returncode == 0, again.stderr
    assert again.stdout.startswith("course: 0 done, 2 reused, 0 failed; ")


def test_a_cluster_with_no_worker_yet_is_said_and_its_course_waits(dask_commands, tmp_path):
    """The course reaches a scheduler that has no worker: it says so and waits; a worker
    that joins then does the course."""
    address = dask_commands.scheduler()
    (tmp_path / "tiny.py").write_text(TINY)
    (tmp_path / "course.toml").write_text(EXTERNAL)
    out, said = tmp_path / "out", tmp_path / "stderr"
    with open(said, "w") as stderr:
        course = subprocess.Popen(
            [sys.executable, "-m", "trex", "course", str(tmp_path / "course.toml"), "-o",
             str(out), "--scheduler", address], stdout=subprocess.PIPE, stderr=stderr,
            text=True, env=dask_commands.env, cwd=REPO)
    try:
        waiting = f"course: no worker at {address} yet; the tasks wait for one"
        deadline = time.monotonic() + 300
        while waiting not in said.read_text():
            assert course.poll() is None, said.read_text()
            assert time.monotonic() < deadline, said.read_text()
            time.sleep(0.2)
        assert not list(out.rglob("*.mp4"))  # nothing done without a worker
        dask_commands.workers(address, 1)
        stdout, _ = course.communicate(timeout=600)
    finally:
        course.kill()
        course.wait()
    assert course.returncode == 0, said.read_text()
    assert stdout.startswith("course: 2 done, 0 reused, 0 failed; ")
    tasks = json.loads((out / "course.json").read_text())["tasks"]
    assert {(t["status"], t["worker"]) for t in tasks} == {("done", "ext")}
    assert "warning" not in said.read_text()


def _frame_sums(path: Path) -> list[str]:
    """SHA-1 of every decoded frame (x264's bytes may differ between runs, not the frames)."""
    import hashlib

    with av.open(str(path)) as container:
        return [hashlib.sha1(f.to_ndarray(format="rgb24").tobytes()).hexdigest()
                for f in container.decode(video=0)]


# --- the course's lecture is trex lecture's -----------------------------------------------------------


def _assert_same_lecture(ours: Path, theirs: Path) -> None:
    """The same lecture: decoded frames of the lecture and of each chapter (x264's bytes may
    differ), the same subtitles, chapter list, chapter page and teacher notes."""
    entries = json.loads((theirs / "chapters.json").read_text())
    assert json.loads((ours / "chapters.json").read_text()) == entries
    for name in ("lecture.srt", "chapters.md", "teacher-notes.md"):
        assert (ours / name).read_text() == (theirs / name).read_text(), name
    assert _frame_sums(ours / "lecture.mp4") == _frame_sums(theirs / "lecture.mp4")
    for entry in entries:
        assert _frame_sums(ours / entry["file"]) == _frame_sums(theirs / entry["file"])


def test_the_courses_lecture_is_trex_lectures(first, folder, tmp_path):
    out, _ = first
    lecture = tmp_path / "lecture"
    chapters = ",".join(f"{folder / 'tiny.py'}:{c}" for c in ("Cues", "MoreCues"))
    made = trex("lecture", "-q", "l", "--chapters", chapters, "-o", str(lecture))
    assert made.returncode == 0, made.stderr
    assert _frame_sums(lecture / "lecture.mp4")  # (frames there to compare)
    _assert_same_lecture(out / "lecture-1", lecture)


@pytest.mark.slow
def test_a_project_chapter_on_a_course_is_trex_lectures(tmp_path):
    """A chapter of the project's own lecture (the one with teacher notes),
    through the course on 2 workers and through trex lecture."""
    (tmp_path / "course.toml").write_text(
        "[[lecture]]\nquality = 'l'\nchapters = ['heuristics']\n")
    out = tmp_path / "out"
    result = trex("course", str(tmp_path / "course.toml"), "-o", str(out), "--workers", "2",
                  timeout=1800)
    assert result.returncode == 0, result.stderr
    lecture = tmp_path / "lecture"
    made = trex("lecture", "-q", "l", "--chapters", "heuristics", "-o", str(lecture),
                timeout=1800)
    assert made.returncode == 0, made.stderr
    assert "## 2. Inner diagonals" in (lecture / "teacher-notes.md").read_text()
    _assert_same_lecture(out / "lecture-1", lecture)
