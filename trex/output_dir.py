"""A directory of output built beside its target and renamed into place (``trex player``,
``trex slides``).

The target may be new, empty, or an earlier output of the same command, which holds that
command's marker file (``.trex-player``, ``.trex-slides``); anything else there is refused.
:func:`built_beside` makes a temporary directory next to the target (same filesystem: the
rename is atomic), writes the marker when the block succeeds, and moves the whole directory
into place; a failure or Ctrl-C removes it and leaves the target as it was.
"""

from __future__ import annotations

import contextlib
import os
import shutil
import tempfile
from collections.abc import Callable, Iterator, Sequence
from pathlib import Path
from typing import TypeVar

import click

from trex.inputs import error_line, make_parent
from trex.signals import EXIT_SIGNAL, Interrupted, interrupts_raise

EXIT_FAILED = 1


def check_output(target: Path, marker: str, earlier: str) -> None:
    """``target`` may be new, empty, or an ``earlier`` output (it holds ``marker``); its
    parent is created. Raises ValueError (one line) if not."""
    if target.exists() and not target.is_dir():
        raise ValueError("exists and is not a directory")
    if target.is_dir() and any(target.iterdir()) and not (target / marker).is_file():
        raise ValueError(f"exists and is not {earlier} (no {marker} in it); "
                         "give a new or empty directory")
    make_parent(target)


def move_into_place(built: Path, target: Path, entries: Sequence[str] | None = None) -> None:
    """Put the finished directory ``built`` at ``target``.

    When ``target`` does not exist yet, or ``entries`` is None, the whole directory: an
    earlier ``target`` is removed after (and put back if the move fails). Else only the
    ``entries`` of ``built`` move into the existing ``target``, each replacing its namesake
    (``trex lecture``: files of the user's in the directory stay). Call with signals held
    (:func:`trex.signals.signals_held`) when the moves must happen together.
    """
    if not target.exists():
        os.replace(built, target)
        return
    old = Path(tempfile.mkdtemp(prefix=f".{target.name}.", suffix=".old", dir=target.parent))
    try:
        for name in (None,) if entries is None else entries:
            _replace(built if name is None else built / name,
                     target if name is None else target / name, old)
    finally:
        shutil.rmtree(old, ignore_errors=True)


def _replace(new: Path, target: Path, old: Path) -> None:
    """``os.replace(new, target)``; a directory at ``target`` (which ``os.replace`` cannot
    overwrite unless empty) is first moved into ``old``, and put back if the move fails."""
    if not target.is_dir():
        os.replace(new, target)
        return
    aside = old / target.name  # the entries' names differ: one each
    os.replace(target, aside)
    try:
        os.replace(new, target)
    except OSError:
        os.replace(aside, target)
        raise


@contextlib.contextmanager
def built_beside(target: Path, marker: str, written_by: str) -> Iterator[Path]:
    """A temporary directory beside ``target`` to build in; when the block ends without an
    exception it gets ``marker`` and replaces ``target``. Removed whatever happens."""
    built = Path(tempfile.mkdtemp(prefix=f".{target.name}.", suffix=".build",
                                  dir=target.parent))
    try:
        yield built
        (built / marker).write_text(f"written by {written_by}\n", encoding="utf-8")
        built.chmod(0o755)  # mkdtemp makes it private
        move_into_place(built, target)
    finally:
        shutil.rmtree(built, ignore_errors=True)


T = TypeVar("T")


def build_guarded(label: str, output: str, what: str, build: Callable[[], T]) -> T:
    """``build()``, with Ctrl-C and SIGTERM raising (its cleanup runs) and any failure one
    line: ``error: LABEL: WHAT failed: …`` and exit 1, or exit 128 + the signal."""
    with interrupts_raise() as signals:
        try:
            done = build()
            signals.done = True
        except Interrupted as exc:
            click.echo(f"error: {label}: interrupted; {output} left as it was", err=True)
            raise click.exceptions.Exit(EXIT_SIGNAL + exc.signum) from None
        except (click.exceptions.Exit, KeyboardInterrupt):
            raise
        except Exception as exc:
            click.echo(f"error: {label}: {what} failed: {type(exc).__name__}: "
                       f"{error_line(exc)}", err=True)
            raise click.exceptions.Exit(EXIT_FAILED) from None
    return done
