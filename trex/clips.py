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
last runs to ``end`` (None: the end of the video). Its clip also ends on frame
``frame_{k+1}``, the first of the next play, a key frame copied once more: manim writes a
play's frames before its animations reach their end, so that frame is the first to show the
step finished, and a clip stops on it (see :func:`cut_clips`).
"""

from __future__ import annotations

import contextlib
import json
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import cast

import av
from PIL import Image

from story.step_marks import StepMark
from tracing import JSON

SCHEMA = "trex-steps/1"
SUFFIX = ".steps.json"


@dataclass(frozen=True)
class Marks:
    """The steps of one video (``end``: the frame after the last step; None: the video's
    end) and what made it (``made_by``: the render's settings, to tell a reusable render)."""

    steps: tuple[StepMark, ...]
    end: int | None = None
    made_by: Mapping[str, JSON] | None = None

    def to_json(self) -> str:
        """The marks as ``NAME.steps.json`` holds them.

        >>> marks = Marks((StepMark(0, "The polygon", None, "polygon"), StepMark(23, "B")), 40)
        >>> Marks.from_json(marks.to_json()) == marks
        True
        """
        return json.dumps({"schema": SCHEMA, "made_by": self.made_by, "end": self.end,
                           "steps": [s.to_dict() for s in self.steps]},
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
        steps = tuple(StepMark(int(s["frame"]), str(s["caption"]), s.get("call"),
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


def step_ranges(marks: Marks, frames: int) -> list[tuple[int, int]]:
    """``[start, stop)`` frames of each step of a video of ``frames`` frames. ValueError for
    marks that do not fit it (out of order, empty, past the end).

    >>> step_ranges(Marks((StepMark(2, "a"), StepMark(23, "b"))), 40)
    [(0, 23), (23, 40)]
    >>> step_ranges(Marks((StepMark(0, "a"), StepMark(0, "b"))), 40)
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


def _spans(packets: Sequence, frame_of: dict[int, int], ranges: list[tuple[int, int]],
           name: str) -> list[tuple[int, int]]:
    """``[first, last)`` indices into ``packets`` (decode order) of each step's packets.
    ValueError if a step does not start on a key frame or its packets are not together."""
    step_of = [0] * len(frame_of)
    for k, (start, stop) in enumerate(ranges):
        step_of[start:stop] = [k] * (stop - start)
    spans = [[0, 0] for _ in ranges]
    last, ended = -1, False
    for i, packet in enumerate(packets):
        frame = frame_of[packet.pts]
        if frame >= ranges[-1][1]:
            ended = True  # after the last step (a closing fade): left out
            continue
        k = step_of[frame]
        if ended or (k != last and (k != last + 1 or not packet.is_keyframe)):
            raise ValueError(f"step {k + 1} of {name} does not start on a key frame "
                             f"(frame {ranges[k][0]}): its packets cannot be copied")
        if k != last:
            spans[k][0] = i
        spans[k][1], last = i + 1, k
    return [(first, stop) for first, stop in spans]


def cut_clips(video: Path, marks: Marks, folder: Path, names: Sequence[str]) -> list[Path]:
    """Copy each step's packets of ``video`` into ``folder/<name>`` (one name per step).

    A clip ends on the first frame of what follows it (when that is a key frame, as the
    start of a play always is): manim writes a play's frames before its animations reach
    their end, and that next frame is the first to show the step finished (a title wholly
    written, a line wholly faded in). So a clip stops on its step's finished picture, and
    the next clip starts from the very same picture.

    Raises ValueError when the marks do not fit the video or a step does not start on a key
    frame (its clip could not be copied).
    """
    with av.open(str(video)) as source:
        stream = source.streams.video[0]
        packets = [p for p in source.demux(stream) if p.dts is not None]
        # a packet with a dts has a pts too (it is not a flush packet)
        frame_of = {pts: k for k, pts in enumerate(sorted(cast(int, p.pts) for p in packets))}
        ranges = step_ranges(marks, len(frame_of))
        if len(names) != len(ranges):
            raise ValueError(f"{len(names)} names for {len(ranges)} steps")
        spans = _spans(packets, frame_of, ranges, video.name)
        paths = []
        for (first, stop), name in zip(spans, names, strict=True):
            closing = packets[stop] if stop < len(packets) else None
            closing = _copy(closing) if closing is not None and closing.is_keyframe else None
            zero = min(cast(int, p.pts) for p in packets[first:stop])
            paths.append(_write_clip(packets[first:stop], closing, zero, stream,
                                     folder / name, source))
    return paths


def _copy(packet):
    """A packet of its own with the same data and times (a packet is muxed only once)."""
    copy = av.Packet(bytes(packet))
    copy.pts, copy.dts, copy.duration = packet.pts, packet.dts, packet.duration
    copy.time_base, copy.is_keyframe = packet.time_base, True
    return copy


def _write_clip(packets: Sequence, closing, zero: int, stream, path: Path, source) -> Path:
    """``packets`` (and the ``closing`` one, if any) into ``path``, presentation times from
    ``zero`` on starting at 0."""
    with av.open(str(path), "w", format="mp4") as out:
        if "comment" in source.metadata:
            out.metadata["comment"] = source.metadata["comment"]
        clip = out.add_stream_from_template(stream)
        for packet in [*packets, *([closing] if closing is not None else [])]:
            packet.pts -= zero
            packet.dts -= zero
            packet.stream = clip
            out.mux(packet)
    return path


def last_frame(clip: Path) -> tuple[Image.Image, float]:
    """The last frame of a clip, decoded (a PIL image), and its time in seconds."""
    final = None
    with av.open(str(clip)) as container:
        for frame in container.decode(video=0):
            final = frame
    if final is None or final.time is None:
        raise ValueError(f"{clip.name}: no frames with times")
    return final.to_image(), round(float(final.time), 6)


def frame_count(video: Path) -> int:
    """The number of frames of a video (demuxed, not decoded)."""
    with contextlib.closing(av.open(str(video))) as container:
        return sum(1 for p in container.demux(container.streams.video[0]) if p.dts is not None)
