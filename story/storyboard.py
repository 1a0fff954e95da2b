"""From a log to beats: the generic walk over a log, and the frame every run shares.

The walk keeps the state of the log (live objects, open calls, claims seen) and hands each
returned call to the *reading* of its traced name: a function ``(walk, call, ret)`` that
yields the typed beats (:mod:`story.beats`) of that step. This module reads the frame the
heuristics share (the left-most vertex, the candidates in T, the claim and its exactly
judged verdict) and the generic steps of a heuristic of one's own; each metaphor module
declares the readings of its own steps (``READS``) and :func:`storyboard` takes them.
The only thing computed here is the verdict on each claimed diagonal, by
:mod:`geometry.check`; all else comes from the log, so a saved log gives the same beats.

No manim here.

>>> import tracing
>>> from geometry.diagonals import find_diagonal
>>> from geometry.polygon import Polygon
>>> from geometry.samples import make_sample
>>> p = Polygon.from_points(make_sample("counterexample"))
>>> with tracing.record(algorithm="scaling") as log:
...     _ = find_diagonal(p, "scaling")
>>> [b.action for b in storyboard(log)]  # the frame only: the water's step needs its reading
['polygon', 'pick', 'triangle', 'candidates', 'claim', 'verdict']
>>> storyboard(log)[-1].caption
'✗ BD is not an inner diagonal: BD crosses edge E–A'
"""

from __future__ import annotations

from collections.abc import Callable, Iterable, Iterator, Mapping, Sequence
from dataclasses import dataclass, replace
from types import MappingProxyType
from typing import Any

from geometry.check import is_inner_diagonal
from geometry.polygon import Polygon
from story.beats import (
    Beat,
    Call,
    Candidates,
    Claim,
    FindDiagonal,
    Hole,
    Note,
    Pick,
    ShapeChange,
    ShowPolygon,
    ShowTriangle,
    Verdict,
    point,
    points_of,
    segment,
)
from story.pseudocode import PseudocodeRow, bound, from_json, lit_row, named
from story.reach import Reach, reach_of
from story.reading import Told, summarised
from story.refs import (
    arg_int,
    arg_ints,
    call_of,
    int_list,
    meta,
    ref,
    result_ints,
    result_list,
    result_object,
    result_ref,
    result_refs,
    result_string,
    state_of,
    string,
    target_of,
)
from story.registry import heuristics, pseudocode, spoken
from story.roles import ROLES
from story.words import number, said, why_not_inner
from tracing import Event, Log

#: A reading: the beats of one returned call (``walk``, its call event, its return event).
Reading = Callable[["Walk", Event, Event], Iterable[Beat]]

#: Traced calls that run a heuristic on a polygon besides the registry's heuristics (the
#: claim inside them is judged on that polygon): prune-and-search's sweep and gravity.
_HEURISTIC_CALLS = frozenset({"sweep_at", "gravity_at"})


@dataclass(frozen=True)
class Pacing:
    """Full detail for the first `full` claims, then `fast` × the run time."""

    full: int = 2
    fast: float = 0.35
    #: each fast claim under a caption of its own saying what it shows (:func:`told_claim`),
    #: not a summary over up to five ("Diagonals 3–7: the same steps, faster")
    told: bool = False


# --- objects of the log by their keys -----------------------------------------------------------


def is_polygon_key(key: str | None) -> bool:
    """Whether a log key is a polygon's (``P(ABCDE)``: the polygon, or a piece of it).

    >>> is_polygon_key("P(ABCDE)"), is_polygon_key("T(ABC)"), is_polygon_key(None)
    (True, False, False)
    """
    return key is not None and key.startswith("P(")


def is_frame_key(key: str | None) -> bool:
    """Whether a log key is the frame's (a polygon, or the triangle T = ``T(ABC)``)."""
    return key is not None and key.startswith(("P(", "T("))


# --- call lines ----------------------------------------------------------------------------------


def show(value: Any) -> str:
    """A value as the call line writes it: refs by key, polygons as P, lists in brackets.

    >>> show({"ref": "P(ABCDE)"}), show([{"ref": "D"}, {"ref": "E"}]), show(2.5), show(None)
    ('P', '[D, E]', '2.5', '—')
    >>> show(1.41421), show(12.0)  # no number on screen has more than one decimal
    ('1.4', '12')
    """
    if isinstance(value, dict) and "ref" in value:
        key = value["ref"]
        return "P" if is_polygon_key(key) else key
    if isinstance(value, list):
        return "[" + ", ".join(show(v) for v in value) + "]"
    if isinstance(value, float):
        return number(value)
    if value is None:
        return "—"
    if isinstance(value, dict):
        return "{…}"
    return str(value)


def call_line(call: Event, ret: Event | None) -> str:
    """A call as the panel's call line writes it: the real call, which Python could run. A
    run traced under its registry name (``ear-clipping-naive``, no identifier) is called
    as :func:`geometry.triangulate.triangulate` calls it.

    >>> from tracing.events import Event
    >>> p = {"polygon": {"ref": "P(ABCDE)"}}
    >>> call_line(Event(0, "call", "ear-clipping-naive", args=p), None)
    'triangulate(P, "ear-clipping-naive")'
    >>> call_line(Event(0, "call", "is_ear", args={"v": {"ref": "B"}}), None)
    'is_ear(B)'

    An argument None is Python's ``None`` (not the dash a result of nothing shows: the
    vertical sweep's call read ``first_hit_sweeping(B, [0, 1], [D, E], —)``):

    >>> call_line(Event(0, "call", "f", args={"b": {"ref": "B"}, "shore": None}), None)
    'f(B, None)'
    """
    args = ", ".join("None" if v is None else show(v) for v in (call.args or {}).values())
    text = (f"{call.name}({args})" if call.name.isidentifier()
            else f'triangulate({args}, "{call.name}")')
    return f"{text} → {_shown_result(ret.result)}" if ret is not None else text


