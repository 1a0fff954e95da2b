"""Join rendered chapters into one lecture: the video, the subtitles, the chapter list.

No manim here: PyAV reads and writes the videos, ``srt`` the subtitles.

The chapters come from one manim quality, so their video streams have the same codec
parameters (codec, size, pixel format, time base, the H.264 headers in ``extradata``). Then
:func:`join_videos` *remuxes*: it copies every packet, untouched, into one mp4, its
timestamps shifted by the running duration of the chapters before it. Nothing is decoded or
encoded, so the lecture's frames are the chapters' frames bit for bit. Only when the
parameters differ (a chapter that sets its own resolution or frame rate) can one mp4 track
not hold the packets as they are; the chapters are then decoded and encoded again as
manim encodes (libx264, crf 23, the first chapter's size, pixel format and frame rate), and
the reason is returned so the caller can say why.

A chapter's duration is that of its video stream: from its first presentation time to the
end of its last frame (``max(pts + duration) - min(pts)``, in the stream's time base). The
lecture's chapter *k* starts at the sum of the durations before it; its subtitle cues are
shifted by that start.

>>> format_clock(0), format_clock(61.9), format_clock(3725)
('00:00', '01:01', '62:05')
"""

from __future__ import annotations

import contextlib
import itertools
import json
from collections.abc import Sequence
from dataclasses import dataclass
from datetime import timedelta
from fractions import Fraction
from pathlib import Path
from typing import Literal, TypedDict, cast

import av
import srt


class Encoding(TypedDict):
    codec: Literal["libx264"]  # a video codec's name (av types add_stream by it)
    options: dict[str, str]


REENCODE: Encoding = {"codec": "libx264", "options": {"crf": "23"}}  # manim's own settings


class ChapterEntry(TypedDict):
    """One chapter in chapters.json and the table of chapters."""

    number: int
    title: str
    start_seconds: float
    duration_seconds: float
    file: str


@dataclass(frozen=True)
class Video:
    """What joining needs to know about one chapter's mp4 (its first video stream)."""

    path: Path
    codec: str
    width: int
    height: int
    pix_fmt: str
    time_base: Fraction
    extradata: bytes
    rate: Fraction | None
    start: int  # first presentation time, in time_base ticks
    ticks: int  # duration in time_base ticks
    frames: int
    first_dts: int  # relative to start
    last_dts: int  # relative to start
    audio: bool  # has an audio stream (joining keeps the video only)

    @property
    def duration(self) -> Fraction:
        """Seconds, exactly."""
        return self.ticks * self.time_base

    def params(self) -> dict[str, object]:
        """The parameters one mp4 track must share to hold these packets as they are."""
        return {"codec": self.codec, "size": f"{self.width}x{self.height}",
                "pixel format": self.pix_fmt, "time base": str(self.time_base),
                "codec headers (extradata)": self.extradata}


def probe(path: Path | str) -> Video:
    """Read a video's stream parameters and timestamps (demuxes; decodes nothing)."""
    path = Path(path)
    with av.open(str(path)) as container:
        if not container.streams.video:
            raise ValueError(f"{path.name}: no video stream")
        stream = container.streams.video[0]
        ctx = stream.codec_context
        pts: list[int] = []
        ends: list[int] = []
        dts: list[int] = []
        for packet in container.demux(stream):
            if packet.dts is None:  # the flushing packet demux ends with
                continue
            if packet.pts is None:
                raise ValueError(f"{path.name}: a packet without a presentation time")
            pts.append(packet.pts)
            ends.append(packet.pts + (packet.duration or 0))
            dts.append(packet.dts)
        if not pts:
            raise ValueError(f"{path.name}: no video frames")
        start = min(pts)
        return Video(
            path=path, codec=ctx.name, width=ctx.width, height=ctx.height,
            pix_fmt=ctx.pix_fmt or "", time_base=Fraction(cast(Fraction, stream.time_base)),  # a video stream's
            extradata=bytes(ctx.extradata or b""),
            rate=Fraction(stream.guessed_rate) if stream.guessed_rate else None,
            start=start, ticks=max(ends) - start, frames=len(pts),
            first_dts=dts[0] - start, last_dts=dts[-1] - start,
            audio=bool(container.streams.audio),
        )


