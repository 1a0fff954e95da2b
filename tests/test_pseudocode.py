"""Pseudocode in the panel (story/pseudocode.py, the registry's Entry.pseudocode): short rows in
the thesis's words for every built-in, each tied to calls its runs make, the lit row following
the running call; a heuristic of one's own carries its docstring's rows; ``--panel`` on the
commands. The scenes' panels themselves are checked in tests/test_scenes.py."""

from __future__ import annotations

import json
import textwrap
from pathlib import Path

import pytest
from click.testing import CliRunner

import tracing
from metaphors.catalog import beats as storyboard
from story.pseudocode import (
    PANELS,
    RESULT,
    PseudocodeRow,
    from_docstring,
    lit_row,
    result_row,
    to_json,
)
from story.registry import REGISTRY, entry, heuristics, names, triangulations
from story.runs import run_logged
from story.storyboard import pseudocode_of
from trex import chapter_command, chapter_pool, chapters, player_steps, render_command
from trex.cli import main
from usercode.heuristic import load_user_heuristic

ROOT = Path(__file__).resolve().parent.parent
EXAMPLE = f"{ROOT / 'examples' / 'my_heuristic.py'}:biggest_angle"
#: what the source shows and pseudocode must not: the plumbing of the implementation
PLUMBING = ("tracing.", "_check_size", "def ", "return ", "polygon.", "(polygon", "_at(")
#: polygons on which the runs take every branch their pseudocode has
POLYGONS = ("counterexample", "counterexample-twin", "gravity-snag", "lecture", "square", "star",
            "two-ears", "comb", "spiral", "random-2opt:12:3", "random-orthogonal:12:1")


def assert_rows_follow_calls(log: tracing.Log, beats, rows: tuple[PseudocodeRow, ...] | None = None):
    """Each beat's lit row covers the innermost running call that a row covers (the beat's own
    event first, when it is a note); when no running call is covered, the row is one covering a
    call begun before the beat (None if none was). Worked out from the log alone."""
    rows = pseudocode_of(log) if rows is None else rows
    covered = {c for step in rows for c in step.calls}
    running: list[str] = []
    at: dict[int, tuple[list[str], set[str]]] = {}
    begun: set[str] = set()
    for e in log.events:
        if e.kind == "call":
            running.append(e.name)
        at[e.seq] = ([*running, *([e.name] if e.kind == "note" else [])], set(begun))
        if e.kind == "call" and e.name in covered:
            begun.add(e.name)
        elif e.kind == "return":
            running.pop()
    for beat in beats:
        names_, before = at[beat.seq]
        inner = next((n for n in reversed(names_) if n in covered), None)
        where = f"{beat.action} at event {beat.seq} ({beat.caption!r})"
        if inner is not None:
            assert beat.row is not None and inner in rows[beat.row].calls, where
        elif before & covered:
            assert beat.row is not None and set(rows[beat.row].calls) & before, where
        else:
            assert beat.row is None, where


def graph_data(graph) -> dict:
    """A scene graph's data, from its JSON text or a :class:`trex.snapshot.SceneGraph`."""
    return graph.data if hasattr(graph, "data") else json.loads(graph)


def code_rows(graph_json) -> list[dict]:
    """The panel's code rows in a scene graph's final picture, in order (not the lit row's
    copy, which is in ink: ``called``)."""

    def walk(node):
        yield node
        for child in node.get("submobjects", ()):
            yield from walk(child)

    return [n for top in graph_data(graph_json)["final"] for n in walk(top)
            if n["name"].startswith("code:") and n["role"] == "idle"]


def shown_source(graph_json) -> list[tuple[str, str]]:
    """(name, text) of each source line in a scene graph's final panel, in order: a wrapped
    line's rows (``code:7``, ``code:7.2`` …) joined, every space left out (a row may end where
    a space was)."""
    lines: list[tuple[str, str]] = []
    for row in code_rows(graph_json):
        text = squeezed(row["text"])
        if "." in row["name"]:  # a continuation row
            lines[-1] = (lines[-1][0], lines[-1][1] + text)
        else:
            lines.append((row["name"], text))
    return lines


def squeezed(text: str) -> str:
    """The text without its spaces."""
    return "".join(text.split())


def _runs(name: str):
    """(polygon, heuristic) of the runs of ``name`` the tests look at."""
    extra = [("lecture", h) for h in heuristics()] if name == "divide-and-conquer" else []
    return [*extra, *((p, None) for p in POLYGONS)]


def _logs(name: str) -> list[tracing.Log]:
    return [run_logged(name, polygon, heuristic) for polygon, heuristic in _runs(name)]


# --- the registry's pseudocode --------------------------------------------------------------------


