"""Issue 22 item 1, the taught words: the thesis's names from one table, crossings named by
their edge, short numbers, the pseudocode naming the picture's own vertices, no code in a
heuristic of one's own's captions — and the words rule of item 10 able to fail."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pytest

import tracing
from geometry.diagonals import find_diagonal
from geometry.polygon import Polygon
from geometry.samples import make_sample
from story.registry import REGISTRY, SPOKEN, entry, spoken
from story.runs import record_user_run
from story.storyboard import (
    pseudocode_of,
    run_vertices,
    spoken_pseudocode,
    staged_pseudocode,
    storyboard,
)
from tests.reading_rules import unspoken_words
from usercode.heuristic import load_user_heuristic, run_heuristic

EXAMPLES = Path(__file__).resolve().parents[1] / "examples"


def _log(heuristic: str, sample: str) -> tracing.Log:
    with tracing.record(algorithm=heuristic) as log:
        find_diagonal(Polygon.from_points(make_sample(sample)), heuristic)
    return log


def test_every_algorithm_has_one_spoken_name_and_its_titles_use_it():
    assert set(SPOKEN) == set(REGISTRY)
    for name, said in SPOKEN.items():
        assert "-" not in said.name and said.name != name, name  # no slug on screen
        assert entry(name).title.startswith(spoken(name, start=True) + ": "), name
    assert spoken("scaling-correct") == "Correct Scaling"
    assert spoken("rotation", first=True) == "Rotation (the clock hand)"
    assert spoken("gravity", first=True) == "Gravity (the ball on a rubber band)"


def test_a_crossing_is_named_by_its_edge_not_its_coordinates():
    verdict = storyboard(_log("scaling", "counterexample"))[-1]
    assert verdict.caption == "✗ BD is not an inner diagonal: BD crosses edge E–A"
    assert verdict.why.startswith("B–D crosses edge E–A at (")  # the command line's text stays


def test_the_pseudocode_names_the_vertex_the_run_picked():
    """Rotation the other way picks E on the twin: the lit row says E, not the screen's D."""
    log = _log("rotation-ccw", "counterexample-twin")
    assert run_vertices(log) == {"A": "A", "B": "B", "C": "C", "D": "E"}
    rows = [step.text.strip() for step in spoken_pseudocode(log)]
    assert "else: E = first hit of a hand at B set to C" in rows
    assert "claim BE is an inner diagonal" in rows
    assert not any("D" in row.split() or "BD" in row for row in rows), rows
    assert [s.calls for s in spoken_pseudocode(log)] == [s.calls for s in pseudocode_of(log)]


def test_the_pseudocode_keeps_its_placeholders_when_the_run_agrees():
    log = _log("scaling", "counterexample")  # picks D: nothing to rename
    assert spoken_pseudocode(log) == pseudocode_of(log)


def _with_an_empty_pick_first(log: tracing.Log) -> tracing.Log:
    """The log with a call of ``pick`` that returns no vertex (None, as a pick that finds no
    candidate) just before the run's own pick; every seq, and each event's call, renumbered."""
    at = next(e.seq for e in log.events if e.kind == "call" and e.name == "pick")
    call = log.events[at]
    back = next(e for e in log.events if e.kind == "return" and e.call == at)
    extra = [replace(call, seq=-2), replace(back, seq=-1, call=-2, result=None)]
    events = [*log.events[:at], *extra, *log.events[at:]]
    seqs = {e.seq: k for k, e in enumerate(events)}
    return tracing.Log(dict(log.meta), [
        replace(e, seq=k, call=None if e.call is None else seqs[e.call])
        for k, e in enumerate(events)])


def test_the_pseudocode_names_the_pick_only_once_the_pick_returns_it():
    """The placeholder D became the run's vertex at the first return of ``pick``, whatever it
    returned: a pick that found nothing, before the real one, put "D = the candidate
    nearest to C" with the run's D on screen before the run had chosen it."""
    log = _with_an_empty_pick_first(_log("scaling", "counterexample"))
    returns = [e for e in log.events if e.kind == "return" and e.name == "pick"]
    assert [e.result for e in returns][:1] == [None] and len(returns) == 2  # the empty one first
    assert run_vertices(log)["D"] == "D"  # the run's pick is still D
    _, picked, _ = staged_pseudocode(log)
    assert picked == returns[1].seq, (picked, [e.seq for e in returns])


