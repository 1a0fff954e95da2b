"""A heuristic of one's own (examples/my_heuristic.py): loaded, run, rendered with the generic
panel (dry run), checked through `trex diagonal`; bad specs are one line and exit 2."""

import json
import os
import signal
import sys
import tempfile
import textwrap
import threading
import types
from pathlib import Path

import pytest
from click.testing import CliRunner

import tracing
from geometry.io import read_polygon
from metaphors.catalog import beats as storyboard
from story.runs import run_logged
from trex.cli import main
from usercode.errors import UserHeuristicError
from usercode.heuristic import load_user_heuristic

ROOT = Path(__file__).resolve().parent.parent
EXAMPLE = f"{ROOT / 'examples' / 'my_heuristic.py'}:biggest_angle"


def run(*args):
    result = CliRunner().invoke(main, list(args))
    return result.exit_code, result.stdout, result.stderr


def write(folder: Path, name: str, text: str) -> str:
    path = folder / name
    path.write_text(textwrap.dedent(text))
    return str(path)


# --- the run and its beats ----------------------------------------------------------------------


def test_the_log_names_the_heuristic_and_carries_its_source():
    log = run_logged(EXAMPLE, "counterexample")
    assert log.meta["user_heuristic"] == "biggest_angle"
    assert log.meta["shown"] == "biggest_angle"
    code = dict((line, text) for line, text in log.meta["code"])
    assert "def biggest_angle(polygon):" in code.values()
    # one traced call for the whole run, and the claim entered like the built-ins do
    calls = [e for e in log.events if e.kind == "call" and e.depth == 0]
    assert [c.name for c in calls] == ["biggest_angle"]
    claims = log.find(kind="enter", target="BE")
    assert len(claims) == 1 and claims[0].state["labels"] == ["B", "E"]
    # a saved log gives the same beats
    assert storyboard(tracing.Log.from_json(log.to_json())) == storyboard(log)


def test_storyboard_generic_beats_light_the_users_lines():
    log = run_logged(EXAMPLE, "counterexample")
    beats = storyboard(log)
    actions = [b.action for b in beats]
    assert actions[0] == "polygon" and actions[-2:] == ["claim", "verdict"]
    shapes = [b for b in beats if b.action == "shape"]
    assert [b.data["event"] for b in shapes] == ["enter", "change", "exit"]
    assert shapes[0].data["key"] == "best"
    assert shapes[0].data["state"] == {"kind": "segment", "points": [[0.4, 2.5], [4, 3.5]]}
    calls = [b for b in beats if b.action == "call" and b.call.startswith("angle_at_b")]
    assert [b.call for b in calls] == ["angle_at_b(B, A, D) → 69.4", "angle_at_b(B, A, E) → 89.2"]
    assert calls[0].roles == {"B": "called", "A": "argument", "D": "argument"}
    code = dict((line, text.strip()) for line, text in log.meta["code"])
    assert code[beats[-1].line] == "return b, best"  # the claim lights the user's return
    assert beats[-1].data["ok"] is True


def test_the_claim_lights_the_return_the_run_left_by():
    # square: no candidate in T, so the example leaves by its early return
    log = run_logged(EXAMPLE, "square")
    code = dict((line, text.strip()) for line, text in log.meta["code"])
    assert code[storyboard(log)[-1].line] == "return t.a, t.c"
    claims = log.find(name="claim")
    assert [e.kind for e in claims] == ["call", "return"]
    assert {code.get(e.line) for e in claims} == {"return t.a, t.c"}


def test_the_log_is_the_same_under_a_debugger_or_coverage():
    def tracer(frame, event, arg):
        return None

    plain = run_logged(EXAMPLE, "counterexample")
    previous = sys.gettrace()
    sys.settrace(tracer)
    try:
        traced = run_logged(EXAMPLE, "counterexample")
    finally:
        sys.settrace(previous)
    assert traced.to_json() == plain.to_json()


