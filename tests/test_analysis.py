"""The lecture's analysis of each heuristic is an animation (issue 12, item 4).

Two layers. :mod:`story.analysis` (the shapes, polygon coordinates): on the counterexample the
wrong heuristics' swept regions reach outside the polygon inside T, and on any polygon the
corrections' regions stay inside it and hold their claim. The chapters, built in dry run
(:func:`trex.scene_graph.build`): for each wrong family an analysis whose red part lies outside
the polygon and inside T, whose crossed edge is drawn and named in a caption and a label, and
whose correction's shaded region lies inside the polygon; gravity's band likewise; every
analysis caption on screen long enough to read.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
import shapely
from hypothesis import HealthCheck, assume, given, settings

import tracing
from geometry.diagonals import find_diagonal
from metaphors import catalog
from metaphors.analysis import Analysis, moment, moment_of
from story.analysis import lies_inside, outside, shape
from story.reading import reading_time
from story.registry import entry, spoken
from tests.reading_rules import animation_nodes, mobject_nodes
from tests.strategies import generated_polygons
from trex.render_command import load_scene_class
from trex.scene_graph import build

ROOT = Path(__file__).resolve().parents[1]
WRONG = ("scaling", "rotation", "translation")
#: the titles of the chapters' analyses, in order
TITLES = {"heuristics": [f"{m}: why {spoken(w)} fails" for m, w in zip(("Water", "Clock", "Sweep"),
                                                                       WRONG, strict=True)],
          "gravity": ["Gravity: why the band is always right"]}
#: scene units a rounded point of the graph may stray (points are kept to 1e-3)
GRAPH_SLACK = 2e-3


# --- the shapes ------------------------------------------------------------------------------


@pytest.mark.parametrize("wrong", WRONG)
def test_a_wrong_heuristics_sweep_leaves_the_polygon_inside_t(wrong):
    seen = moment(wrong, "counterexample")
    points, t = seen.points, seen.triangle
    astray = seen.motion.astray(points)
    assert seen.motion.reached == "D" and seen.verdict.edge == ("E", "A")
    assert astray.area > 0.05  # a visible part, not a sliver
    assert lies_inside(astray, t) and shape(points).intersection(astray).area < 1e-6
    # the part outside P holds the stretch of BD beyond the crossed edge, next to D
    beyond = shapely.LineString([seen.verdict.point, points[seen.labels.index("D")]])
    # the water is a 256-gon inscribed in its circle: D, on the circle, lies off it by up to
    # the polygon's sagitta, r (1 − cos(π / 256))
    radius = math.dist(points[seen.labels.index("B")], points[seen.labels.index("D")])
    assert astray.buffer(1e-6 + radius * (1 - math.cos(math.pi / 256))).covers(beyond)


@pytest.mark.parametrize("wrong", WRONG)
def test_its_correction_sweeps_only_the_inside_and_holds_its_claim(wrong):
    right = moment(entry(wrong).correction, "counterexample")
    u, v = right.claim.labels
    witness = right.motion.witness()
    assert (u, v) == ("B", "E") and right.verdict.ok
    assert witness.area > 1.0 and lies_inside(witness, right.points)
    where = dict(zip(right.labels, right.points, strict=True))
    assert witness.buffer(1e-6).covers(shapely.LineString([where[u], where[v]]))


def _beats(polygon, heuristic):
    with tracing.record(algorithm=heuristic) as log:
        find_diagonal(polygon, heuristic)
    return catalog.beats(log)


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(generated_polygons(max_n=16))
def test_the_corrections_regions_lie_inside_every_polygon(polygon):
    """The thesis's argument, on random polygons: what the corrected tool sweeps on its way
    to its pick (the rising water: what is still dry) holds no part outside P."""
    for heuristic in ("translation-correct", "rotation-correct", "scaling-correct"):
        seen = moment_of(heuristic, _beats(polygon, heuristic))
        assume(seen.motion is not None)  # T held a candidate
        assert lies_inside(seen.motion.witness(), seen.points), heuristic
        assert outside(seen.motion.tool(1.0), seen.points).length < 1e-6, heuristic


def test_gravitys_band_sweeps_inside_the_polygon():
    seen = moment("gravity", "gravity-snag")
    band = seen.band
    assert seen.claim.labels == ("C", "H") and band.y is not None
    assert 0 < band.snag_time < 1
    for t in (0.25, band.snag_time, 0.75, 1.0):
        assert lies_inside(band.swept(t), seen.points)
    assert band.corners(1.0)[1] == band.y


@pytest.mark.parametrize(("heuristic", "polygon", "why"), [
    ("scaling", "square", "no candidate in T"),
    # a seeded random polygon where Scaling claims an inner diagonal among two candidates
    ("scaling", "random-2opt:9:3", "is an inner diagonal, so there is no failure"),
])
def test_an_analysis_with_nothing_to_show_is_one_clear_error(heuristic, polygon, why):
    from metaphors.lecture import LectureScene

    class Nothing(LectureScene):
        def chapter_segments(self):
            return (Analysis(heuristic, polygon),)

    with pytest.raises(ValueError, match=why) as error:
        build(Nothing)
    assert str(error.value).startswith(f"{heuristic} on {polygon}: ")
    assert "\n" not in str(error.value)


# --- the chapters, in dry run ------------------------------------------------------------------


def _chapter(file: str):
    cls = load_scene_class(ROOT / "scenes" / "chapters" / file, None)
    return cls, build(cls.handed())[1]


@pytest.fixture(scope="module")
def heuristics():
    return _chapter("ch2_heuristics.py")


@pytest.fixture(scope="module")
def gravity():
    return _chapter("ch3_gravity.py")


def _segments(plays, titles) -> list[list]:
    """The plays of each analysis: from the one that puts up its title to the one that clears
    the screen after it (fading its polygon out)."""
    return [plays[start:end] for start, end in _spans(plays, titles)]


def _spans(plays, titles) -> list[tuple[int, int]]:
    """Where each analysis starts and the play that clears it. An analysis on its own stage
    writes its title (``analysis:title``) and clears its own polygon; one that goes on from
    the run's picture (:attr:`Analysis.on_run`, chapter 3) retitles the run's board and
    clears the run's polygon."""
    starts = [(k, a["mobject"]["text"]) for k, p in enumerate(plays)
              for a in p.graph["animations"] if _puts_up_title(a, titles)]
    assert [title for _, title in starts] == titles
    return [(k, _cleared(plays, k)) for k, _ in starts]


