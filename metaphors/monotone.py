"""Monotone partition (Garey et al.): a horizontal line sweeps down, vertices are classified,
split and merge vertices get diagonals, the pieces are y-monotone, a stack triangulates each.

Positions, kinds, diagonals, pieces and triangles come from the log (the beats' data).
"""

from __future__ import annotations

from collections.abc import Iterator, Mapping

from manim import Create, DashedLine, FadeIn, FadeOut, Indicate, Line, Transform, VGroup
from manim import Polygon as MPolygon

from metaphors.board import Board
from metaphors.drawing import triangulation_pieces
from metaphors.performing import Performances, act, performs
from metaphors.tags import tag
from rendering.typeset import text
from story.beats import Beat, beat_kind
from story.storyboard import Reading, Walk
from tracing import Event


def _sweep_line(board: Board, y: float) -> DashedLine:
    theme = board.theme
    x0 = board.frame.center[0] - 2.9
    at = board.at((0.0, y))[1]
    return tag(DashedLine((x0, at, 0), (x0 + 5.8, at, 0), color=theme.sweep,
                          stroke_width=theme.thin_stroke), "called", "sweep")


def classify(board: Board, beat: Classify) -> None:
    """The sweep line reaches a vertex; the vertex shows its kind."""
    theme, data = board.theme, beat
    line = _sweep_line(board, data.at[1])
    kind = tag(text(data.kind, font=theme.font, size=theme.label_size + 2,
                    colour=theme.rejected if data.kind in ("split", "merge") else theme.called),
               None, "kind")
    kind.next_to(board.markers[data.vertex], direction=[1, 0, 0], buff=0.1)
    anims: list[FadeIn | Indicate | Transform | Create] = [FadeIn(kind), Indicate(board.markers[data.vertex])]
    if "sweep" in board.objects:
        anims.append(Transform(board.objects["sweep"], line))
    else:
        board.keep("sweep", line)
        anims.append(Create(line))
    board.play(beat, *anims, run_time=0.8)
    board.scene.play(FadeOut(kind), run_time=0.2 * beat.pace)


def monotone_diagonal(board: Board, beat: MonotoneDiagonal) -> None:
    u, w = beat.points
    line = tag(Line(board.at(u), board.at(w), color=board.theme.argument,
                    stroke_width=board.theme.stroke * 1.3), "argument",
               f"diagonal:{''.join(beat.labels)}")
    board.keep(f"diagonal:{''.join(beat.labels)}", line)
    board.play(beat, Create(line), run_time=1.0)


def pieces(board: Board, beat: Pieces) -> None:
    theme = board.theme
    tints = []
    for k, points in enumerate(beat.pieces):
        colour = theme.pieces[k % len(theme.pieces)]
        tint = tag(MPolygon(*[board.at(p) for p in points], color=colour, stroke_width=1,
                            fill_color=colour, fill_opacity=theme.piece_opacity), None,
                   f"piece:{k + 1}")
        board.keep(f"piece:{k + 1}", tint)
        tints.append(FadeIn(tint))
    board.play(beat, *board.drop("sweep"), *tints, run_time=1.2)


def stack(board: Board, beat: Stack) -> None:
    theme = board.theme
    drawn = []
    for k, triangle in enumerate(beat.triangles):
        t = tag(MPolygon(*[board.at(p) for p in triangle], color=theme.ink,
                         stroke_width=theme.thin_stroke, fill_opacity=0), None, "triangle")
        board.keep(f"triangle:{beat.step}:{k}", t)
        drawn.append(Create(t))
    board.play(beat, *drawn, run_time=1.0)
    if beat.triangulation:
        _whole(board, beat)