def run_call(log: Log) -> str | None:
    """The run's own call (the log's first traced call) as the call line writes it, without
    its result: what the call line says at the run's end, with the result the picture shows
    (:func:`metaphors.drawing.ending_beat`). None for a log with no call.

    >>> from story.runs import run_logged
    >>> run_call(run_logged("divide-and-conquer", "counterexample", "gravity"))
    'divide_and_conquer(P, gravity)'
    """
    first = next((e for e in log.events if e.kind == "call"), None)
    return call_line(first, None) if first is not None else None


def _shown_result(value: Any) -> str:
    """A result as the call line writes it (:func:`show`); a list of more than two lists
    (a piece's triangles) by its first two and an ellipsis: the whole would take four lines
    of the panel and run over its pseudocode.

    >>> _shown_result([[0, 1, 2], [0, 2, 3], [0, 3, 4]]), _shown_result([[0, 1, 2]])
    ('[[0, 1, 2], [0, 2, 3], …]', '[[0, 1, 2]]')
    """
    if isinstance(value, list) and len(value) > 2 and any(isinstance(v, list) for v in value):
        return "[" + ", ".join(show(v) for v in value[:2]) + ", …]"
    return show(value)


def refs(value: Any) -> list[str]:
    """The keys an encoded value refers to, in order."""
    if isinstance(value, dict) and "ref" in value:
        return [value["ref"]]
    if isinstance(value, list):
        return [k for v in value for k in refs(v)]
    return []


def call_roles(call: Event, ret: Event | None) -> dict[str, str]:
    """First referenced argument (not the polygon) is called, the others arguments, result green."""
    found = [k for v in (call.args or {}).values() for k in refs(v) if not is_polygon_key(k)]
    roles = {k: "argument" for k in found[1:]}
    if found:
        roles[found[0]] = "called"
    for k in refs(ret.result) if ret is not None else []:
        roles[k] = "result"
    return roles


def pick_roles(call: Event, ret: Event) -> dict[str, str]:
    """A heuristic's step that picks one of T's candidates: its first input (B, or T) is
    called, the candidates stay candidates (neutral), and what it picks is amber, the claim to
    be, until the verdict makes it green or red: one legend for the whole chapter (chapter 2
    lit the candidates amber, the pick green and the candidates not hit amber, then the
    claim amber)."""
    found = [k for v in (call.args or {}).values() for k in refs(v) if not is_polygon_key(k)]
    roles = {k: "candidate" for k in refs((call.args or {}).get("candidates"))}
    if found and found[0] not in roles:
        roles[found[0]] = "called"
    roles.update({k: "argument" for k in refs(ret.result)})
    return roles


# --- the walk ------------------------------------------------------------------------------------