def test_several_returns_one_return_and_none_to_name(tmp_path):
    path = write(tmp_path, "returns.py", """
        from geometry.frame import leftmost_vertex

        def single(polygon):
            b = leftmost_vertex(polygon)
            return b.index, (b.index + 2) % polygon.n

        def checked(polygon):
            b = leftmost_vertex(polygon)
            if polygon.n > 4:
                return b.index, (b.index + 2) % polygon.n
            b = leftmost_vertex(polygon)
            return b.index, (b.index + 2) % polygon.n
    """)
    lines = Path(path).read_text().splitlines()
    for name, polygon, expected in [("single", "counterexample", 6),
                                    ("checked", "counterexample", 11),
                                    ("checked", "square", 13)]:
        heuristic = load_user_heuristic(f"{path}:{name}")
        with tracing.record() as log:
            heuristic.run(read_polygon(polygon))
        assert [e.line for e in log.find(name="claim")] == [expected] * 2, (name, polygon)
        assert lines[expected - 1].strip().startswith("return ")
    # a callable without source of its own: no return to name, the claim is still made once
    partial = write(tmp_path, "partial.py", """
        import functools

        def pair(first, polygon):
            return first, 3

        f = functools.partial(pair, 1)
    """)
    with tracing.record() as log:
        diagonal = load_user_heuristic(f"{partial}:f").run(read_polygon("counterexample"))
    assert diagonal.name == "BD" and len(log.find(kind="call", name="claim")) == 1


def _claim_lines(spec: str, polygon: str) -> list:
    heuristic = load_user_heuristic(spec)
    with tracing.record() as log:
        heuristic.run(read_polygon(polygon))
    return [e.line for e in log.find(name="claim")]


def _line_of(path: str, text: str) -> int:
    """The 1-based line of the file that holds ``text`` (exactly once)."""
    found = [n for n, line in enumerate(Path(path).read_text().splitlines(), 1) if text in line]
    assert len(found) == 1, (text, found)
    return found[0]


@pytest.mark.parametrize(("limit", "polygon", "lit"), [
    (100, "counterexample", "return b.index, (b.index + 2) % polygon.n"),  # the loop runs out
    (2, "counterexample", "return b.index, (b.index + k) % polygon.n"),  # it returns inside
])
def test_a_loop_that_runs_out_lights_the_later_return(tmp_path, limit, polygon, lit):
    path = write(tmp_path, "loop.py", f"""
        from geometry.frame import leftmost_vertex

        def scan(polygon):
            b = leftmost_vertex(polygon)
            for k in range(2, polygon.n):
                if k >= {limit}:
                    return b.index, (b.index + k) % polygon.n
            return b.index, (b.index + 2) % polygon.n
    """)
    assert _claim_lines(f"{path}:scan", polygon) == [_line_of(path, lit)] * 2


def test_a_function_that_logs_nothing_lights_the_return_that_ran(tmp_path):
    path = write(tmp_path, "quiet.py", """
        def quiet(polygon):
            if polygon.n > 4:
                return 1, 3
            return 0, 2
    """)
    assert _claim_lines(f"{path}:quiet", "counterexample") == [_line_of(path, "return 1, 3")] * 2
    assert _claim_lines(f"{path}:quiet", "square") == [_line_of(path, "return 0, 2")] * 2


