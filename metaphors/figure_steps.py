"""A card's figure drawn step by step with its lines: a part waits for the words that say it.

A figure (:mod:`metaphors.figures`) is computed whole, but a part of it may wait for the
card's line that speaks of it (:func:`comes_with`): a metaphor's pick is amber only once a
line names it, the frame's "Reflex" ring once a line says what reflex is. A part may also
grow as it comes in (:func:`grows`): the water spreads from B as its line says it does; and
go with a later line (:func:`goes_with`): the diagonal drawn amber as "a diagonal" gives way
to the green one as the next line says it is inner.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Sequence

from manim import Animation, FadeIn, Mobject, UpdateFromAlphaFunc, linear, smooth

#: seconds a growing part takes to come in (the water spreading, the hand turning)
GROW = 2.0


def comes_with(part: Mobject, word: str) -> Mobject:
    """``part``, to come in with the first line of its card naming ``word`` (a whole word,
    case kept: "D" is not "d"); "" the card's first line. Returns it."""
    vars(part)["trex_with"] = word
    return part


def goes_with(part: Mobject, word: str) -> Mobject:
    """``part``, to go with the first line after the one it came with that names ``word``
    (as :func:`comes_with` finds it). Returns it."""
    vars(part)["trex_until"] = word
    return part


def said_only(part: Mobject, word: str) -> Mobject:
    """``part``, as :func:`comes_with`, but left out of a card none of whose lines names
    ``word`` (the frame card's "is BG inner?" line, drawn only where a line asks it)."""
    vars(part)["trex_only_said"] = True
    return comes_with(part, word)


def with_line(part: Mobject, line: int) -> Mobject:
    """``part``, to come in with the card's line number ``line`` (0: the first), whatever it
    says (a figure that draws one rule per line). Returns it."""
    vars(part)["trex_line"] = line
    return part


def replacing(part: Mobject, group: str, *takes_off: str) -> Mobject:
    """``part``, one of ``group``; as it comes in, the parts on screen of ``takes_off``
    (default: its own group) go (the recap's rules, one picture after another on one
    polygon). Returns it."""
    vars(part)["trex_group"] = group
    vars(part)["trex_takes_off"] = takes_off or (group,)
    return part


def going(shown: Sequence[Mobject], coming: Sequence[Mobject]) -> list[Mobject]:
    """The parts of ``shown`` that the parts ``coming`` take off (:func:`replacing`)."""
    off = {g for part in coming for g in vars(part).get("trex_takes_off", ())}
    return [part for part in shown if vars(part).get("trex_group") in off]


def grows(part: Mobject, drawn_at: Callable[[float], Mobject]) -> Mobject:
    """``part`` (``drawn_at(1.0)``), to come in drawn as ``drawn_at(t)`` while t runs from 0
    to 1. Returns it."""
    vars(part)["trex_grow"] = drawn_at
    return part


def steps(parts: Sequence[Mobject], lines: Sequence[str]) -> list[list[Mobject]]:
    """``parts`` by when they come in: the first list with the card's title, then one per
    line of ``lines``; a part whose word no line names comes with the title (unless it is
    :func:`said_only`)."""
    shown: list[list[Mobject]] = [[] for _ in range(len(lines) + 1)]
    for part in parts:
        line = vars(part).get("trex_line")
        if line is not None:
            if not 0 <= line < len(lines):
                raise ValueError(f"a part comes with line {line}: the card has {len(lines)}")
            shown[line + 1].append(part)
            continue
        word = vars(part).get("trex_with")
        said = (k + 1 for k, line in enumerate(lines) if _naming(line, str(word)))
        at = 0 if word is None else next(said, None)
        if at is None and vars(part).get("trex_only_said"):
            continue
        shown[at or 0].append(part)
    return shown


def _naming(line: str, word: str) -> bool:
    return word == "" or bool(re.search(rf"(?<!\w){re.escape(word)}(?!\w)", line))


def leaving(shown: Sequence[Sequence[Mobject]], lines: Sequence[str]) -> list[list[Mobject]]:
    """Per line of ``lines``, the parts (of ``shown``, :func:`steps`' lists) that go as it
    comes: each at the first line after its own that names its :func:`goes_with` word."""
    gone: list[list[Mobject]] = [[] for _ in lines]
    for came, parts in enumerate(shown):
        for part in parts:
            word = vars(part).get("trex_until")
            if word is None:
                continue
            at = next((k for k in range(came, len(lines)) if _naming(lines[k], str(word))),
                      None)
            if at is not None:
                gone[at].append(part)
    return gone


def coming(part: Mobject) -> tuple[Animation, float]:
    """The animation that brings ``part`` in, and its seconds (0: as long as the play)."""
    drawn_at = vars(part).get("trex_grow")
    if drawn_at is None:
        return FadeIn(part), 0.0
    return UpdateFromAlphaFunc(part, lambda m, a: m.become(drawn_at(a)), rate_func=linear,
                               run_time=GROW), GROW


def done_by(share: float) -> Callable[[float], float]:
    """A rate function that ends at ``share`` of its play (0 < share ≤ 1), then holds: a
    card's line fades in in its usual time while a part of its figure grows on for longer
    (stretched to the whole play, the line stood faint for 2 s)."""
    return lambda t: smooth(min(1.0, t / share))


__all__ = ["GROW", "comes_with", "coming", "done_by", "goes_with", "going", "grows", "leaving",
           "replacing", "said_only", "steps", "with_line"]
