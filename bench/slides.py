"""Wall time and size on disk of ``trex slides``, beside the render it is cut from.

Each run is the real command in a process of its own, timed from start to exit, writing
into a temporary directory removed afterwards:

- ``trex render SCENE`` (the baseline: the one render) and ``trex slides SCENE``, three
  times each in turn (medians); the difference is cutting the clips, decoding their last
  frames and drawing the handout;
- with ``--lecture``: ``trex lecture -j J`` (the baseline), ``trex slides lecture -j J``
  (rendering every chapter again) and ``trex slides lecture --lecture <that lecture>``
  (reusing its chapters: no render at all).

Prints numbers only, e.g. ::

    gravity: render 9.8 s, 0.9 MB; slides 11.2 s (1.14x), 8 steps, 1.2 MB (clips 0.9, handout 0.3)

Run from the repository root: ``python -m bench.slides [--scene gravity] [--lecture]
[-j 2] [-q l]``.
"""

from __future__ import annotations

import argparse
import statistics
import sys
import tempfile
from pathlib import Path

from bench.lecture import run_timed


def timed(command: list[str]) -> float:
    return run_timed(command, " ".join(command[1:3]))[0]


def size(path: Path) -> int:
    """Bytes of a file, or of every file under a directory."""
    if path.is_file():
        return path.stat().st_size
    return sum(p.stat().st_size for p in path.rglob("*") if p.is_file())


def mb(n: int) -> str:
    return f"{n / 1e6:.1f} MB"


def described(folder: Path) -> str:
    steps = len(list((folder / "clips").glob("*.mp4")))
    return (f"{steps} steps, {mb(size(folder))} (clips {size(folder / 'clips') / 1e6:.1f}, "
            f"handout {size(folder / 'handout.pdf') / 1e6:.1f})")


def bench_scene(trex: Path, scene: str, quality: str, temp: Path, repeat: int = 3) -> None:
    """The render and the slides, ``repeat`` times each, taking turns; medians."""
    video, folder = temp / f"{scene}.mp4", temp / f"{scene}-slides"
    renders, slides = [], []
    for _ in range(repeat):
        renders.append(timed([str(trex), "render", scene, "-q", quality, "-o", str(video)]))
        slides.append(timed([str(trex), "slides", scene, "-q", quality, "-o", str(folder)]))
    render, sliced = statistics.median(renders), statistics.median(slides)
    print(f"{scene}: render {render:.1f} s, {mb(size(video))}; slides {sliced:.1f} s "
          f"({sliced / render:.2f}x), {described(folder)} (medians of {repeat})")


def bench_lecture(trex: Path, jobs: int, quality: str, temp: Path) -> None:
    lecture = temp / "lecture"
    base = timed([str(trex), "lecture", "-q", quality, "-j", str(jobs), "-o", str(lecture)])
    print(f"lecture -j {jobs}: {base:.1f} s, {mb(size(lecture))} "
          f"(chapters {mb(size(lecture / 'chapters'))})")
    fresh = temp / "slides-fresh"
    again = timed([str(trex), "slides", "lecture", "-q", quality, "-j", str(jobs), "--lecture",
                   str(temp / "none"), "-o", str(fresh)])
    print(f"slides lecture -j {jobs}, rendering: {again:.1f} s ({again / base:.2f}x), "
          f"{described(fresh)}")
    reused = temp / "slides-reused"
    cut = timed([str(trex), "slides", "lecture", "-q", quality, "--lecture", str(lecture),
                 "-o", str(reused)])
    print(f"slides lecture reusing it: {cut:.1f} s ({cut / base:.2f}x), {described(reused)}")


def main(argv: list[str] | None = None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--scene", default="gravity")
    parser.add_argument("--lecture", action="store_true", help="the lecture too (minutes)")
    parser.add_argument("-j", "--jobs", type=int, default=2)
    parser.add_argument("-q", "--quality", default="l", choices=list("lmhk"))
    args = parser.parse_args(argv)
    trex = Path(sys.executable).with_name("trex")
    with tempfile.TemporaryDirectory(prefix="bench-slides-") as temp:
        bench_scene(trex, args.scene, args.quality, Path(temp))
        if args.lecture:
            bench_lecture(trex, args.jobs, args.quality, Path(temp))


if __name__ == "__main__":
    main()