def _puts_up_title(animation: dict, titles) -> bool:
    name = animation.get("mobject", {}).get("name")
    return ((animation["type"] == "Write" and name == "analysis:title")
            or (animation["type"] == "FadeIn" and name == "title"
                and animation["mobject"].get("text") in titles))


def _on_run(plays, start: int) -> bool:
    """Whether the analysis starting at ``start`` goes on from the run's picture."""
    return not any(a["type"] == "Write" and a["mobject"].get("name") == "analysis:title"
                   for a in plays[start].graph["animations"])


def _cleared(plays, start: int) -> int:
    polygon = "polygon" if _on_run(plays, start) else "analysis:polygon"
    return next(k for k in range(start + 1, len(plays)) for a in plays[k].graph["animations"]
                if a["type"] == "FadeOut" and a.get("mobject", {}).get("name") == polygon)


def _named(plays, name: str) -> list[dict]:
    return [n for p in plays for a in p.graph["animations"] for n in animation_nodes(a)
            if n.get("name") == name]


def _outline(node) -> shapely.Polygon:
    """A drawn polygon (an MPolygon's graph: its corners start every cubic) as shapely."""
    points = np.array(node["points"])[::4, :2]
    return shapely.Polygon(points)


def _regions(node) -> shapely.Geometry:
    parts = [_outline(c) for c in node.get("submobjects", []) if len(c["points"]) >= 12]
    return shapely.union_all([p.buffer(0) for p in parts])


def _lines(node) -> shapely.Geometry:
    return shapely.union_all([shapely.LineString(np.array(c["points"])[:, :2])
                              for c in node.get("submobjects", []) if len(c["points"]) >= 4])


def _frame_of(plays) -> tuple[shapely.Polygon, shapely.Polygon | None]:
    polygon = _outline(_named(plays, "analysis:polygon")[0])
    t = _named(plays, "analysis:T")
    return polygon, (_outline(t[0]) if t else None)


def _captions(plays) -> list[str]:
    return [p.subcaption for p in plays if p.subcaption]


def _held(plays) -> list[tuple[str, float]]:
    """Each caption and how long it stays on screen: until the next caption (the last: until
    the screen clears)."""
    held, caption, since = [], None, 0.0
    for p in plays:
        if p.subcaption:
            if caption is not None:
                held.append((caption, since))
            caption, since = p.subcaption, 0.0
        since += p.run_time
    return [*held, (caption, since)] if caption is not None else held


def _families(cls) -> list[Analysis]:
    return [s for s in cls.__new__(cls).chapter_segments() if isinstance(s, Analysis)]


def test_the_lecture_analyses_each_wrong_family_not_a_text_card(heuristics):
    cls, plays = heuristics
    analyses = _families(cls)
    assert [a.heuristic for a in analyses] == list(WRONG)
    cards = [c for c in _captions(plays) if "why it fails" in c]
    assert cards == []  # the old bullet-point cards are gone
    assert len(_segments(plays, TITLES["heuristics"])) == 3


