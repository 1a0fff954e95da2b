"""``trex render``: one scene to an mp4, gif or png, written atomically.

The scene is a name (``scaling`` → ``scenes/scaling.py``, ``rotation:RotationCcw``) or a
path (``my_scene.py[:Class]``). Everything that can be checked without manim is checked
first: the polygon (as ``trex check`` does), the scene's file, the output path. Manim is
imported only then. It renders into a temporary directory beside the output; the finished
file is moved into place with ``os.replace``, so an interrupted (Ctrl-C, SIGTERM) or failed
render leaves nothing at the output path, and no temporary files behind.

:func:`render_into` is the shared machinery (``trex exercises`` renders its stills with it).
"""

from __future__ import annotations

import contextlib
import importlib.util
import os
import shutil
import sys
import tempfile
from collections.abc import Callable
from pathlib import Path

import click

from geometry.errors import GeometryError
from geometry.triangulate import HOLE_ALGORITHMS
from geometry.user_heuristics import UserHeuristicError
from story.pseudocode import PANELS
from story.scene_kinds import (
    Handed,
    WithHeuristic,
    WithPanel,
    algorithm_of,
    heuristic_of,
    plays_one,
    plays_several,
)
from trex.inputs import call_timeout_option, error_line, fail, load_or_exit, make_parent
from trex.signals import EXIT_SIGNAL, Interrupted, Signals, interrupts_raise, signals_held

SCENES_DIR = Path(__file__).resolve().parent.parent / "scenes"
QUALITIES = {"l": "low_quality", "m": "medium_quality", "h": "high_quality", "k": "fourk_quality"}
FORMATS = ("mp4", "gif", "png")
EXIT_FAILED = 1
#: x264's options, as manim.cfg sets them for ``manim`` itself: one thread and no macroblock
#: tree, so that the same input gives the same video, byte for byte (see manim.cfg)
X264_OPTIONS = {"threads": "1", "x264-params": "mbtree=0"}


# --- finding the scene (no manim) ----------------------------------------------------------------


def known_scenes() -> list[str]:
    """Names of the scene files in ``scenes/``.

    >>> "scaling" in known_scenes()
    True
    """
    return sorted(p.stem for p in SCENES_DIR.glob("*.py") if not p.stem.startswith("_"))


def resolve_scene(arg: str) -> tuple[Path, str | None]:
    """The file and the class name (None: the first one) of a SCENE argument.

    >>> path, name = resolve_scene("rotation:RotationCcw")
    >>> path.name, name
    ('rotation.py', 'RotationCcw')
    >>> resolve_scene("divide-and-conquer")[0].name
    'divide_and_conquer.py'
    >>> resolve_scene("nonesuch")
    Traceback (most recent call last):
    ...
    ValueError: unknown scene 'nonesuch'; known: ...
    """
    target, _, class_name = arg.partition(":")
    if not target:
        raise ValueError("empty scene name")
    if target.endswith(".py") or os.sep in target or "/" in target:
        path = Path(target)
        if not path.is_file():
            raise ValueError(f"no such scene file: {target}")
        return path.resolve(), class_name or None
    path = SCENES_DIR / f"{target.replace('-', '_')}.py"
    if not path.is_file():
        raise ValueError(f"unknown scene '{target}'; known: {', '.join(known_scenes())}")
    return path, class_name or None


def default_output(path: Path, class_name: str | None, fmt: str) -> Path:
    """``media/<scene>.<ext>`` (``media/<scene>-<Class>.<ext>`` when a class is named).

    >>> default_output(Path("scenes/rotation.py"), "RotationCcw", "gif").as_posix()
    'media/rotation-RotationCcw.gif'
    """
    stem = path.stem if class_name is None else f"{path.stem}-{class_name}"
    return Path("media") / f"{stem}.{fmt}"


def prepare_output(output: Path) -> Path:
    """Make sure the output's directory exists and the output is not a directory.

    Raises ValueError with a one-line reason.
    """
    if output.is_dir():
        raise ValueError("is a directory; give a file path")
    make_parent(output)
    return output


# --- loading the scene (imports manim) -----------------------------------------------------------


