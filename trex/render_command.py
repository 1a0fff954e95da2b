"""``trex render``: one scene to an mp4, gif or png, written atomically.

The scene is a name (``scaling`` → ``scenes/scaling.py``, ``rotation:RotationCcw``) or a
path (``my_scene.py[:Class]``). Everything that can be checked without manim is checked
first: the polygon (as ``trex check`` does), the scene's file, the output path and format
(:func:`format_of`). Manim is imported only then; the polygon, read once, is checked by the
scene's rule and handed to it (:func:`scene_input`). It renders into a temporary directory beside the output; the finished
file is moved into place with ``os.replace``, so an interrupted (Ctrl-C, SIGTERM) or failed
render leaves nothing at the output path, and no temporary files behind.

:func:`render_into` is the shared machinery (``trex exercises`` renders its stills with it).
"""

from __future__ import annotations

import configparser
import contextlib
import importlib.util
import os
import shutil
import sys
import tempfile
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import TYPE_CHECKING, Any

import click

import tracing
from geometry.errors import GeometryError
from geometry.io import AnyPolygon
from story.pseudocode import PANELS
from story.scene_kinds import (
    Handed,
    WithHeuristic,
    WithPanel,
    algorithm_of,
    heuristic_of,
    plays_several,
)
from story.spec import RunSpec
from tracing import JSON
from trex import encoders, exit_status
from trex.inputs import (
    call_timeout_option,
    error_line,
    fail,
    load_or_exit,
    load_run,
    make_parent,
)
from trex.signals import Interrupted, Signals, interrupts_raise
from usercode.errors import UserHeuristicError

if TYPE_CHECKING:  # manim, imported when a scene is rendered
    from manim import Scene

SCENES_DIR = Path(__file__).resolve().parent.parent / "scenes"
#: The project's manim settings, which plain ``manim`` reads when run from the repository
MANIM_CFG = SCENES_DIR.parent / "manim.cfg"
QUALITIES = {"l": "low_quality", "m": "medium_quality", "h": "high_quality", "k": "fourk_quality"}
FORMATS = ("mp4", "gif", "png")
EXIT_FAILED = exit_status.FINDING
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


#: What running a scene's algorithm once may raise for its input: the polygon's (or the
#: heuristic's) fault, said in one line with exit status 2 by the command that asked.
RUN_ERRORS = (GeometryError, ValueError, KeyError)


def scene_run(cls: type, polygon: str, polygon_read: AnyPolygon | None = None) -> RunSpec | None:
    """The run the scene class ``cls`` plays on ``polygon`` (``polygon_read``: that polygon read
    already, so the run reads no file; None: the run reads it); None for a scene that plays
    no algorithm, or several runs on polygons of its own."""
    algorithm = algorithm_of(cls)
    if algorithm is None or plays_several(cls):
        return None
    return RunSpec(algorithm, polygon, heuristic=heuristic_of(cls), polygon_read=polygon_read)


def run_once(spec: RunSpec) -> tracing.Log:
    """Run ``spec`` once, without drawing, so that an input the algorithm rejects (a triangle
    has no diagonal …) is found before rendering starts; its log, for a command that shows it
    (the player, the slides' page). Raises one of :data:`RUN_ERRORS`; the caller says it in
    one line, naming the polygon."""
    return spec.log()


def scene_input(cls: type, polygon: str | None, panel: str | None = None,
                polygon_read: AnyPolygon | None = None) -> type:
    """The scene class handed its run as data (a subclass carrying a
    :class:`story.spec.RunSpec`, see :class:`metaphors.scene.SpecScene`): on ``polygon`` if
    given, else as ``manim`` would give it (its default run, with ``TREX_POLYGON`` and
    ``TREX_LOG`` from the environment). A polygon given, or from ``TREX_POLYGON``, is read
    here once and checked by the run's rule (:func:`trex.inputs.load_run`; ``polygon_read``: it read
    already), one line and exit 2 if bad: the scene plays what was checked and reads no file.
    A scene of several runs plays its own polygons; a Scene that takes no run comes back as
    it is. ``panel`` (one of :data:`story.pseudocode.PANELS`), if given, is what a scene with
    a panel shows there (:meth:`metaphors.scene.TraceScene.with_panel`); None: the scene's
    own. Raises ValueError for a ``TREX_LOG`` the scene cannot play."""
    if panel is not None and isinstance(cls, WithPanel):
        cls = cls.with_panel(panel)
    if not isinstance(cls, Handed):
        return cls
    if plays_several(cls):
        return cls.handed(polygon) if polygon is not None else cls.from_environment()
    if polygon is not None:
        return cls.with_spec(load_run(cls.default_spec().on(polygon), polygon_read))
    spec: RunSpec = cls.from_environment().spec  # type: ignore[attr-defined]  # the subclass from_environment makes carries the run it was handed
    if spec.saved or spec == cls.default_spec():
        return cls.with_spec(spec)  # a replay, or the default run: nothing handed to check
    return cls.with_spec(load_run(spec))


# --- rendering --------------------------------------------------------------------------------------