@pytest.mark.parametrize("k", range(3), ids=WRONG)
def test_the_red_part_lies_outside_the_polygon_inside_t(heuristics, k):
    segment = _segments(heuristics[1], TITLES["heuristics"])[k]
    polygon, t = _frame_of(segment)
    red = _regions(_named(segment, "analysis:outside")[0])
    assert red.area > 0.02
    assert red.intersection(polygon).area < 0.02 * red.area  # outside P …
    assert t.buffer(GRAPH_SLACK).covers(red)  # … but inside T
    tool = _lines(_named(segment, "analysis:astray")[0])
    assert tool.length > 0.05 and t.buffer(GRAPH_SLACK).covers(tool)
    assert tool.difference(polygon.buffer(GRAPH_SLACK)).length > 0.9 * tool.length


@pytest.mark.parametrize("k", range(3), ids=WRONG)
def test_the_crossed_edge_flashes_and_is_named(heuristics, k):
    segment = _segments(heuristics[1], TITLES["heuristics"])[k]
    assert any(c.endswith("BD crosses edge E–A") for c in _captions(segment))  # no coordinates
    edge = _named(segment, "analysis:edge:E–A")
    assert len(edge) >= 3  # drawn, then flashing (twice)
    assert [n["text"] for n in _named(segment, "analysis:edge-name")][:1] == ["edge E–A"]
    assert any(a["type"] == "Indicate" and a["mobject"]["name"] == "analysis:edge:E–A"
               for p in segment for a in p.graph["animations"])


@pytest.mark.parametrize("k", range(3), ids=WRONG)
def test_the_corrections_shaded_region_lies_inside_the_polygon(heuristics, k):
    segment = _segments(heuristics[1], TITLES["heuristics"])[k]
    polygon, _ = _frame_of(segment)
    shaded = _regions(_named(segment, "analysis:witness")[0])
    assert shaded.area > 1.0 and polygon.buffer(GRAPH_SLACK).covers(shaded)
    claim = _named(segment, "analysis:claim")[-1]  # the correction's, green
    assert claim["stroke"] == "#4CC46B"
    assert shaded.buffer(GRAPH_SLACK).covers(shapely.LineString(np.array(claim["points"])[:, :2]))
    holds = _families(heuristics[0])[k].holds.format(pick="E", claim="BE")
    assert holds in _captions(segment)


#: what gravity's run and analysis draw of the band: the band, the part it has swept (shaded as
#: it sweeps) and that part turned green when the analysis says why
BAND_REGIONS, BAND_LINES = ("swept", "analysis:witness"), ("band",)


def _turned(plays, name: str, before: int) -> int:
    """The last play before ``before`` that turns ``name`` (a Turn's graph holds where it
    starts from), or -1."""
    return max((k for k in range(before) for a in plays[k].graph["animations"]
                if a["type"] == "Turn" and a.get("mobject", {}).get("name") == name), default=-1)


def test_gravitys_band_is_shown_always_inside_the_polygon(gravity):
    """The analysis goes on from the run's picture (issue 22 item 4: one picture per idea):
    the band, the part it swept as the run went and that part shaded green when the analysis
    says why, lie inside P — the run's polygon as the run turned it — in every play that draws
    them, from the run's turn to the analysis clearing the screen."""
    plays = gravity[1]
    ((start, end),) = _spans(plays, TITLES["gravity"])
    assert _on_run(plays, start)
    polygon = _outline(_named(plays[end:end + 1], "polygon")[0])  # as it goes: turned
    turn = _turned(plays, "polygon", start)
    assert turn >= 0 and _turned(plays, "polygon", end + 1) == turn  # not turned again
    shaded = _regions(_named(plays[start:end], "analysis:witness")[0])
    assert shaded.area > 0.5
    shown = {"regions": 0, "lines": 0}
    for k in range(turn + 1, end + 1):
        for node in (n for name in BAND_REGIONS for n in _named(plays[k:k + 1], name)):
            region = _regions(node) if node.get("submobjects") else _outline(node).buffer(0)
            if region.area < 1e-6:  # not swept yet: a sliding animation's graph is its start
                continue
            assert polygon.buffer(GRAPH_SLACK).covers(region), (k, node["name"])
            shown["regions"] += 1
        for node in (n for name in BAND_LINES for n in _named(plays[k:k + 1], name)):
            line = shapely.LineString(np.array(node["points"])[:, :2])
            if line.length < 1e-6:  # the band before the ball falls: C itself
                continue
            assert polygon.buffer(GRAPH_SLACK).covers(line), (k, node["name"])
            shown["lines"] += 1
    # the band as the ball falls, slides, snags and stays; its shading as it slides and snags,
    # then green
    assert shown["regions"] >= 3 and shown["lines"] >= 4, shown
    # said once: the analysis says why, on the run's picture, and none of the run's steps again
    # (review r34 item 2); it draws nothing again (the polygon, the ball and the band stay)
    said = _captions(plays[start:end])
    run = _captions(plays[:start])
    assert said == [_families(gravity[0])[0].holds.format(pick="H", claim="CH")]
    assert run.count("The rubber band snags H") == 1 and not set(said) & set(run)
    assert not [a["mobject"]["name"] for p in plays[start:end] for a in p.graph["animations"]
                if a["type"] in ("Create", "Write", "FadeIn")
                and a["mobject"].get("name") in ("polygon", "analysis:polygon", "ball", "band")]
    assert not any("Why the band is always right" in c for c in _captions(plays))


