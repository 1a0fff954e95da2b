"""``trex studio``: serve the studio's page and API on this machine until Ctrl-C.

Everything is checked before the server starts (one line, exit 2): the heuristics of
one's own, the polygon, the port. The studio writes only under its work directory (a
fresh temporary one, removed on exit; ``--keep DIR`` keeps it).
"""

from __future__ import annotations

import shutil
import sys
import tempfile
import webbrowser
from pathlib import Path

import click

from trex.inputs import call_timeout_option, fail, load_or_exit
from trex.signals import EXIT_SIGNAL
from trex.studio.api import rings_of_polygon
from trex.studio.children import COMMANDS as JOB_COMMANDS
from usercode.errors import UserHeuristicError
from usercode.heuristic import UserHeuristic, load_user_heuristic
from usercode.limits import call_timeout
from usercode.loading import is_user_spec


def _own_heuristics(specs: tuple[str, ...]) -> dict[str, UserHeuristic]:
    """Each ``FILE.py:FUNCTION``, loaded now, by the name the page shows (its spec)."""
    own: dict[str, UserHeuristic] = {}
    for spec in specs:
        if not is_user_spec(spec):
            fail(f"--heuristic {spec}: expected FILE.py:FUNCTION (the built-ins are always there)")
        try:
            own[spec] = load_user_heuristic(spec)
        except UserHeuristicError as exc:
            fail(f"--heuristic {spec}: {exc}")
    return own


def _work_dir(keep: str | None) -> Path:
    if keep is None:
        return Path(tempfile.mkdtemp(prefix="trex-studio-"))
    path = Path(keep)
    try:
        path.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        fail(f"--keep {keep}: cannot create it: {exc.strerror or exc}")
    return path


def _served_hosts(host: str, port: int) -> set[str]:
    """The Host headers the guard accepts: the one served, and its loopback aliases."""
    shown = f"[{host}]" if ":" in host else host
    hosts = {f"{shown}:{port}"}
    if host in ("127.0.0.1", "localhost", "::1"):
        hosts |= {f"127.0.0.1:{port}", f"localhost:{port}", f"[::1]:{port}"}
    return hosts


@click.command(name="studio")
@click.option("--host", default="127.0.0.1", show_default=True,
              help="Where to listen (only this machine by default).")
@click.option("--port", type=click.IntRange(0, 65535), default=8765, show_default=True,
              help="The port (0: any free one).")
@click.option("--no-browser", is_flag=True, help="Do not open the page in the browser.")
@click.option("--heuristic", "heuristics", multiple=True, metavar="FILE.py:FUNCTION",
              help="A heuristic of your own, shown beside the built-ins (repeatable).")
@click.option("--polygon", metavar="POLYGON", help="The polygon the page opens with.")
@click.option("--keep", metavar="DIR", help="Work in DIR and keep it (default: a temporary "
                                            "directory, removed on exit).")
@call_timeout_option
def studio(host: str, port: int, no_browser: bool, heuristics: tuple[str, ...],
           polygon: str | None, keep: str | None) -> None:
    """Draw a polygon in the browser and see every heuristic decide on it; hunt,
    triangulate and render it. Stops on Ctrl-C."""
    from trex.studio import server  # uvicorn: only for this command
    from trex.studio.app import create_app

    own = _own_heuristics(heuristics)
    initial = rings_of_polygon(load_or_exit(polygon, holes=True)) if polygon else None
    try:
        sock = server.bind(host, port)
    except server.PortInUse as exc:
        fail(str(exc))
    url = server.url_of(sock, host)
    work = _work_dir(keep)
    bound = sock.getsockname()[1]
    app = create_app(hosts=_served_hosts(host, bound), own=own, work=work, initial=initial,
                     call_timeout=call_timeout(),
                     any_address_port=bound if host in ("0.0.0.0", "::") else None)

    def listening() -> None:
        click.echo(f"studio: {url}")
        sys.stdout.flush()
        if not no_browser:
            webbrowser.open(url)

    try:
        stopped_by = server.serve(app, sock, listening)
    finally:
        sock.close()
        if keep is None:
            shutil.rmtree(work, ignore_errors=True)
    if stopped_by is not None:
        raise click.exceptions.Exit(EXIT_SIGNAL + stopped_by)


COMMANDS = (studio, *JOB_COMMANDS)