@pytest.mark.parametrize("name", names())
def test_pseudocode_is_a_few_short_rows_in_words(name):
    rows = entry(name).pseudocode
    if entry(name).source is None:  # the reference triangulation: nothing shown
        assert rows == ()
        return
    assert 3 <= len(rows) <= 10, name
    for step in rows:
        indent = len(step.text) - len(step.text.lstrip(" "))
        assert step.text.strip() and step.text == step.text.rstrip() and indent % 2 == 0, step
        assert len(step.text) <= 46, step
        assert not any(word in step.text for word in PLUMBING), step
        assert all(isinstance(c, str) and c for c in step.calls), step
    assert sum(bool(step.calls) for step in rows) >= 2


@pytest.mark.parametrize("name", [n for n in names() if entry(n).pseudocode])
def test_every_row_covers_calls_its_runs_make(name):
    """A row is lit by the traced names it lists: each of them occurs in some run."""
    made = {e.name for log in _logs(name) for e in log.events if e.kind in ("call", "note")}
    listed = {c for step in entry(name).pseudocode for c in step.calls} - {RESULT}
    assert listed <= made, listed - made


@pytest.mark.parametrize("name", [n for n in triangulations() if entry(n).pseudocode])
def test_a_triangulations_listing_ends_on_its_result(name):
    """Issue 22: the whole triangulation drawn at a run's end lights a row saying so (the
    union of the pieces, the slices, the pieces' triangles), the last row, one only: not the
    last step's row, which no longer says what is on screen."""
    rows = entry(name).pseudocode
    assert [k for k, row in enumerate(rows) if RESULT in row.calls] == [len(rows) - 1], name
    assert result_row(rows) == len(rows) - 1
    assert "triangulation of P" in rows[-1].text, name


def test_the_triangle_heuristics_share_their_frame():
    frames = {entry(n).pseudocode[:4] for n in heuristics() if n != "gravity"}
    assert len(frames) == 1
    rules = [entry(n).pseudocode[4].text for n in heuristics() if n != "gravity"]
    assert all(rule.startswith("else: D = ") for rule in rules) and len(set(rules)) == len(rules)


# --- which row is lit -----------------------------------------------------------------------------


@pytest.mark.parametrize("name", [n for n in names() if entry(n).pseudocode])
def test_each_beat_lights_the_row_of_its_running_call(name):
    for log in _logs(name):
        beats = storyboard(log)
        assert_rows_follow_calls(log, beats)
        assert sum(b.row is not None for b in beats) >= len(beats) - 1  # all but the polygon


def test_the_claim_lights_its_branch():
    rows = entry("scaling").pseudocode
    square = storyboard(run_logged("scaling", "square"))  # T holds no candidate: AC
    assert {rows[b.row].text for b in square if b.action in ("claim", "verdict")} == {
        "none: claim AC is an inner diagonal"}
    wrong = storyboard(run_logged("scaling", "counterexample"))  # D, the nearest: BD
    assert [rows[b.row].text for b in wrong[1:]] == [
        "B = the left-most vertex (lowest on ties)", "A, C = its neighbours; T = triangle ABC",
        "candidates = the other vertices inside T", "else: D = the candidate closest to B",
        "  claim BD is an inner diagonal", "  claim BD is an inner diagonal"]


@pytest.mark.parametrize("name", ["ear-clipping", "ear-clipping-naive"])
def test_every_row_of_ear_clipping_that_says_a_step_lights(name):
    """A row that says a step (not a loop's head, ending in ":") lights in some run, on
    polygons with holes too: ear clipping's "else go on to the next vertex" and "only V−1
    and V+1 change: test again" covered no call and never lit (KeyholeEars: dark under "Is
    C an ear? no", review)."""
    logs = [*_logs(name), *([run_logged(name, "keyhole")] if name == "ear-clipping" else [])]
    for log in logs:
        rows = pseudocode_of(log)
        lit = {b.row for other in logs if pseudocode_of(other) == rows
               for b in storyboard(other)} | {result_row(rows)}
        dark = [row.text for k, row in enumerate(rows)
                if k not in lit and not row.text.endswith(":")]
        assert dark == [], (name, log.meta.get("polygon"))


def test_lit_row_goes_on_from_the_row_lit_and_round_loops():
    rows = (PseudocodeRow("test", ("is_ear",)), PseudocodeRow("clip", ("clip_ear",)), PseudocodeRow("last", ("run",)))
    assert lit_row(rows, ["run", "is_ear"], 1) == 0  # round the loop
    assert lit_row(rows, ["run", "clip_ear", "helper"], 0) == 1  # innermost covered
    assert lit_row(rows, ["run"], 1) == 2
    assert lit_row(rows, ["other"], 1) is None and lit_row((), ["run"], None) is None