def test_nested_functions_lambdas_and_classes_keep_their_returns(tmp_path):
    path = write(tmp_path, "nested.py", """
        def nested(polygon):
            def smaller(a, b):
                if a < b:
                    return a
                return b

            class Pick:
                def first(self):
                    return 1

            def done():
                return None

            key = lambda i: -i
            try:
                if polygon.n > 4:
                    return Pick().first(), smaller(3, 4)
                return sorted([0, 2], key=key)
            finally:
                done()
    """)
    # done() runs after the return: had its own return been rewritten, it would be lit
    assert _claim_lines(f"{path}:nested", "counterexample") == [
        _line_of(path, "return Pick().first(), smaller(3, 4)")] * 2
    assert _claim_lines(f"{path}:nested", "square") == [
        _line_of(path, "return sorted([0, 2], key=key)")] * 2
    # only the heuristic's own code calls the hook
    raw = load_user_heuristic(f"{path}:nested").raw

    def codes(code):
        for const in code.co_consts:
            if isinstance(const, types.CodeType):
                yield const
                yield from codes(const)

    inner = {c.co_name: c for c in codes(raw.__code__)}
    assert {"smaller", "Pick", "first", "done", "<lambda>"} <= set(inner)
    assert "__trex_answer__" in raw.__code__.co_names
    assert not [name for name, c in inner.items() if "__trex_answer__" in c.co_names]


def test_a_lambda_heuristic_lights_its_line(tmp_path):
    path = write(tmp_path, "short.py", """
        from geometry.frame import leftmost_vertex

        first_and_third = lambda polygon: (1, 3)
        from_b = lambda polygon: (
            leftmost_vertex(polygon), 3)
    """)
    assert _claim_lines(f"{path}:first_and_third", "counterexample") == [
        _line_of(path, "first_and_third = lambda")] * 2
    heuristic = load_user_heuristic(f"{path}:from_b")
    with tracing.record() as log:
        assert heuristic.run(read_polygon("counterexample")).name == "BD"
    # the claim on the line where the body starts, the call in it on its own line
    assert [e.line for e in log.find(name="claim")] == [_line_of(path, "from_b = lambda")] * 2
    assert [e.line for e in log.find(name="leftmost_vertex")] == [
        _line_of(path, "leftmost_vertex(polygon), 3)")] * 2


def test_decorated_heuristics_run_rewritten(tmp_path):
    path = write(tmp_path, "decorated.py", """
        import functools

        import tracing
        from geometry.frame import leftmost_vertex

        def noted(f):
            @functools.wraps(f)
            def wrapper(polygon):
                tracing.note("noted", n=polygon.n)
                return f(polygon)
            return wrapper

        @tracing.traced
        def traced_one(polygon):
            b = leftmost_vertex(polygon)
            for k in range(2, polygon.n):
                if k > 100:
                    return b.index, k
            return b.index, (b.index + 2) % polygon.n

        @noted
        def noted_one(polygon):
            if polygon.n > 4:
                return 1, 3
            return 0, 2
    """)
    spec = f"{path}:traced_one"
    with tracing.record() as log:
        load_user_heuristic(spec).run(read_polygon("square"))
    assert [e.line for e in log.find(name="claim")] == [
        _line_of(path, "return b.index, (b.index + 2) % polygon.n")] * 2
    assert [e.depth for e in log.find(kind="call", name="traced_one")] == [0]  # traced once
    with tracing.record() as log:
        load_user_heuristic(f"{path}:noted_one").run(read_polygon("counterexample"))
    assert [e.line for e in log.find(name="claim")] == [_line_of(path, "return 1, 3")] * 2
    assert [e.line for e in log.find(kind="note", name="noted")] == [
        _line_of(path, 'tracing.note("noted"')]  # the decorator ran, around the rewritten body