class Walk:
    """State of one pass over the log: live objects, open calls, claims seen.

    Readings use it to find what the log says around a call (:meth:`changes`,
    :meth:`entered_after`, :meth:`root_points`) and to make beats (:meth:`beat`); a reading
    that needs state of its own across calls keeps it in :meth:`memo`.
    """

    def __init__(self, log: Log, pacing: Pacing, shown_code: str | None, user: str | None,
                 rows: tuple[PseudocodeRow, ...] = (), heuristic_function: str | None = None,
                 black_box: bool = False):
        self.log, self.pacing, self.shown_code, self.user = log, pacing, shown_code, user
        self.black_box = black_box  # the heuristic's steps unseen: see :func:`storyboard`
        self.rows = rows  # the pseudocode of the run
        self.lit: int | None = None  # the pseudocode row lit so far
        self.live: dict[str, dict[str, Any]] = {}
        self.returns = {e.call: e for e in log.events if e.kind == "return"}
        self.claims = 0
        self.noun = "diagonal"  # what a claim is, in the summary captions of repeated ones
        self.counted: dict[int, int] = {}  # id of each beat made → claims counted by then
        self.of_noun: dict[str, int] = {}  # claims counted of each noun (diagonal, slice …)
        # id of each beat made → claims of each noun counted by then: a summary numbers its
        # beats by the claims it names (prune and search claims diagonals between slices)
        self.counted_of: dict[int, dict[str, int]] = {}
        # noun → claim number → the label on screen of the claim (a vertex classified): a
        # summary names such claims by their labels, not by numbers the picture never shows
        self.named: dict[str, dict[int, str]] = {}
        self.kept: set[int] = set()  # ids of the key steps: never fast, never summarised
        self.heuristic_polygon: list[str] = []
        self.shown_polygon = False
        self.stack: list[Event] = []  # open calls, outermost first
        self.drawn: set[str] = set()  # keys of the shapes the generic beats drew
        self.claimed: set[str] = set()  # keys of the claims (the frame draws them)
        self._memo: dict[str, Any] = {}
        # a heuristic of one's own that divide and conquer runs (log meta
        # ``heuristic_function``) is a heuristic too: its claims are judged on its piece
        self._heuristics = (frozenset(heuristics()) | _HEURISTIC_CALLS
                            | ({heuristic_function} if heuristic_function else set()))

    #: the log's keys a call's argument and a function's result refer to (:mod:`story.refs`)
    ref = staticmethod(ref)
    result_ref = staticmethod(result_ref)
    result_refs = staticmethod(result_refs)
    #: the log's values a reading takes for indices, a list, a string or an object (checked)
    arg_int = staticmethod(arg_int)
    arg_ints = staticmethod(arg_ints)
    int_list = staticmethod(int_list)
    result_ints = staticmethod(result_ints)
    result_list = staticmethod(result_list)
    result_string = staticmethod(result_string)
    result_object = staticmethod(result_object)

    def memo(self, name: str, make: Callable[[], Any]) -> Any:
        """A reading's own state for the whole walk (made on first use)."""
        if name not in self._memo:
            self._memo[name] = make()
        return self._memo[name]

    def entered_after(self, event: Event, key: str) -> dict[str, Any]:
        """The state with which object `key` enters the log after `event`."""
        for later in self.log.events[event.seq:]:
            if later.kind == "enter" and later.target == key:
                return state_of(later)
        return self.live.get(key, {})

    def root_polygon(self) -> tuple[list[str], list[Any]]:
        """Labels and points of the first polygon of the log."""
        for event in self.log.events:
            if event.kind == "enter" and is_polygon_key(event.target):
                return state_of(event)["labels"], state_of(event)["points"]
        return [], []

    def root_holes(self) -> list[dict[str, Any]]:
        """The holes (each ``{"points", "labels"}``) of the first polygon of the log."""
        for event in self.log.events:
            if event.kind == "enter" and is_polygon_key(event.target):
                holes: list[dict[str, Any]] = state_of(event).get("holes", [])
                return holes
        return []

    def root_points(self) -> dict[str, list[Any]]:
        """Label → point of the first polygon of the log (its holes' vertices too)."""
        labels, points = self.root_polygon()
        where = dict(zip(labels, points, strict=True))
        for hole in self.root_holes():
            where.update(zip(hole["labels"], hole["points"], strict=True))
        return where

    def reach(self, call: Event, ret: Event) -> Reach:
        """How far the heuristic's motion travels to each candidate (:mod:`story.reach`)."""
        labels, points = self.root_polygon()
        found = reach_of(call, ret, dict(zip(labels, points, strict=True)), labels,
                         lambda key: self.live.get(key) or self.entered_after(call, key))
        return found or []

    def code_line(self, event: Event) -> int | None:
        """The line lit in the shown function: the line of its direct callee, or of the event."""
        for k, call in enumerate(self.stack):
            if call.name == self.shown_code:
                inner = self.stack[k + 1] if k + 1 < len(self.stack) else event
                return inner.line
        return None

    def pseudocode_row(self, event: Event) -> int | None:
        """The pseudocode row lit at ``event``: the row covering the innermost running call a
        row covers (the event itself first, when it is a call or a note), else the row lit
        last (:func:`story.pseudocode.lit_row`)."""
        running = [c.name for c in self.stack]
        if event.kind in ("call", "note") and (not self.stack or self.stack[-1] is not event):
            running.append(event.name)
        row = lit_row(self.rows, running, self.lit)
        if row is None:
            return self.lit
        self.lit = row
        return row

    def count_claim(self, noun: str = "diagonal", label: str | None = None) -> None:
        """One more claim (a ``noun``: a diagonal, a slice) made: after ``pacing.full`` of
        them the beats go faster, under summary captions (:func:`story.reading.summarised`).
        ``label``: the claim's label on screen (a vertex's letter), which a summary then says
        instead of the claim's number."""
        self.claims += 1
        self.noun = noun
        self.of_noun[noun] = self.of_noun.get(noun, 0) + 1
        if label is not None:
            self.named.setdefault(noun, {})[self.of_noun[noun]] = label

    def pace(self) -> float:
        return 1.0 if self.claims < self.pacing.full else self.pacing.fast

    def beat(self, beat_type: type[Beat], caption: str, event: Event, /,
             key_step: bool = False, **fields: Any) -> Beat:
        """A beat of ``beat_type`` at ``event``: its lit line, lit row and pace from the walk.
        A key step (``key_step``: a split or merge vertex and its diagonal) plays at full pace under its
        own caption however many claims came before: fast-forwarding never hides it."""
        fields.setdefault("within", self.within())
        beat = beat_type(caption=caption, seq=event.seq, line=self.code_line(event),
                         row=self.pseudocode_row(event), pace=1.0 if key_step else self.pace(),
                         **fields)
        self.counted[id(beat)] = self.claims
        self.counted_of[id(beat)] = dict(self.of_noun)
        if key_step:
            self.kept.add(id(beat))
        return beat

    def within(self, key: str | None = None) -> tuple[str, ...]:
        """The labels of the piece ``key`` (default: the one the running heuristic works on),
        when it is a part of P and not all of it (divide and conquer's piece); else none."""
        key = key or (self.heuristic_polygon[-1] if self.heuristic_polygon else None)
        state = self.live.get(key) if key is not None else None
        labels = tuple(state.get("labels", ())) if state else ()
        return labels if 3 <= len(labels) < len(self.root_polygon()[0]) else ()

    def closing_claim(self, beat: Beat) -> Beat:
        """``beat`` (made after its claim's verdict: the split along the diagonal verified)
        as a beat of that claim, not of the next: its pace and its summary are the claim's.
        Counted with the next, chapter 1's split along diagonal 9 came under "Diagonal 10:
        the same steps, faster" while 9's ✓ was still on screen."""
        if self.claims == 0:
            return beat
        claims = self.claims - 1
        closed = beat if id(beat) in self.kept else replace(
            beat, pace=1.0 if claims < self.pacing.full else self.pacing.fast)
        self.counted[id(closed)] = claims
        self.counted_of[id(closed)] = {**self.of_noun, self.noun: self.of_noun[self.noun] - 1}
        return closed

    def call_beat(self, beat_type: type[Beat], caption: str, call: Event, ret: Event, /,
                  key_step: bool = False, **fields: Any) -> Beat:
        """The beat of a returned call: its call line, and the call's roles unless ``fields``
        give others (``key_step``: as :meth:`beat`)."""
        fields.setdefault("roles", call_roles(call, ret))
        return self.beat(beat_type, caption, call, key_step=key_step, call=call_line(call, ret),
                         **fields)

    def is_heuristic(self, name: str) -> bool:
        return name in self._heuristics or name == self.user

    def track(self, event: Event) -> None:
        if event.kind == "call":
            self.stack.append(event)
            self.pseudocode_row(event)  # a call no beat shows lights its row too
        elif event.kind == "return":
            self.stack.pop()
        elif event.kind in ("enter", "change"):
            self.live[target_of(event)] = state_of(event)
        elif event.kind == "exit":
            self.live.pop(target_of(event), None)


