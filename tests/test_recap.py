"""The recap (chapter 7) says what its figures draw, and what the thesis says: each rule with
the picture of why (issue 22 item 8), the correct rules' argument as the thesis gives it
(ch. 2), each claim named as it is drawn."""

from __future__ import annotations

import re

import pytest

from geometry.check import is_inner_diagonal
from geometry.diagonals import find_diagonal
from geometry.io import read_polygon
from metaphors.analysis import moment
from metaphors.figure_steps import steps
from metaphors.figures import Figure, figure_mobjects
from metaphors.lecture import Card, LectureScene
from scenes.chapters.ch7_recap import FAILING, HOLDING, POLYGON, Recap
from story.registry import spoken


def _cards() -> list[Card]:
    return [s for s in Recap.__new__(Recap).chapter_segments() if isinstance(s, Card)]


def _verdict_cards() -> list[Card]:
    return [c for c in _cards() if "rules that" in c.title]


def _parts(card: Card) -> list[list]:
    """The card's figure's parts by when they come: with the title, then with each line."""
    assert card.figure is not None
    return steps(figure_mobjects(card.figure, "lecture"), card.lines)


def _names(parts) -> set[str]:
    return {m.name for m in parts}


def _named(words: str) -> set[str]:
    return set(re.findall(r"\b[A-Z]{2}\b", words))


def test_each_wrong_rule_comes_with_its_picture_of_why():
    """Review: one picture of BD crossing E–A stood for all three wrong rules ("Their motion
    leaves P before it reaches the vertex it picks" was never drawn). Each line names its
    rule and brings its tool, stopped at its pick, with what left P red; the last line names
    the claim and brings it, and the edge it crosses."""
    card = next(c for c in _verdict_cards() if "fail" in c.title)
    assert card.figure is not None and card.figure.heuristics == FAILING
    parts = _parts(card)
    for k, rule in enumerate(FAILING):
        assert card.lines[k].startswith(spoken(rule, first=True)), card.lines[k]
        tools = [m for m in parts[k + 1] if m.name == "figure:tool"]
        assert len(tools) == 1, card.lines[k]
        assert "figure:outside" in {m.name for m in tools[0].submobjects}
    claim = find_diagonal(read_polygon(POLYGON), FAILING[0]).name
    last = parts[len(FAILING) + 1]
    assert claim in _named(card.lines[len(FAILING)])
    assert {"figure:claim", "figure:edge:E–A"} <= _names(last), _names(last)


def test_each_holding_rule_comes_with_the_region_its_argument_is_about():
    """The holding rules' motion was never drawn: each line names its rule and brings its
    tool and the region its argument is about, green (gravity: its band and what it swept),
    its claim named as it is drawn."""
    card = next(c for c in _verdict_cards() if "hold" in c.title)
    assert card.figure is not None
    assert set(card.figure.heuristics) == {*HOLDING, "gravity"}
    parts = _parts(card)
    for k, rule in enumerate(card.figure.heuristics):
        assert card.lines[k].startswith(spoken(rule, start=True)), card.lines[k]
        want = {"figure:band", "figure:band-swept"} if rule == "gravity" else {
            "figure:witness", "figure:tool"}
        assert want <= _names(parts[k + 1]), (card.lines[k], _names(parts[k + 1]))
        # its claim named with it: the corrections' one claim comes with the first line
        assert find_diagonal(read_polygon(POLYGON), rule).name in _named(card.lines[k])
        assert ("figure:claim" in _names(parts[k + 1])) == (k == 0 or rule == "gravity")


def test_the_holding_card_gives_the_thesis_argument():
    """Review: "Their motion stays inside T until it meets the first candidate" is true of
    the wrong clock hand as well, so it tells nothing: the thesis's argument (ch. 2) is that
    no part of a correct rule's motion inside T leaves P before it meets its first
    candidate. On the counterexample, what each correction swept on its way lies in P, while
    each wrong rule's motion, inside T too, leaves it."""
    card = next(c for c in _verdict_cards() if "hold" in c.title)
    said = " ".join(card.lines)
    assert not re.search(r"\binside T until\b|\bstays? inside T\b", said), said
    assert re.search(r"before any part of (it|them) in(side)? T leaves P", said), said
    polygon = read_polygon(POLYGON)
    for rule in HOLDING:
        seen = moment(rule, POLYGON)
        assert seen.moved.astray(polygon.points).is_empty, rule
    for rule in FAILING:
        seen = moment(rule, POLYGON)
        assert not seen.moved.astray(polygon.points).is_empty, rule
        assert seen.moved.swept(1.0).difference(seen.moved.t_shape).area < 1e-9, rule


def test_the_claim_is_told_from_the_edge_it_crosses():
    """Review: BD and E–A, the same red at the same width, read as one red cross. The claim
    is solid, on a dark casing; the crossed edge dashed."""
    from manim import DashedLine, Line

    card = next(c for c in _verdict_cards() if "fail" in c.title)
    last = _parts(card)[len(FAILING) + 1]
    claim = next(m for m in last if m.name == "figure:claim")
    edge = next(m for m in last if m.name.startswith("figure:edge:"))
    assert any(type(m) is Line for m in claim.submobjects)
    assert not any(isinstance(m, DashedLine) for m in claim.submobjects)
    assert any(isinstance(m, DashedLine) for m in edge.submobjects)


