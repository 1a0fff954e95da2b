"""Scene graphs: what a manim Scene plays, serialised deterministically, without rendering video.

A *scene graph* lists every ``play`` call of a scene in order (``wait`` is a play of
``Wait``): the total run time, the subcaption, and each animation with its class name, its
run time and its mobjects. A mobject is written as its type, its role (``trex_role``, set
by :func:`metaphors.panel.tag`), its name, stroke and fill colours as hex (with opacities
and stroke width), and its points rounded to 1e-3; a ``Text`` is written as its string and
its bounding box instead of its glyphs (and its letters' height, ``cap``, if it says it); submobjects follow recursively. The mobjects on
screen when the scene ends close the graph (``final``), and the subtitles of its ``.srt``
follow (``cues``). The document is versioned
(``"schema": "trex-scene-graph/1"``, :mod:`trex.graph_format`); docs/scene-graph.md
describes it.

Mobjects are serialised at the moment ``play`` is called, so each animation shows the
state it starts from (and, for transforms, the target it moves to).

Nothing here knows about this project's scenes: :func:`recording` works on any manim
``Scene`` instance, and :func:`build_graph` on any ``Scene`` subclass.

Examples
--------
>>> import json
>>> from manim import Circle, Create, Scene
>>> class OneCircle(Scene):
...     def construct(self):
...         self.play(Create(Circle(radius=1, color="#FF0000")), run_time=0.5)
>>> graph = json.loads(build_graph(OneCircle))
>>> [(a["type"], a["run_time"]) for play in graph["plays"] for a in play["animations"]]
[('Create', 0.5)]
>>> circle = graph["plays"][0]["animations"][0]["mobject"]
>>> circle["type"], circle["stroke"], circle["points"][0]
('Circle', '#FF0000', [1.0, 0.0, 0.0])
>>> build_graph(OneCircle) == build_graph(OneCircle)
True
"""

from __future__ import annotations

import atexit
import shutil
import tempfile
from collections.abc import Iterator, Mapping
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Any, TypedDict, TypeGuard, cast

import numpy as np
from manim import Animation, AnimationGroup, ManimColor, Mobject, Scene, VMobject, tempconfig
from manim.renderer.cairo_renderer import CairoRenderer

from tracing import JSON
from trex.graph_format import SCHEMA, to_json

#: Decimal places kept for points, bounding boxes, run times, widths and opacities.
DECIMALS = 3

#: Play keyword arguments that belong to the scene, not to the animations.
_SUBCAPTION_KEYS = ("subcaption", "subcaption_duration", "subcaption_offset")


# --- numbers and colours --------------------------------------------------------------------


def _number(x: float) -> float:
    """``x`` rounded to :data:`DECIMALS` places, as a plain float without ``-0.0``."""
    return float(round(float(x), DECIMALS)) + 0.0


def _points(points: np.ndarray) -> list[list[float]]:
    return (np.round(np.asarray(points, dtype=float), DECIMALS) + 0.0).tolist()


def _hex(colours) -> str | list[str] | None:
    """One hex colour, or the distinct ones in order when a mobject has a gradient."""
    found: list[str] = []
    for colour in colours or ():
        if colour is None:
            continue
        text = colour.to_hex()
        if text not in found:
            found.append(text)
    if not found:
        return None
    return found[0] if len(found) == 1 else found


# --- mobjects --------------------------------------------------------------------------------


def _text_of(mobject: Mobject) -> str | None:
    """The source string of a text-like mobject (Text, MarkupText, Tex …), else None."""
    for attribute in ("original_text", "tex_string"):
        value = getattr(mobject, attribute, None)
        if isinstance(value, str):
            return value
    return None


def _letters(mobject: Mobject, node: dict[str, Any]) -> None:
    """A text that says how tall its letters stand as drawn (a ``cap_height()`` method, as
    :class:`rendering.typeset.FlatText` has) has it written as ``cap``: what a viewer reads
    its size by, which its box, holding descenders and the gaps between lines, is not."""
    measure = getattr(mobject, "cap_height", None)
    height = measure() if callable(measure) else None
    if isinstance(height, int | float):
        node["cap"] = _number(height)