def test_a_heuristic_of_ones_own_is_captioned_in_words():
    heuristic = load_user_heuristic(f"{EXAMPLES / 'nearest_to_c.py'}:nearest_to_c")
    p = Polygon.from_points(make_sample("counterexample"))
    captions = [b.caption for b in storyboard(record_user_run(heuristic, p, "counterexample"))]
    # the picture's own vertices, in capitals: "Distance to C for D: 2.2", not "to c for C, D"
    steps = [c for c in captions if c.startswith("Distance to C for ")]
    assert steps and not any(" c " in c or ", " in c.split(":")[0] for c in steps), steps
    log = record_user_run(heuristic, p, "counterexample")
    claimed = run_heuristic(p, heuristic)  # the pseudocode's D is the vertex it claims
    assert claimed.u.label == "B" and run_vertices(log)["D"] == claimed.v.label
    assert steps and all("_" not in c for c in captions), captions
    assert not any(c.startswith("Triangle at") or "triangle_at" in c for c in captions)


def _graph(*texts: str) -> dict:
    """A scene graph holding these texts on screen, one subtitle each."""
    return {"plays": [{"subcaption": None, "animations": [
        {"type": "FadeIn", "mobject": {"name": "subtitle", "text": t, "fill_opacity": 1}}]}
        for t in texts], "cues": []}


@pytest.mark.parametrize(("text", "kind"), [
    ("scaling on the counterexample", "slug"),
    ("rotation-correct: the correction", "slug"),
    ("nearest_to(B, [D, E]) → D", "code"),
    ("[[12, 7, 8], [0, 1, 12]]", "code"),
    ("trex hunt tried 35 polygons", "code"),
    ("B–D crosses edge E–A at (2.86087, 6.36087)", "number"),
])
def test_the_words_rule_finds_slugs_code_and_long_numbers(text, kind):
    assert unspoken_words(_graph(text)) == [f"{kind}: {text!r}"]


def test_the_words_rule_passes_the_taught_words():
    fine = ("Scaling (spilled water) on a polygon where it happens to work",
            "Gravity: the ball falls until it hits the boundary", "BD crosses edge E–A",
            "The diagonals cut the polygon into 3 y-monotone pieces", "distance 2.8")
    assert unspoken_words(_graph(*fine)) == []


def test_the_call_line_is_left_out_only_when_allowed():
    data = {"plays": [{"subcaption": None, "animations": [{"type": "FadeIn", "mobject": {
        "name": "panel:call", "text": "", "submobjects": [
            {"name": "FlatText", "text": "nearest_to(B, [D, E]) → D", "fill_opacity": 1}]}}]}],
        "cues": []}
    assert unspoken_words(data, call_line=True) == []
    assert unspoken_words(data) == ["code: 'nearest_to(B, [D, E]) → D'"]


# --- a summary of fast beats names the vertices by their labels, as the picture shows them ---


def _classifying(caption: str, *labels: str) -> list[dict]:
    """Plays of the monotone sweep under one caption: each shows a vertex's kind."""
    return [{"subcaption": caption, "animations": [
        {"type": "FadeIn", "mobject": {"name": "kind", "text": "regular"}},
        {"type": "Indicate", "mobject": {"name": f"vertex:{v}"}}]} for v in labels]


def test_a_summary_of_the_sweep_names_its_vertices_by_their_labels():
    """Chapter 5's monotone run: the fast-forwarded vertices are named by the letters on
    screen, in the order the sweep meets them ("Vertices 7–10" numbered what is never shown)."""
    from metaphors.catalog import beats
    from story.runs import run_logged

    log = run_logged("monotone", "lecture")
    labels = set(next(b.labels for b in beats(log) if b.action == "polygon"))
    summaries = list(dict.fromkeys(b.caption for b in beats(log)
                                   if b.caption.endswith("the same steps, faster")))
    # (F, whose helper step a diagonal uses, and E, the first end vertex, are steps of their
    # own since mono5)
    assert summaries == ["Vertices H, B and G: the same steps, faster"]
    for caption in summaries:
        named = caption.removeprefix("Vertices ").split(":")[0].replace(" and ", ", ")
        assert not any(c.isdigit() for c in named) and set(named.split(", ")) <= labels


