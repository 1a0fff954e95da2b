"""``trex hunt``: search for a counterexample to a heuristic, shrink it, say why it fails.

The search and the shrinker are :mod:`story.hunt` (no manim); this is the command: the
verdict in words and the polygon, or one JSON line; ``-o`` writes the polygon for
``trex render --polygon``. Exit status 1: a counterexample was found, or a polygon on which a
function of one's own raises, answers nonsense or does not return within ``--call-timeout``
seconds (a finding too: the polygon is what its author needs, shrunk while it fails the same
way); 0: none within the budget; 2: bad input (an unknown heuristic, a broken file, a
function of one's own that calls ``sys.exit()``); 130: interrupted (Ctrl-C).
"""

from __future__ import annotations

import contextlib
import json
import sys
from pathlib import Path
from typing import cast

import click

from geometry.io import polygon_to_json_points, write_polygon
from geometry.polygon import Polygon
from story.hunt import (
    MAX_SHRINK_TIMEOUTS,
    Hunt,
    hunt,
    polygon_lines,
    reason,
    skipped_note,
    verdict_line,
)
from story.registry import REGISTRY, entry
from trex.exit_status import FINDING as EXIT_FOUND
from trex.inputs import call_timeout_option, error_line, fail, output_or_exit
from trex.run_commands import HeuristicOrFile
from usercode.errors import UserHeuristicError
from usercode.heuristic import UserHeuristic


def hunt_record(result: Hunt) -> dict:
    """The one JSON line: indices into ``polygon`` as listed (counter-clockwise from A).
    ``why`` says why the claim is wrong (as ``trex diagonal`` does), ``error`` what a function
    of one's own did instead of claiming (then ``diagonal``, ``inner`` and ``why`` are null);
    ``skipped`` counts the draws of the budget that made no polygon."""
    found = result.found and result.polygon is not None
    claimed = found and result.error is None
    return {
        "heuristic": result.heuristic,
        "found": result.found,
        "polygon": (polygon_to_json_points(list(result.polygon.points))
                    if found and result.polygon is not None else None),  # (found says so)
        "diagonal": list(result.diagonal) if claimed and result.diagonal else None,
        "inner": False if claimed else None,
        "why": reason(result) if claimed else None,
        "error": result.error if found else None,
        "tried": result.tried,
        "skipped": result.skipped,
        "max_vertices": result.max_vertices,
        "seconds": round(result.seconds, 3),
    }


@click.command(name="hunt")
@click.argument("heuristic", type=HeuristicOrFile())
@click.option("--budget", type=click.IntRange(min=1), default=5000, show_default=True,
              metavar="N", help="How many polygons to try (the result depends on it, not on "
                                "the clock).")
@click.option("--seed", type=int, default=0, show_default=True, help="Seed of the search.")
@click.option("--max-vertices", type=click.IntRange(min=4), default=8, show_default=True,
              metavar="N", help="The largest polygons tried (fewest vertices first).")
@click.option("-o", "--output", metavar="FILE",
              help="Write the counterexample here (format by extension), for trex render "
                   "--polygon.")
@click.option("--general-position", "general", is_flag=True,
              help="Only polygons with no three vertices on a line, on which the wrong claim "
                   "crosses an edge (not only passes through a vertex): one a class can see "
                   "fail.")
@click.option("--json", "as_json", is_flag=True, help="One JSON line.")
@click.option("--render", "render", is_flag=False, flag_value="", default=None,
              metavar="[FILE.mp4]",
              help="Render the heuristic's video on the counterexample (480p) into FILE.mp4 "
                   "(default: media/hunt-<name>.mp4) and print the mp4's path.")
@call_timeout_option
def hunt_command(heuristic: str | UserHeuristic, budget: int, seed: int, max_vertices: int,
                 output: str | None, general: bool, as_json: bool,
                 render: str | None) -> None:
    """Search small polygons for one on which HEURISTIC's claim is not an inner diagonal,
    shrink it to a minimal one and say why the claim is wrong.

    HEURISTIC is a built-in name or FILE.py:FUNCTION of your own. Exit status 1: found;
    0: none within the budget; 2: bad input.
    """
    if output is not None:
        output_or_exit(output, polygon=True)  # before the search: one line, exit 2
    video = _video_target(heuristic, render)
    show_bar = not as_json and sys.stderr.isatty()
    bar_context = (click.progressbar(length=budget, label="hunting", file=sys.stderr)
                   if show_bar else contextlib.nullcontext())
    with bar_context as bar:
        try:
            result = hunt(heuristic, budget=budget, seed=seed, max_vertices=max_vertices,
                          progress=bar.update if bar is not None else None, general=general)
        except UserHeuristicError as exc:  # it tried to end the program: no polygon explains it
            fail(f"{heuristic}: {exc}")
        except ValueError as exc:  # a built-in heuristic that refuses a polygon
            fail(f"{heuristic}: {error_line(exc)}")
    if as_json:
        click.echo(json.dumps(hunt_record(result), separators=(",", ":"), ensure_ascii=False))
    else:
        click.echo(verdict_line(result))
        if result.found and result.polygon is not None:
            click.echo("\n".join(polygon_lines(result.polygon)))
            noun = "polygon" if result.tried == 1 else "polygons"
            click.echo(f"(found among {result.tried:,} {noun}, on one of {result.first} "
                       f"vertices, shrunk in {result.checks:,} checks{_stopped(result)}, "
                       f"{result.seconds:.2f} s){skipped_note(result)}")
    if result.found and result.polygon is not None:
        if output is not None:
            try:
                write_polygon(list(result.polygon.points), output)
            except (OSError, ValueError) as exc:
                fail(f"{output}: cannot write: {error_line(exc)}")
            if not as_json:
                click.echo(f"wrote {output}")
        if video is not None and result.error is not None:
            click.echo("note: --render: no video of a run that does not end in a claim",
                       err=True)
        elif video is not None:
            click.echo(str(render_counterexample(heuristic, result, output, video)),
                       err=as_json)  # --json: stdout stays one JSON line
        raise click.exceptions.Exit(EXIT_FOUND)