def _artifact(scene, fmt: str, media: Path) -> Path:
    """The file manim wrote for this scene (asked from its writer, else found in media/)."""
    writer: Any = getattr(scene.renderer, "file_writer", None)  # None: AttributeError, below
    with contextlib.suppress(AttributeError, TypeError):
        path = Path(writer.image_file_path if fmt == "png" else writer.movie_file_path)
        if path.is_file():
            return path
    found = [p for p in media.rglob(f"*.{fmt}") if "partial_movie_files" not in p.parts]
    if len(found) != 1:
        raise RuntimeError(f"manim wrote no single .{fmt} file ({len(found)} found)")
    return found[0]


def inflight_encoders(cfg: Path = MANIM_CFG) -> int | None:
    """How many encoders manim.cfg lets run at once (``[CLI] max_inflight_encoders``; None:
    not set, manim's own default). Read from the project's file, so that ``trex render``
    encodes as plain ``manim`` does from the repository, wherever it is run from.

    >>> inflight_encoders()
    4
    """
    parser = configparser.ConfigParser()
    parser.read(cfg, encoding="utf-8")
    return parser.getint("CLI", "max_inflight_encoders", fallback=None)


def render_into(make_scene: Callable[[], Scene], output: Path, fmt: str, quality: str,
                *, progress: bool = True, srt: bool = True,
                signals: Signals | None = None, marks_made_by: Mapping[str, JSON] | None = None,
                ) -> Path:
    """Render ``make_scene()`` with manim and move the finished file to ``output``.

    With ``progress``, manim's progress bars are shown when stderr is a terminal.
    Renders inside a temporary directory next to ``output`` (same filesystem, so the final
    ``os.replace`` is atomic) and removes it whatever happens. With ``srt``, the subtitle
    file manim writes beside a video is moved to ``output`` with suffix ``.srt``.
    With ``signals`` (from :func:`interrupts_raise`), a signal whose exception got lost
    still cancels the move, and one arriving after the move no longer counts. With
    ``marks_made_by`` (what made the render: its settings), the step marks the scene noted
    while rendering (:mod:`metaphors.steps`) are written beside the video as
    ``NAME.steps.json`` (:mod:`trex.clips`), ``marks_made_by`` as their ``made_by``. Without
    ``signals``, SIGINT and SIGTERM raise :class:`Interrupted` while it renders (:func:`interrupts_raise`): either
    way, manim's encoder threads are closed however the render ends (:mod:`trex.encoders`).
    """
    with contextlib.ExitStack() as own:
        if signals is None:  # deferring a signal needs our handler (see Signals.deferred)
            signals = own.enter_context(interrupts_raise())
        temp = Path(tempfile.mkdtemp(prefix=f".{output.name}.", suffix=".render",
                                     dir=output.parent))
        try:
            with signals.stuck_cleanup(lambda: shutil.rmtree(temp, ignore_errors=True)):
                return _render_in(make_scene, temp, output, fmt, quality, progress=progress,
                                  srt=srt, signals=signals, marks_made_by=marks_made_by)
        finally:  # still under the handler: a second signal does not stop the removal
            shutil.rmtree(temp, ignore_errors=True)


def _settings(media: Path, fmt: str, quality: str, progress: bool) -> dict:
    """What manim is told for one render into ``media``."""
    settings = {
        "quality": quality,
        "format": fmt,
        "media_dir": str(media),
        "disable_caching": True,
        "verbosity": "WARNING",
        # manim's bars redraw a line in place: on a terminal only (a pipe or a log file
        # would get every redraw, hundreds of lines)
        "progress_bar": "display" if progress and sys.stderr.isatty() else "none",
        "preview": False,
        # x264 as manim.cfg has it (the same input, the same bytes)
        "video_encoder_options": dict(X264_OPTIONS),
    }
    inflight = inflight_encoders(MANIM_CFG)
    if inflight is not None:  # as many encoders at once as plain manim runs (manim.cfg)
        settings["max_inflight_encoders"] = inflight
    return settings


def _render_in(make_scene: Callable[[], Scene], temp: Path, output: Path, fmt: str,
               quality: str, *, progress: bool, srt: bool, signals: Signals,
               marks_made_by: Mapping[str, JSON] | None) -> Path:
    """:func:`render_into`'s work, in its temporary directory ``temp``."""
    from manim import tempconfig

    media = temp / "media"
    with tempconfig(_settings(media, fmt, quality, progress)):
        scene = make_scene()
        guard = encoders.guard(scene, signals.deferred)
        try:
            scene.render()
        except BaseException:
            guard.stop()  # no encoder thread left waiting for frames: the process can exit
            raise
        produced = _artifact(scene, fmt, media)
    marks = (_write_marks(scene, produced, marks_made_by) if marks_made_by is not None
             else None)
    with signals.deferred():  # the moves happen together, or not at all
        signals.check()
        subtitles = produced.with_suffix(".srt")
        if srt and fmt != "png" and subtitles.is_file():
            os.replace(subtitles, output.with_suffix(".srt"))
        if marks is not None:
            from trex.clips import marks_path  # loaded already: _write_marks used it

            os.replace(marks, marks_path(output))
        os.replace(produced, output)
        signals.done = True
    return output


