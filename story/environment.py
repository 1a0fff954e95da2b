"""The one module that reads the environment: ``TREX_POLYGON`` and ``TREX_LOG``.

``manim -pql scenes/x.py`` cannot pass a scene anything but the environment, so a scene
handed no :class:`~story.spec.RunSpec` builds its own here: its default run, on
``TREX_POLYGON`` (a polygon file or sample) if set, replaying ``TREX_LOG`` (a saved log)
if set — the saved log wins, as it has its own polygon. A scene of several runs reads
``TREX_LOG`` as one saved log per run, joined with ``os.pathsep``, and never
``TREX_POLYGON`` (its runs name their own polygons). A variable set to the empty string
counts as unset. ``trex`` commands read the environment through here too, where they
document it (``trex player`` without ``--polygon`` or ``--log``, say); nothing else in
the library looks at ``os.environ``. (A command hands the processes it starts their
settings as named options, not variables: ``trex chapter --call-timeout``.)

>>> from story.spec import RunSpec
>>> default = RunSpec("gravity", "gravity-snag")
>>> spec_from_environment(default, {"TREX_POLYGON": "star"})
RunSpec(algorithm='gravity', polygon='star', heuristic=None, saved=None)
>>> spec_from_environment(default, {"TREX_LOG": "run.json", "TREX_POLYGON": ""}).saved
'run.json'
>>> spec_from_environment(default, {}) == default
True
"""

from __future__ import annotations

import os
from collections.abc import Mapping, Sequence
from dataclasses import replace

from story.spec import RunSpec

__all__ = ["LOG", "POLYGON", "environment_values", "inherited", "spec_from_environment",
           "specs_from_environment"]

#: The polygon a scene runs on (a file or a sample name).
POLYGON = "TREX_POLYGON"
#: A saved log to replay (several, joined with ``os.pathsep``, for a scene of several runs).
LOG = "TREX_LOG"


def inherited(**extra: str) -> dict[str, str]:
    """The environment of a process a command starts: this process's, with ``extra`` set
    (its scratch folder, a search path). trex's own settings go to it as named options.

    >>> inherited(TMPDIR="/tmp/job")["TMPDIR"]
    '/tmp/job'
    """
    return {**os.environ, **extra}


def environment_values(environ: Mapping[str, str] | None = None) -> dict[str, str]:
    """``TREX_POLYGON`` and ``TREX_LOG`` as set (non-empty) in ``environ`` (default: the
    process's environment).

    >>> environment_values({"TREX_LOG": "", "TREX_POLYGON": "star", "HOME": "/root"})
    {'TREX_POLYGON': 'star'}
    """
    env = os.environ if environ is None else environ
    return {name: env[name] for name in (POLYGON, LOG) if env.get(name)}


def spec_from_environment(default: RunSpec,
                          environ: Mapping[str, str] | None = None) -> RunSpec:
    """The run a scene plays under plain ``manim``: ``default`` on ``TREX_POLYGON`` if set,
    replaying ``TREX_LOG`` if set."""
    values = environment_values(environ)
    return replace(default, polygon=values.get(POLYGON, default.polygon),
                   saved=values.get(LOG, default.saved))


def specs_from_environment(defaults: Sequence[RunSpec],
                           environ: Mapping[str, str] | None = None) -> tuple[RunSpec, ...]:
    """The runs of a scene of several runs: ``defaults``, or each replaying its saved log when
    ``TREX_LOG`` lists one per run (joined with ``os.pathsep``). Raises ValueError when it
    lists another number of logs.

    >>> runs = (RunSpec("scaling", "counterexample"), RunSpec("rotation", "counterexample"))
    >>> [s.saved for s in specs_from_environment(runs, {"TREX_LOG": os.pathsep.join("ab")})]
    ['a', 'b']
    >>> specs_from_environment(runs, {"TREX_LOG": "a"})  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: TREX_LOG lists 1 logs; this scene plays 2 runs (join their paths with ...)
    """
    saved = environment_values(environ).get(LOG)
    if saved is None:
        return tuple(defaults)
    paths = saved.split(os.pathsep)
    if len(paths) != len(defaults):
        raise ValueError(f"{LOG} lists {len(paths)} logs; this scene plays "
                         f"{len(defaults)} runs (join their paths with {os.pathsep!r})")
    return tuple(spec.replaying(path) for spec, path in zip(defaults, paths, strict=True))