def remux_obstacle(videos: Sequence[Video]) -> str | None:
    """Why the videos cannot be remuxed into one track (None: they can).

    >>> a = Video(Path("a.mp4"), "h264", 854, 480, "yuv420p", Fraction(1, 15360), b"x",
    ...           Fraction(15), 0, 15360, 15, -2048, 12288, False)
    >>> remux_obstacle([a, a]) is None
    True
    >>> from dataclasses import replace
    >>> remux_obstacle([a, replace(a, path=Path("b.mp4"), width=1280, height=720)])
    'b.mp4 differs from a.mp4 in size (1280x720, not 854x480)'
    """
    if not videos:
        raise ValueError("no videos to join")
    first = videos[0]
    reference = first.params()
    for video in videos[1:]:
        for name, value in video.params().items():
            if value != reference[name]:
                shown = "" if isinstance(value, bytes) else f" ({value}, not {reference[name]})"
                return f"{video.path.name} differs from {first.path.name} in {name}{shown}"
    for before, after in itertools.pairwise(videos):
        # after's decode times, shifted to follow before, must come after before's
        if before.ticks + after.first_dts <= before.last_dts:
            return f"{after.path.name}'s decode times would overlap {before.path.name}'s"
    return None


def join_videos(videos: Sequence[Video], output: Path | str) -> str | None:
    """Write the videos one after another into ``output`` (mp4).

    Remuxes when :func:`remux_obstacle` finds nothing in the way and returns None; else
    encodes again and returns the obstacle (the reason for encoding again).
    """
    reason = remux_obstacle(videos)
    if reason is None:
        _remux(videos, Path(output))
    else:
        _reencode(videos, Path(output))
    return reason


def _remux(videos: Sequence[Video], output: Path) -> None:
    with contextlib.ExitStack() as stack:
        first = stack.enter_context(av.open(str(videos[0].path)))
        out = stack.enter_context(av.open(str(output), "w", format="mp4"))
        if "comment" in first.metadata:
            out.metadata["comment"] = first.metadata["comment"]
        stream = out.add_stream_from_template(first.streams.video[0])
        offset = 0  # ticks of the chapters already written
        for video in videos:
            with av.open(str(video.path)) as source:
                for packet in source.demux(source.streams.video[0]):
                    if packet.dts is None:
                        continue
                    # a packet with a dts has a pts too (it is not a flush packet)
                    packet.pts = cast(int, packet.pts) + (offset - video.start)
                    packet.dts += offset - video.start
                    packet.stream = stream  # mux rebases from the source time base
                    out.mux(packet)
            offset += video.ticks


def _reencode(videos: Sequence[Video], output: Path) -> None:
    first = videos[0]
    rate = first.rate or Fraction(15)
    with av.open(str(output), "w", format="mp4") as out:
        stream = out.add_stream(REENCODE["codec"], rate=rate, options=dict(REENCODE["options"]))
        stream.width, stream.height, stream.pix_fmt = first.width, first.height, first.pix_fmt
        index = 0
        for video in videos:
            with av.open(str(video.path)) as source:
                for frame in source.decode(video=0):
                    frame = frame.reformat(width=first.width, height=first.height,
                                           format=first.pix_fmt)
                    frame.pts, frame.time_base = index, Fraction(1) / rate
                    index += 1
                    out.mux(stream.encode(frame))
        out.mux(stream.encode(None))


# --- subtitles ---------------------------------------------------------------------------------


def _delta(seconds: Fraction | float) -> timedelta:
    return timedelta(microseconds=round(Fraction(seconds) * 1_000_000))


def _to_ms(time: timedelta) -> timedelta:
    """Rounded to the millisecond .srt writes (``srt`` itself would truncate)."""
    return timedelta(milliseconds=round(time / timedelta(milliseconds=1)))


