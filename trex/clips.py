"""A scene's video cut into one clip per step, at the step marks its render noted.

No manim here: PyAV reads and writes the videos.

The marks (:mod:`metaphors.steps`) are frame indices of the scene's video, noted while it
rendered, and kept beside the video as ``NAME.steps.json`` (:func:`write_marks`). manim
encodes each ``play`` and ``wait`` as a movie file of its own and joins them packet by
packet, and a mark always falls between two plays, so every step starts on a key frame.
:func:`cut_clips` therefore *copies* the packets of each step into a clip of its own, its
timestamps shifted to start at zero: nothing is decoded or encoded, and a clip's frames are
the video's frames. A step that would not start on a key frame (a video encoded again after
manim) is refused, not re-encoded: its clip would not be the same frames.

Step *k* is the frames ``[frame_k, frame_{k+1})``; the first starts at the video's start, the
last runs to ``end`` (None: the end of the video).
"""

from __future__ import annotations

import contextlib
import json
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import av

SCHEMA = "trex-steps/1"
SUFFIX = ".steps.json"


@dataclass(frozen=True)
class Step:
    """One step of a video: the frame it starts at, its caption, call line and kind."""

    frame: int
    caption: str
    call: str | None = None
    kind: str = "beat"


@dataclass(frozen=True)
class Marks:
    """The steps of one video (``end``: the frame after the last step; None: the video's
    end) and what made it (``made_by``: the render's settings, to tell a reusable render)."""

    steps: tuple[Step, ...]
    end: int | None = None
    made_by: dict | None = None

    def to_json(self) -> str:
        """The marks as ``NAME.steps.json`` holds them.

        >>> marks = Marks((Step(0, "The polygon", None, "polygon"), Step(23, "B")), 40)
        >>> Marks.from_json(marks.to_json()) == marks
        True
        """
        return json.dumps({"schema": SCHEMA, "made_by": self.made_by, "end": self.end,
                           "steps": [{"frame": s.frame, "caption": s.caption, "call": s.call,
                                      "kind": s.kind} for s in self.steps]},
                          indent=1, ensure_ascii=False, sort_keys=True) + "\n"

    @classmethod
    def from_json(cls, text: str) -> Marks:
        """Read marks; ValueError (one line) when they are not marks of steps.

        >>> Marks.from_json('{"schema": "x"}')
        Traceback (most recent call last):
        ...
        ValueError: not step marks (schema 'x')
        """
        data = json.loads(text)
        if not isinstance(data, dict) or data.get("schema") != SCHEMA:
            schema = data.get("schema") if isinstance(data, dict) else None
            raise ValueError(f"not step marks (schema {schema!r})")
        steps = tuple(Step(int(s["frame"]), str(s["caption"]), s.get("call"),
                           str(s.get("kind", "beat"))) for s in data["steps"])
        end = data.get("end")
        return cls(steps, None if end is None else int(end), data.get("made_by"))


def marks_path(video: Path) -> Path:
    """``NAME.steps.json`` beside ``NAME.mp4``.

    >>> marks_path(Path("chapters/03-gravity.mp4")).as_posix()
    'chapters/03-gravity.steps.json'
    """
    return video.with_name(video.stem + SUFFIX)


def write_marks(marks: Marks, video: Path) -> Path:
    path = marks_path(video)
    path.write_text(marks.to_json(), encoding="utf-8")
    return path


def read_marks(video: Path) -> Marks:
    """The marks beside ``video``; OSError or ValueError when missing or unreadable."""
    return Marks.from_json(marks_path(video).read_text(encoding="utf-8"))


def _packets(path: Path) -> tuple[list, dict[int, int]]:
    """The video's packets in decode order (flushing ones left out) and each presentation
    time's frame index."""
    with av.open(str(path)) as container:
        packets = [(p.pts, p.dts, p.is_keyframe) for p in container.demux(
            container.streams.video[0]) if p.dts is not None]
    frame_of = {pts: k for k, pts in enumerate(sorted(p[0] for p in packets))}
    return packets, frame_of