def test_the_summary_rule_finds_vertices_numbered_or_named_wrong():
    from tests.reading_rules import broken_summaries

    numbered = {"plays": _classifying("Vertices 1–2: the same steps, faster", "H", "B")}
    assert broken_summaries(numbered) == [
        "'Vertices 1–2: the same steps, faster' numbers vertices"]
    wrong = {"plays": _classifying("Vertices H and C: the same steps, faster", "H", "B")}
    assert broken_summaries(wrong) == ["'Vertices H and C: the same steps, faster' over H, B"]
    fine = {"plays": [*_classifying("Vertices H, B and G: the same steps, faster", "H", "B", "G"),
                      *_classifying("Vertices I–K: the same steps, faster", "I", "J", "K")]}
    assert broken_summaries(fine) == []


# --- grav7: gravity's rows say the picture's vertices, one by one, as the run gives them ---------


def _gravity_log(sample: str) -> tracing.Log:
    from story.spec import RunSpec

    return RunSpec("gravity", sample).log()


@pytest.mark.parametrize("sample, tied", [
    ("gravity-snag", ["V = C, the first reflex vertex after B",
                      "it slides down the edge to a vertex X = G",
                      "Y = H, the first vertex the band snags (if any)",
                      "claim VY = CH, or VX if the band stays straight"]),
    ("counterexample", ["V = E, the first reflex vertex after B",
                        "it slides down the edge to a vertex X = C",
                        "claim VY, or VX = EC if the band stays straight"])])
def test_gravity_rows_tie_v_x_y_to_the_runs_vertices_as_it_gives_them(sample, tied):
    """The card and the rows say V, X, Y, the picture C, G, H: the rows tie each to its vertex
    from the beat that gives it (V at its pick, X at the slide, Y at the snag, the claim as it
    is made), never before; B, a label on screen, is the left-most vertex's own name."""
    from story.storyboard import pseudocode_stages

    log = _gravity_log(sample)
    first, stages = pseudocode_stages(log)
    assert [r.text for r in first] == [r.text for r in pseudocode_of(log)]
    assert [r.text for r in spoken_pseudocode(log) if r.text not in
            {s.text for s in pseudocode_of(log)}] == tied
    from metaphors import catalog

    played = catalog.beats(log)
    beats = {b.action: b.seq for b in played}
    seqs = [seq for seq, _ in stages]
    assert seqs[0] == min(b.seq for b in played if "reflex vertex" in b.caption)
    assert beats["slide"] in seqs and beats["claim"] == seqs[-1]
    # "side" is said "edge", as the captions say it
    assert not any("side" in r.text.split() or "sides" in r.text for r in pseudocode_of(log))


def test_gravity_picks_b_first_and_says_v_is_the_first_reflex_vertex_after_it():
    """B is shown and its row lit before V, "the first reflex vertex after B" (B was never
    lit nor marked: chapter 3)."""
    from metaphors import catalog

    beats = [b for b in catalog.beats(_gravity_log("gravity-snag")) if b.action == "pick"]
    assert [b.caption for b in beats] == [
        "B is the left-most vertex (lowest on ties): convex",
        "C is the first reflex vertex after B: the ball will hang there"]
    rows = pseudocode_of(_gravity_log("gravity-snag"))
    assert [rows[b.row].text for b in beats] == ["B = the left-most vertex",
                                                 "V = the first reflex vertex after B"]


def test_a_row_renamed_later_keeps_inside_the_panel():
    """The rows are set as wide as the widest they will be: "claim VY = CH, or VX …", renamed
    as the claim was made, ran off the frame's right edge."""
    from metaphors.panel import Panel
    from story.beats import Note
    from story.storyboard import pseudocode_stages

    log = _gravity_log("gravity-snag")
    first, stages = pseudocode_stages(log)
    p = Polygon.from_points(make_sample("gravity-snag"))
    panel = Panel(p.points, p.labels, None)
    panel.show_pseudocode(first, stages)
    right = panel.code_box.x + panel.code_box.width / 2
    panel.follow_text(Note(caption="", seq=10**6))
    assert [row.original_text for row in panel.code][-2].startswith("claim VY = CH")
    assert max(row.get_right()[0] for row in panel.code) <= right + 1e-6