def pseudocode_of(log: Log) -> tuple[PseudocodeRow, ...]:
    """The pseudocode of a log's run: its own (meta ``pseudocode``: a heuristic of one's own
    whose docstring has some), else its algorithm's in the registry; none for any other.

    >>> import tracing
    >>> with tracing.record(algorithm="gravity") as log:
    ...     pass
    >>> pseudocode_of(log)[1].calls
    ('reflex_vertex', 'straight_vertex')
    >>> log.meta["pseudocode"] = [["claim BD", ["claim"]]]
    >>> pseudocode_of(log)
    (PseudocodeRow(text='claim BD', calls=('claim',)),)
    """
    if "pseudocode" in log.meta:
        return from_json(log.meta["pseudocode"])
    algorithm = meta(log, "algorithm")
    rows = pseudocode(algorithm) if algorithm is not None else ()
    own = meta(log, "heuristic_function")
    if own is not None:  # divide and conquer with one's own: its row covers that too
        rows = tuple(replace(r, calls=(*r.calls, own)) if set(r.calls) & set(heuristics())
                     else r for r in rows)
    return rows


#: The traced calls whose result is a vertex the pseudocode names by a placeholder: the
#: frame's B and D (thesis ch. 2.1), gravity's V, X and Y.
_PLACEHOLDERS = MappingProxyType({"leftmost_vertex": "B", "pick": "D", "reflex_vertex": "V",
                                  "straight_vertex": "V", "slide_to_vertex": "X",
                                  "band_snag": "Y"})


def run_vertices(log: Log) -> dict[str, str]:
    """Each placeholder of the pseudocode → the vertex the run gave it (``{"B": "B", "A":
    "A", "C": "C", "D": "E"}``): A, B, C from T as it enters, the others from the calls of
    :data:`_PLACEHOLDERS`, D also from a claim BD. A placeholder given two different vertices (divide and conquer
    runs the frame on every piece) is left out: no one vertex is it.

    >>> import tracing
    >>> from geometry.diagonals import find_diagonal
    >>> from geometry.polygon import Polygon
    >>> from geometry.samples import make_sample
    >>> with tracing.record(algorithm="rotation-ccw") as log:
    ...     _ = find_diagonal(Polygon.from_points(make_sample("counterexample-twin")),
    ...                       "rotation-ccw")
    >>> run_vertices(log)
    {'A': 'A', 'B': 'B', 'C': 'C', 'D': 'E'}
    """
    given: dict[str, set[str]] = {}
    claims: list[list[str]] = []
    for e in log.events:
        if e.kind == "enter" and is_frame_key(e.target) and not is_polygon_key(e.target):
            for placeholder, label in zip("ABC", state_of(e)["labels"], strict=False):
                given.setdefault(placeholder, set()).add(label)
        elif (e.kind == "return" and e.name in _PLACEHOLDERS and isinstance(e.result, dict)
              and "ref" in e.result):
            given.setdefault(_PLACEHOLDERS[e.name], set()).add(e.result["ref"])
        elif e.kind == "call" and e.name == "claim":
            claims.append([k for v in (e.args or {}).values() for k in refs(v)])
    found = {k: next(iter(v)) for k, v in given.items() if len(v) == 1}
    # a claim BD names D too (a heuristic of one's own picks D by a step of its own)
    for ends in claims:
        if len(ends) == 2 and ends[0] == found.get("B") and ends[1] not in (found.get("A"),
                                                                            found.get("C")):
            given.setdefault("D", set()).add(ends[1])
    return {k: next(iter(v)) for k, v in sorted(given.items()) if len(v) == 1}


def _labels_shown(log: Log) -> tuple[str, ...]:
    return tuple(next((state_of(e)["labels"] for e in log.events
                       if e.kind == "enter" and is_polygon_key(e.target)), ()))


