"""The words of a scene of several runs (``scenes/counterexample.py``): each run's beats as a
scene that tells them one after another says them, every caption said once.

Runs on one polygon go on on one board (:func:`metaphors.play.go_on`): a run after the first
there does not draw the polygon again nor pick B again, and its T and candidates share one
caption naming the rule (:func:`going_on`). A later polygon's frame is said in one caption
too (:func:`framed_again`). Every claim and verdict names its rule (:func:`in_its_name`):
three wrong rules claim BD on the same polygon, and "✗ BD is not an inner diagonal" said
three times read as one run replayed (review of the counterexample scene).

No manim here.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import replace

from story.beats import Beat, Candidates, Claim, Pick, ShowPolygon, ShowTriangle, Verdict

__all__ = ["FRAME", "framed_again", "going_on", "in_its_name"]

#: the beats of a run's frame, up to its candidates
FRAME = (ShowPolygon, Pick, ShowTriangle, Candidates)


def _frame_words(beats: Sequence[Beat]) -> tuple[str, str, str]:
    """B's label, T's name and the candidates, as the run's frame says them."""
    b = next((x.vertex for x in beats if isinstance(x, Pick)), "B")
    t = next(("".join(x.labels) for x in beats if isinstance(x, ShowTriangle)), "ABC")
    found = next((x.candidates for x in beats if isinstance(x, Candidates)), ())
    return b, t, ", ".join(found) if found else "none"


def going_on(beats: Sequence[Beat], name: str, picture: str) -> list[Beat]:
    """The beats of a run that goes on on the board of the run before it, on the same
    ``picture`` (its polygon, named: "polygon", "mirror image"): no polygon drawn again nor
    B picked again; T drawn again (the verdict before took it off) and its candidates lit
    under one caption naming the rule, B held in its blue as its pick held it.

    >>> beats = [ShowPolygon(caption="The polygon", seq=0, points=(), labels=()),
    ...          Pick(caption="B is …", seq=1, vertex="B", roles={"B": "called"}),
    ...          ShowTriangle(caption="T = ABC …", seq=2, points=(), labels=("A", "B", "C")),
    ...          Candidates(caption="Candidates …", seq=3, candidates=("D", "E")),
    ...          Claim(caption="Claim: BE …", seq=4, labels=("B", "E"), points=((0, 0), (1, 1)))]
    >>> [(b.action, b.caption) for b in going_on(beats, "Correct Scaling", "polygon")][:2]
    [('triangle', 'Correct Scaling, on the same polygon: T = ABC, candidates D, E'), ('candidates', 'Correct Scaling, on the same polygon: T = ABC, candidates D, E')]
    >>> dict(going_on(beats, "Correct Scaling", "polygon")[0].roles)
    {'B': 'called'}
    """
    _, t, found = _frame_words(beats)
    words = f"{name}, on the same {picture}: T = {t}, candidates {found}"
    held = next((dict(x.roles) for x in beats if isinstance(x, Pick)), {})
    kept: list[Beat] = []
    for beat in beats:
        if isinstance(beat, (ShowPolygon, Pick)):
            continue
        if isinstance(beat, ShowTriangle):
            beat = replace(beat, caption=words, roles={**held, **beat.roles})
        elif isinstance(beat, Candidates):
            beat = replace(beat, caption=words)
        kept.append(beat)
    return kept


def framed_again(beats: Sequence[Beat], picture: str, opening: str) -> list[Beat]:
    """The beats of the first run on a later polygon, its ``picture``: the polygon drawn
    under ``opening`` (what the scene says of it), then B, T and the candidates under one
    caption (each said before, word for word, of the first polygon).

    >>> beats = [ShowPolygon(caption="The polygon", seq=0, points=(), labels=()),
    ...          Pick(caption="B is …", seq=1, vertex="B"),
    ...          ShowTriangle(caption="T = ABC …", seq=2, points=(), labels=("A", "B", "C")),
    ...          Candidates(caption="Candidates …", seq=3, candidates=("D", "E"))]
    >>> [b.caption for b in framed_again(beats, "mirror image", "Its mirror image")]
    ['Its mirror image', 'On the mirror image, B is left-most again: T = ABC, candidates D, E', 'On the mirror image, B is left-most again: T = ABC, candidates D, E', 'On the mirror image, B is left-most again: T = ABC, candidates D, E']
    """
    b, t, found = _frame_words(beats)
    words = f"On the {picture}, {b} is left-most again: T = {t}, candidates {found}"
    return [replace(beat, caption=opening) if isinstance(beat, ShowPolygon)
            else replace(beat, caption=words) if isinstance(beat, FRAME) else beat
            for beat in beats]


def in_its_name(beats: Sequence[Beat], name: str, said: set[str]) -> list[Beat]:
    """The beats with their claim and verdict said in the rule's ``name`` ("Rotation claims:
    BD is an inner diagonal", "✗ Rotation fails: BD crosses edge E–A", "✓ Correct Rotation
    holds: BE is an inner diagonal"), and any other caption already ``said`` in the scene
    said with the rule's name before it; ``said`` gets every caption the beats say.

    >>> said = {"The clock hand turns; the first candidate it passes is E"}
    >>> beats = [Beat(caption="The clock hand turns; the first candidate it passes is E", seq=0),
    ...          Claim(caption="Claim: BE is an inner diagonal", seq=1, labels=("B", "E"),
    ...                points=((0, 0), (1, 1))),
    ...          Verdict(caption="✗ BE is not an inner diagonal: BE crosses edge C–D", seq=2,
    ...                  ok=False, labels=("B", "E"), why="", code="crosses")]
    >>> for b in in_its_name(beats, "Rotation the other way", said):
    ...     print(b.caption)
    Rotation the other way: the clock hand turns; the first candidate it passes is E
    Rotation the other way claims: BE is an inner diagonal
    ✗ Rotation the other way fails: BE crosses edge C–D
    """
    out: list[Beat] = []
    for beat in beats:
        caption = beat.caption
        if isinstance(beat, Claim):
            caption = f"{name} claims: {''.join(beat.labels)} is an inner diagonal"
        elif isinstance(beat, Verdict):
            diagonal = "".join(beat.labels)
            why = caption.split(": ", 1)[1] if ": " in caption else caption
            caption = (f"✓ {name} holds: {diagonal} is an inner diagonal" if beat.ok
                       else f"✗ {name} fails: {why}")
        elif caption in said and (not out or out[-1].caption != caption):
            # lower-case its first word, unless a label's ("B is …")
            first = caption[:1].lower() if caption[1:2].islower() else caption[:1]
            caption = f"{name}: {first}{caption[1:]}"
        if caption != beat.caption:
            beat = replace(beat, caption=caption)
        said.add(caption)
        out.append(beat)
    return out