def load_scene_class(path: Path, class_name: str | None) -> type:
    """Import a scene file and return its named Scene class, or the first one it defines."""
    from manim import Scene

    module_name = f"_trex_scene_{path.stem}"
    spec = importlib.util.spec_from_file_location(module_name, path)
    if spec is None or spec.loader is None:
        raise ValueError(f"cannot load {path}")
    module = importlib.util.module_from_spec(spec)
    sys.modules[module_name] = module
    try:
        spec.loader.exec_module(module)
    except Exception as exc:
        sys.modules.pop(module_name, None)
        raise ValueError(f"cannot load {path.name}: {type(exc).__name__}: {error_line(exc)}") from None
    classes = [
        value for value in vars(module).values()
        if isinstance(value, type) and issubclass(value, Scene) and value.__module__ == module_name
    ]
    if not classes:
        raise ValueError(f"{path.name} defines no Scene class")
    if class_name is None:
        return classes[0]
    for cls in classes:
        if cls.__name__ == class_name:
            return cls
    names = ", ".join(c.__name__ for c in classes)
    raise ValueError(f"{path.name} has no scene class '{class_name}'; it has: {names}")


def dry_run(cls: type, polygon: str) -> None:
    """Run the scene's algorithm on the polygon once, without drawing: an input the algorithm
    rejects (a triangle has no diagonal …) is then reported before rendering starts."""
    algorithm = algorithm_of(cls)
    if algorithm is None or plays_several(cls):
        return
    from story.spec import RunSpec

    RunSpec(algorithm, polygon, heuristic=heuristic_of(cls)).log()


def _environment_polygon(cls: type) -> str | None:
    """The polygon plain ``manim`` would hand a one-run scene from ``TREX_POLYGON`` (None: its
    default, a saved log, or not a one-run scene)."""
    if not plays_one(cls):
        return None
    try:
        spec = cls.from_environment().spec
    except ValueError:
        return None  # a TREX_LOG it cannot play: reported when the render starts
    if spec is None or spec.saved is not None or spec.polygon == cls.default_spec().polygon:
        return None
    return spec.polygon


def scene_input(cls: type, polygon: str | None, panel: str | None = None) -> type:
    """The scene class handed its run as data (a subclass carrying a
    :class:`story.spec.RunSpec`, see :class:`metaphors.scene.SpecScene`): on ``polygon`` if
    given, else as ``manim`` would give it (its default run, with ``TREX_POLYGON`` and
    ``TREX_LOG`` from the environment). A scene of several runs plays its own polygons; a
    Scene that takes no run comes back as it is. ``panel`` (one of
    :data:`story.pseudocode.PANELS`), if given, is what a scene with a panel shows there
    (:meth:`metaphors.scene.TraceScene.with_panel`); None: the scene's own. Raises ValueError
    for a ``TREX_LOG`` the scene cannot play."""
    if panel is not None and isinstance(cls, WithPanel):
        cls = cls.with_panel(panel)
    if not isinstance(cls, Handed):
        return cls
    return cls.handed(polygon) if polygon is not None else cls.from_environment()


# --- rendering --------------------------------------------------------------------------------------


def _artifact(scene, fmt: str, media: Path) -> Path:
    """The file manim wrote for this scene (asked from its writer, else found in media/)."""
    writer = getattr(scene.renderer, "file_writer", None)
    with contextlib.suppress(AttributeError, TypeError):
        path = Path(writer.image_file_path if fmt == "png" else writer.movie_file_path)
        if path.is_file():
            return path
    found = [p for p in media.rglob(f"*.{fmt}") if "partial_movie_files" not in p.parts]
    if len(found) != 1:
        raise RuntimeError(f"manim wrote no single .{fmt} file ({len(found)} found)")
    return found[0]


def _abort_encoders(scene) -> None:
    """Stop manim's encoder threads after an interrupt (they would keep the process alive)."""
    writer = getattr(getattr(scene, "renderer", None), "file_writer", None)
    abort = getattr(writer, "abort_encode_jobs", None)
    if abort is not None:
        with contextlib.suppress(Exception):
            abort()