def step_ranges(marks: Marks, frames: int) -> list[tuple[int, int]]:
    """``[start, stop)`` frames of each step of a video of ``frames`` frames. ValueError for
    marks that do not fit it (out of order, empty, past the end).

    >>> step_ranges(Marks((Step(2, "a"), Step(23, "b"))), 40)
    [(0, 23), (23, 40)]
    >>> step_ranges(Marks((Step(0, "a"), Step(0, "b"))), 40)
    Traceback (most recent call last):
    ...
    ValueError: step 1 has no frames (it starts at frame 0, where step 2 does)
    """
    end = frames if marks.end is None else marks.end
    starts = [s.frame for s in marks.steps]
    if not starts:
        raise ValueError("no steps")
    starts[0] = 0  # what plays before the first step opens it
    if end > frames:
        raise ValueError(f"the steps end at frame {end}, after the video's {frames} frames")
    ranges = list(zip(starts, [*starts[1:], end], strict=True))
    for k, (start, stop) in enumerate(ranges, 1):
        if stop <= start:
            after = f"where step {k + 1} does" if k < len(ranges) else "the end of the steps"
            raise ValueError(f"step {k} has no frames (it starts at frame {start}, {after})")
    return ranges


def cut_clips(video: Path, marks: Marks, folder: Path, names: Sequence[str]) -> list[Path]:
    """Copy each step's packets of ``video`` into ``folder/<name>`` (one name per step).

    Raises ValueError when the marks do not fit the video or a step does not start on a key
    frame (its clip could not be copied).
    """
    packets, frame_of = _packets(video)
    ranges = step_ranges(marks, len(frame_of))
    if len(names) != len(ranges):
        raise ValueError(f"{len(names)} names for {len(ranges)} steps")
    step_of = [0] * len(frame_of)
    for k, (start, stop) in enumerate(ranges):
        step_of[start:stop] = [k] * (stop - start)
    by_step: list[list] = [[] for _ in ranges]
    last, ended = -1, False
    for pts, dts, key in packets:
        frame = frame_of[pts]
        if frame >= ranges[-1][1]:
            ended = True  # after the last step (a closing fade): left out
            continue
        k = step_of[frame]
        if ended or (k != last and (k < last or by_step[k] or not key)):
            raise ValueError(f"step {k + 1} of {video.name} does not start on a key frame "
                             f"(frame {ranges[k][0]}): its packets cannot be copied")
        by_step[k].append((pts, dts))
        last = k
    paths = []
    with av.open(str(video)) as source:
        stream = source.streams.video[0]
        demuxed = (p for p in source.demux(stream) if p.dts is not None)
        for k, name in enumerate(names):
            paths.append(_write_clip(demuxed, stream, len(by_step[k]),
                                     _first_pts(by_step[k], frame_of, ranges[k][0]),
                                     folder / name, source))
    return paths


def _first_pts(step: list, frame_of: dict[int, int], start: int) -> int:
    return next(pts for pts, _ in step if frame_of[pts] == start)


def _write_clip(demuxed, stream, count: int, zero: int, path: Path, source) -> Path:
    """The next ``count`` packets that belong to a step (skipping those after the steps end,
    which come last) into ``path``, presentation times starting at 0."""
    with av.open(str(path), "w", format="mp4") as out:
        if "comment" in source.metadata:
            out.metadata["comment"] = source.metadata["comment"]
        clip = out.add_stream_from_template(stream)
        written = 0
        while written < count:
            packet = next(demuxed)
            packet.pts -= zero
            packet.dts -= zero
            packet.stream = clip
            out.mux(packet)
            written += 1
    return path


def last_frame(clip: Path):
    """The last frame of a clip, decoded (a PIL image)."""
    final = None
    with av.open(str(clip)) as container:
        for frame in container.decode(video=0):
            final = frame
    if final is None:
        raise ValueError(f"{clip.name}: no frames")
    return final.to_image()


def frame_count(video: Path) -> int:
    """The number of frames of a video (demuxed, not decoded)."""
    with contextlib.closing(av.open(str(video))) as container:
        return sum(1 for p in container.demux(container.streams.video[0]) if p.dts is not None)