def _video_target(heuristic: str | UserHeuristic, render: str | None) -> Path | None:
    """Where ``--render`` writes (None: no video): the path given, checked before the search
    (an mp4, in a directory that exists and can be written to: one line, exit 2), else
    ``media/hunt-<name>.mp4``."""
    if render is None:
        return None
    if not render:
        name = heuristic.name if isinstance(heuristic, UserHeuristic) else str(heuristic)
        return Path("media") / f"hunt-{name}.mp4"
    if Path(render).suffix.lower() != ".mp4":
        fail(f"{render}: --render writes an mp4; give a path ending in .mp4")
    return output_or_exit(render)


def _stopped(result: Hunt) -> str:
    if not result.stopped:
        return ""
    return f" (stopped: more than {MAX_SHRINK_TIMEOUTS} of them ran out of time)"


def heuristic_video(heuristic: str | UserHeuristic) -> type:
    """The Scene class of a heuristic's video: a built-in's own scene in ``scenes/`` (the
    single run of it), or the scene of a heuristic of one's own. An algorithm with no scene
    of its own (prune and search, constrained Delaunay) plays in the scene of another with
    its metaphor (its plate and counter), else in a plain one."""
    from manim import Scene

    from metaphors.scene import SequenceScene, TraceScene, heuristic_scene
    from trex.render_command import known_scenes, load_scene_class, resolve_scene

    if isinstance(heuristic, UserHeuristic):
        return heuristic_scene(heuristic)
    kin: dict[str, type] = {}  # a scene of the same metaphor, for an algorithm with none
    for name in known_scenes():
        path, _ = resolve_scene(name)
        module_classes = [load_scene_class(path, None)]
        module = sys.modules.get(f"_trex_scene_{path.stem}")
        if module is not None:
            module_classes = [v for v in vars(module).values()
                              if isinstance(v, type) and issubclass(v, Scene)
                              and v.__module__ == module.__name__]
        for cls in module_classes:
            if (issubclass(cls, TraceScene) and not issubclass(cls, SequenceScene)
                    and cls.algorithm == heuristic):
                return cls
            if (issubclass(cls, TraceScene) and not issubclass(cls, SequenceScene)
                    and heuristic in REGISTRY and entry(cls.algorithm).metaphor is not None
                    and entry(cls.algorithm).metaphor == entry(heuristic).metaphor):
                kin.setdefault(heuristic, cls)
    if heuristic not in REGISTRY:
        raise ValueError(f"no scene in scenes/ plays {heuristic}")
    known, base = entry(heuristic), kin.get(heuristic, TraceScene)
    name = "".join(word.capitalize() for word in heuristic.split("-"))  # PruneAndSearch
    return type(name, (base,), {"algorithm": heuristic, "polygon": known.polygon,
                                "title": known.title, "heuristic": None})


def render_counterexample(heuristic: str | UserHeuristic, result: Hunt,
                          output: str | None, target: Path) -> Path:
    """Render the heuristic's video on the counterexample (the polygon written to ``output``,
    else beside ``target`` as ``.json``) into ``target``, as ``trex render`` does
    (atomically, interrupts leaving nothing); its path."""
    from trex.render_command import (
        QUALITIES,
        Interrupted,
        interrupts_raise,
        prepare_output,
        render_into,
        scene_input,
    )

    name = heuristic.name if isinstance(heuristic, UserHeuristic) else str(heuristic)
    polygon = Path(output) if output is not None else target.with_suffix(".json")
    try:
        prepare_output(target)
        if output is None:
            write_polygon(list(cast(Polygon, result.polygon).points), str(polygon))  # a hunt found
        cls = heuristic_video(heuristic)
    except (OSError, ValueError) as exc:
        fail(f"{target}: {error_line(exc)}")
    with interrupts_raise() as signals:
        try:
            render_into(scene_input(cls, str(polygon)), target, "mp4", QUALITIES["l"],
                        signals=signals)
        except Interrupted as exc:
            click.echo(f"error: {name}: render interrupted; nothing written", err=True)
            raise click.exceptions.Exit(128 + exc.signum) from None
        except UserHeuristicError as exc:
            fail(f"{name}: {exc}")
    return target


COMMANDS = (hunt_command,)
