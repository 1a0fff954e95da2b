"""The studio's ASGI app (Starlette): the JSON routes, the page, and the Host/Origin guard.

The guard refuses, 403, a request whose ``Host`` is not the served one (DNS rebinding)
or whose ``Origin`` is foreign (a cross-site POST): the page runs heuristics on the
user's machine, so only the page the studio served may call it.
"""

from __future__ import annotations

import contextlib
import ipaddress
import tempfile
from collections.abc import Callable
from pathlib import Path

from starlette.applications import Starlette
from starlette.concurrency import run_in_threadpool
from starlette.requests import Request
from starlette.responses import FileResponse, JSONResponse, Response
from starlette.routing import Mount, Route
from starlette.staticfiles import StaticFiles
from starlette.types import ASGIApp, Receive, Scope, Send

from story.registry import SPOKEN, entry, heuristics, spoken, triangulations
from trex.inputs import first_line
from trex.studio import api, job_routes
from trex.studio.jobs import Jobs
from trex.studio.own import OwnHeuristics
from usercode.heuristic import UserHeuristic

STATIC = Path(__file__).with_name("static")


def _is_address_on(host: str, port: int) -> bool:
    """Whether a Host header is an IP address (not a name) with ``port``."""
    name, _, given = host.rpartition(":")
    try:
        ipaddress.ip_address(name.removeprefix("[").removesuffix("]"))
    except ValueError:
        return False
    return given == str(port)


class HostGuard:
    """ASGI middleware: 403 unless Host is one of ``hosts`` and Origin, if any, matches it.

    Served on every interface (``--host 0.0.0.0``), any IP address with the served port
    (``any_address_port``) is accepted too: the machine's own addresses cannot be listed
    ahead, and DNS rebinding needs a host *name*.
    """

    def __init__(self, app: ASGIApp, hosts: set[str], any_address_port: int | None = None) -> None:
        self.app, self.hosts, self.any_address_port = app, hosts, any_address_port

    def serves(self, host: str) -> bool:
        return host in self.hosts or (self.any_address_port is not None
                                      and _is_address_on(host, self.any_address_port))

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] == "http":
            headers = {k.decode("latin-1"): v.decode("latin-1") for k, v in scope["headers"]}
            host = headers.get("host", "")
            origin = headers.get("origin")
            if not self.serves(host):
                await _forbidden(f"host {host!r} is not served here")(scope, receive, send)
                return
            if origin is not None and origin != f"http://{host}":
                await _forbidden(f"origin {origin!r} is foreign")(scope, receive, send)
                return
        await self.app(scope, receive, send)


def _forbidden(message: str) -> Response:
    return JSONResponse({"error": message}, status_code=403)


def _json_route(work: Callable[[dict], object], *, threaded: bool = False) -> Callable:
    """A POST endpoint: parse the body, run ``work``, answer its result or a 4xx one-liner.
    ``threaded``: in the thread pool, for work that may wait (on one's own heuristics'
    worker), so that the loop keeps answering; short work runs in the loop, which is
    faster under load than threads contending for the interpreter."""

    async def endpoint(request: Request) -> Response:
        try:
            body = api.parse_body(await request.body())
            answer = await run_in_threadpool(work, body) if threaded else work(body)
            return JSONResponse(answer)
        except api.BadRequest as exc:
            return JSONResponse({"error": str(exc)}, status_code=exc.status)
        except Exception as exc:  # a bug of ours: still one line, never a traceback
            return JSONResponse({"error": f"internal error: {type(exc).__name__}: "
                                          f"{first_line(str(exc))}"}, status_code=500)

    return endpoint


def _rules(own: dict[str, UserHeuristic]) -> list[dict]:
    """Every rule the page asks about: the built-ins with their metaphor, then one's own."""
    built_in = [{"name": n, "metaphor": entry(n).metaphor, "title": entry(n).title,
                 "spoken": spoken(n), "picture": SPOKEN[n].picture,
                 "correct": entry(n).correct} for n in heuristics()]
    return built_in + [{"name": n, "metaphor": None, "title": h.title, "spoken": n,
                        "picture": None, "correct": None} for n, h in own.items()]