def test_a_saved_log_lights_the_same_rows():
    log = run_logged("gravity", "gravity-snag")
    again = tracing.Log.from_json(log.to_json())
    assert [b.row for b in storyboard(again)] == [b.row for b in storyboard(log)]


# --- a heuristic of one's own -------------------------------------------------------------------

EXPLAINED = '''
import tracing
from geometry.frame import candidates_in_triangle, leftmost_vertex, triangle_at


@tracing.traced
def angle_at_b(b, a, d):
    """The angle ABD, as a number that grows with it."""
    return (a.point[0] - b.point[0]) * (d.point[1] - b.point[1]) - (
        a.point[1] - b.point[1]) * (d.point[0] - b.point[0])


def widest(polygon):
    """Claim BD for the candidate D with the largest angle ABD.

    Pseudocode:
        B = the left-most vertex; T = ABC   [leftmost_vertex, triangle_at]
        candidates: the vertices inside T   [candidates_in_triangle]
        for each candidate D:
          how wide is the angle ABD?        [angle_at_b]
        claim BD for the widest             [claim]

    Not pseudocode any more.
    """
    b = leftmost_vertex(polygon)
    t = triangle_at(polygon, b)
    with tracing.alive(t):
        candidates = candidates_in_triangle(polygon, t)
        if not candidates:
            return t.a, t.c
        return b, max(candidates, key=lambda d: angle_at_b(b, t.a, d))
'''
WIDEST_ROWS = (
    PseudocodeRow("B = the left-most vertex; T = ABC", ("leftmost_vertex", "triangle_at")),
    PseudocodeRow("candidates: the vertices inside T", ("candidates_in_triangle",)),
    PseudocodeRow("for each candidate D:"),
    PseudocodeRow("  how wide is the angle ABD?", ("angle_at_b",)),
    PseudocodeRow("claim BD for the widest", ("claim",)),
)


@pytest.fixture
def explained(tmp_path) -> str:
    path = tmp_path / "explained.py"
    path.write_text(EXPLAINED)
    return f"{path}:widest"


def test_a_docstrings_pseudocode_is_read_and_carried_in_the_log(explained):
    heuristic = load_user_heuristic(explained)
    assert from_docstring(heuristic.raw.__doc__) == WIDEST_ROWS
    log = run_logged(explained, "counterexample")
    assert log.meta["pseudocode"] == to_json(WIDEST_ROWS)
    beats = storyboard(log)
    assert_rows_follow_calls(log, beats)
    assert [WIDEST_ROWS[b.row].text for b in beats if b.action in ("claim", "verdict")] == [
        "claim BD for the widest"] * 2
    assert any(b.row == 3 for b in beats if b.action == "call")  # angle_at_b
    again = tracing.Log.from_json(log.to_json())
    assert pseudocode_of(again) == WIDEST_ROWS and storyboard(again) == beats


def test_a_heuristic_without_pseudocode_carries_none():
    log = run_logged(EXAMPLE, "counterexample")
    assert "pseudocode" not in log.meta and pseudocode_of(log) == ()
    assert all(b.row is None for b in storyboard(log))


def test_a_heuristics_scene_shows_its_docstrings_pseudocode_else_its_source(explained):
    from metaphors.scene import scene_for_heuristic
    from trex.scene_graph import build_graph

    shown = code_rows(build_graph(scene_for_heuristic(explained).handed()))
    assert [r["text"] for r in shown] == [s.text.strip() for s in WIDEST_ROWS]
    assert [r["name"] for r in shown] == [f"code:{k}" for k in range(1, len(WIDEST_ROWS) + 1)]
    source = code_rows(build_graph(scene_for_heuristic(explained).with_panel("source").handed()))
    assert source[0]["text"] == "def widest(polygon):"
    own = build_graph(scene_for_heuristic(EXAMPLE).handed())  # no pseudocode: its source
    code = run_logged(EXAMPLE, "counterexample").meta["code"]
    listing = [(f"code:{k}", squeezed(text)) for k, (_, text) in enumerate(code, start=1)]
    shown = shown_source(own)  # the window of it that holds the last lit line
    first = listing.index(shown[0])
    assert shown == listing[first:first + len(shown)] and shown[-1] == listing[-1]
    notes = [n["text"] for n in graph_data(own)["final"] for n in [n, *n.get("submobjects", ())]
             if n["name"] == "panel:above"]
    assert notes == ([f"⋮ {first} lines above"] if first else [])


def test_docstring_rows_keep_indentation_and_may_cover_nothing():
    doc = textwrap.dedent("""\
        Title.

        Pseudocode:
          first  [a]
            inside [b, c]
          plain text, [] kept as text? no: the brackets at the end are the calls []
        """)
    assert from_docstring(doc) == (
        PseudocodeRow("first", ("a",)), PseudocodeRow("  inside", ("b", "c")),
        PseudocodeRow("plain text, [] kept as text? no: the brackets at the end are the calls"))
    assert from_docstring("Pseudocode:\n\n\n") == () and from_docstring("Pseudocode") == ()


