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


@pytest.mark.parametrize("card", _claims_figures(), ids=lambda c: c.title)
def test_a_claims_card_names_every_claim_its_figure_draws(card):
    polygon = read_polygon(card.figure.polygon)
    drawn = {find_diagonal(polygon, h).name for h in card.figure.heuristics}
    said = set(re.findall(r"\b[A-Z]{2}\b", " ".join(card.lines)))
    assert drawn <= said, (card.title, drawn - said)


@pytest.mark.parametrize("card", _claims_figures(), ids=lambda c: c.title)
def test_each_line_of_a_claims_card_is_a_sentence(card):
    """Each line is its own caption: none ends half-way through a sentence."""
    assert all(line.rstrip().endswith((".", "?", "!")) for line in card.lines), card.title