def _page_routes() -> list:
    """The page and its script and style sheet, all served from the package: no CDN."""

    async def index(_request: Request) -> Response:
        return FileResponse(STATIC / "index.html", media_type="text/html; charset=utf-8")

    return [Route("/", index), Mount("/static", StaticFiles(directory=STATIC), name="static")]


def _live_routes(own: OwnHeuristics) -> list:
    """The live answers: built-ins here, one's own by their worker process."""

    def diagonal(body: dict) -> dict:
        api.check_heuristic(body.get("heuristic"), own)
        if body["heuristic"] in own:
            return own.call("diagonal", body)
        return api.diagonal(body, {})

    def claims(body: dict) -> list[dict]:
        rows = api.claims(body, {}, names=heuristics())
        for name in own:  # one call each: one that ends its worker takes only its own row
            try:
                rows += own.call("claims", {**body, "rules": [name]})
            except api.BadRequest as exc:
                rows.append(api.failed_claim(name, str(exc)))
        return rows

    def triangulate(body: dict) -> dict:
        if body.get("heuristic") in own:
            return own.call("triangulate", body)
        return api.triangulate(body, {})

    return [
        Route("/api/check", _json_route(api.check), methods=["POST"]),
        Route("/api/diagonal", _json_route(diagonal, threaded=True), methods=["POST"]),
        Route("/api/claims", _json_route(claims, threaded=True), methods=["POST"]),
        Route("/api/triangulate", _json_route(triangulate, threaded=True), methods=["POST"]),
    ]


def _job_routes(jobs: Jobs, own: OwnHeuristics, timeout: float | None) -> list:
    """Start a hunt or a render, follow or cancel a job, fetch what it made (``/media``)."""

    async def status(request: Request) -> Response:
        job = jobs.get(request.path_params["job"])
        if job is None:
            return JSONResponse({"error": "no such job"}, status_code=404)
        if request.method == "DELETE":
            await run_in_threadpool(jobs.cancel, job.id)
        return JSONResponse(job.status())

    return [
        Route("/api/hunt", _json_route(lambda b: job_routes.hunt(b, jobs, own, timeout)),
              methods=["POST"]),
        Route("/api/render", _json_route(lambda b: job_routes.render(b, jobs, own, timeout)),
              methods=["POST"]),
        Route("/api/jobs/{job}", status, methods=["GET", "DELETE"]),
        Mount("/media", StaticFiles(directory=jobs.root), name="media"),
    ]


def create_app(*, hosts: set[str], own: dict[str, UserHeuristic] | None = None,
               work: Path | None = None, initial: dict | None = None,
               call_timeout: float | None = None, any_address_port: int | None = None) -> ASGIApp:
    """The studio app, serving ``hosts`` (``"127.0.0.1:8765"`` and the like) only.

    ``own``: the heuristics named on the command line (loaded: their titles; they are called
    only by worker processes); ``work``: the only directory the app writes to; ``initial``:
    the polygon the page opens with (``polygon`` and ``holes``); ``call_timeout``: the limit
    for one's own heuristics; ``any_address_port``: see :class:`HostGuard`. When the app
    shuts down, its jobs and worker are ended.
    """
    own = dict(own or {})
    work = work if work is not None else Path(tempfile.mkdtemp(prefix="trex-studio-"))
    jobs = Jobs(work)
    jobs.root.mkdir(parents=True, exist_ok=True)
    worker = OwnHeuristics(list(own), call_timeout)

    async def rules(_request: Request) -> Response:
        return JSONResponse(_rules(own))

    async def setup(_request: Request) -> Response:
        return JSONResponse({"samples": api.samples(), "algorithms": list(triangulations()),
                             "initial": initial, "max_vertices": api.MAX_VERTICES})

    @contextlib.asynccontextmanager
    async def lifespan(_app: Starlette):
        yield
        await run_in_threadpool(jobs.close)
        await run_in_threadpool(worker.close)

    routes = [
        *_page_routes(),
        Route("/api/rules", rules),
        Route("/api/setup", setup),
        *_live_routes(worker),
        Route("/api/load", _json_route(lambda b: api.load(b, work / "uploads")), methods=["POST"]),
        *_job_routes(jobs, worker, call_timeout),
    ]
    app = Starlette(routes=routes, lifespan=lifespan)
    app.state.jobs = jobs
    return HostGuard(app, hosts, any_address_port)