def spoken_pseudocode(log: Log) -> tuple[PseudocodeRow, ...]:
    """The pseudocode the panel shows for a log once the run has picked its vertices:
    :func:`pseudocode_of`, its placeholders naming the run's own vertices where the picture
    has a vertex of that name (:func:`story.pseudocode.named`), and tied to them where it
    has none (:func:`story.pseudocode.bound`: gravity's ``V = C``)."""
    rows = _named_rows(log)
    stages = bound_stages(log, rows)
    return stages[-1][1] if stages else rows


def _named_rows(log: Log) -> tuple[PseudocodeRow, ...]:
    """The pseudocode naming the run's own vertices where the picture has one of that name."""
    return named(pseudocode_of(log), run_vertices(log), _labels_shown(log))


def _bindings(log: Log) -> list[tuple[int, str, str]]:
    """When the run gives a placeholder that is no label on screen its vertex: (seq of the
    call, placeholder, label) for each first return of a call of :data:`_PLACEHOLDERS`
    naming one vertex, and (seq, "claim", the two labels) for its first claim."""
    shown, found = set(_labels_shown(log)), []
    seen: set[str] = set()
    for e in log.events:
        placeholder = _PLACEHOLDERS.get(e.name or "")
        if (e.kind == "return" and placeholder is not None and placeholder not in shown
                and placeholder not in seen and len(refs(e.result)) == 1):
            seen.add(placeholder)
            # from the beat of its call on: the beat that shows the return is the call's
            found.append((e.call if e.call is not None else e.seq, placeholder,
                          refs(e.result)[0]))
        elif e.kind == "call" and e.name == "claim" and "claim" not in seen:
            ends = [k for v in (e.args or {}).values() for k in refs(v)]
            if len(ends) == 2:
                seen.add("claim")
                found.append((e.seq, "claim", "".join(ends)))
    return found


def bound_stages(log: Log, rows: tuple[PseudocodeRow, ...]
                 ) -> list[tuple[int, tuple[PseudocodeRow, ...]]]:
    """``rows`` as the run ties its placeholders to its vertices, one by one: (seq, rows from
    the beat of that seq on) for each placeholder given a vertex (:func:`_bindings`); none
    for a run whose rows have no such placeholder. Divide and conquer, which runs a
    heuristic on every piece, ties none: no one vertex is its V."""
    labels = _labels_shown(log)
    defined = {p: name for name, p in _PLACEHOLDERS.items()
               if any(name in row.calls for row in rows) and p not in labels}
    if not defined:
        return []
    one = run_vertices(log)  # each placeholder given one vertex in the whole run
    claims = sum(1 for e in log.events if e.kind == "call" and e.name == "claim")
    stages: list[tuple[int, tuple[PseudocodeRow, ...]]] = []
    given: dict[str, str] = {}
    claim: tuple[str, str] | None = None
    for seq, placeholder, label in _bindings(log):
        if placeholder == "claim" and claims == 1:
            claim = (label[0], label[1:])
        elif one.get(placeholder) == label and placeholder in defined:
            given[placeholder] = label
        else:
            continue
        stages.append((seq, bound(rows, given, defined, labels, claim)))
    return stages


#: letters for the pick before it is made, when the picture has a vertex D: the first of
#: them neither on screen nor in the pseudocode stands for it
_UNKNOWNS = "XYZWQRSU"


def staged_pseudocode(log: Log) -> tuple[tuple[PseudocodeRow, ...], int | None,
                                         tuple[PseudocodeRow, ...]]:
    """The pseudocode before the run picks its D, the seq of the event that picks it (None:
    none does), and after (:func:`spoken_pseudocode`). Before, the rows say the placeholder,
    not the vertex the run will pick (review r567: "E = the candidate nearest to C" and
    "claim BE" stood on screen before the distances were computed); a placeholder that is
    also a vertex on screen is another letter then (the screen's D is not the rule's D)."""
    after, rows, labels = _named_rows(log), pseudocode_of(log), _labels_shown(log)
    seq = _picked_at(log, run_vertices(log))
    if seq is None:
        return after, None, after
    vertices = {k: v for k, v in run_vertices(log).items() if k != "D"}
    used = set(labels) | {c for row in rows for c in row.text if c.isupper()}
    vertices["D"] = next(c for c in _UNKNOWNS if c not in used) if "D" in labels else "D"
    return named(rows, vertices, labels), seq, after


def pseudocode_stages(log: Log) -> tuple[tuple[PseudocodeRow, ...],
                                         list[tuple[int, tuple[PseudocodeRow, ...]]]]:
    """The rows the panel shows first, and (seq, rows) for each change the run makes to them
    as it goes: its pick named once picked (:func:`staged_pseudocode`), gravity's
    placeholders tied to their vertices one by one (:func:`bound_stages`)."""
    before, picked, after = staged_pseudocode(log)
    stages = [] if picked is None else [(picked, after)]
    return before, sorted([*stages, *bound_stages(log, after)], key=lambda stage: stage[0])


