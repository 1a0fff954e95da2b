"""Slides from rendered videos and their step marks: the clips, the page, the handout.

No manim here. Each source is one video with the marks its render noted
(:mod:`trex.clips`); a scene's slides have one source, the lecture's one per chapter. Every
step becomes ``clips/NNN.mp4`` (its packets copied from the video), a slide of
``index.html`` (:mod:`trex.slides_page`) and a picture of ``handout.pdf``
(:mod:`trex.handout`): the clip's last frame, decoded from the clip itself.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

from trex.clips import Marks, cut_clips, last_frame
from trex.handout import Handout
from trex.slides_page import CLIPS_DIR, Slide, write_slides

HANDOUT = "handout.pdf"


@dataclass(frozen=True)
class Source:
    """A rendered video, its step marks, the chapter it is (None: not a lecture) and the
    chapter's notes for its teacher (the speaker window and the handout show them)."""

    video: Path
    marks: Marks
    chapter: str | None = None
    notes: tuple[str, ...] = ()


def clip_names(count: int) -> list[str]:
    """``001.mp4`` …: as many digits as the count needs, at least three.

    >>> clip_names(2), clip_names(1000)[-1]
    (['001.mp4', '002.mp4'], '1000.mp4')
    """
    digits = max(3, len(str(count)))
    return [f"{k:0{digits}d}.mp4" for k in range(1, count + 1)]


def build_slides(folder: Path, sources: Sequence[Source], title: str, subtitle: str,
                 pixels: tuple[int, int],
                 progress: Callable[[int, int], None] | None = None) -> list[Slide]:
    """Write ``folder/clips/``, ``folder/index.html`` and ``folder/handout.pdf``; returns the
    slides. ``progress(k, n)`` after each step's clip and picture."""
    clips = folder / CLIPS_DIR
    clips.mkdir(parents=True, exist_ok=True)
    total = sum(len(s.marks.steps) for s in sources)
    names = iter(clip_names(total))
    handout = Handout(folder / HANDOUT, title, total,
                      [(s.chapter or title, s.notes) for s in sources])
    slides: list[Slide] = []
    for source in sources:
        mine = [next(names) for _ in source.marks.steps]
        call = None
        for path, step in zip(cut_clips(source.video, source.marks, clips, mine),
                              source.marks.steps, strict=True):
            call = step.call if step.call is not None else call
            picture, last = last_frame(path)
            slides.append(Slide(f"{CLIPS_DIR}/{path.name}", step.caption, call, step.kind,
                                source.chapter, last, source.notes))
            handout.add(picture, str(len(slides)), step.caption)
            if progress is not None:
                progress(len(slides), total)
    handout.close()
    write_slides(folder, slides, title, subtitle, pixels)
    return slides