def _whole(board: Board, beat: Stack) -> None:
    """After the last piece: the pieces' tints give way to the whole triangulation, each
    triangle its own colour, and the count it had to reach, n − 2."""
    theme = board.theme
    tints = [k for k in board.objects if k.startswith("piece:")]
    whole = triangulation_pieces(beat.triangulation, board.at, theme)
    n = board.polygon.n
    count = tag(text(f"n − 2 = {n} − 2 = {len(whole)} triangles", font=theme.font,
                     size=theme.label_size + 2, colour=theme.result), None, "counter")
    count.next_to(board.shape, direction=[0, -1, 0], buff=0.3)
    board.keep("triangulation", VGroup(*whole))
    board.keep("counter", count)
    board.scene.play(*board.drop(*tints), *[FadeIn(t) for t in whole], FadeIn(count),
                     run_time=1.2)
    board.scene.wait(1.0)


# --- what the monotone triangulation reads from the log ------------------------------------------

KINDS = {
    "start": "both neighbours below, interior below: a start vertex",
    "end": "both neighbours above, interior above: an end vertex",
    "split": "both neighbours below, interior above: a split vertex needs a diagonal up",
    "merge": "both neighbours above, interior below: a merge vertex needs a diagonal down",
    "regular": "one neighbour above, one below: a regular vertex",
}


@beat_kind("classify")
class Classify(Beat):
    """The sweep reaches ``vertex`` (at ``at``): its ``kind`` (start, end, split, merge …)."""

    vertex: str
    kind: str
    at: list


@beat_kind("monotone-diagonal")
class MonotoneDiagonal(Beat):
    """A diagonal that removes a split or merge vertex."""

    labels: list[str]
    points: list


@beat_kind("pieces")
class Pieces(Beat):
    """The y-monotone pieces (their points)."""

    pieces: list


@beat_kind("stack")
class Stack(Beat):
    """The triangles the stack cuts from one monotone piece; after the last piece, every
    triangle of the run (``triangulation``; else empty)."""

    triangles: list
    triangulation: list


def read_classify(walk: Walk, call: Event, ret: Event) -> Iterator[Beat]:
    v, kind = walk.ref(call, "v"), ret.result
    yield walk.step(Classify, f"{v}: {KINDS.get(kind, kind)}", call, ret,
                    roles={v: "rejected" if kind in ("split", "merge") else "called"},
                    vertex=v, kind=kind, at=walk.root_points()[v])


def read_diagonal(walk: Walk, call: Event, ret: Event) -> Iterator[Beat]:
    where = walk.root_points()
    labels = list(where)
    u, w = (labels[k] for k in ret.result)
    yield walk.step(MonotoneDiagonal, f"Diagonal {u}{w} removes a split or merge vertex", call, ret,
                    labels=[u, w],
                    points=[where[u], where[w]])
    walk.count_claim()  # after its beat: the beat belongs to the diagonal it draws


def read_pieces(walk: Walk, call: Event, ret: Event) -> Iterator[Beat]:
    pieces = [walk.entered_after(call, key) for key in walk.result_refs(ret)]
    yield walk.step(Pieces, f"The diagonals cut the polygon into {len(pieces)} y-monotone "
                    "pieces", call, ret, pieces=[p.get("points", []) for p in pieces])


def read_stack(walk: Walk, call: Event, ret: Event) -> Iterator[Beat]:
    where = walk.root_points()
    labels = list(where)
    triangles = [[where[labels[k]] for k in t] for t in ret.result]
    done = walk.memo("monotone.triangles", list)  # the triangles of the pieces so far
    done.extend(triangles)
    yield walk.step(Stack, f"The stack triangulates a monotone piece: "
                    f"{len(triangles)} triangle{'s' if len(triangles) != 1 else ''}", call, ret,
                    triangles=triangles,
                    triangulation=list(done) if len(done) == len(labels) - 2 else [])


READS: Mapping[str, Reading] = {"classify_vertex": read_classify, "add_diagonal": read_diagonal,
         "monotone_pieces": read_pieces, "triangulate_monotone_piece": read_stack}
PERFORMS: Performances = performs(act(Classify, classify),
                                  act(MonotoneDiagonal, monotone_diagonal),
                                  act(Pieces, pieces), act(Stack, stack))
