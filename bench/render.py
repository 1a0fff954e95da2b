"""How fast our scenes render, beside bare manim doing the same animations.

In one run, all at ``-ql`` (854×480, 15 fps), each render into a fresh temporary media
directory, in this process (so imports are not counted; the text caches of
:mod:`rendering.typeset` are emptied before each render, so each typesets as a fresh process):

1. ``scenes/gravity.py`` (``Gravity``) rendered with caching off: video seconds per wall second;
2. a bare manim scene with the same plays — the same animation classes, as many per play, with
   the same run times — on simple mobjects (squares), built from Gravity's scene graph
   (:mod:`trex.scene_graph`; for our own ``Turn``, a ``Transform``): video seconds per
   wall second. Both are rendered ``--repeat`` times, alternately, and the best time of each
   counts (this machine's speed wanders by a third between runs; the median is printed beside
   it), with the CPU time of the main thread (building, interpolating, drawing) and of
   manim's encoder threads (x264), and the ratio's ceiling those allow on this machine;
3. the dry-run build time of every scene in ``scenes/*.py`` (what ``tests/test_scenes.py``
   pays per build), and their sum;
4. Gravity rendered twice with manim's cache on, in one media directory: the time of the
   second render and how many plays it took from the cache ("Using cached data" in manim's
   log; the cache key hashes the mobjects and animations, so every play hits only if the
   scene builds the same points every time). Target: ≤ 2 s;
5. the commands side by side, each a fresh process as a user starts it, from the repository
   root (so plain manim reads manim.cfg): ``trex render gravity -q l`` against
   ``manim -ql --disable_caching scenes/gravity.py Gravity``, alternately ``--repeat``
   times, best and median wall time of each and their ratio (trex ÷ manim; target ≤ 1.05,
   issue 24 item 13: trex render once held one encoder in flight where manim.cfg has 4),
   with the CPU time of each (``--trex-code DIR`` runs an older checkout's trex).

It prints numbers and never fails on timings. The last line is exactly
``render throughput ratio vs bare manim: N.NN`` (ours ÷ bare; target ≥ 0.8).

Run from the repository root: ``python bench/render.py`` (``--skip-builds`` leaves out 3,
``--commands-only`` runs 5 alone; ``--quality`` sets 5's quality).
"""

from __future__ import annotations

import argparse
import importlib.util
import inspect
import logging
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
if str(ROOT) not in sys.path:  # run as ``python bench/render.py``
    sys.path.insert(0, str(ROOT))

import av  # noqa: E402
import manim  # noqa: E402
from manim import RED, Scene, Square, tempconfig  # noqa: E402

from rendering import typeset  # noqa: E402
from trex.scene_graph import build, scene_graph  # noqa: E402

#: The scene rendered.
SCENE_FILE, SCENE_NAME = "gravity", "Gravity"


# --- scenes ----------------------------------------------------------------------------------------


def load_module(file: str):
    name = f"trex_scenes_{file}"
    if name not in sys.modules:
        spec = importlib.util.spec_from_file_location(name, ROOT / "scenes" / f"{file}.py")
        module = importlib.util.module_from_spec(spec)
        sys.modules[name] = module
        spec.loader.exec_module(module)
    return sys.modules[name]


def all_scenes() -> list[tuple[str, type[Scene]]]:
    found = []
    for path in sorted((ROOT / "scenes").glob("*.py")):
        if path.name.startswith("_"):
            continue
        module = load_module(path.stem)
        for name, value in sorted(vars(module).items()):
            if (inspect.isclass(value) and issubclass(value, Scene)
                    and value.__module__ == module.__name__):
                found.append((f"{path.stem}.{name}", handed(value)))
    return found


def handed(cls: type[Scene]) -> type[Scene]:
    """The scene handed its default run (whatever TREX_POLYGON and TREX_LOG say)."""
    return cls.handed() if callable(getattr(cls, "handed", None)) else cls


#: Our own animation classes, and the manim class the bare scene plays for each: a Turn
#: replaced a Transform along an arc, and the bare scene goes on playing the Transform it
#: played for it before (manim's Rotate would cost the bare scene more, flattering our ratio).
OWN = {"Turn": "Transform"}


