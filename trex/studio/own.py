"""One's own heuristics, answered live by a worker process of their own.

The studio never calls a user's function in the server: a ``while True`` would freeze it,
an ``os._exit`` or a crash in C would end it. A worker, ``trex studio-own`` (in
:mod:`trex.studio.children`), loads the ``--heuristic`` files once and answers one JSON line
per request (``{"route", "body"}`` → ``{"ok": answer}`` or ``{"error", "status"}``), with
``--call-timeout`` applied there as on the command line. If it does not answer in time, or
dies, it is killed and the request fails in one line; the next request starts a new one.
"""

from __future__ import annotations

import contextlib
import json
import subprocess
import sys
import threading
from pathlib import Path
from typing import IO, Any, cast

from trex.studio.api import BadRequest

GRACE_SECONDS = 10.0
"""Beyond the call timeout: loading the files and starting Python, on a loaded machine."""


class OwnHeuristics:
    """The worker for the heuristics ``specs`` (``FILE.py:FUNCTION``), started on first use."""

    def __init__(self, specs: list[str], timeout: float | None,
                 python: str = sys.executable) -> None:
        self.specs, self.timeout, self.python = list(specs), timeout, python
        self.process: subprocess.Popen | None = None
        self.lock = threading.Lock()

    def __contains__(self, name: object) -> bool:
        return name in self.specs

    def __iter__(self):
        return iter(self.specs)

    def _worker(self) -> subprocess.Popen:
        if self.process is None or self.process.poll() is not None:
            argv = [self.python, "-m", "trex", "studio-own", "--call-timeout",
                    f"{self.timeout or 0:g}", *self.specs]
            self.process = subprocess.Popen(
                argv, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                text=True, encoding="utf-8", cwd=Path(__file__).resolve().parents[2],
                start_new_session=True)  # a Ctrl-C reaches the server, which ends it
        return self.process

    def call(self, route: str, body: dict) -> Any:
        """The worker's answer to ``route`` (diagonal, claims, triangulate) on ``body``;
        BadRequest if it refused, or failed to answer."""
        with self.lock:  # one worker, one request at a time
            worker = self._worker()
            stdin, stdout = cast(IO[str], worker.stdin), cast(IO[str], worker.stdout)  # PIPEs
            answer: list[str] = []
            reader = threading.Thread(target=lambda: answer.append(stdout.readline()),
                                      daemon=True)
            try:
                stdin.write(json.dumps({"route": route, "body": body}) + "\n")
                stdin.flush()
            except OSError:
                answer.append("")
            else:
                reader.start()
                reader.join((self.timeout or 60) + GRACE_SECONDS)
            line = answer[0] if answer else None
            if not line:
                self._end()
                how = "did not answer in time" if line is None else "ended"
                raise BadRequest(f"your heuristics' process {how}; it is restarted", 422)
        reply = json.loads(line)
        if "error" in reply:
            raise BadRequest(reply["error"], reply.get("status", 422))
        return reply["ok"]

    def _end(self) -> None:
        if self.process is not None:
            with contextlib.suppress(OSError):
                self.process.kill()
            self.process.wait()
            self.process = None

    def close(self) -> None:
        with self.lock:
            self._end()