def _picked_at(log: Log, vertices: Mapping[str, str]) -> int | None:
    """The seq of the event that gives the run's D its vertex: the return of its ``pick``
    that names it, or the claim of BD (a heuristic of one's own); None if the run gives D
    none. A return that names no vertex (a pick that found none, or raised) picks nothing:
    taken for the pick, it put the run's D in the pseudocode before the run had chosen it."""
    d, b = vertices.get("D"), vertices.get("B")
    if d is None:
        return None
    for e in log.events:
        if e.kind == "return" and _PLACEHOLDERS.get(e.name) == "D" and refs(e.result) == [d]:
            return e.seq
        if e.kind == "call" and e.name == "claim":
            ends = [k for v in (e.args or {}).values() for k in refs(v)]
            if ends == [b, d]:
                return e.seq
    return None


def storyboard(log: Log, pacing: Pacing | None = None, shown_code: str | None = None,
               readings: Mapping[str, Reading] = MappingProxyType({}), *,
               black_box: bool = False) -> list[Beat]:
    """The beats of a log, in order.

    ``readings`` map traced names to the readings of the metaphors' steps (the frame's are
    always read). ``shown_code`` names the traced function whose source the panel shows
    (default: the log's ``shown``, else ``algorithm`` meta); each beat's ``line`` is the
    source line lit in it, and its ``row`` the row of the run's pseudocode
    (:func:`pseudocode_of`) lit in it. ``black_box``: divide and conquer's heuristic is
    a black box — each call of it is one question (a :class:`~story.beats.FindDiagonal`)
    and the diagonal that comes out (its claim and verdict), none of its own steps.

    >>> from story.runs import run_logged
    >>> log = run_logged("divide-and-conquer", "counterexample", "gravity")
    >>> [b.action for b in storyboard(log, black_box=True)][:6]
    ['polygon', 'find', 'claim', 'verdict', 'find', 'claim']
    """
    shown = shown_code or meta(log, "shown") or meta(log, "algorithm")
    walk = Walk(log, pacing or Pacing(), shown, meta(log, "user_heuristic"),
                pseudocode_of(log), meta(log, "heuristic_function"), black_box)
    table = {**FRAME_READS, **readings}
    beats: list[Beat] = []
    for event in log.events:
        made = list(_beats_for(walk, event, table))
        beats.extend(_boxed(walk, made) if walk.black_box and walk.heuristic_polygon else made)
        walk.track(event)
    return summarised(beats, [walk.counted.get(id(b), 0) for b in beats], walk.pacing.full,
                      walk.noun, total=walk.claims, kept=[id(b) in walk.kept for b in beats],
                      numbers=[walk.counted_of.get(id(b), {}).get(walk.noun, 0) for b in beats],
                      names=walk.named.get(walk.noun, {}), order=tuple(walk.root_polygon()[0]),
                      told=told_claim(walk.noun, meta(log, "heuristic")) if walk.pacing.told
                      else None)


def told_claim(noun: str, heuristic: str | None) -> Told:
    """The caption of one fast claim of divide and conquer (:attr:`Pacing.told`): its
    number, the vertex its run starts from (its first pick, the left-most, lit blue: named,
    as every vertex lit is), who finds it, in the part lit up (the blue one: the part worked
    on), the split along it and the triangles done under it — what its beats show.

    >>> told = told_claim("diagonal", "gravity")
    >>> from story.beats import beat_kind
    >>> claim = Claim(caption="Claim: GB is an inner diagonal", seq=1, labels=("G", "B"),
    ...               points=((0.0, 0.0), (1.0, 0.0)))
    >>> told(3, [claim])
    'Diagonal 3: Gravity finds GB in the blue part; split along it'
    >>> told(3, [Pick(caption="B is the left-most vertex", seq=0, vertex="B"), claim])
    'Diagonal 3: from B, Gravity finds GB in the blue part; split along it'
    >>> @beat_kind("done")
    ... class Done(Beat):
    ...     labels: tuple[str, ...] = ()
    >>> told(5, [claim, Done(caption="MAH is a triangle: done", seq=2, labels=("M", "A", "H"))])
    'Diagonal 5: Gravity finds GB in the blue part; split, MAH done'
    """
    who = spoken(heuristic, start=True) if heuristic else "The rule"

    def told(number: int, beats: Sequence[Beat]) -> str:
        claim = next((b for b in beats if isinstance(b, Claim)), None)
        if claim is None:  # no claim under it: nothing of its own to say
            return f"{noun.capitalize()} {number}: the same steps, faster"
        start = next((b.vertex for b in beats if isinstance(b, Pick)), None)
        said = (f"{noun.capitalize()} {number}: {f'from {start}, ' if start else ''}{who} finds "
                f"{''.join(claim.labels)} in the blue part")
        done = ["".join(getattr(b, "labels", ())) for b in beats if b.action == "done"]
        return f"{said}; split, {' and '.join(done)} done" if done else f"{said}; split along it"

    return told


def _boxed(walk: Walk, beats: list[Beat]) -> list[Beat]:
    """The beats made inside a black-boxed heuristic that the viewer sees: the question,
    and the diagonal that comes out (the claim, said as the box's answer, and its verdict)."""
    seen: list[Beat] = []
    for beat in beats:
        if isinstance(beat, Claim):
            answer = replace(beat, caption=f"Out comes {''.join(beat.labels)}")
            walk.counted[id(answer)] = walk.counted[id(beat)]  # counted as the claim it says
            walk.counted_of[id(answer)] = walk.counted_of[id(beat)]
            seen.append(answer)
        elif isinstance(beat, (FindDiagonal, Verdict)):
            seen.append(beat)
    return seen


