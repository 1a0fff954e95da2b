"""``trex exercises``: exercise stills (PNG) and ``answers.md``, every answer checked.

The exercises come from :mod:`story.exercises` (no manim); each still is rendered by
manim at medium quality into a temporary directory beside it and moved into place, and
``answers.md`` is written atomically last. The same seed gives the same files.
"""

from __future__ import annotations

import functools
import os
from collections.abc import Callable
from pathlib import Path

import click

from geometry.io import write_atomic
from story.exercises import answers_markdown, make_exercises
from trex.inputs import error_line, fail
from trex.render_command import EXIT_FAILED, render_into
from trex.signals import EXIT_SIGNAL, Interrupted, interrupts_raise

STILL_QUALITY = "medium_quality"
ANSWERS = "answers.md"


def prepare_directory(arg: str) -> Path:
    """The output directory, created if missing; ValueError with a one-line reason if not usable."""
    directory = Path(arg)
    if directory.exists() and not directory.is_dir():
        raise ValueError("not a directory")
    try:
        directory.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise ValueError(f"cannot create directory: {exc.strerror or exc}") from None
    if not os.access(directory, os.W_OK | os.X_OK):
        raise ValueError("directory is not writable")
    return directory


@click.command()
@click.option("--n", "n", type=click.IntRange(1, 99), default=6, show_default=True,
              help="How many exercises (kinds in turn: pick, claim, inner).")
@click.option("--seed", type=int, default=0, show_default=True, help="Seed of the search.")
@click.option("-o", "--output", "out_dir", required=True, metavar="DIR",
              help="Directory for the PNG stills and answers.md (created if missing).")
def exercises(n: int, seed: int, out_dir: str) -> None:
    """Write N exercise stills and answers.md (each answer checked by the geometry code)."""
    try:
        directory = prepare_directory(out_dir)
    except ValueError as exc:
        fail(f"{out_dir}: {exc}")
    items = make_exercises(n, seed)
    try:
        answers = write_exercises(items, directory, seed, click.echo)[-1]
    except Interrupted as exc:
        click.echo("error: exercises interrupted; the files listed above are complete", err=True)
        raise click.exceptions.Exit(EXIT_SIGNAL + exc.signum) from None
    except OSError as exc:
        fail(f"{out_dir}: cannot write: {exc.strerror or error_line(exc)}")
    except Exception as exc:
        click.echo(f"error: exercises: {type(exc).__name__}: {error_line(exc)}", err=True)
        raise click.exceptions.Exit(EXIT_FAILED) from None
    click.echo(str(answers))


def write_exercises(items: list, directory: Path, seed: int,
                    echo: Callable[[str], None] | None = None) -> list[Path]:
    """Render each exercise's still into ``directory`` (``echo`` its path when done), then
    write ``answers.md``; the files written, ``answers.md`` last (``trex course`` writes
    each student's sheets with it)."""
    from metaphors.stills import ExerciseStill

    written = []
    for exercise in items:
        target = directory / exercise.still
        with interrupts_raise() as signals:
            render_into(functools.partial(ExerciseStill, exercise), target, "png",
                        STILL_QUALITY, progress=False, srt=False, signals=signals)
        if echo is not None:
            echo(str(target))
        written.append(target)
    answers = directory / ANSWERS
    write_atomic(answers, answers_markdown(items, seed))
    return [*written, answers]


COMMANDS = (exercises,)