def test_the_files_other_lines_are_its_own(tmp_path):
    path = write(tmp_path, "lines.py", """
        import tracing

        @tracing.traced
        def pick(a, b):
            return a, b

        def shaped(polygon):
            with tracing.Shape("s", "segment", points=[[0, 0], [1, 1]]) as s:
                s.update(points=[[0, 0], [2, 2]])
            if polygon.n == 4:
                raise RuntimeError("a square")
            if polygon.n == 3:
                return (1,
                        1 // (polygon.n - 3))
            return (
                pick(1, 3))
    """)
    spec = f"{path}:shaped"
    heuristic = load_user_heuristic(spec)
    with tracing.record() as log:
        heuristic.run(read_polygon("counterexample"))
    shape = _line_of(path, "tracing.Shape(")
    assert [(e.kind, e.line) for e in log.find(target="s")] == [
        ("enter", shape), ("change", shape + 1), ("exit", shape)]
    assert [e.line for e in log.find(name="pick")] == [_line_of(path, "pick(1, 3))")] * 2
    assert [e.line for e in log.find(name="claim")] == [_line_of(path, "pick(1, 3))") - 1] * 2
    # tracebacks name the file's lines, also inside a rewritten return
    for polygon, text in [("square", 'raise RuntimeError("a square")'),
                          ("triangle", "1 // (polygon.n - 3))")]:
        with pytest.raises(UserHeuristicError) as caught:
            heuristic.run(read_polygon(polygon))
        assert str(caught.value).endswith(f"(lines.py, line {_line_of(path, text)})")
    # a debugger or coverage sees the same line events as for the file compiled as it is
    plain: dict = {}
    exec(compile(Path(path).read_text(), path, "exec"), plain)

    def line_events(function):
        seen = []

        def tracer(frame, event, arg):
            if frame.f_code.co_name == "shaped":
                seen.append((event, frame.f_lineno))
            return tracer

        previous = sys.gettrace()
        sys.settrace(tracer)
        try:
            function(read_polygon("counterexample"))
        finally:
            sys.settrace(previous)
        return seen

    assert line_events(heuristic.raw) == line_events(plain["shaped"])
    assert heuristic.raw.__code__.co_firstlineno == plain["shaped"].__code__.co_firstlineno


def test_no_answer_is_one_line_and_the_module_runs_once(tmp_path, monkeypatch):
    path = write(tmp_path, "none.py", """
        import os

        with open(os.environ["TREX_TEST_RUNS"], "a") as runs:
            runs.write("ran\\n")

        def bare(polygon):
            if polygon.n > 4:
                return
            return 1, 3

        def falls_off(polygon):
            polygon.n
    """)
    runs = tmp_path / "runs.txt"
    monkeypatch.setenv("TREX_TEST_RUNS", str(runs))
    for name in ("bare", "falls_off"):
        heuristic = load_user_heuristic(f"{path}:{name}")
        with pytest.raises(UserHeuristicError) as caught:
            heuristic.run(read_polygon("counterexample"))
        assert str(caught.value).startswith(f"{name} returned None: expected a Diagonal")
    assert _claim_lines(f"{path}:bare", "square") == [_line_of(path, "return 1, 3")] * 2
    assert runs.read_text() == "ran\n" * 3  # once per load, never twice


def test_runs_in_two_threads_keep_their_own_returns(tmp_path):
    path = write(tmp_path, "threads.py", """
        import functools
        import threading

        returned = threading.Event()  # set by the test once `second` has returned
        waiting = threading.Event()

        def wait_for_the_other(f):
            @functools.wraps(f)
            def wrapper(polygon):
                answer = f(polygon)  # its return line is recorded now …
                waiting.set()
                returned.wait(10)  # … and read only after the other thread's return
                return answer
            return wrapper

        @wait_for_the_other
        def first(polygon):
            return 1, 3

        def second(polygon):
            return 0, 2
    """)
    first, second = (load_user_heuristic(f"{path}:{name}") for name in ("first", "second"))
    waiting, returned = (first.raw.__globals__[k] for k in ("waiting", "returned"))  # its load
    seen = {}

    def run_first():
        with tracing.record() as log:
            first.run(read_polygon("counterexample"))
        seen["first"] = [e.line for e in log.find(name="claim")]

    thread = threading.Thread(target=run_first)
    thread.start()
    try:
        assert waiting.wait(10)
        with tracing.record() as log:
            second.run(read_polygon("counterexample"))
        seen["second"] = [e.line for e in log.find(name="claim")]
    finally:
        returned.set()
        thread.join(10)
    assert seen == {"first": [_line_of(path, "return 1, 3")] * 2,
                    "second": [_line_of(path, "return 0, 2")] * 2}