def join_subtitles(texts: Sequence[str | None], starts: Sequence[Fraction | float],
                   durations: Sequence[Fraction | float]) -> str:
    """One .srt of every chapter's cues, each shifted by its chapter's start, numbered 1..N.

    A cue ending after its chapter does is cut at the chapter's end (the next chapter's
    cues then do not overlap it); a chapter without subtitles (None or "") has no cues.
    Times are rounded to the millisecond.

    >>> one = "1\\n00:00:00,000 --> 00:00:01,500\\nhello\\n\\n"
    >>> two = "1\\n00:00:00,500 --> 00:00:09,000\\nworld\\n\\n"
    >>> print(join_subtitles([one, None, two], [0, 2, 5], [2, 3, 4]), end="")
    1
    00:00:00,000 --> 00:00:01,500
    hello
    <BLANKLINE>
    2
    00:00:05,500 --> 00:00:09,000
    world
    <BLANKLINE>
    """
    cues: list[srt.Subtitle] = []
    for text, start, duration in zip(texts, starts, durations, strict=True):
        if not text:
            continue
        shift, end = _delta(start), _delta(Fraction(start) + Fraction(duration))
        for cue in srt.parse(text):
            cue_start, cue_end = _to_ms(cue.start + shift), _to_ms(min(cue.end + shift, end))
            if cue_start < end:
                cues.append(srt.Subtitle(0, cue_start, max(cue_end, cue_start), cue.content))
    cues.sort(key=lambda c: (c.start, c.end))  # stable: a chapter's own order on ties
    return srt.compose(cues, reindex=True, start_index=1)


# --- the chapter list ---------------------------------------------------------------------------


def format_clock(seconds: float | Fraction) -> str:
    """``mm:ss`` (minutes past 59 keep counting), seconds rounded down."""
    whole = int(seconds)
    return f"{whole // 60:02d}:{whole % 60:02d}"


def chapter_entries(chapters: Sequence, videos: Sequence[Video],
                    files: Sequence[str]) -> list[ChapterEntry]:
    """``[{number, title, start_seconds, duration_seconds, file}]``: starts are the sums of
    the durations before (seconds, rounded to microseconds)."""
    entries: list[ChapterEntry] = []
    start = Fraction(0)
    for chapter, video, file in zip(chapters, videos, files, strict=True):
        entries.append({"number": chapter.number, "title": chapter.title,
                        "start_seconds": round(float(start), 6),
                        "duration_seconds": round(float(video.duration), 6), "file": file})
        start += video.duration
    return entries


def chapters_json(entries: Sequence[ChapterEntry]) -> str:
    return json.dumps(list(entries), indent=2, ensure_ascii=False) + "\n"


def chapters_markdown(entries: Sequence[ChapterEntry], video: str = "lecture.mp4") -> str:
    """A table of the chapters with their starts and lengths as mm:ss.

    >>> print(chapters_markdown([{"number": 1, "title": "Overview", "start_seconds": 0,
    ...     "duration_seconds": 75.5, "file": "chapters/01-overview.mp4"}]), end="")
    # Chapters of lecture.mp4
    <BLANKLINE>
    | # | chapter | start | length | file |
    |---:|---|---:|---:|---|
    | 1 | Overview | 00:00 | 01:15 | chapters/01-overview.mp4 |
    """
    lines = [f"# Chapters of {video}", "", "| # | chapter | start | length | file |",
             "|---:|---|---:|---:|---|"]
    for e in entries:
        title = str(e["title"]).replace("|", "\\|")
        lines.append(f"| {e['number']} | {title} | {format_clock(e['start_seconds'])} | "
                     f"{format_clock(e['duration_seconds'])} | {e['file']} |")
    return "\n".join(lines) + "\n"


def starts_of(videos: Sequence[Video]) -> list[Fraction]:
    """Each video's start in the joined one (seconds, exact)."""
    starts, total = [], Fraction(0)
    for video in videos:
        starts.append(total)
        total += video.duration
    return starts