def mobject_graph(mobject: Mobject) -> dict[str, Any]:
    """A mobject as plain data: type, role, name, colours, rounded points, submobjects.

    Text-like mobjects (anything with an ``original_text`` or ``tex_string``) are written
    as their string and rounded bounding box (and, where the text says it, its letters'
    height: :func:`_letters`); their glyphs are left out.

    Examples
    --------
    >>> from manim import Line
    >>> line = Line([0, 0, 0], [1, 0.12345, 0], color="#00FF00")
    >>> line.trex_role, line.name = "result", "claim"
    >>> g = mobject_graph(line)
    >>> g["type"], g["role"], g["name"], g["stroke"], g["points"][-1]
    ('Line', 'result', 'claim', '#00FF00', [1.0, 0.123, 0.0])
    """
    node: dict[str, Any] = {
        "type": type(mobject).__name__,
        "role": getattr(mobject, "trex_role", None),
        "name": str(getattr(mobject, "name", "")),
    }
    if isinstance(mobject, VMobject):
        node["stroke"] = _hex(mobject.get_stroke_colors())
        node["fill"] = _hex(mobject.get_fill_colors())
        node["stroke_opacity"] = _number(mobject.get_stroke_opacity())
        node["fill_opacity"] = _number(mobject.get_fill_opacity())
        node["stroke_width"] = _number(mobject.get_stroke_width())
        if mobject.get_stroke_width(background=True) > 0:  # a halo drawn behind the fill
            node["halo"] = {"stroke": _hex(mobject.get_stroke_colors(background=True)),
                            "stroke_opacity": _number(mobject.get_stroke_opacity(background=True)),
                            "stroke_width": _number(mobject.get_stroke_width(background=True))}
    else:
        colour = mobject.__dict__.get("color")
        node["color"] = colour.to_hex() if colour is not None and hasattr(colour, "to_hex") else None
    if mobject.z_index:  # drawn above (or below) what came later: the drawing order
        node["z"] = _number(mobject.z_index)
    text = _text_of(mobject)
    if text is not None:
        node["text"] = text
        if mobject.has_points() or mobject.submobjects:
            low, high = mobject.get_corner((-1, -1, 0)), mobject.get_corner((1, 1, 0))
            node["box"] = [_number(v) for v in (*low[:2], *high[:2])]
            _letters(mobject, node)
        else:
            node["box"] = None
        return node
    node["points"] = _points(mobject.points)
    if mobject.submobjects:
        node["submobjects"] = [mobject_graph(m) for m in mobject.submobjects]
    return node


def _has_content(mobject: Mobject | None) -> TypeGuard[Mobject]:
    return mobject is not None and (mobject.has_points() or bool(mobject.submobjects))


def animation_graph(animation: Animation) -> dict[str, Any]:
    """An animation as plain data: class name, run time, its mobject (and target, if any).

    A group of animations lists its members instead of its mobject.

    Examples
    --------
    >>> from manim import Square, FadeIn
    >>> g = animation_graph(FadeIn(Square(side_length=1), run_time=2))
    >>> g["type"], g["run_time"], g["mobject"]["type"], g["mobject"]["points"][0]
    ('FadeIn', 2.0, 'Square', [0.5, 0.5, 0.0])
    """
    node: dict[str, Any] = {
        "type": type(animation).__name__,
        "run_time": _number(animation.run_time),
    }
    if isinstance(animation, AnimationGroup):
        node["animations"] = [animation_graph(a) for a in animation.animations]
        return node
    node["mobject"] = mobject_graph(cast(Mobject, animation.mobject))  # Cairo's (not OpenGL)
    # a pulse's colour (Indicate, Flash): it shows while the pulse plays, in no mobject
    pulse = getattr(animation, "color", None)
    if isinstance(pulse, str | ManimColor):
        node["color"] = ManimColor(pulse).to_hex()
    target = getattr(animation, "target_mobject", None)
    if _has_content(target) and target is not animation.mobject:
        node["target"] = mobject_graph(target)
    return node


# --- recording plays ---------------------------------------------------------------------------


class PlayGraph(TypedDict):
    """One play as the scene graph writes it (docs/scene-graph.md): its run time, its
    subcaption and its animations (:func:`animation_graph`)."""

    run_time: float
    subcaption: str | None
    animations: list[Mapping[str, JSON]]


@dataclass
class Play:
    """One ``Scene.play`` call: the animations (live objects, which go on changing), the
    total run time, the subcaption, and ``graph``, the animations serialised when the call
    was made."""

    animations: list[Animation]
    run_time: float
    subcaption: str | None
    graph: PlayGraph