def test_builtin_logs_get_no_generic_beats():
    for algorithm in ("scaling", "gravity"):
        actions = {b.action for b in storyboard(run_logged(algorithm, "counterexample"))}
        assert not actions & {"shape", "call"}


# --- the scene, in dry run ------------------------------------------------------------------------


def _dry_render(spec: str, polygon: str | None, monkeypatch):
    from manim import tempconfig

    from metaphors.scene import scene_for_heuristic

    cls = scene_for_heuristic(spec).handed(polygon)  # its run, on the polygon if given
    played = []
    settings = {"dry_run": True, "disable_caching": True, "verbosity": "WARNING",
                "progress_bar": "none", "media_dir": tempfile.mkdtemp(prefix="trex-test-")}
    with tempconfig(settings):
        scene = cls(skip_animations=True)  # end states only: no frames drawn
        original = scene.play

        def play(*args, **kwargs):
            animations = scene.compile_animations(*args, **{k: v for k, v in kwargs.items()
                                                            if k == "run_time"})
            played.extend((type(a).__name__, getattr(a.mobject, "name", "")) for a in animations)
            return original(*args, **kwargs)

        scene.play = play
        scene.render()
    return cls, scene, played


@pytest.mark.parametrize(("polygon", "ok"), [(None, True), ("counterexample-twin", False)])
def test_scene_plays_the_generic_beats(polygon, ok, monkeypatch):
    cls, scene, played = _dry_render(EXAMPLE, polygon, monkeypatch)
    assert cls.title.startswith("biggest_angle: Claim BD for the candidate D")
    actions = [b.action for b in scene.played_beats]
    assert {"shape", "call", "claim", "verdict"} <= set(actions)
    assert ("Create", "shape:best") in played  # the shape appeared …
    assert ("Transform", "shape:best") in played  # … moved to the better candidate …
    assert ("FadeOut", "shape:best") in played  # … and went
    assert "shape:best" not in scene.played_board.objects
    verdict = scene.played_beats[-1]
    assert verdict.action == "verdict" and verdict.data["ok"] is ok
    assert ("FadeIn", "tick" if ok else "cross") in played
    if not ok:
        assert ("Create", "edge:C–D") in played  # the edge the claim crosses
    rows = [text.strip() for _, text in scene.played_board.panel.code_lines]
    assert rows[0] == "def biggest_angle(polygon):" and rows[-1] == "return b, best"


def test_scene_for_heuristic_errors_and_scene_classes(tmp_path):
    from metaphors.scene import scene_for_heuristic

    with pytest.raises(UserHeuristicError, match="no such file"):
        scene_for_heuristic(f"{tmp_path}/missing.py:f")
    path = write(tmp_path, "scene_file.py", """
        from manim import Scene

        class Still(Scene):
            pass
    """)
    assert scene_for_heuristic(f"{path}:Still").__name__ == "Still"


# --- trex diagonal -------------------------------------------------------------------------------


def test_trex_diagonal_with_the_example_json():
    code, out, err = run("diagonal", "--heuristic", EXAMPLE, "counterexample",
                         "counterexample-twin", "--json")
    assert code == 1, err  # a finding: its claim on the twin is not an inner diagonal
    first, second = (json.loads(line) for line in out.splitlines())
    assert first["polygon"] == "counterexample"
    assert first["inner"] is True and first["why"] is None and sorted(first["diagonal"]) == [0, 3]
    assert second["inner"] is False and second["why"].startswith("B–E crosses edge C–D")


def test_trex_diagonal_with_the_example_relative_path_human():
    cwd = os.getcwd()
    os.chdir(ROOT)
    try:
        code, out, _ = run("diagonal", "--heuristic", "examples/my_heuristic.py:biggest_angle",
                           "counterexample")
    finally:
        os.chdir(cwd)
    assert code == 0
    assert out == ("counterexample: examples/my_heuristic.py:biggest_angle claims BE "
                   "(input vertices 0 and 3): inner diagonal\n")