#: an analysis on its own stage speaks in steps; gravity's says why in one caption on the
#: run's picture, and the run's verdict it takes over from is read in its time too
LEAST_SAID = {"heuristics": 3, "gravity": 2}


@pytest.mark.parametrize("chapter", ["heuristics", "gravity"])
def test_every_analysis_caption_is_on_screen_long_enough_to_read(chapter, request):
    plays = request.getfixturevalue(chapter)[1]
    for start, end in _spans(plays, TITLES[chapter]):
        if _on_run(plays, start):  # from the run's last caption, which the analysis ends
            start = max(k for k in range(start) if plays[k].subcaption)
        held = _held(plays[start:end])
        assert len(held) >= LEAST_SAID[chapter]
        for caption, seconds in held:  # as the .srt writes it: whole milliseconds
            assert int(seconds * 1000) / 1000 >= reading_time(caption), (caption, seconds)


# --- issue 22 item 4: one pass, the red at the freeze, one swept colour -----------------------


def _fills(node) -> set[str]:
    return {n["fill"].upper() for n in mobject_nodes(node)
            if n.get("fill") and (n.get("fill_opacity") or 0) > 0}


def test_the_swept_region_is_one_colour_in_every_metaphor():
    """Issue 22 item 4: what water, hand and line sweep is one colour (the theme's ``swept``),
    red nowhere while the tool moves (the red comes when it has stopped)."""
    from metaphors.analysis import tool_colour, tool_drawing
    from metaphors.drawing import Frame
    from metaphors.figure_metaphors import Sheet
    from metaphors.theme import THEME
    from trex.scene_graph import mobject_graph

    for wrong in WRONG:
        seen = moment(wrong, "counterexample")
        sheet = Sheet(Frame(seen.points, (0, 0), 8, 6), THEME)
        for t in (0.5, 1.0):
            drawn = mobject_graph(tool_drawing(sheet, seen.motion, t, tool_colour(THEME, wrong)))
            assert _fills(drawn) == {THEME.swept.upper()}, (wrong, t)
            strokes = {n["stroke"].upper() for n in mobject_nodes(drawn)
                       if (n.get("stroke_opacity") or 0) > 0}
            assert THEME.rejected.upper() not in strokes, (wrong, t)


def _played(segment, kind: str, name: str) -> int:
    return next(k for k, p in enumerate(segment) for a in p.graph["animations"]
                if a["type"] == kind and a["mobject"].get("name") == name)


@pytest.mark.parametrize("k", range(3), ids=WRONG)
def test_the_tool_freezes_at_its_pick_before_the_red(heuristics, k):
    """The tool runs once, stops at its pick and the picture holds still; only then does the
    part outside P turn red. Its legend keeps one colour for what is swept in all three."""
    from metaphors.theme import THEME

    cls, plays = heuristics
    analysis = _families(cls)[k]
    segment = _segments(plays, TITLES["heuristics"])[k]
    ran = _played(segment, "UpdateFromAlphaFunc", "analysis:tool")
    red = _played(segment, "FadeIn", "analysis:outside")
    assert segment[ran].run_time == analysis.slow and ran < red
    held = [p for p in segment[ran + 1:red] if p.graph["animations"][0]["type"] == "Wait"]
    assert sum(p.run_time for p in held) >= analysis.freeze
    assert all(p.subcaption is None for p in segment[ran:red])  # frozen under its caption
    key = _named(segment, "legend:swept")[0]  # as it comes in (the rising water takes it off)
    swatches = [n for n in mobject_nodes(key) if n["type"] == "Square"]
    assert [n["fill"].upper() for n in swatches] == [THEME.swept.upper()]
    # the tool runs once: the wrong one, then its correction, each a single motion
    motions = [p for p in segment for a in p.graph["animations"]
               if a["type"] == "UpdateFromAlphaFunc"]
    assert len(motions) == 2