def _hold_signals_while_encoders_start(scene, signals: Signals | None) -> None:
    """Defer SIGINT/SIGTERM while manim opens a segment: its encoder thread starts before the
    writer keeps the job, and an interrupt in between would orphan a thread that waits for
    frames forever (the process never exits)."""
    writer = getattr(getattr(scene, "renderer", None), "file_writer", None)
    opener = getattr(writer, "open_partial_movie_stream", None)
    if opener is None:
        return

    def open_held(*args, **kwargs):
        with signals.deferred() if signals is not None else signals_held():
            return opener(*args, **kwargs)

    writer.open_partial_movie_stream = open_held


def render_into(make_scene: Callable[[], object], output: Path, fmt: str, quality: str,
                *, progress: bool = True, srt: bool = True,
                signals: Signals | None = None, steps: dict | None = None) -> Path:
    """Render ``make_scene()`` with manim and move the finished file to ``output``.

    Renders inside a temporary directory next to ``output`` (same filesystem, so the final
    ``os.replace`` is atomic) and removes it whatever happens. With ``srt``, the subtitle
    file manim writes beside a video is moved to ``output`` with suffix ``.srt``.
    With ``signals`` (from :func:`interrupts_raise`), a signal whose exception got lost
    still cancels the move, and one arriving after the move no longer counts. With ``steps``
    (what made the render: its settings), the step marks the scene noted while rendering
    (:mod:`metaphors.steps`) are written beside the video as ``NAME.steps.json``
    (:mod:`trex.clips`), ``steps`` as their ``made_by``.
    """
    from manim import tempconfig

    temp = Path(tempfile.mkdtemp(prefix=f".{output.name}.", suffix=".render", dir=output.parent))
    try:
        media = temp / "media"
        settings = {
            "quality": quality,
            "format": fmt,
            "media_dir": str(media),
            "disable_caching": True,
            "verbosity": "WARNING",
            "progress_bar": "display" if progress else "none",
            "preview": False,
            # x264 as manim.cfg has it (the same input, the same bytes); but one encoder at a
            # time, not manim.cfg's 4: with several in flight, an interrupted render now and
            # then never exited (tests/test_render_command.py, two renders interrupted at once
            # under load)
            "max_inflight_encoders": 1,
            "video_encoder_options": dict(X264_OPTIONS),
        }
        with tempconfig(settings):
            scene = make_scene()
            _hold_signals_while_encoders_start(scene, signals)
            try:
                scene.render()
            except BaseException:
                _abort_encoders(scene)
                raise
            produced = _artifact(scene, fmt, media)
        marks = _write_marks(scene, produced, steps) if steps is not None else None
        with signals_held(), (signals.deferred() if signals is not None
                               else contextlib.nullcontext()):
            if signals is not None:
                signals.check()
            subtitles = produced.with_suffix(".srt")
            if srt and fmt != "png" and subtitles.is_file():
                os.replace(subtitles, output.with_suffix(".srt"))
            if marks is not None:
                from trex.clips import marks_path  # loaded already: _write_marks used it

                os.replace(marks, marks_path(output))
            os.replace(produced, output)
            if signals is not None:
                signals.done = True
        return output
    finally:
        shutil.rmtree(temp, ignore_errors=True)


def _write_marks(scene, video: Path, made_by: dict) -> Path:
    """The scene's step marks, beside the video it rendered."""
    from metaphors.recorded import recorded_steps, steps_end
    from trex.clips import Marks, Step, write_marks

    steps = tuple(Step(m.frame, m.caption, m.call, m.kind) for m in recorded_steps(scene))
    return write_marks(Marks(steps, steps_end(scene), made_by), video)


def _format_of(fmt: str | None, output: str | None) -> str:
    if fmt:
        return fmt
    suffix = Path(output).suffix.lower().lstrip(".") if output else ""
    return suffix if suffix in FORMATS else "mp4"


@click.command()
@click.argument("scene")
@click.option("--polygon", metavar="POLYGON", help="Polygon file or sample (default: the scene's).")
@click.option("-q", "--quality", type=click.Choice(list(QUALITIES)), default="l",
              show_default=True, help="l 480p15, m 720p30, h 1080p60, k 2160p60.")