@pytest.mark.parametrize("answer", [
    "claim(polygon.vertex(1), polygon.vertex(3))",  # a Diagonal it claimed itself
    "Diagonal(polygon.vertex(1), polygon.vertex(3))",
    "(1, 3)", "['B', 'D']", "(polygon.vertex(1), 'D')", "(numpy.int64(1), 3)",
])
def test_every_answer_form_is_one_claim(tmp_path, answer):
    path = write(tmp_path, "forms.py", f"""
        import numpy
        from geometry.frame import Diagonal, claim

        def mine(polygon):
            return {answer}
    """)
    heuristic = load_user_heuristic(f"{path}:mine")
    with tracing.record(user_heuristic=heuristic.name) as log:
        diagonal = heuristic.run(read_polygon("counterexample"))
    assert diagonal.name == "BD"
    assert len(log.find(kind="call", name="claim")) == 1
    assert [b.action for b in storyboard(log)][-2:] == ["claim", "verdict"]


BAD_SPECS = {
    "missing file": ("{d}/nope.py:f", "error: {d}/nope.py: no such file"),
    "no function named": ("{d}/good.py", "name the function too, as {d}/good.py:FUNCTION"),
    "syntax error": ("{d}/broken.py:f", "{d}/broken.py:2: syntax error: '(' was never closed"),
    "fails to import": ("{d}/imports.py:f", "{d}/imports.py:1: ModuleNotFoundError while "
                        "loading: No module named 'no_such_module_here'"),
    "missing function": ("{d}/good.py:nothing", "{d}/good.py: no function 'nothing' "
                         "(it defines: good, pair)"),
    "not callable": ("{d}/good.py:LIMIT", "{d}/good.py: 'LIMIT' is an int, not a function"),
    "wrong arity": ("{d}/good.py:pair", "{d}/good.py: pair() must take one argument, the "
                    "polygon"),
    "unknown name": ("nonesuch", "error: unknown heuristic 'nonesuch' (try 'main diagonal "
                     "--help')"),
    "raises": ("{d}/good.py:good", "error: counterexample: good raised ZeroDivisionError: "
               "division by zero (good.py, line 5)"),
    "bad answer": ("{d}/answers.py:f", "error: counterexample: f returned ('B', 'Q'): 'Q' is not "
                   "a vertex label (A … E)"),
}


@pytest.mark.parametrize("case", list(BAD_SPECS))
def test_bad_specs_are_one_line_and_exit_2(tmp_path, case):
    write(tmp_path, "good.py", """
        LIMIT = 3

        def good(polygon):
            return 1 / 0

        def pair(a, b):
            return a, b
    """)
    write(tmp_path, "broken.py", "def f(polygon):\n    return (1,\n")
    write(tmp_path, "imports.py", "import no_such_module_here\n")
    write(tmp_path, "answers.py", "def f(polygon):\n    return 'B', 'Q'\n")
    spec, expected = (s.format(d=tmp_path) for s in BAD_SPECS[case])
    code, out, err = run("diagonal", "--heuristic", spec, "counterexample")
    assert code == 2
    assert out == ""
    assert err.count("\n") == 1 and err.startswith("error: ")
    assert expected in err
    assert "Traceback" not in err


# --- trex render routes file.py:function to the generic scene -------------------------------------


def test_trex_render_builds_the_generic_scene(tmp_path, monkeypatch):
    from trex import render_command

    seen = {}

    def fake_render_into(cls, target, fmt, quality, **kwargs):
        seen["cls"] = cls
        target.write_bytes(b"")
        return target

    monkeypatch.setattr(render_command, "render_into", fake_render_into)
    code, out, err = run("render", EXAMPLE, "--polygon", "counterexample-twin",
                         "-o", str(tmp_path / "mine.mp4"))
    assert code == 0, err
    assert out == f"{tmp_path / 'mine.mp4'}\n"
    assert seen["cls"].algorithm == EXAMPLE
    assert seen["cls"].title.startswith("biggest_angle: ")


