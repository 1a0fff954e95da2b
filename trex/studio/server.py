"""Serving the studio: the listening socket, uvicorn, and a clean stop on Ctrl-C or SIGTERM.

The socket is bound here, before uvicorn starts, so that a port in use is one line
(:class:`PortInUse`) rather than uvicorn's log and ``sys.exit(1)``. Uvicorn's own signal
handling is replaced by ours: the first SIGINT or SIGTERM asks the server to finish
(answers in flight complete, then the app's shutdown ends the running jobs), and the
signal is remembered so that the command exits as an interrupted one (130 for Ctrl-C)
instead of re-raising it inside the clean-up.
"""

from __future__ import annotations

import contextlib
import errno
import signal
import socket
from collections.abc import Callable, Iterator

import uvicorn


class PortInUse(Exception):
    """The address cannot be bound; the message is one line."""


def bind(host: str, port: int) -> socket.socket:
    """A listening TCP socket on ``host:port`` (port 0: any free one)."""
    try:
        infos = socket.getaddrinfo(host, port, type=socket.SOCK_STREAM)
    except socket.gaierror as exc:
        raise PortInUse(f"cannot resolve host {host!r}: {exc.strerror}") from None
    family, _, _, _, address = infos[0]
    sock = socket.socket(family, socket.SOCK_STREAM)
    sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    try:
        sock.bind(address)
        sock.listen(128)
    except OSError as exc:
        sock.close()
        if exc.errno == errno.EADDRINUSE:
            raise PortInUse(f"port {port} on {host} is in use (try --port)") from None
        raise PortInUse(f"cannot listen on {host}:{port}: {exc.strerror or exc}") from None
    return sock


def url_of(sock: socket.socket, host: str) -> str:
    """The page's address: the host as given, the port as bound."""
    port = sock.getsockname()[1]
    shown = f"[{host}]" if ":" in host else host
    return f"http://{shown}:{port}/"


class Server(uvicorn.Server):
    """Uvicorn with our signal handling, telling ``on_listening`` once it serves."""

    def __init__(self, config: uvicorn.Config, on_listening: Callable[[], None]) -> None:
        super().__init__(config)
        self.on_listening = on_listening
        self.stopped_by: int | None = None

    async def startup(self, sockets: list[socket.socket] | None = None) -> None:
        await super().startup(sockets=sockets)
        if self.started:
            self.on_listening()

    @contextlib.contextmanager
    def capture_signals(self) -> Iterator[None]:
        """The first SIGINT/SIGTERM stops serving; a second one forces the exit. Unlike
        uvicorn's, the signal is not raised again afterwards: the command exits with it."""
        previous = {s: signal.signal(s, self._stop) for s in (signal.SIGINT, signal.SIGTERM)}
        try:
            yield
        finally:
            for s, handler in previous.items():
                signal.signal(s, handler)

    def _stop(self, signum: int, _frame: object) -> None:
        if self.stopped_by is not None:
            self.force_exit = True
        self.stopped_by = signum
        self.should_exit = True


def serve(app, sock: socket.socket, on_listening: Callable[[], None]) -> int | None:
    """Serve ``app`` on ``sock`` until a signal; the signal's number, or None."""
    config = uvicorn.Config(app, log_level="warning", access_log=False, lifespan="on")
    server = Server(config, on_listening)
    server.run(sockets=[sock])
    return server.stopped_by
