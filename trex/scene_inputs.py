"""What ``trex player`` and ``trex slides`` play: a scene of one run and that run, checked.

SCENE is what ``trex render`` takes: a name from ``scenes/`` (``gravity``,
``rotation:RotationCcw``), a scene file, or a heuristic of one's own (``file.py:function``);
it must be a :class:`metaphors.scene.TraceScene` of one run. The run is the one
``trex render SCENE`` would play (a :class:`story.spec.RunSpec`): ``--log FILE`` (a saved
log) or ``--polygon`` if given, else ``TREX_LOG``, else a live run on ``TREX_POLYGON`` or
the scene's default polygon (read by :mod:`story.environment`). A saved log must be of the
algorithm (and heuristic) the scene plays.

:func:`choose` checks the inputs, :func:`run_of` computes the run; each bad input is one line
and exit status 2 (:func:`trex.inputs.fail`), before anything is drawn.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, cast

from story.registry import spoken
from story.scene_kinds import heuristic_of, plays_several
from trex.inputs import error_line, fail, load_or_exit, load_run
from trex.render_command import RUN_ERRORS, run_once
from usercode.loading import is_user_spec

if TYPE_CHECKING:  # manim's, imported when a scene is loaded
    from metaphors.scene import TraceScene
    from story.spec import RunSpec
    from tracing import Log


def load_scene(scene: str, command: str = "player", several_runs: bool = False) -> type[TraceScene]:
    """The TraceScene subclass SCENE names (imports manim); one that plays several runs
    only if ``several_runs``. Raises ValueError (one line)."""
    if ".py:" in scene:
        from metaphors.scene import scene_for_heuristic

        cls = scene_for_heuristic(scene)
    else:
        from trex.render_command import load_scene_class, resolve_scene

        cls = load_scene_class(*resolve_scene(scene))
    from metaphors.scene import TraceScene

    plural = command.endswith("s")  # "the slides step", "the player steps"
    if not (isinstance(cls, type) and issubclass(cls, TraceScene)):
        raise ValueError(f"{cls.__name__} does not play an algorithm's log; the {command} "
                         f"{'need' if plural else 'needs'} a TraceScene")
    if plays_several(cls) and not several_runs:
        raise ValueError(f"{cls.__name__} plays several runs; the {command} "
                         f"{'step' if plural else 'steps'} through one (pick a scene of one "
                         "algorithm)")
    return cls


def read_log(path: str) -> Log:
    """The saved log at ``path`` (a :class:`tracing.Log` of one run). Raises ValueError (one
    line) for a file that cannot be read or is not a trex log of a run."""
    from story.runs import saved_log

    try:
        log = saved_log(path)
    except OSError as exc:
        raise ValueError(f"cannot read: {exc.strerror or error_line(exc)}") from None
    except (ValueError, KeyError, TypeError, RecursionError) as exc:  # JSON, UTF-8, schema
        raise ValueError(f"not a trex log: {error_line(exc)}") from None
    algorithm = log.meta.get("algorithm")
    if not isinstance(algorithm, str) or not algorithm:
        raise ValueError("not the log of a run: its meta names no algorithm")
    return log


def _same_algorithm(plays: str, logged: str) -> bool:
    """A heuristic of one's own is the same when its function is (the path may be spelled
    differently)."""
    if plays == logged:
        return True
    return (is_user_spec(plays) and is_user_spec(logged)
            and plays.rpartition(":")[2] == logged.rpartition(":")[2])


def check_log(cls: type[TraceScene], log: Log, scene: str | None = None) -> None:
    """A saved log must be a run of what the scene (named ``scene``) plays and give steps
    that start with the polygon. Raises ValueError (one line)."""
    from metaphors.catalog import beats as storyboard

    logged, plays, name = log.meta.get("algorithm"), cls.algorithm, scene or cls.__name__
    if not isinstance(logged, str):
        raise ValueError("is no log of a run: its meta names no algorithm")
    if not _same_algorithm(plays, logged):
        raise ValueError(f"is a log of {logged}, but {name} plays {plays}")
    ran_with, wants = log.meta.get("heuristic"), heuristic_of(cls)
    if ran_with and wants and ran_with != wants:
        raise ValueError(f"is a log of {logged} with {ran_with}, but {name} plays "
                         f"{plays} with {wants}")
    try:
        beats = storyboard(log)
    except Exception as exc:  # a malformed event: whatever it breaks, the log is at fault
        raise ValueError(f"cannot be played: {type(exc).__name__}: {error_line(exc)}") from None
    if not beats or not {"points", "labels"} <= set(beats[0].data):
        raise ValueError("cannot be played: it does not start with the polygon")


@dataclass(frozen=True)
class Chosen:
    """The scene class and where its run comes from, checked: a saved log (read, and its
    path as the user named it) or a polygon (None: the scene's default), and for a scene of
    one run, the run on that polygon with the polygon read (``spec``, see
    :func:`trex.inputs.load_run`; None: the default run)."""

    cls: type[TraceScene]
    log: Log | None
    saved: str | None
    saved_as: str | None
    polygon: str | None
    spec: RunSpec | None = None


def choose(scene: str, polygon: str | None, saved: str | None,
           command: str = "player", several_runs: bool = False) -> Chosen:
    """Check SCENE, ``--polygon`` and ``--log`` (or ``TREX_LOG``, ``TREX_POLYGON``); one
    line and exit 2 for the first that is bad (a scene of several runs is bad unless
    ``several_runs``)."""
    if polygon is not None and saved is not None:
        fail("--polygon and --log: give one of them (a saved log has its own polygon)")
    saved_as = saved
    if polygon is None and saved is None:  # as scenes do: TREX_LOG, else TREX_POLYGON
        from story.environment import LOG, POLYGON, environment_values

        values = environment_values()
        if LOG in values:
            saved, saved_as = values[LOG], f"{LOG}={values[LOG]}"
        else:
            polygon = values.get(POLYGON)
    log = None
    if saved is not None:  # bad input: one line, exit 2, before anything is drawn
        try:
            log = read_log(saved)
        except ValueError as exc:
            fail(f"{saved_as}: {exc}")
    try:
        cls = load_scene(scene, command, several_runs)
    except ValueError as exc:
        fail(f"{scene}: {exc}")
    spec = None
    if log is None and polygon is not None:
        if plays_several(cls):  # ignored (its runs name their own), but not bad
            load_or_exit(polygon, holes=True)
        else:
            spec = load_run(cls.default_spec().on(polygon))  # read once, by the run's rule
    if log is not None:
        try:
            check_log(cls, log, scene)
        except ValueError as exc:
            fail(f"{saved_as}: {exc}")
    return Chosen(cls, log, saved, saved_as, polygon, spec)


def _said(log) -> str:
    """The log's algorithm as the page says it: its spoken name (``Correct Scaling``), never
    the command line's slug (issue 22)."""
    return spoken(str(log.meta.get("algorithm")), start=True)


def run_of(chosen: Chosen):
    """``(spec, log, subtitle)``: the run the scene plays (computed now when live; a polygon
    the algorithm rejects is one line and exit 2) and the line saying what it is."""
    spec = chosen.cls.default_spec()
    if chosen.log is None:
        spec = chosen.spec if chosen.spec is not None else spec  # the polygon, read once
        try:
            log = run_once(spec)
        except RUN_ERRORS as exc:
            fail(f"{spec.polygon}: {error_line(exc)}")
        return spec, log, f"{_said(log)} on {spec.polygon}"
    log = chosen.log
    saved = cast(str, chosen.saved)  # the log was read from it
    return (spec.replaying(saved), log,
            f"{_said(log)} on {log.meta.get('polygon', '?')}, "
            f"saved in {Path(saved).name}")
