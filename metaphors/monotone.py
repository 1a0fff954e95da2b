"""Monotone partition (Garey et al.): a horizontal line sweeps down, vertices are classified,
split and merge vertices get diagonals, the pieces are y-monotone, a stack triangulates each.

Positions, kinds, diagonals, pieces and triangles come from the log (the beats' data).
"""

from __future__ import annotations

from manim import Create, DashedLine, FadeIn, FadeOut, Indicate, Line, Transform
from manim import Polygon as MPolygon

from metaphors.tags import tag
from rendering.typeset import text


def _sweep_line(board, y: float):
    theme = board.theme
    x0 = board.frame.center[0] - 2.9
    at = board.at((0.0, y))[1]
    return tag(DashedLine((x0, at, 0), (x0 + 5.8, at, 0), color=theme.sweep,
                          stroke_width=theme.thin_stroke), "called", "sweep")


def classify(board, beat) -> None:
    """The sweep line reaches a vertex; the vertex shows its kind."""
    theme, data = board.theme, beat.data
    line = _sweep_line(board, data["at"][1])
    kind = tag(text(data["kind"], font=theme.font, size=18,
                    colour=theme.rejected if data["kind"] in ("split", "merge") else theme.called),
               None, "kind")
    kind.next_to(board.markers[data["vertex"]], direction=[1, 0, 0], buff=0.1)
    anims = [FadeIn(kind), Indicate(board.markers[data["vertex"]])]
    if "sweep" in board.objects:
        anims.append(Transform(board.objects["sweep"], line))
    else:
        board.keep("sweep", line)
        anims.append(Create(line))
    board.play(beat, *anims, run_time=0.8)
    board.scene.play(FadeOut(kind), run_time=0.2 * beat.pace)


def monotone_diagonal(board, beat) -> None:
    u, w = beat.data["points"]
    line = tag(Line(board.at(u), board.at(w), color=board.theme.argument,
                    stroke_width=board.theme.stroke * 1.3), "argument",
               f"diagonal:{''.join(beat.data['labels'])}")
    board.keep(f"diagonal:{''.join(beat.data['labels'])}", line)
    board.play(beat, Create(line), run_time=1.0)


def pieces(board, beat) -> None:
    theme = board.theme
    tints = []
    for k, points in enumerate(beat.data["pieces"]):
        colour = theme.pieces[k % len(theme.pieces)]
        tint = tag(MPolygon(*[board.at(p) for p in points], color=colour, stroke_width=1,
                            fill_color=colour, fill_opacity=theme.piece_opacity), None,
                   f"piece:{k + 1}")
        board.keep(f"piece:{k + 1}", tint)
        tints.append(FadeIn(tint))
    board.play(beat, *board.drop("sweep"), *tints, run_time=1.2)


def stack(board, beat) -> None:
    theme = board.theme
    drawn = []
    for k, triangle in enumerate(beat.data["triangles"]):
        t = tag(MPolygon(*[board.at(p) for p in triangle], color=theme.ink,
                         stroke_width=theme.thin_stroke, fill_opacity=0), None, "triangle")
        board.keep(f"triangle:{beat.step}:{k}", t)
        drawn.append(Create(t))
    board.play(beat, *drawn, run_time=1.0)