def bare_scene(plays: list[dict]) -> tuple[type[Scene], list[str]]:
    """A Scene class playing the same animation classes and run times on plain squares;
    also the class names it had to stand in for (played as ``FadeIn``)."""
    stand_ins: list[str] = []

    def animation(node: dict, k: int):
        kind, run_time = node["type"], node["run_time"]
        square = Square(side_length=0.5).shift([(k % 12) - 5.5, (k // 12 % 6) - 2.5, 0])
        if kind == "Wait":
            return manim.Wait(run_time=run_time)
        if kind in OWN:
            kind = OWN[kind]
            return getattr(manim, kind)(square, Square(side_length=0.7).move_to(square),
                                        run_time=run_time)
        if kind == "_MethodAnimation":
            return square.animate(run_time=run_time).set_color(RED).shift([0.1, 0, 0])
        if kind in ("AnimationGroup", "Succession", "LaggedStart"):  # the same members inside
            members = [animation(child, k + j) for j, child in enumerate(node["animations"])]
            return getattr(manim, kind)(*members, run_time=run_time)
        cls = getattr(manim, kind, None)
        try:
            if cls is None:
                raise TypeError(kind)
            if kind == "Flash":
                return cls(square.get_center(), run_time=run_time)
            if "target" in node:  # a transform given its target (Transform, ReplacementTransform …)
                return cls(square, Square(side_length=0.7).move_to(square), run_time=run_time)
            return cls(square, run_time=run_time)
        except TypeError:
            stand_ins.append(kind)
            return manim.FadeIn(square, run_time=run_time)

    class Bare(Scene):
        def construct(self):
            for play in plays:
                self.play(*[animation(a, k) for k, a in enumerate(play["animations"])])
                self.clear()

    return Bare, stand_ins


# --- rendering -------------------------------------------------------------------------------------


class CacheHits(logging.Handler):
    """Counts manim's "Using cached data" log records."""

    def __init__(self):
        super().__init__(logging.INFO)
        self.hits = 0

    def emit(self, record):
        if "Using cached data" in record.getMessage():
            self.hits += 1


@dataclass
class Run:
    """One render: wall seconds, video seconds, cache hits, and CPU seconds of the whole
    process and of this (the main) thread; the rest is manim's encoder threads (x264)."""

    wall: float
    video: float
    hits: int
    cpu: float
    main: float


def render(cls: type[Scene], media: Path, caching: bool) -> Run:
    """Render at -ql into ``media``."""
    settings = {"quality": "low_quality", "media_dir": str(media), "disable_caching": not caching,
                "verbosity": "INFO", "progress_bar": "none"}
    counter = CacheHits()
    log = logging.getLogger("manim")
    quiet = [(h, h.level) for h in log.handlers]
    for handler, _ in quiet:  # manim's console: warnings only; the counter sees INFO
        handler.setLevel(logging.WARNING)
    log.addHandler(counter)
    typeset.forget()  # typeset every text again, as a fresh process would
    try:
        with tempconfig(settings):
            start, cpu, main = time.perf_counter(), time.process_time(), time.thread_time()
            cls().render()
            wall = time.perf_counter() - start
            cpu, main = time.process_time() - cpu, time.thread_time() - main
    finally:
        log.removeHandler(counter)
        for handler, level in quiet:
            handler.setLevel(level)
    videos = [p for p in media.rglob(f"{cls.__name__}.mp4") if "partial" not in str(p)]
    with av.open(str(videos[0])) as container:
        seconds = container.duration / av.time_base
    return Run(wall, seconds, counter.hits, cpu, main)


def command_time(argv: list[str], media: Path, env: dict | None = None) -> tuple[float, float]:
    """Wall and CPU seconds (user + system, all its threads) of one command run from the
    repository root (its output to /dev/null: both print progress bars). The CPU time hardly
    depends on what else the machine runs; the wall time does."""
    media.mkdir()
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run(argv, cwd=ROOT, check=True, stdout=subprocess.DEVNULL,
                   stderr=subprocess.DEVNULL, env=env)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def commands_side_by_side(scratch: Path, repeat: int, quality: str,
                          trex_code: Path | None = None) -> float:
    """Section 5: ``trex render`` against plain ``manim`` on Gravity; returns the ratio of
    their best wall times (trex ÷ manim). ``trex_code``: the checkout whose trex runs
    (PYTHONPATH; None: the installed one), to compare a change with what came before."""
    bin_dir = Path(sys.executable).parent
    scene = ROOT / "scenes" / f"{SCENE_FILE}.py"

    def trex(out: Path) -> list[str]:
        return [str(bin_dir / "trex"), "render", SCENE_FILE, "-q", quality,
                "-o", str(out / f"{SCENE_NAME}.mp4")]

    def manim_cli(out: Path) -> list[str]:
        return [str(bin_dir / "manim"), f"-q{quality}", "--disable_caching",
                "--media_dir", str(out), str(scene), SCENE_NAME]

    env = None if trex_code is None else {**os.environ, "PYTHONPATH": str(trex_code)}
    runs: dict[str, list[tuple[float, float]]] = {"trex render": [], "manim": []}
    for k in range(repeat):  # interleaved, so that a slow spell of the machine hits both
        runs["trex render"].append(command_time(trex(scratch / f"trex{k}"),
                                                scratch / f"trex{k}", env))
        runs["manim"].append(command_time(manim_cli(scratch / f"manim{k}"),
                                          scratch / f"manim{k}"))
    print(f"{SCENE_NAME} at -q {quality}, each a fresh process (best of {repeat}; median), "
          f"load average {os.getloadavg()[0]:.1f} on {os.cpu_count()} cores:")
    best = {name: min(w for w, _ in done) for name, done in runs.items()}
    for name, done in runs.items():
        walls, cpus = [w for w, _ in done], [c for _, c in done]
        print(f"  {name:12s} wall {best[name]:7.2f} s ({statistics.median(walls):.2f} s)   "
              f"CPU {min(cpus):7.2f} s ({statistics.median(cpus):.2f} s)")
    ratio = best["trex render"] / best["manim"]

    def median_ratio(at: int) -> float:
        return (statistics.median(r[at] for r in runs["trex render"])
                / statistics.median(r[at] for r in runs["manim"]))

    print(f"  trex render ÷ manim: wall {ratio:.3f} (target ≤ 1.05; medians "
          f"{median_ratio(0):.3f}), CPU medians {median_ratio(1):.3f}")
    return ratio


def _main(runs: list[Run]) -> float:
    return statistics.median(r.main for r in runs)


def _encoders(runs: list[Run]) -> float:
    return statistics.median(r.cpu - r.main for r in runs)


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--skip-builds", action="store_true", help="no dry-run build times")
    parser.add_argument("--repeat", type=int, default=3,
                        help="renders of each scene for the throughput (the best counts)")
    parser.add_argument("--commands-only", action="store_true",
                        help="only trex render against plain manim (section 5)")
    parser.add_argument("--quality", choices=["l", "m", "h", "k"], default="l",
                        help="the quality of section 5")
    parser.add_argument("--trex-code", type=Path, default=None,
                        help="section 5 runs the trex of this checkout (e.g. an older one)")
    args = parser.parse_args(argv)
    logging.getLogger("manim").setLevel(logging.INFO)
    scratch = Path(tempfile.mkdtemp(prefix="trex-bench-render-"))
    if args.commands_only:
        try:
            commands_side_by_side(scratch, args.repeat, args.quality, args.trex_code)
        finally:
            shutil.rmtree(scratch, ignore_errors=True)
        return
    try:
        ours_cls = handed(getattr(load_module(SCENE_FILE), SCENE_NAME))
        scene, plays = build(ours_cls)
        graph = scene_graph(plays, scene)["plays"]
        bare_cls, stand_ins = bare_scene(graph)
        kinds = sorted({a["type"] for p in graph for a in p["animations"]})
        count = sum(len(p["animations"]) for p in graph)
        print(f"{SCENE_NAME}: {len(graph)} plays, {count} animations ({', '.join(kinds)})")
        if stand_ins:
            print(f"  bare scene plays FadeIn for: {', '.join(sorted(set(stand_ins)))}")

        render(bare_cls, scratch / "warm", caching=False)  # encoder and caches warm, not counted
        runs: dict[str, list[Run]] = {"ours": [], "bare": []}
        for k in range(args.repeat):  # interleaved, so that a slow spell of the machine hits both
            runs["ours"].append(render(ours_cls, scratch / f"ours{k}", caching=False))
            runs["bare"].append(render(bare_cls, scratch / f"bare{k}", caching=False))
        rates = {}
        for name, done in runs.items():
            best = min(done, key=lambda r: r.wall)
            rates[name] = best.video / best.wall
            print(f"{name}  (-ql, no cache): {best.video:6.2f} s video in {best.wall:6.2f} s "
                  f"= {rates[name]:.2f} video s / wall s (best of {len(done)}; median "
                  f"{statistics.median(r.wall for r in done):.2f} s)")
            print(f"      CPU (medians): main thread {_main(done):.2f} s"
                  f" + encoder threads {_encoders(done):.2f} s")
        # Both renders keep the two cores busy, so wall time follows total CPU. Were our main
        # thread as cheap as bare's, the encoders' work on our frames alone would leave:
        bare_cpu = _main(runs["bare"]) + _encoders(runs["bare"])
        print(f"CPU-bound ceiling (our main thread costing what bare's does): "
              f"{bare_cpu / (_main(runs['bare']) + _encoders(runs['ours'])):.2f}")

        if not args.skip_builds:
            print("dry-run build, s")
            total = 0.0
            for name, cls in all_scenes():
                start = time.perf_counter()
                build(cls)
                total += time.perf_counter() - start
                print(f"  {name:38s}{time.perf_counter() - start:7.2f}")
            print(f"  {'all scenes':38s}{total:7.2f}")

        cached = scratch / "cached"
        first = render(ours_cls, cached, caching=True)
        second = render(ours_cls, cached, caching=True)
        print(f"cached render: first {first.wall:.2f} s ({first.hits} hits), second "
              f"{second.wall:.2f} s with {second.hits}/{len(graph)} plays from cache "
              "(target ≤ 2 s)")
        commands_side_by_side(scratch, args.repeat, args.quality, args.trex_code)
        print(f"render throughput ratio vs bare manim: {rates['ours'] / rates['bare']:.2f}")
    finally:
        shutil.rmtree(scratch, ignore_errors=True)


if __name__ == "__main__":
    main()
