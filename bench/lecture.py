"""Wall time of ``trex lecture`` rendered serially (-j 1) and with -j 2, and the speed-up.

Each run is the real command (``trex lecture -q l -j N -o <temp>``) in a process of its own,
timed from start to exit; both write into a temporary directory that is removed afterwards.
The chapters are the lecture's own (``scenes/chapters/``); ``--chapters`` picks
slugs or scenes instead (``--chapters scaling,polygon``). Prints numbers only; the last line is

    lecture: NNN.N s of video, serial NN.N s, -j 2 NN.N s (N.NNx)

Run from the repository root: ``python -m bench.lecture [--chapters …] [-q l]``.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import subprocess
import sys
import tempfile
import time
from pathlib import Path


def frame_sums(path: Path) -> list[str]:
    """SHA-1 of every decoded frame (x264 may vary its bits between runs, not the frames)."""
    import av

    with av.open(str(path)) as container:
        return [hashlib.sha1(f.to_ndarray(format="rgb24").tobytes()).hexdigest()
                for f in container.decode(video=0)]


def run_timed(command: list[str], what: str) -> tuple[float, str]:
    """Run a command: its wall time in seconds and its output; a failure ends the bench with
    one line naming ``what`` failed."""
    began = time.perf_counter()
    result = subprocess.run(command, capture_output=True, text=True)
    seconds = time.perf_counter() - began
    if result.returncode != 0:
        sys.exit(f"{what} failed ({result.returncode}): "
                 f"{result.stderr.strip().splitlines()[-1:]}")
    return seconds, result.stdout


def timed_lecture(trex: Path, out: Path, jobs: int, quality: str,
                  chapters: str | None) -> float:
    command = [str(trex), "lecture", "-q", quality, "-j", str(jobs), "-o", str(out)]
    if chapters:
        command += ["--chapters", chapters]
    seconds, stdout = run_timed(command, f"trex lecture -j {jobs}")
    for line in stdout.splitlines():
        if line.startswith("chapter "):
            print(f"  -j {jobs}  {line}")
    return seconds


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--chapters", help="slugs or scenes, comma-separated")
    parser.add_argument("-q", "--quality", default="l", choices=list("lmhk"))
    args = parser.parse_args(argv)
    chapters = args.chapters
    trex = Path(sys.executable).with_name("trex")
    with tempfile.TemporaryDirectory(prefix="bench-lecture-") as temp:
        serial_dir, parallel_dir = Path(temp) / "serial", Path(temp) / "parallel"
        serial = timed_lecture(trex, serial_dir, 1, args.quality, chapters)
        parallel = timed_lecture(trex, parallel_dir, 2, args.quality, chapters)
        entries = json.loads((serial_dir / "chapters.json").read_text(encoding="utf-8"))
        same = ((serial_dir / "lecture.mp4").read_bytes()
                == (parallel_dir / "lecture.mp4").read_bytes())
        same_frames = (frame_sums(serial_dir / "lecture.mp4")
                       == frame_sums(parallel_dir / "lecture.mp4"))
    for e in entries:
        print(f"  {e['number']:2d} {e['title']}: start {e['start_seconds']:.1f} s, "
              f"{e['duration_seconds']:.1f} s")
    video = sum(e["duration_seconds"] for e in entries)
    print(f"chapters: {len(entries)}; -j 1 and -j 2 mp4: byte-identical {same}, "
          f"decoded frames identical {same_frames}")
    print(f"lecture: {video:.1f} s of video, serial {serial:.1f} s, -j 2 {parallel:.1f} s "
          f"({serial / parallel:.2f}x)")


if __name__ == "__main__":
    main()