@click.option("--format", "fmt", type=click.Choice(FORMATS),
              help="png = the last frame. Default: from -o's extension, else mp4.")
@click.option("-o", "--output", metavar="PATH", help="Where to write (default media/<scene>.<ext>).")
@click.option("--panel", type=click.Choice(PANELS), default=None,
              help="What the panel shows: the pseudocode (the scenes' default; the source "
                   "when the run has none) or the real source.")
@click.option("--heuristic", metavar="NAME|FILE.py:FUNCTION", default=None,
              help="For divide_and_conquer: how each diagonal is found, a built-in or one of "
                   "your own; the video ends on its first wrong claim.")
@call_timeout_option
def render(scene: str, polygon: str | None, quality: str, fmt: str | None,
           output: str | None, panel: str | None, heuristic: str | None) -> None:
    """Render SCENE (a name such as gravity or rotation:RotationCcw, or a file.py[:Class]).

    Prints the output path. An interrupted or failed render leaves nothing at it.
    """
    if polygon is not None:
        load_or_exit(polygon)  # bad input: one line, exit 2, before manim is even imported
    try:
        path, class_name = resolve_scene(scene)
    except ValueError as exc:
        fail(f"{scene}: {exc}")
    fmt = _format_of(fmt, output)
    target = Path(output) if output else default_output(path, class_name, fmt)
    try:
        prepare_output(target)
    except ValueError as exc:
        fail(f"{target}: {exc}")
    with interrupts_raise() as signals:
        try:
            _render(scene, path, class_name, polygon, target, fmt, quality, signals, panel,
                    heuristic)
        except Interrupted as exc:
            click.echo(f"error: {scene}: render interrupted; nothing written", err=True)
            raise click.exceptions.Exit(EXIT_SIGNAL + exc.signum) from None
    click.echo(str(target))


def with_heuristic(cls: type, heuristic: str | None) -> type:
    """The scene class with divide and conquer's heuristic (``--heuristic``) set; as it is for
    None. Raises ValueError (one line) for a scene that takes none or a bad heuristic."""
    if heuristic is None:
        return cls
    if not isinstance(cls, WithHeuristic):
        raise ValueError("takes no heuristic")
    return cls.with_heuristic(heuristic)


def _render(scene: str, path: Path, class_name: str | None, polygon: str | None, target: Path,
            fmt: str, quality: str, signals: Signals, panel: str | None = None,
            heuristic: str | None = None) -> None:
    try:
        if ".py:" in scene:  # the file's Scene class, or a heuristic of one's own
            from metaphors.scene import scene_for_heuristic

            cls = scene_for_heuristic(scene)
        else:
            cls = load_scene_class(path, class_name)
        cls = with_heuristic(cls, heuristic)
    except ValueError as exc:
        fail(f"{scene}: {exc}")
    if polygon is not None and plays_several(cls):
        click.echo(f"warning: {scene}: plays its own polygons; --polygon is ignored", err=True)
    else:
        given = polygon if polygon is not None else _environment_polygon(cls)
        if given is not None:  # a bad polygon, given or from TREX_POLYGON: one line, exit 2
            load_or_exit(given, holes=algorithm_of(cls) in HOLE_ALGORITHMS)
            try:
                dry_run(cls, given)
            except (GeometryError, ValueError, KeyError) as exc:
                fail(f"{given}: {error_line(exc)}")
    try:
        render_into(scene_input(cls, polygon, panel), target, fmt, QUALITIES[quality],
                    signals=signals)
    except (KeyboardInterrupt, click.exceptions.Exit):
        raise
    except UserHeuristicError as exc:  # raised, answered nonsense or was stopped: one line
        signals.check()
        fail(f"{scene}: {exc}")
    except Exception as exc:
        signals.check()  # an interrupt that surfaced as another error is still an interrupt
        click.echo(f"error: {scene}: render failed: {type(exc).__name__}: {error_line(exc)}",
                   err=True)
        raise click.exceptions.Exit(EXIT_FAILED) from None


COMMANDS = (render,)
__all__ = ["COMMANDS", "render", "render_into", "with_heuristic"]