@contextmanager
def recording(scene: Scene) -> Iterator[list[Play]]:
    """Record every ``play`` (and so every ``wait``) of a scene instance into a list.

    The scene's ``play`` is replaced on the instance for the duration of the block: it
    compiles the arguments to animations (``.animate`` builders included), serialises them,
    and hands the same animations to the real ``play``.

    Examples
    --------
    >>> from manim import Dot, FadeIn
    >>> with tempconfig({"dry_run": True, "verbosity": "WARNING", "progress_bar": "none"}):
    ...     scene = Scene(skip_animations=True)
    ...     with recording(scene) as plays:
    ...         scene.play(FadeIn(Dot()), subcaption="a dot")
    ...         scene.wait(0.5)
    >>> [(p.graph["animations"][0]["type"], p.run_time, p.subcaption) for p in plays]
    [('FadeIn', 1.0, 'a dot'), ('Wait', 0.5, None)]
    """
    plays: list[Play] = []
    original = scene.play

    def play(*args, **kwargs):
        captions = {k: kwargs.pop(k) for k in _SUBCAPTION_KEYS if k in kwargs}
        animations = scene.compile_animations(*args, **kwargs)
        run_time = max((a.run_time for a in animations), default=0.0)
        subcaption = captions.get("subcaption")
        graph: PlayGraph = {
            "run_time": _number(run_time),
            "subcaption": subcaption,
            "animations": [animation_graph(a) for a in animations],
        }
        plays.append(Play(animations, run_time, subcaption, graph))
        return original(*animations, **captions, **kwargs)

    scene.play = play  # type: ignore[method-assign]  # the scene's own play, wrapped to record each play's graph
    try:
        yield plays
    finally:
        del scene.play


def scene_graph(plays: list[Play], scene: Scene | None = None) -> dict[str, Any]:
    """The graph of recorded plays, closed by the scene's mobjects at the end (if given)."""
    graph: dict[str, Any] = {"schema": SCHEMA, "plays": [p.graph for p in plays]}
    if scene is not None:
        graph["final"] = [mobject_graph(m) for m in scene.mobjects]
        graph["cues"] = cues(scene)
    return graph


def cues(scene: Scene) -> list[dict[str, Any]]:
    """The subtitles the scene's ``.srt`` would hold, as data: each cue's ``start`` and
    ``end`` (seconds, rounded) and its ``text``."""
    writer = getattr(scene.renderer, "file_writer", None)
    return [{"start": _number(c.start.total_seconds()), "end": _number(c.end.total_seconds()),
             "text": c.content} for c in getattr(writer, "subcaptions", None) or ()]


# --- building a scene without video ------------------------------------------------------------


class GraphRenderer(CairoRenderer):
    """A Cairo renderer that draws no pixels: frames stay blank, the scene logic runs as usual."""

    def update_frame(self, *args, **kwargs) -> None:  # nothing to draw
        return None


_scratch: Path | None = None


def _scratch_dir() -> Path:
    """One temporary media directory per process (Text caches its SVGs there), removed at exit."""
    global _scratch
    if _scratch is None or not _scratch.exists():
        _scratch = Path(tempfile.mkdtemp(prefix="trex-graph-"))
        atexit.register(shutil.rmtree, _scratch, True)
    return _scratch


def build(scene_class: type[Scene],
          media_dir: str | Path | None = None) -> tuple[Scene, list[Play]]:
    """Build a scene in dry run (no video, no pixels, animations skipped to their ends) and
    return it with its recorded plays.

    The scene's input is the class's business: hand it one first (for this project's
    scenes, ``Scaling.handed(polygon="star")``, see :class:`metaphors.scene.SpecScene`).
    ``media_dir`` is where manim may cache text SVGs (default: a temporary directory of
    this process).
    """
    settings = {
        "dry_run": True,
        "write_to_movie": False,
        "save_last_frame": False,
        "disable_caching": True,
        "media_dir": str(media_dir or _scratch_dir()),
        "verbosity": "WARNING",
        "progress_bar": "none",
    }
    with tempconfig(settings):
        scene = scene_class(renderer=GraphRenderer(skip_animations=True), skip_animations=True)
        with recording(scene) as plays:
            scene.render()
    return scene, plays


def build_graph(scene_class: type[Scene], media_dir: str | Path | None = None) -> str:
    """The scene graph of a Scene subclass as JSON text (see the module docs).

    Parameters
    ----------
    scene_class
        Any manim ``Scene`` subclass; it is instantiated and rendered in dry run (a scene
        of this project handed its run first, e.g. ``Gravity.handed(saved=["run.json"])``).
    media_dir
        Scratch media directory (default: a temporary one); nothing else is written.

    Returns
    -------
    str
        Stable JSON (sorted keys): equal scenes give equal text.

    Examples
    --------
    >>> import json
    >>> from manim import Square, Scene, Write
    >>> class Boxed(Scene):
    ...     def construct(self):
    ...         self.play(Write(Square(side_length=2)), run_time=2)
    ...         self.wait()
    >>> graph = json.loads(build_graph(Boxed))
    >>> [a["type"] for p in graph["plays"] for a in p["animations"]]
    ['Write', 'Wait']
    >>> graph["final"][0]["points"][:2]
    [[1.0, 1.0, 0.0], [0.333, 1.0, 0.0]]
    """
    scene, plays = build(scene_class, media_dir)
    return to_json(scene_graph(plays, scene))
