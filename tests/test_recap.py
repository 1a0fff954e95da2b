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
