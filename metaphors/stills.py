"""Still pictures of exercises: the polygon with labelled vertices, T = ABC marked, the
candidates lit, the diagonals a question names dashed, the question as a title line.

A still is a one-frame Scene (nothing is played), rendered with ``format=png``.
Colours come from the theme: T and its corners in the *called* colour, candidates in the
*candidate* colour (the legend's neutral one, as in the runs), the named diagonals *idle*.
"""

from __future__ import annotations

from typing import cast

from manim import DL, UR, Camera, DashedLine, LineJointType, Scene, VGroup, VMobject
from manim import Polygon as MPolygon
from shapely.geometry import Polygon as Region
from shapely.geometry import box as area

from geometry.diagonals import find_diagonal
from metaphors.drawing import Frame, polygon_mobject
from metaphors.labels import LABEL_HALO, placed_vertex_markers
from metaphors.theme import THEME, Theme
from rendering import typeset
from rendering.typeset import FlatText
from story.exercises import Exercise, front

TITLE_Y, LEGEND_Y = 3.45, -3.6
BOX_CENTER, BOX_WIDTH, BOX_HEIGHT = (0.0, -0.1), 12.4, 5.6
MAX_TEXT_WIDTH = 13.4
T_OPACITY = 0.15  # as the scenes draw T


def _text(text: str, size: int, colour: str, theme: Theme) -> FlatText:
    return typeset.text(text, font=theme.font, size=size, colour=colour, width=MAX_TEXT_WIDTH)


def still_mobjects(exercise: Exercise, theme: Theme = THEME,
                   box: tuple[tuple[float, float], float, float] = (BOX_CENTER, BOX_WIDTH,
                                                                    BOX_HEIGHT)) -> list:
    """Everything the still shows, back to front: the polygon fitted in ``box`` (centre,
    width, height; the lecture keeps a column beside it for the answer), its legend below."""
    p = exercise.polygon
    center, width, height = box
    frame = Frame(p.points, center=center, width=width, height=height)
    a, b, c = exercise.triangle
    t = MPolygon(*frame.many([p.points[k] for k in (a, b, c)]), color=theme.called,
                 stroke_width=theme.thin_stroke, fill_color=theme.called, fill_opacity=T_OPACITY)
    options = [
        DashedLine(frame.to_scene(p.points[i]), frame.to_scene(p.points[j]), color=theme.idle,
                   stroke_width=theme.stroke, dash_length=theme.dash_length * 1.5)
        for i, j in exercise.options
    ]
    # labels placed by measuring, clear of the edges, of T's AC and of every diagonal the
    # question names or the answer draws: a class reads them with no run to explain them
    markers = placed_vertex_markers(p, frame, theme, diagonals=drawn_diagonals(exercise),
                                    lines=answer_front(exercise))
    _haloed_on(markers, [frame.to_scene(p.points[k])[:2] for k in (a, b, c)], theme)
    for k in (a, b, c):
        markers[k].set_color(theme.called)
    for k in exercise.candidates:
        markers[k].set_color(theme.candidate)
        markers[k][0].scale(1.5)
    title = _text(exercise.title, theme.caption_size + 4, theme.ink, theme)
    title.move_to((0, TITLE_Y, 0))
    names = ", ".join(p.labels[k] for k in exercise.candidates)
    legend = VGroup(
        _text(f"T = {''.join(p.labels[k] for k in (a, b, c))}", theme.label_size, theme.called,
              theme),
        _text(f"candidates in T: {names}", theme.label_size, theme.candidate, theme),
    ).arrange(buff=0.6)
    legend.move_to((center[0], LEGEND_Y, 0))
    return [polygon_mobject(p, frame, theme), t, *options, markers, title, legend]


def _haloed_on(markers: VGroup, corners: list, theme: Theme) -> None:
    """Each label that stands over T's tint (a candidate's must: its vertex lies in T) on a
    dark halo, so that it reads as on the background (E, F, G and M stood on the tint)."""
    t = Region(corners)
    for marker in markers:
        label = cast(VMobject, marker[1])  # a marker is its dot and its label's text
        (x0, y0, _), (x1, y1, _) = label.get_corner(DL), label.get_corner(UR)
        if t.intersects(area(x0, y0, x1, y1)):
            label.joint_type = LineJointType.ROUND  # a mitred halo spikes at M's points
            label.set_stroke(theme.background, width=LABEL_HALO, background=True)


#: where :func:`still_mobjects` puts the vertices' markers (dot and label each) in its list
MARKERS_AT = -3


def drawn_diagonals(exercise: Exercise) -> tuple[tuple[int, int], ...]:
    """The diagonals the still and the answer draw on the polygon: T's AC, the options, the
    claim asked about, the pairs a rule of one's own measured."""
    a, _, c = exercise.triangle
    claimed = ((exercise.claim,) if exercise.claim is not None else
               (find_diagonal(exercise.polygon, exercise.heuristic).pair,)
               if exercise.kind == "claim" and exercise.heuristic else ())
    return ((a, c), *exercise.options, *claimed, *exercise.measured)


def answer_front(exercise: Exercise) -> list[list[tuple[float, float]]]:
    """The front the answer of a pick draws (:func:`story.exercises.front`; none for the
    other kinds): the still's labels are placed clear of it."""
    if exercise.kind != "pick" or exercise.heuristic is None \
            or exercise.answer not in exercise.polygon.labels:
        return []  # not a pick, or a made-up one with no answer yet
    pick = exercise.polygon.label_of(exercise.answer)
    return front(exercise.polygon, exercise.triangle, exercise.heuristic, pick)


class ExerciseStill(Scene):
    """One exercise as a single frame."""

    camera: Camera  # Cairo's: this project renders with Cairo only (not OpenGLCamera)

    def __init__(self, exercise: Exercise, theme: Theme = THEME, **kwargs) -> None:
        self.exercise = exercise
        self.theme = theme
        super().__init__(**kwargs)

    def construct(self) -> None:
        self.camera.background_color = self.theme.background  # type: ignore[assignment]  # manim's setter is typed ManimColor, and parses any colour
        self.add(*still_mobjects(self.exercise, self.theme))