@pytest.mark.parametrize("card", _verdict_cards(), ids=lambda c: c.title)
def test_a_verdict_card_names_every_claim_its_figure_draws(card):
    polygon = read_polygon(POLYGON)
    assert card.figure is not None
    drawn = {find_diagonal(polygon, h).name for h in card.figure.heuristics}
    assert drawn <= _named(" ".join(card.lines)), drawn - _named(" ".join(card.lines))
    for h in card.figure.heuristics:
        verdict = is_inner_diagonal(polygon, *find_diagonal(polygon, h).pair)
        assert verdict.ok == (h in (*HOLDING, "gravity")), h


@pytest.mark.parametrize("card", _cards(), ids=lambda c: c.title)
def test_each_line_of_a_card_is_a_sentence(card):
    """Each line is its own caption: none ends half-way through a sentence."""
    assert all(line.rstrip().endswith((".", "?", "!")) for line in card.lines), card.title


def test_the_algorithms_say_each_bound_once_under_a_picture_to_count():
    """Review: each bound stood under a 110-px thumbnail and again in a bullet beside it,
    and its 11 triangles could not be counted. One line per algorithm, under its picture;
    the pictures at least 30 % of the frame's height."""
    card = next(c for c in _cards() if c.figure == Figure("three-triangulations"))
    assert card.layout == "columns"
    drawn = figure_mobjects(card.figure, "lecture")
    # over each picture its name and bound, as its line says them (exer9: the three stood
    # unnamed and alike until their lines came, one by one)
    names = [m.original_text for m in drawn if m.name == "figure:name"]
    assert len(names) == len(card.lines)
    for name, line in zip(names, card.lines, strict=True):
        algorithm, _, bound = name.partition(", ")
        assert line.startswith(algorithm) and bound in line, (name, line)
    pictures = [m for m in drawn if m.name == "figure:polygon"]
    assert len(pictures) == len(card.lines)
    assert all(p.height >= 0.3 * 8.0 for p in pictures), [p.height for p in pictures]


def early_claims(card: Card) -> list[str]:
    """The claims a ``claims`` card draws before its words name them: the figure's own (up
    with the title) unless the title names them, each line's unless that line does."""
    def drawn(figure):
        polygon = read_polygon(figure.polygon)
        return {find_diagonal(polygon, h).name for h in figure.heuristics}

    early = sorted(drawn(card.figure) - _named(card.title))
    for line, figure in zip(card.lines, card.line_figures, strict=False):
        early += sorted(drawn(figure) - _named(line)) if figure else []
    return early


def test_early_claims_sees_the_old_card():
    """Review r567: "the rules that hold" drew BE and EC, both green, from its title on (one
    path along B–C); EC stood there before "Gravity claims EC" was said."""
    old = Card("Recap: the rules that hold", ("Correct Scaling … claim BE, inside P.", "…",
                                              "Gravity claims EC: …"),
               Figure("claims", "counterexample",
                      heuristics=("scaling-correct", "rotation-correct", "gravity")))
    assert early_claims(old) == ["BE", "EC"]


def early_edges(card: Card, plan) -> list[str]:
    """The crossed edges a card draws red before its words name them, as ``"line 0: E–A"``
    (``plan``: per line, the claims and crossed edges it brings, as
    :meth:`metaphors.lecture.LectureScene._line_claims` gives them)."""
    return [f"line {k}: {edge.name.removeprefix('figure:edge:')}"
            for k, (line, (_, edges)) in enumerate(zip(card.lines, plan, strict=True))
            for edge in edges if edge.name.removeprefix("figure:edge:") not in line]


def test_a_crossed_edge_of_a_claims_card_turns_red_when_its_words_name_it():
    """Review s567: E–A was thick red from the moment BD was drawn, 5.5 s before "BD crosses
    edge E–A" was said: a ``claims`` card's line figures bring it with the line naming it;
    the old plan, the edge with its claim, is seen."""
    card = Card("The rules that fail", ("All three claim BD.", "BD crosses edge E–A."),
                Figure("claims", POLYGON, heuristics=()),
                line_figures=(Figure("claims", POLYGON, heuristics=FAILING),))
    scene = LectureScene.__new__(LectureScene)
    scene.lecture_polygon = lambda: "lecture"  # type: ignore[method-assign]  # the card names its own polygon
    plan = scene._line_claims(card)
    assert early_edges(card, plan) == []
    moved = [(claims, [e for _, es in plan for e in es] if k == 0 else [])
             for k, (claims, _) in enumerate(plan)]
    assert early_edges(card, moved) == ["line 0: E–A"]


@pytest.mark.parametrize("card", _verdict_cards(), ids=lambda c: c.title)
def test_the_labels_stand_over_what_the_rules_shade(card):
    """The tools' shading grows in after the labels: at their layer, the red outside P
    covered D's label (pink under it) and the green E's. The labels and the pick's dot are
    drawn over every part of the figure."""
    drawn = figure_mobjects(card.figure, "lecture")
    labels = next(m for m in drawn if m.name == "figure:vertices")
    shading = [m for m in drawn if m.name not in ("figure:vertices", "figure:pick")]
    assert all(labels.z_index > m.z_index for m in shading), [
        (m.name, m.z_index) for m in shading if m.z_index >= labels.z_index]
    assert all(m.z_index > labels.z_index for m in drawn if m.name == "figure:pick")
