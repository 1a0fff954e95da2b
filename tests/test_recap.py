"""The recap (chapter 7) says what its figures draw: each claim a card's figure draws is
named in the card's words (issue 22: no caption contradicting, or leaving out, the picture)."""

from __future__ import annotations

import re

import pytest

from geometry.diagonals import find_diagonal
from geometry.io import read_polygon
from metaphors.lecture import Card
from scenes.chapters.ch7_recap import Recap


def _claims_figures() -> list[Card]:
    cards = [s for s in Recap.__new__(Recap).chapter_segments() if isinstance(s, Card)]
    return [c for c in cards if c.figure is not None and c.figure.kind == "claims"]


def _drawn(figure) -> set[str]:
    polygon = read_polygon(figure.polygon)
    return {find_diagonal(polygon, h).name for h in figure.heuristics}


def _named(words: str) -> set[str]:
    return set(re.findall(r"\b[A-Z]{2}\b", words))


@pytest.mark.parametrize("card", _claims_figures(), ids=lambda c: c.title)
def test_a_claims_card_names_every_claim_its_figure_draws(card):
    drawn = set().union(_drawn(card.figure), *(_drawn(f) for f in card.line_figures if f))
    assert drawn, card.title
    assert drawn <= _named(" ".join(card.lines)), (card.title, drawn - _named(" ".join(card.lines)))


def early_claims(card: Card) -> list[str]:
    """The claims a card draws before its words name them: the figure's own (up with the
    title) unless the title names them, each line's unless that line does."""
    early = sorted(_drawn(card.figure) - _named(card.title))
    for line, figure in zip(card.lines, card.line_figures, strict=False):
        early += sorted(_drawn(figure) - _named(line)) if figure else []
    return early


@pytest.mark.parametrize("card", _claims_figures(), ids=lambda c: c.title)
def test_each_claim_is_drawn_when_its_words_say_it(card):
    """Review r567: "the rules that hold" drew BE and EC, both green, from its title on (one
    path along B–C); EC stood there before "Gravity claims EC" was said."""
    assert early_claims(card) == [], card.title


def test_early_claims_sees_the_old_card():
    from metaphors.figures import Figure

    old = Card("Recap: the rules that hold", ("Correct Scaling … claim BE, inside P.", "…",
                                              "Gravity claims EC: …"),
               Figure("claims", "counterexample",
                      heuristics=("scaling-correct", "rotation-correct", "gravity")))
    assert early_claims(old) == ["BE", "EC"]


@pytest.mark.parametrize("card", _claims_figures(), ids=lambda c: c.title)
def test_each_line_of_a_claims_card_is_a_sentence(card):
    """Each line is its own caption: none ends half-way through a sentence."""
    assert all(line.rstrip().endswith((".", "?", "!")) for line in card.lines), card.title


def early_edges(card: Card, plan) -> list[str]:
    """The crossed edges a card draws red before its words name them, as ``"line 0: E–A"``
    (``plan``: per line, the claims and crossed edges it brings, as
    :meth:`metaphors.lecture.LectureScene._line_claims` gives them)."""
    return [f"line {k}: {edge.name.removeprefix('figure:edge:')}"
            for k, (line, (_, edges)) in enumerate(zip(card.lines, plan, strict=True))
            for edge in edges if edge.name.removeprefix("figure:edge:") not in line]


def _plan(card: Card):
    scene = Recap.__new__(Recap)
    scene.lecture_polygon = lambda: "lecture"  # type: ignore[method-assign]  # the cards name their own polygon
    return scene._line_claims(card)


@pytest.mark.parametrize("card", _claims_figures(), ids=lambda c: c.title)
def test_a_crossed_edge_turns_red_when_its_words_name_it(card):
    """Review s567: E–A was thick red from the moment BD was drawn, 5.5 s before "BD crosses
    edge E–A" was said."""
    plan = _plan(card)
    assert early_edges(card, plan) == [], card.title
    drawn = [e for _, edges in plan for e in edges]
    assert all(e.name.startswith("figure:edge:") for e in drawn)


def test_early_edges_sees_the_edge_drawn_with_its_claim():
    """The old plan: the crossed edge came with the claim, on the line before its name."""
    card = next(c for c in _claims_figures() if "fail" in c.title)
    plan = _plan(card)
    moved = [(claims, [e for _, es in plan for e in es] if k == 0 else [])
             for k, (claims, _) in enumerate(plan)]
    assert early_edges(card, moved) == ["line 0: E–A"]