def test_trex_render_bad_spec_is_one_line(tmp_path, monkeypatch):
    from trex import render_command

    monkeypatch.setattr(render_command, "render_into", lambda *a, **k: pytest.fail("rendered"))
    path = write(tmp_path, "mine.py", "def f(polygon):\n    return 1, 3\n")
    code, out, err = run("render", f"{path}:g", "-o", str(tmp_path / "x.mp4"))
    assert code == 2 and out == ""
    assert err == f"error: {path}:g: {path}: no function 'g' (it defines: f)\n"


# --- what the user's code may do besides answering (issue 24 items 5 and 6) --------------------

ENDINGS = '''
import os, signal, sys, time

def quits(polygon):
    sys.exit("done")

def own_interrupt(polygon):
    raise KeyboardInterrupt

def swallowed_exit(polygon):
    try:
        sys.exit(1)
    except SystemExit:
        return 1, 3

def ctrl_c(polygon):
    os.kill(os.getpid(), signal.SIGINT)
    for _ in range(100):  # short sleeps: the process's signal may land on another thread
        time.sleep(0.1)   # (xdist's), which does not wake one long sleep in this one

def chatty(polygon):
    print("thinking")
    return 1, 3
'''


@pytest.fixture
def endings(tmp_path):
    path = write(tmp_path, "endings.py", ENDINGS)
    return lambda name: load_user_heuristic(f"{path}:{name}")


def test_its_own_exit_or_interrupt_is_an_error_of_the_function(endings):
    from usercode.errors import UserHeuristicExit

    polygon = read_polygon("counterexample")
    with pytest.raises(UserHeuristicExit, match=r"^quits called sys\.exit\('done'\) "
                                                r"\(endings\.py, line 5\)"):
        endings("quits").run(polygon)
    with pytest.raises(UserHeuristicExit, match=r"^own_interrupt raised KeyboardInterrupt"):
        endings("own_interrupt").run(polygon)
    assert endings("swallowed_exit").run(polygon).name == "BD"  # what it catches is its own


def test_a_real_ctrl_c_passes_through_as_the_interrupt_it_is(endings):
    """SIGINT while the function runs is the command's: KeyboardInterrupt (Python's handler),
    or the interrupt of the handler in force (trex render's), never the function's error."""
    from trex.render_command import Interrupted, interrupts_raise

    polygon = read_polygon("counterexample")
    # The premise, set rather than assumed: Python's own handler, SIGINT not blocked. A suite
    # started in the background by a non-interactive shell (`make test &`, as a runner may)
    # starts with SIGINT ignored (POSIX), and Python keeps SIG_IGN: then nothing raises here.
    before = signal.signal(signal.SIGINT, signal.default_int_handler)
    mask = signal.pthread_sigmask(signal.SIG_UNBLOCK, {signal.SIGINT})
    try:
        with pytest.raises(KeyboardInterrupt) as caught:
            endings("ctrl_c").run(polygon)
        assert not isinstance(caught.value, UserHeuristicError)
        with interrupts_raise(), pytest.raises(Interrupted):
            endings("ctrl_c").run(polygon)
    finally:
        signal.signal(signal.SIGINT, before)
        signal.pthread_sigmask(signal.SIG_SETMASK, mask)


def test_its_prints_go_to_stderr(endings, capsys):
    endings("chatty").run(read_polygon("counterexample"))
    captured = capsys.readouterr()
    assert captured.out == "" and captured.err == "thinking\n"


def test_off_the_main_thread_its_interrupt_is_its_error(endings):
    from usercode.errors import UserHeuristicExit

    errors = []

    def run():
        try:
            endings("own_interrupt").run(read_polygon("counterexample"))
        except BaseException as exc:  # what came out is the test
            errors.append(exc)

    thread = threading.Thread(target=run)
    thread.start()
    thread.join()
    assert len(errors) == 1 and isinstance(errors[0], UserHeuristicExit)
