"""How long a caption must stay on screen to be read, and the short captions of repeated steps.

A class reads a caption while it watches the animation: a caption is on screen at least
:data:`LEAST_CUE` seconds and needs at most :data:`READING_SPEED` characters per second (the
BBC's and Netflix's limit for children's programmes). :func:`reading_time` is that rule;
the scenes hold each caption until it has been read (:mod:`metaphors.captions`).

Steps that repeat what the viewer has seen get one caption for many beats instead of a
caption each (:func:`summarised`, :func:`frame_summarised`): the beats stay, quick, and the
caption does not flash.

>>> reading_time("Claim: BD is an inner diagonal")  # 30 characters
1.7647058823529411
>>> reading_time("T = ABC")  # short: at least LEAST_CUE
0.83
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import replace
from types import MappingProxyType
from typing import Any, cast

from story.beats import Beat, Candidates, Pick, ShowPolygon, ShowTriangle, Verdict

#: characters per second a viewer reads at, at most
READING_SPEED = 17
#: seconds a caption stays on screen, at least
LEAST_CUE = 0.83
#: repeated claims one summary caption covers, at most (the viewer still sees progress)
SUMMARY_CLAIMS = 5
#: the beats every heuristic's run begins with: the frame (polygon, B, T, candidates)
FRAME_BEATS = (ShowPolygon, Pick, ShowTriangle, Candidates)

#: what a run says of one repeated claim, its own caption instead of a summary's, from the
#: claim's number and its beats (:func:`summarised` ``told``)
Told = Callable[[int, Sequence[Beat]], str]


def reading_time(caption: str) -> float:
    """Seconds ``caption`` must stay on screen: :data:`LEAST_CUE`, or longer at
    :data:`READING_SPEED` characters per second."""
    return max(LEAST_CUE, len(caption) / READING_SPEED)


def readable(caption: str, seconds: float) -> bool:
    """Whether ``caption`` shown for ``seconds`` keeps the reading rule.

    >>> readable("B is the left-most vertex", 1.0), readable("B is the left-most vertex", 2.0)
    (False, True)
    """
    return seconds >= LEAST_CUE and len(caption) <= READING_SPEED * seconds


def summarised(beats: Sequence[Beat], claims: Sequence[int], full: int, noun: str,
               kept: Sequence[bool] = (), numbers: Sequence[int] = (),
               names: Mapping[int, str] = MappingProxyType({}),
               order: Sequence[str] = (), total: int | None = None,
               told: Told | None = None) -> list[Beat]:
    """The beats with the captions of repeated claims replaced by summaries.

    ``claims[k]`` is how many claims were counted when beat ``k`` was made (beat ``k``
    belongs to claim ``claims[k] + 1``): beats made after ``full`` claims repeat what was
    shown, so each group of up to :data:`SUMMARY_CLAIMS` claims shares one caption
    (``"Diagonals 3–7: the same steps, faster"``). Kept as they are: the beats of the last
    count (the run's end), a failing verdict with all after it (the crossed edge is named on
    screen), and the key steps (``kept[k]`` true: a split or merge vertex and its diagonal,
    each its own step). ``numbers[k]``: how many claims of ``noun`` were counted when beat
    ``k`` was made, the numbers the summary says (default ``claims``: a run whose claims
    are all ``noun``s; prune and search counts its diagonals too, not as slices).
    ``names[c]``: the label on screen of claim ``c`` (a vertex's letter): a summary whose
    claims all have one names them by it (:func:`_named_summary`, ``order`` the labels'
    order a range means), for the picture never shows their numbers. ``total``: the claims
    of the whole run (default ``claims[-1]``), the count at which the run's end is kept (a
    beat closing the last claim, counted with it, is not the end). ``told``: each repeated
    claim gets a caption of its own, ``told(number, its beats)``, saying what its beats
    show, not one summary over up to five (divide and conquer's: one summary stood over
    five runs, each a part lit, gravity's ball, a claim, its ✓ and a split).

    A summary covers one unbroken run of fast beats (:func:`_fast_runs`): a key step ends
    it, and the fast beats after it get a summary of their own that names only the claims
    they belong to — never the one from before the key step again. A run of one beat keeps
    its own caption (a summary of one step says less than the step).

    >>> from story.beats import Note
    >>> beats = [Note(caption=f"step {k}", seq=k) for k in range(6)]
    >>> [b.caption for b in summarised(beats, [0, 1, 1, 2, 2, 3], 1, "diagonal")]
    ['step 0', 'Diagonals 2–3: the same steps, faster', 'Diagonals 2–3: the same steps, faster', 'Diagonals 2–3: the same steps, faster', 'Diagonals 2–3: the same steps, faster', 'step 5']
    >>> beats = [Note(caption=f"step {k}", seq=k) for k in range(8)]
    >>> [b.caption for b in summarised(beats, [0, 1, 1, 2, 3, 3, 4, 5], 1, "vertex",
    ...                                [False, False, False, True, False, False, False, False])]
    ['step 0', 'Vertex 2: the same steps, faster', 'Vertex 2: the same steps, faster', 'step 3', 'Vertices 4–5: the same steps, faster', 'Vertices 4–5: the same steps, faster', 'Vertices 4–5: the same steps, faster', 'step 7']
    >>> [b.caption for b in summarised(beats[:6], [0, 1, 2, 3, 4, 5], 1, "vertex",
    ...                                names={2: "H", 3: "B", 4: "G", 5: "F"})][1]
    'Vertices H, B, G and F: the same steps, faster'
    >>> [b.caption for b in summarised(beats[:6], [0, 1, 1, 2, 2, 3], 1, "diagonal",
    ...                                told=lambda n, run: f"{n}: {len(run)} beats")]
    ['step 0', '2: 2 beats', '2: 2 beats', '3: 2 beats', '3: 2 beats', 'step 5']
    """
    if not beats:
        return []
    out = list(beats)
    said = list(numbers) or list(claims)
    for run in _fast_runs(beats, claims, full, kept, total, 1 if told else SUMMARY_CLAIMS):
        if len(run) < 2:
            continue  # one beat: its own caption says more than a summary of it
        first, last = said[run[0]] + 1, said[run[-1]] + 1
        labels = [names.get(c) for c in range(first, last + 1)]
        if told is not None:
            caption = told(first, [beats[k] for k in run])
        elif names and None not in labels:
            caption = _named_summary(noun, cast(list[str], labels), order)
        else:
            caption = _summary(noun, first, last)
        for k in run:
            out[k] = replace(beats[k], caption=caption)
    return out


def _fast_runs(beats: Sequence[Beat], claims: Sequence[int], full: int,
               kept: Sequence[bool], total: int | None = None,
               size: int = SUMMARY_CLAIMS) -> list[list[int]]:
    """The indices of the beats that go under summaries, in unbroken runs: consecutive fast
    beats of at most ``size`` claims, counted from the run's first. A beat kept as it is (a
    key step, the run's end, a failing verdict and after) ends a run."""
    last = claims[-1] if total is None else total
    keep = list(kept) or [False] * len(beats)
    runs: list[list[int]] = []
    failed, open_run = False, False
    for k, (beat, counted, key) in enumerate(zip(beats, claims, keep, strict=True)):
        failed = failed or (isinstance(beat, Verdict) and not beat.ok)
        if failed or key or counted < full or counted >= last:
            open_run = False
            continue
        if not open_run or counted - claims[runs[-1][0]] >= size:
            runs.append([])
        runs[-1].append(k)
        open_run = True
    return runs


#: the plural of a noun whose plural is not its name and an s
_PLURALS = {"vertex": "vertices"}


def _summary(noun: str, first: int, last: int) -> str:
    if first == last:
        return f"{noun.capitalize()} {first}: the same steps, faster"
    return f"{_PLURALS.get(noun, noun + 's').capitalize()} {first}–{last}: the same steps, faster"


def _named_summary(noun: str, labels: list[str], order: Sequence[str]) -> str:
    """The summary of claims named by their labels on screen, in the order they came: a
    range when they follow one another in ``order`` (the polygon's labels), else a list.

    >>> _named_summary("vertex", ["H", "I", "J"], "ABCDEFGHIJ")
    'Vertices H–J: the same steps, faster'
    >>> _named_summary("vertex", ["E", "C"], "ABCDE")
    'Vertices E and C: the same steps, faster'
    """
    if len(labels) == 1:
        return f"{noun.capitalize()} {labels[0]}: the same steps, faster"
    plural = _PLURALS.get(noun, noun + "s").capitalize()
    at = [list(order).index(x) if x in order else -1 for x in labels]
    if len(labels) > 2 and -1 not in at and at == list(range(at[0], at[0] + len(at))):
        return f"{plural} {labels[0]}–{labels[-1]}: the same steps, faster"
    listed = f"{', '.join(labels[:-1])} and {labels[-1]}"
    return f"{plural} {listed}: the same steps, faster"


def frame_key(beats: Sequence[Beat]) -> tuple[tuple[Any, ...], tuple[Any, ...], tuple[str, ...]] | None:
    """What the first frame of a run shows: the polygon (its points and labels), T and the
    candidates; None if the run shows no frame. Two runs with the same key show the viewer
    the same frame.

    >>> frame_key([Candidates(caption="c", seq=1, candidates=("D", "E"))])
    ((), (), ('D', 'E'))
    """
    polygon: tuple[Any, ...] = ()
    triangle: tuple[Any, ...] = ()
    for beat in beats:
        if isinstance(beat, ShowPolygon) and not polygon:
            polygon = (tuple(map(tuple, beat.points)), tuple(beat.labels))
        elif isinstance(beat, ShowTriangle) and not triangle:
            triangle = (tuple(map(tuple, beat.points)), tuple(beat.labels))
        elif isinstance(beat, Candidates):
            return polygon, triangle, tuple(beat.candidates)
    return None


def frame_summarised(beats: Sequence[Beat]) -> list[Beat]:
    """The beats of a run whose first frame the viewer saw in a run before (the same
    :func:`frame_key`): that frame's beats (polygon, B, T, up to its candidates) share one
    short caption; later frames keep theirs.

    >>> from story.beats import Note
    >>> beats = [Pick(caption="B is the left-most vertex", seq=1, vertex="B"),
    ...          Candidates(caption="Candidates inside T: D, E", seq=2, candidates=("D", "E")),
    ...          Note(caption="on", seq=3),
    ...          Candidates(caption="Candidates inside T: F", seq=4, candidates=("F",))]
    >>> [b.caption for b in frame_summarised(beats)]
    ['The frame as before: candidates D, E', 'The frame as before: candidates D, E', 'on', 'Candidates inside T: F']
    """
    end = next((k for k, b in enumerate(beats) if isinstance(b, Candidates)), None)
    if end is None:
        return list(beats)
    found = cast(Candidates, beats[end]).candidates  # the first Candidates beat, found above
    summary = ("The frame as before: candidates " + ", ".join(found) if found
               else "The frame as before: no vertex inside T")
    return [replace(b, caption=summary) if k <= end and isinstance(b, FRAME_BEATS) else b
            for k, b in enumerate(beats)]