def _write_marks(scene, video: Path, made_by: Mapping[str, JSON]) -> Path:
    """The scene's step marks, beside the video it rendered."""
    from metaphors.recorded import recorded_steps, steps_end
    from trex.clips import Marks, write_marks

    marks = Marks(tuple(recorded_steps(scene)), steps_end(scene), made_by)
    return write_marks(marks, video)


def format_of(fmt: str | None, output: str | None) -> str:
    """The format to render: ``--format`` if given, else ``-o``'s extension, else mp4. Raises
    ValueError (one line) for an extension that contradicts ``--format``, or, with no
    ``--format``, one that names no format :data:`FORMATS` has.

    >>> format_of(None, "clock.GIF"), format_of("png", None), format_of(None, None)
    ('gif', 'png', 'mp4')
    >>> format_of("png", "p.mp4")
    Traceback (most recent call last):
    ...
    ValueError: the extension .mp4 contradicts --format png; give -o p.png, or drop --format
    >>> format_of(None, "out.webm")
    Traceback (most recent call last):
    ...
    ValueError: unknown format '.webm'; expected .mp4, .gif or .png (or --format)
    """
    if output is None:
        return fmt or "mp4"
    path = Path(output)
    suffix = path.suffix.lower().lstrip(".")
    if fmt is not None and suffix and suffix != fmt:
        raise ValueError(f"the extension .{suffix} contradicts --format {fmt}; give -o "
                         f"{path.with_suffix('.' + fmt).name}, or drop --format")
    if fmt is not None:
        return fmt
    if suffix in FORMATS:
        return suffix
    named = f"unknown format '{path.suffix}'" if suffix else "no extension to name the format"
    expected = ", ".join(f".{f}" for f in FORMATS[:-1]) + f" or .{FORMATS[-1]}"
    raise ValueError(f"{named}; expected {expected} (or --format)")


@click.command()
@click.argument("scene")
@click.option("--polygon", metavar="POLYGON", help="Polygon file or sample (default: the scene's).")
@click.option("-q", "--quality", type=click.Choice(list(QUALITIES)), default="l",
              show_default=True, help="l 480p15, m 720p30, h 1080p60, k 2160p60.")
@click.option("--format", "fmt", type=click.Choice(FORMATS),
              help="png = the last frame. Default: from -o's extension (which must not "
                   "contradict --format), else mp4.")
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
    # bad input: one line, exit 2, before manim is even imported (holes: the scene's rule,
    # once its algorithm is known)
    polygon_read = load_or_exit(polygon, holes=True) if polygon is not None else None
    try:
        path, class_name = resolve_scene(scene)
    except ValueError as exc:
        fail(f"{scene}: {exc}")
    if output == "":
        fail("'': empty path; give a file path")
    if output is not None and Path(output).is_dir():  # said as such, not as a bad extension
        fail(f"{output}: is a directory; give a file path")
    try:
        fmt = format_of(fmt, output)
    except ValueError as exc:
        fail(f"{output}: {exc}")
    target = Path(output) if output else default_output(path, class_name, fmt)
    try:
        prepare_output(target)
    except ValueError as exc:
        fail(f"{target}: {exc}")
    interrupted = f"error: {scene}: render interrupted; nothing written"
    with interrupts_raise(interrupted) as signals:
        try:
            _render(scene, path, class_name, (polygon, polygon_read), target, fmt, quality, signals,
                    panel, heuristic)
        except Interrupted as exc:
            click.echo(interrupted, err=True)
            raise click.exceptions.Exit(exit_status.interrupted(exc.signum)) from None
    click.echo(str(target))


def with_heuristic(cls: type, heuristic: str | None) -> type:
    """The scene class with divide and conquer's heuristic (``--heuristic``) set; as it is for
    None. Raises ValueError (one line) for a scene that takes none or a bad heuristic."""
    if heuristic is None:
        return cls
    if not isinstance(cls, WithHeuristic):
        raise ValueError("takes no heuristic")
    return cls.with_heuristic(heuristic)


def _render(scene: str, path: Path, class_name: str | None,
            given: tuple[str | None, AnyPolygon | None], target: Path, fmt: str, quality: str,
            signals: Signals, panel: str | None = None, heuristic: str | None = None) -> None:
    polygon, polygon_read = given  # --polygon, and that polygon read already
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
    try:
        handed = scene_input(cls, polygon, panel, polygon_read)  # a bad polygon: one line, exit 2
    except ValueError as exc:  # a TREX_LOG it cannot play
        fail(f"{scene}: {error_line(exc)}")
    spec = handed.spec if isinstance(handed, Handed) else None
    if spec is not None and spec.polygon_read is not None:  # a polygon handed: run it once, now
        try:
            run_once(spec)
        except RUN_ERRORS as exc:
            fail(f"{spec.polygon}: {error_line(exc)}")
    try:
        render_into(handed, target, fmt, QUALITIES[quality], signals=signals)
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