def _beats_for(walk: Walk, e: Event, table: Mapping[str, Reading]) -> Iterator[Beat]:
    if e.kind == "enter" and state_of(e).get("kind") == "polygon" and is_polygon_key(e.target):
        if not walk.shown_polygon:
            walk.shown_polygon = True
            yield walk.beat(ShowPolygon, "The polygon", e, points=points_of(state_of(e)["points"]),
                            labels=tuple(state_of(e)["labels"]),
                            holes=tuple(Hole.of(h) for h in state_of(e).get("holes", [])))
        return
    if e.kind == "call" and "polygon" in (e.args or {}) and walk.is_heuristic(e.name):
        if walk.black_box and not walk.heuristic_polygon:  # asked once, not again inside
            yield walk.beat(FindDiagonal, "Find an inner diagonal of this polygon", e,
                            piece=ref(e, "polygon"), within=walk.within(ref(e, "polygon")))
        walk.heuristic_polygon.append(ref(e, "polygon"))
        return
    if e.kind == "return" and walk.is_heuristic(e.name) and walk.heuristic_polygon:
        walk.heuristic_polygon.pop()
        return
    if e.kind == "enter" and is_frame_key(e.target):
        corners = state_of(e)["labels"]  # the run's own: a piece keeps its parent's labels
        middle = corners[1] if len(corners) == 3 else "B"
        yield walk.beat(ShowTriangle, f"T = {''.join(corners)}: {middle} and its two neighbours", e,
                        points=points_of(state_of(e)["points"]), labels=tuple(corners))
        return
    if e.kind == "return":
        call = walk.log.events[call_of(e)]
        reading = table.get(e.name)
        if reading is not None:
            yield from reading(walk, call, e)
        elif walk.user:
            yield walk.beat(Call, _call_caption(call, e), call, call=call_line(call, e),
                            roles=call_roles(call, e))
        return
    if e.kind == "note":
        yield walk.beat(Note, string(e.args.get("reason", e.name), f"the log's note {e.name}")
                        if e.args else e.name, e,
                        details=dict(e.args or {}))
    elif walk.user and e.kind in ("enter", "change", "exit"):
        yield from _shape_beats(walk, e, table)


# --- the frame: left-most vertex, candidates, claim and verdict ----------------------------------


def read_pick(caption: str, none_caption: str | None = None, role: str | None = None) -> Reading:
    """The reading of a call that picks a vertex (its result), or finds none; ``role``: the
    vertex's role, if not the call's (a result's green)."""

    def read(walk: Walk, call: Event, ret: Event) -> Iterator[Beat]:
        if ret.result is None:
            if none_caption:
                yield walk.call_beat(Note, none_caption, call, ret)
            return
        vertex = show(ret.result)
        roles = call_roles(call, ret)
        if role is not None:
            roles.update({k: role for k in refs(ret.result)})
        yield walk.call_beat(Pick, caption.format(result=vertex), call, ret, vertex=vertex,
                             roles=roles)

    return read


def _read_candidates(walk: Walk, call: Event, ret: Event) -> Iterator[Beat]:
    found = [show(v) for v in result_list(ret)]
    caption = (f"Candidates inside T: {', '.join(found)}" if found
               else f"No vertex inside T: {_outer_corners(walk, call)} is an inner diagonal")
    # neutral: a candidate is neither claimed nor judged (green is a verdict's)
    yield walk.call_beat(Candidates, caption, call, ret, candidates=tuple(found),
                         roles={**call_roles(call, None),
                                **{k: "candidate" for k in refs(ret.result)}})


def _outer_corners(walk: Walk, call: Event) -> str:
    """T's corners but B, named as the run's own vertices (``AC`` on the whole polygon, the
    piece's own on a piece of divide and conquer): T as the call was handed it."""
    state = walk.live.get(ref(call, "t"))
    labels = state.get("labels") if state else None
    return f"{labels[0]}{labels[2]}" if labels and len(labels) == 3 else "AC"


def _read_claim(walk: Walk, call: Event, ret: Event) -> Iterator[Beat]:
    key = result_ref(ret)
    walk.claimed.add(key)
    state = walk.live.get(key) or walk.entered_after(ret, key)
    u, v = state["labels"]
    name = f"{u}{v}"
    # amber ("argument") until the verdict: green is kept for a claim that holds
    yield walk.call_beat(Claim, f"Claim: {name} is an inner diagonal", call, ret,
                         roles={u: "argument", v: "argument"},
                         labels=(u, v), points=segment(state["points"]))
    polygon = _claim_polygon(walk)
    if polygon is None:
        walk.count_claim()
        return
    i, j = polygon.labels.index(u), polygon.labels.index(v)
    verdict = is_inner_diagonal(polygon, i, j)
    # the screen names the crossed edge; verdict.why (with coordinates) is the command line's
    caption = f"✓ {name} is an inner diagonal" if verdict else (
        f"✗ {name} is not an inner diagonal: {why_not_inner(verdict, polygon.labels, name)}")
    roles = {u: "result", v: "result"} if verdict else {u: "rejected", v: "rejected"}
    yield walk.beat(Verdict, caption, call, roles=roles, ok=verdict.ok, labels=(u, v),
                    why=verdict.why, code=verdict.code,
                    point=point(verdict.point) if verdict.point else None,
                    edge=(polygon.labels[verdict.edge[0]], polygon.labels[verdict.edge[1]])
                    if verdict.edge else None)
    walk.count_claim()  # after its verdict: the verdict belongs to the claim it judges


