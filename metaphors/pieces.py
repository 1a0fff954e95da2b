"""Divide and conquer (Lennes): the verified diagonal becomes an edge and the polygon falls into
two pieces, each tinted unlike its neighbours; a piece that is a triangle is finished and fills
in. The pieces, their points and labels come from the log (the ``split`` call and the pieces it
enters).
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping, Sequence

from manim import FadeIn, Mobject
from manim import Polygon as MPolygon

from metaphors.board import Board
from metaphors.performing import Performances, act, performs
from metaphors.tags import tag
from story.beats import Beat, beat_kind
from story.refs import state_of, target_of
from story.storyboard import Reading, Walk
from tracing import Event


@beat_kind("split")
class Split(Beat):
    """The piece ``parent`` is cut into ``pieces`` (keys), with their points and labels."""

    pieces: list[str]
    parent: str
    points: list[list[list[float]]]  # one ring of points per piece
    labels: list[list[str]]


def read_split(walk: Walk, call: Event, ret: Event) -> Iterator[Beat]:
    pieces = walk.result_refs(ret)
    entered = {target_of(e): state_of(e) for e in walk.log.events[ret.seq:]
               if e.kind == "enter" and e.target in pieces}
    yield walk.step(Split, "Split along the diagonal into two smaller polygons", call, ret,
                    pieces=pieces,
                    parent=walk.ref(call, "piece"),
                    points=[entered[k]["points"] for k in pieces if k in entered],
                    labels=[entered[k]["labels"] for k in pieces if k in entered])


def _tint_colour(board: Board, labels: list[str], avoid: set[str]) -> str:
    """A palette colour for a new piece: unlike its neighbours (tints sharing an edge), then the
    least used; ties by palette order."""
    palette = board.theme.pieces
    tints = [m for k, m in board.objects.items() if k.startswith(("piece:", "triangle:"))]
    near = {_colour(m) for m in tints if len(set(_labels(m)) & set(labels)) >= 2}
    used = [_colour(m) for m in tints]
    return min(palette, key=lambda c: (c in avoid, c in near, used.count(c), palette.index(c)))


def _colour(tint: Mobject) -> str:
    """The palette colour of a tint (an attribute of its own, set by :func:`_tint`)."""
    colour: str = vars(tint)["trex_colour"]
    return colour


def _labels(tint: Mobject) -> list[str]:
    """The labels of a tint's corners (an attribute of its own, set by :func:`_tint`)."""
    labels: list[str] = vars(tint)["trex_labels"]
    return labels


def _tint(board: Board, points: Sequence[Sequence[float]], labels: Sequence[str], colour: str,
          done: bool) -> MPolygon:
    theme = board.theme
    role, name = ("result", "triangle:") if done else ("idle", "piece:")
    mobject = MPolygon(*[board.at(p) for p in points], stroke_width=0, fill_color=colour,
                       fill_opacity=theme.done_opacity if done else theme.piece_opacity)
    mobject.set_z_index(-1)
    vars(mobject).update(trex_colour=colour, trex_labels=list(labels))  # see _colour, _labels
    return tag(mobject, role, name + "".join(labels))


def split(board: Board, beat: Split) -> None:
    """The verified diagonal becomes an edge; the two halves get their own tints, and a half
    that is a triangle is finished: it fills in."""
    theme = board.theme
    anims = []
    line = board.objects.pop("claim", None)
    if line is not None:
        k = sum(1 for key in board.objects if key.startswith("diagonal:"))
        board.keep(f"diagonal:{k}", tag(line, "idle", line.name))
        anims.append(line.animate.set_color(theme.ink).set_stroke(width=theme.stroke))
    anims += board.drop("verdict", f"piece:{beat.parent}")
    if board.shape.get_fill_opacity() > 0:
        anims.append(board.shape.animate.set_fill(opacity=0))
    chosen: set[str] = set()
    for piece, points, labels in zip(beat.pieces, beat.points,
                                     beat.labels, strict=False):
        done = len(points) == 3
        colour = _tint_colour(board, labels, chosen)
        chosen.add(colour)
        tint = _tint(board, points, labels, colour, done)
        board.keep(f"triangle:{''.join(labels)}" if done else f"piece:{piece}", tint)
        anims.append(FadeIn(tint))
    board.play(beat, *anims, run_time=1.2)


READS: Mapping[str, Reading] = {"split": read_split}
PERFORMS: Performances = performs(act(Split, split))
