"""A signalled command that cannot end (a thread of manim's left waiting, a swallowed
interrupt) is stopped by the watchdog of :mod:`trex.signals`: its temporary files removed, its
one line said, exit 128 + the signal. Run in a child process, as a real command is."""

from __future__ import annotations

import signal
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

#: a command stuck after its signal: it swallows the interrupt and waits for ever
STUCK = textwrap.dedent("""\
    import sys, time
    from pathlib import Path
    import trex.signals as signals
    signals.STUCK_SECONDS = 1.0
    temp = Path(sys.argv[1])
    temp.mkdir()
    with signals.interrupts_raise("error: x: render interrupted; nothing written") as seen:
        with seen.stuck_cleanup(lambda: __import__("shutil").rmtree(temp)):
            told = False
            while True:
                try:
                    if not told:  # inside the try: a signal at once is swallowed too
                        told = True
                        print("ready", flush=True)
                    time.sleep(60)
                except KeyboardInterrupt:
                    pass  # swallowed, as code one does not own may do
    """)



@pytest.mark.parametrize("sig", [signal.SIGINT, signal.SIGTERM])
def test_a_stuck_interrupted_command_is_stopped_with_nothing_left(tmp_path, sig):
    temp = tmp_path / "render.tmp"
    root = Path(__file__).resolve().parents[1]
    proc = subprocess.Popen([sys.executable, "-c", STUCK, str(temp)], cwd=root,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    try:
        assert proc.stdout is not None and proc.stdout.readline() == "ready\n"
        assert temp.is_dir()
        proc.send_signal(sig)
        _, stderr = proc.communicate(timeout=60)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    assert proc.returncode == 128 + sig
    assert stderr == "error: x: render interrupted; nothing written\n"
    assert not temp.exists()


def test_a_command_that_ends_in_time_is_not_stopped(tmp_path):
    """The watchdog is a daemon: a command that ends before it fires exits as it means to."""
    script = textwrap.dedent("""\
        import sys
        import trex.signals as signals
        signals.STUCK_SECONDS = 30.0
        with signals.interrupts_raise("never said") as seen:
            with seen.stuck_cleanup(lambda: None):
                try:
                    signals.signal.raise_signal(signals.signal.SIGTERM)
                except signals.Interrupted:
                    sys.exit(5)
    """)
    done = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True,
                          cwd=Path(__file__).resolve().parents[1], timeout=60)
    assert (done.returncode, done.stderr) == (5, "")  # not the watchdog's 143


def test_the_watchdog_leaves_a_command_that_got_out_alone(monkeypatch):
    """Once :func:`interrupts_raise` has ended, the watchdog does nothing: here, in pytest's
    own process, it would otherwise end the test run (it did, once: both xdist workers)."""
    import threading

    import trex.signals as signals

    monkeypatch.setattr(signals, "STUCK_SECONDS", 0.05)
    cleaned = []
    with (signals.interrupts_raise("never said") as seen,
          seen.stuck_cleanup(lambda: cleaned.append(True)),
          pytest.raises(signals.Interrupted)):
        signal.raise_signal(signal.SIGTERM)
    assert seen.watchdog is not None
    seen.watchdog.join(5)  # cancelled: it ends at once, without running
    # and were it to run late, it would find the command over
    signals._stop_if_stuck(seen, signal.SIGTERM)
    assert cleaned == [] and threading.main_thread().is_alive()