# --- the commands --------------------------------------------------------------------------------


def run(*args):
    result = CliRunner().invoke(main, list(args))
    return result.exit_code, result.stdout, result.stderr


@pytest.mark.parametrize("panel", [*PANELS, None])
def test_trex_render_hands_the_panel_to_the_scene(tmp_path, monkeypatch, panel):
    seen = {}

    def fake_render(cls, output, fmt, quality, **kw):
        seen["panel"] = cls.panel
        output.write_bytes(b"x")
        return output

    monkeypatch.setattr(render_command, "render_into", fake_render)
    args = ["render", "scaling", "-o", str(tmp_path / "s.mp4")]
    code, _, stderr = run(*args, *(["--panel", panel] if panel else []))
    assert code == 0, stderr
    assert seen == {"panel": panel or "pseudocode"}


def test_trex_player_hands_the_panel_to_the_scene(tmp_path, monkeypatch):
    seen = {}

    def fake(cls, log, folder, *args, **kwargs):
        seen["panel"] = cls.panel
        (folder / "steps").mkdir()
        (folder / "steps" / "001.png").write_bytes(b"png")
        return [player_steps.Still("steps/001.png", "The polygon", None, "polygon")]

    monkeypatch.setattr(player_steps, "render_steps", fake)
    code, _, stderr = run("player", "gravity", "--panel", "source", "-o", str(tmp_path / "p"))
    assert code == 0, stderr
    assert seen == {"panel": "source"}


def test_a_lecture_chapter_gets_the_panel_as_an_argument(tmp_path, monkeypatch):
    started = {}

    class Process:
        def __init__(self, command, **kwargs):
            started["command"] = command

    monkeypatch.setattr(chapter_pool.subprocess, "Popen", Process)
    chapter = chapters.Chapter(1, "gravity", "Gravity", "scenes/gravity.py", None)
    chapter_pool._start(0, chapter, tmp_path, tmp_path, "l", None, "source")
    given = chapter_command.chapter.make_context("chapter", started["command"][4:]).params
    assert (given["quality"], given["polygon"], given["panel"]) == ("l", None, "source")
    seen = {}

    def fake_render(cls, output, *args, **kwargs):
        seen["panel"] = cls.panel
        return output

    monkeypatch.setattr(chapter_command, "render_into", fake_render)
    code = chapter_command.render_chapter(str(ROOT / "scenes" / "gravity.py"), "",
                                          str(tmp_path / "g.mp4"), "l", "", "source")
    assert code == 0 and seen == {"panel": "source"}


@pytest.mark.parametrize("command", [["render", "scaling"], ["player", "scaling", "-o", "p"],
                                     ["lecture"]])
def test_a_bad_panel_is_one_line_and_exit_2(tmp_path, monkeypatch, command):
    monkeypatch.chdir(tmp_path)
    code, stdout, stderr = run(*command, "--panel", "slides")
    assert code == 2 and stdout == ""
    assert "'slides' is not one of 'pseudocode', 'source'" in stderr
    assert stderr.count("\n") == 1, stderr


def test_a_scene_refuses_an_unknown_panel():
    from metaphors.scene import TraceScene

    with pytest.raises(ValueError, match="unknown panel 'slides'"):
        TraceScene.with_panel("slides")
    assert TraceScene.panel == "pseudocode" and TraceScene.with_panel("source").panel == "source"


def test_a_builtins_log_carries_no_pseudocode():
    """The meta of a built-in's log carries no pseudocode: the registry has it."""
    for name in REGISTRY:
        log = run_logged(name, entry(name).polygon)
        assert "pseudocode" not in json.loads(log.to_json())["meta"], name


#: the traced calls that run a diagonal finder taught by name, and the name it was taught by
_TAUGHT_FINDERS = {"sweep_at": "translation-correct", "gravity_at": "gravity"}


@pytest.mark.parametrize("name", names())
def test_a_row_running_a_taught_finder_names_it(name):
    """panel7 (review of chapter 4): a row lit while a heuristic taught by name runs says
    that name: prune and search's "(V convex: the sweep; else gravity)" left the viewer to
    guess which of the sweeps (Translation, wrong; Correct Translation, the line parallel to
    AC) it was."""
    from story.registry import spoken

    for row in entry(name).pseudocode:
        for call in row.calls:
            if call in _TAUGHT_FINDERS:
                assert spoken(_TAUGHT_FINDERS[call]) in row.text, (name, row.text)