def _claim_polygon(walk: Walk) -> Polygon | None:
    """The polygon the running heuristic works on, from the live states of the log."""
    if not walk.heuristic_polygon:
        return None
    state = walk.live.get(walk.heuristic_polygon[-1])
    if state is None:
        # A sub-polygon the algorithm did not log (what ear clipping left): it is cut from the
        # whole polygon by inner diagonals, so a diagonal inside it is inside the whole too.
        labels, points = walk.root_polygon()
        if not labels:
            return None
        state = {"points": points, "labels": labels}
    return Polygon(
        points=tuple(tuple(p) for p in state["points"]),
        labels=tuple(state["labels"]),
        source=tuple(range(len(state["points"]))),
    )


def read_step(kind: type[Beat], caption: str,
              fields: Callable[[Walk, Event, Event], dict[str, Any]], *,
              picks: bool = False) -> Reading:
    """The reading of a metaphor's step: one beat of ``kind``, its ``caption`` naming the
    call's result (``{result}``), its own fields from ``fields(walk, call, ret)``. ``picks``:
    the step picks one of T's candidates, in their roles (:func:`pick_roles`)."""

    def read(walk: Walk, call: Event, ret: Event) -> Iterator[Beat]:
        result = show(ret.result)
        made = fields(walk, call, ret)
        if picks:
            made["roles"] = pick_roles(call, ret)
        yield walk.call_beat(kind, caption.format(result=result), call, ret, result=result,
                             **made)

    return read


def _read_nothing(walk: Walk, call: Event, ret: Event) -> Iterator[Beat]:
    """A step the frame shows otherwise: ``triangle_at``'s T is drawn as it enters the log,
    so a heuristic of one's own that calls it gets no second caption naming the call."""
    return iter(())


FRAME_READS: Mapping[str, Reading] = MappingProxyType({
    # B in blue, T's corner as T is drawn (review r567: B green, the answer's colour)
    "leftmost_vertex": read_pick("{result} is the left-most vertex (lowest on ties): convex",
                                 role="called"),
    "triangle_at": _read_nothing,
    "candidates_in_triangle": _read_candidates,
    "claim": _read_claim,
})


# --- generic beats: a heuristic of one's own (log meta ``user_heuristic``) ----------------------


def _call_caption(call: Event, ret: Event) -> str:
    """A step of one's own in words (its call line shows the code), naming the picture's own
    vertices (:func:`_step_words`): ``distance_to_c(c, d)`` on C and E is ``Distance to C
    for E: 1.4``."""
    step = _step_words(call.name, call.args or {})
    if isinstance(ret.result, dict) and "raised" in ret.result:
        return f"{step}: it raised {ret.result['raised']}"
    return f"{step}: done" if ret.result is None else f"{step}: {show(ret.result)}"


def _step_words(name: str, args: Mapping[str, Any]) -> str:
    """A function's name said with its arguments: a word of the name that is also the name
    of a parameter given an object on screen (a vertex, T, P) says that object, and the
    arguments not said so follow after "for"; any other one-letter word (but "a") is a
    vertex's capital.

    >>> _step_words("distance_to_c", {"c": {"ref": "C"}, "d": {"ref": "E"}})
    'Distance to C for E'
    >>> _step_words("angle_at_b", {"p": {"ref": "D"}}), _step_words("is_a_fit", {})
    ('Angle at B for D', 'Is a fit')
    """
    names = {key.lower(): key for key in args}
    words, spoken = [], set()
    for word in said(name).split():
        key = names.get(word)
        if key is not None and isinstance(args[key], dict) and "ref" in args[key]:
            words.append(show(args[key]))
            spoken.add(key)
        else:
            words.append(word.upper() if len(word) == 1 and word != "a" else word)
    step = " ".join(words)
    step = step[:1].upper() + step[1:]
    given = [show(v) for key, v in args.items() if key not in spoken]
    return f"{step} for {', '.join(given)}" if given else step


def _shape_beats(walk: Walk, e: Event, table: Mapping[str, Reading]) -> Iterator[Beat]:
    """A shape of the user's run appears, changes or goes (state None on exit).

    Shapes drawn inside a step that has a reading (a metaphor draws them) or inside a
    built-in heuristic are left to that step."""
    key = e.target
    if key is None or is_frame_key(key) or key in walk.claimed:
        return
    if any(c.name in table or (walk.is_heuristic(c.name) and c.name != walk.user)
           for c in walk.stack):
        return
    if e.kind != "enter" and key not in walk.drawn:
        return
    state = e.state if e.kind != "exit" else None
    if state is None:
        walk.drawn.discard(key)
        caption = f"Gone: {key}"
    else:
        walk.drawn.add(key)
        kind = state.get("kind", "shape")
        caption = str(state.get("caption") or (
            f"Drawn: {key} ({kind})" if e.kind == "enter" else f"Changed: {key}"))
    inner = walk.stack[-1] if walk.stack and walk.stack[-1].name != walk.user else None
    roles = call_roles(inner, None) if inner is not None else {}
    if state is not None:
        role = state.get("role")
        roles[key] = role if role in ROLES else "argument"
    yield walk.beat(ShapeChange, str(caption), e, call=call_line(inner, None) if inner else None,
                    roles=roles, key=key, event=e.kind, state=state)
