"""From a log to beats: plain data saying what each moment of the video shows.

A beat names its metaphor action, the objects and their roles (called,
argument, result, rejected, idle), the numbers the animation needs (radii,
angles, offsets, points — all read from the log, never recomputed), the
call line, the pseudocode line and a caption. The only thing computed here
is the verdict on each claimed diagonal, by :mod:`geometry.check`.

This module does not import manim: beats are data, so a log saved as JSON
and loaded again gives the same beats, hence the same video.

>>> import tracing
>>> from geometry.diagonals import find_diagonal
>>> from geometry.polygon import Polygon
>>> from geometry.samples import make_sample
>>> p = Polygon.from_points(make_sample("counterexample"))
>>> with tracing.record(algorithm="scaling") as log:
...     _ = find_diagonal(p, "scaling")
>>> [b.action for b in storyboard(log)]
['polygon', 'pick', 'triangle', 'candidates', 'water', 'claim', 'verdict']
>>> storyboard(log)[4].call
'nearest_to(B, [D, E]) → D'
>>> storyboard(log)[-1].caption
'✗ BD is not an inner diagonal: B–D crosses edge E–A at (2.86087, 6.36087)'
"""

from __future__ import annotations

from collections.abc import Iterator
from dataclasses import dataclass, field

from geometry.check import is_inner_diagonal
from geometry.polygon import Polygon
from story.registry import heuristics
from story.roles import ROLES
from tracing import Event, Log

#: Steps whose call and return become one metaphor beat, with the shape they animate.
METAPHOR_STEPS = {
    "nearest_to": ("water", "water"),
    "nearest_visible": ("walled-water", "water"),
    "last_dry": ("flood", "flood"),
    "first_hit_rotating": ("clock", "hand"),
    "first_hit_sweeping": ("sweep", "sweep"),
    "drop_ball": ("drop", "ball"),
    "slide_to_vertex": ("slide", "ball"),
    "band_snag": ("snag", "band"),
}

CAPTIONS = {
    "leftmost_vertex": "{result} is the left-most vertex (lowest on ties): convex, it plays B",
    "reflex_vertex": "{result} is a reflex vertex: the ball will hang there",
    "straight_vertex": "{result} is a straight vertex: the ball hangs there instead",
}
NONE_CAPTIONS = {
    "reflex_vertex": "No reflex vertex: the polygon is convex",
}


@dataclass(frozen=True)
class Beat:
    """One moment of the video, as plain data."""

    action: str
    caption: str
    step: int
    call: str | None = None
    line: int | None = None
    roles: dict[str, str] = field(default_factory=dict)
    data: dict = field(default_factory=dict)
    pace: float = 1.0

    def to_dict(self) -> dict:
        return {
            "action": self.action, "caption": self.caption, "step": self.step,
            "call": self.call, "line": self.line, "roles": self.roles, "data": self.data,
            "pace": self.pace,
        }


@dataclass(frozen=True)
class Pacing:
    """Full detail for the first `full` claims, then `fast` × the run time."""

    full: int = 2
    fast: float = 0.35


# --- call lines ----------------------------------------------------------------------------------


def show(value) -> str:
    """A value as the call line writes it: refs by key, polygons as P, lists in brackets.

    >>> show({"ref": "P(ABCDE)"}), show([{"ref": "D"}, {"ref": "E"}]), show(2.5), show(None)
    ('P', '[D, E]', '2.5', '—')
    """
    if isinstance(value, dict) and "ref" in value:
        key = value["ref"]
        return "P" if key.startswith("P(") else key
    if isinstance(value, list):
        return "[" + ", ".join(show(v) for v in value) + "]"
    if isinstance(value, float):
        return f"{value:.3g}"
    if value is None:
        return "—"
    if isinstance(value, dict):
        return "{…}"
    return str(value)


def call_line(call: Event, ret: Event | None) -> str:
    args = ", ".join(show(v) for v in (call.args or {}).values())
    text = f"{call.name}({args})"
    return f"{text} → {show(ret.result)}" if ret is not None else text


def _refs(value) -> list[str]:
    if isinstance(value, dict) and "ref" in value:
        return [value["ref"]]
    if isinstance(value, list):
        return [k for v in value for k in _refs(v)]
    return []


def call_roles(call: Event, ret: Event | None) -> dict[str, str]:
    """First referenced argument (not the polygon) is called, the others arguments, result green."""
    refs = [k for v in (call.args or {}).values() for k in _refs(v) if not k.startswith("P(")]
    roles = {k: "argument" for k in refs[1:]}
    if refs:
        roles[refs[0]] = "called"
    for k in _refs(ret.result) if ret is not None else []:
        roles[k] = "result"
    return roles


# --- the walk ------------------------------------------------------------------------------------


class _Walk:
    """State of one pass over the log: live objects, open calls, claims seen."""

    def __init__(self, log: Log, pacing: Pacing, shown_code: str | None):
        self.log, self.pacing = log, pacing
        self.live: dict[str, dict] = {}
        self.returns = {e.call: e for e in log.events if e.kind == "return"}
        self.claims = 0
        self.heuristic_polygon: list[str] = []
        self.shown_polygon = False
        self.stack: list[Event] = []  # open calls, outermost first
        self.shown_code = shown_code
        self.user = log.meta.get("user_heuristic")  # a heuristic of one's own: generic beats
        self.drawn: set[str] = set()  # keys of the shapes the generic beats drew
        self.clipped: list[list[str]] = []  # the ears cut so far (fruit)

    def entered_after(self, event: Event, key: str) -> dict:
        """The state with which object `key` enters the log after `event`."""
        for later in self.log.events[event.seq:]:
            if later.kind == "enter" and later.target == key:
                return later.state
        return self.live.get(key, {})

    def root_points(self) -> dict[str, list]:
        """Label → point of the first polygon of the log."""
        for event in self.log.events:
            if event.kind == "enter" and event.target.startswith("P("):
                return dict(zip(event.state["labels"], event.state["points"], strict=True))
        return {}

    def fruit_polygon(self, call: Event, ret: Event):
        """Labels and points of the polygon the ear clipping runs on (its first state)."""
        for event in self.log.events:
            if event.kind == "enter" and event.target.startswith("P("):
                return event.state["labels"], event.state["points"]
        return None

    def code_line(self, event: Event) -> int | None:
        """The line lit in the shown function: the line of its direct callee, or of the event."""
        for k, call in enumerate(self.stack):
            if call.name == self.shown_code:
                inner = self.stack[k + 1] if k + 1 < len(self.stack) else event
                return inner.line
        return None

    def pace(self) -> float:
        return 1.0 if self.claims < self.pacing.full else self.pacing.fast

    def beat(self, action: str, caption: str, event: Event, **kw) -> Beat:
        return Beat(action, caption, event.seq, line=self.code_line(event), pace=self.pace(), **kw)

    def changes(self, call: Event, target: str) -> list[dict]:
        ret = self.returns.get(call.seq)
        end = ret.seq if ret is not None else len(self.log.events)
        return [
            e.state for e in self.log.events[call.seq:end]
            if e.kind in ("enter", "change") and e.target == target
        ]


def storyboard(log: Log, pacing: Pacing | None = None, shown_code: str | None = None) -> list[Beat]:
    """The beats of a log, in order.

    ``shown_code`` names the traced function whose source the panel shows (default: the
    log's ``algorithm`` meta); each beat's ``line`` is the source line lit in it.
    """
    shown = shown_code or log.meta.get("shown") or log.meta.get("algorithm")
    walk = _Walk(log, pacing or Pacing(), shown)
    beats: list[Beat] = []
    for event in log.events:
        beats.extend(_beats_for(walk, event))
        _track(walk, event)
    return beats


def _track(walk: _Walk, event: Event) -> None:
    if event.kind == "call":
        walk.stack.append(event)
    elif event.kind == "return":
        walk.stack.pop()
    elif event.kind in ("enter", "change"):
        walk.live[event.target] = event.state
    elif event.kind == "exit":
        walk.live.pop(event.target, None)


def _beats_for(walk: _Walk, e: Event) -> Iterator[Beat]:
    if e.kind == "enter" and e.state.get("kind") == "polygon" and e.target.startswith("P("):
        if not walk.shown_polygon:
            walk.shown_polygon = True
            yield walk.beat("polygon", "The polygon", e, data=_polygon_data(e.state))
        return
    if e.kind == "call" and "polygon" in (e.args or {}) and _is_heuristic(walk, e.name):
        walk.heuristic_polygon.append(e.args["polygon"]["ref"])
        return
    if e.kind == "return" and _is_heuristic(walk, e.name) and walk.heuristic_polygon:
        walk.heuristic_polygon.pop()
        return
    if e.kind == "enter" and e.target.startswith("T("):
        labels = "".join(e.state["labels"])
        yield walk.beat("triangle", f"T = {labels}: B and its two neighbours", e,
                        data={"points": e.state["points"], "labels": e.state["labels"]})
        return
    if e.kind == "return":
        yield from _return_beats(walk, e)
        return
    if e.kind == "note":
        yield walk.beat("note", e.args.get("reason", e.name) if e.args else e.name, e,
                        data=dict(e.args or {}))
    elif walk.user and e.kind in ("enter", "change", "exit"):
        yield from _shape_beats(walk, e)


_HEURISTIC_NAMES = {
    *heuristics(),
    "sweep_at", "gravity_at",  # traced heuristics at a given vertex (prune and search, gravity)
}


def _return_beats(walk: _Walk, ret: Event) -> Iterator[Beat]:
    call = walk.log.events[ret.call]
    roles = call_roles(call, ret)
    line = call_line(call, ret)
    kw = {"call": line, "roles": roles}
    if ret.name in CAPTIONS:
        if ret.result is None:
            if ret.name in NONE_CAPTIONS:
                yield walk.beat("note", NONE_CAPTIONS[ret.name], call, **kw)
            return
        caption = CAPTIONS[ret.name].format(result=show(ret.result))
        yield walk.beat("pick", caption, call, data={"vertex": show(ret.result)}, **kw)
    elif ret.name == "candidates_in_triangle":
        found = [show(v) for v in ret.result or []]
        caption = (f"Candidates inside T: {', '.join(found)}" if found
                   else "No vertex inside T: AC is an inner diagonal")
        yield walk.beat("candidates", caption, call, data={"candidates": found}, **kw)
    elif ret.name == "gravity_direction":
        yield walk.beat("gravity-turn", "Turn the polygon so that gravity points down", call,
                        data={**ret.result, "polygon": call.args["polygon"]["ref"]}, **kw)
    elif ret.name in METAPHOR_STEPS:
        action, shape = METAPHOR_STEPS[ret.name]
        data = {"states": walk.changes(call, shape), "result": show(ret.result)}
        data.update(_extra(walk, call, ret))
        yield walk.beat(action, _metaphor_caption(action, data), call, data=data, **kw)
    elif ret.name == "claim":
        yield from _claim_beats(walk, call, walk.live[ret.result["ref"]], line)
    elif ret.name in SWEEP_STEPS:
        yield from _monotone_beats(walk, call, ret, kw)
    elif ret.name == "good_subpolygon":
        state = walk.entered_after(ret, ret.result["ref"])
        yield walk.beat("good", "A good sub-polygon: one cut edge, about half the vertices; "
                        "its middle vertex is tested next", call,
                        data={"points": state["points"], "labels": state["labels"]}, **kw)
    elif ret.name in FRUIT_STEPS:
        yield from _fruit_beats(walk, call, ret, kw)
    elif ret.name == "split":
        pieces = [r["ref"] for r in ret.result]
        entered = {e.target: e.state for e in walk.log.events[ret.seq:]
                   if e.kind == "enter" and e.target in pieces}
        yield walk.beat("split", "Split along the diagonal into two smaller polygons", call,
                        data={"pieces": pieces, "parent": call.args["piece"]["ref"],
                              "points": [entered[k]["points"] for k in pieces if k in entered],
                              "labels": [entered[k]["labels"] for k in pieces if k in entered]},
                        **kw)
    elif walk.user:
        yield walk.beat("call", _call_caption(call, ret), call, **kw)


# --- generic beats: a heuristic of one's own (log meta ``user_heuristic``) ----------------------

#: Calls whose shapes a metaphor (or the claim) already draws.
_MAPPED = set(METAPHOR_STEPS) | {"claim", "candidates_in_triangle", "gravity_direction", "split"}


def _is_heuristic(walk: _Walk, name: str) -> bool:
    return name in _HEURISTIC_NAMES or name == walk.user


def _call_caption(call: Event, ret: Event) -> str:
    if isinstance(ret.result, dict) and "raised" in ret.result:
        return f"{call.name} raised {ret.result['raised']}"
    return f"{call.name} is done" if ret.result is None else f"{call.name} gives {show(ret.result)}"


def _shape_beats(walk: _Walk, e: Event) -> Iterator[Beat]:
    """A shape of the user's run appears, changes or goes; data = its state (None on exit)."""
    key = e.target
    if key is None or key.startswith(("P(", "T(")):
        return
    if any(c.name in _MAPPED or c.name in _HEURISTIC_NAMES for c in walk.stack):
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
        caption = state.get("caption") or (
            f"Drawn: {key} ({kind})" if e.kind == "enter" else f"Changed: {key}")
    inner = walk.stack[-1] if walk.stack and walk.stack[-1].name != walk.user else None
    roles = call_roles(inner, None) if inner is not None else {}
    if state is not None:
        role = state.get("role")
        roles[key] = role if role in ROLES else "argument"
    yield walk.beat("shape", str(caption), e, call=call_line(inner, None) if inner else None,
                    roles=roles, data={"key": key, "event": e.kind, "state": state})


def _extra(walk: _Walk, call: Event, ret: Event) -> dict:
    """Per-step data from the log besides the shape's states."""
    if call.name == "nearest_visible":
        inside = walk.log.events[call.seq:ret.seq]
        sees = [e for e in inside if e.kind == "call" and e.name == "sees"]
        return {"visible": [(show(s.args["v"]), bool(walk.returns[s.seq].result)) for s in sees]}
    if call.name == "drop_ball":
        hit = next(e.state for e in walk.log.events[call.seq:ret.seq]
                   if e.kind == "enter" and e.target == "hit")
        return {"hit": hit["at"], "vertex": show(call.args["v"])}
    return {}


_METAPHOR_CAPTIONS = {
    "water": "Water spilled at B spreads; the first candidate it wets is {result}",
    "walled-water": "Water that respects the walls reaches {result} first",
    "flood": "Water rises from the shore AC; the last dry candidate is {result}",
    "clock": "The clock hand turns; the first candidate it passes is {result}",
    "sweep": "The line sweeps across T; the first candidate it touches is {result}",
    "drop": "The ball falls until it hits the boundary",
    "slide": "It slides down the edge to {result}",
    "snag": "The rubber band snags {result}",
}


def _metaphor_caption(action: str, data: dict) -> str:
    if action == "snag" and data["result"] == "—":
        return "The rubber band stays straight"
    return _METAPHOR_CAPTIONS[action].format(result=data["result"])


def _claim_beats(walk: _Walk, e: Event, state: dict, call: str) -> Iterator[Beat]:
    u, v = state["labels"]
    name = f"{u}{v}"
    yield walk.beat("claim", f"Claim: {name} is an inner diagonal", e, call=call,
                    roles={u: "result", v: "result"},
                    data={"labels": [u, v], "points": state["points"]})
    polygon = _claim_polygon(walk)
    walk.claims += 1
    if polygon is None:
        return
    i, j = polygon.labels.index(u), polygon.labels.index(v)
    verdict = is_inner_diagonal(polygon, i, j)
    data = {"ok": verdict.ok, "labels": [u, v], "why": verdict.why, "code": verdict.code,
            "point": list(verdict.point) if verdict.point else None,
            "edge": [polygon.labels[k] for k in verdict.edge] if verdict.edge else None}
    caption = f"✓ {name} is an inner diagonal" if verdict else (
        f"✗ {name} is not an inner diagonal: {verdict.why}")
    roles = {u: "result", v: "result"} if verdict else {u: "rejected", v: "rejected"}
    yield walk.beat("verdict", caption, e, roles=roles, data=data)


def _claim_polygon(walk: _Walk) -> Polygon | None:
    """The polygon the running heuristic works on, from the live states of the log."""
    if not walk.heuristic_polygon:
        return None
    state = walk.live.get(walk.heuristic_polygon[-1])
    if state is None:
        # A sub-polygon the algorithm did not log (what ear clipping left): it is cut from the
        # whole polygon by inner diagonals, so a diagonal inside it is inside the whole too.
        where = walk.root_points()
        if not where:
            return None
        state = {"points": list(where.values()), "labels": list(where)}
    return Polygon(
        points=tuple(tuple(p) for p in state["points"]),
        labels=tuple(state["labels"]),
        source=tuple(range(len(state["points"]))),
    )


def _polygon_data(state: dict) -> dict:
    return {"points": state["points"], "labels": state["labels"]}


# --- fruit: ear clipping ---------------------------------------------------------------------------

FRUIT_STEPS = {"is_ear", "clip_ear", "ear-clipping", "ear-clipping-naive"}


def _fruit_beats(walk: _Walk, call: Event, ret: Event, kw: dict) -> Iterator[Beat]:
    """An ear test, a slice cut off, and at the end the last slice (the triangle left over)."""
    if ret.name == "is_ear":
        v, ear = show(call.args["v"]), bool(ret.result)
        caption = f"Is {v} an ear? " + ("yes: its triangle holds no other vertex" if ear
                                         else "no: a cut between its neighbours is not a clean slice")
        kw["roles"] = {v: "result" if ear else "rejected"}
        yield walk.beat("ear-test", caption, call, data={"vertex": v, "ear": ear}, **kw)
        return
    fruit = walk.fruit_polygon(call, ret)
    if fruit is None:
        return
    labels, points = fruit
    if ret.name == "clip_ear":
        corners = [show(r) for r in ret.result]
        walk.clipped.append(corners)
        walk.claims += 1
        yield walk.beat("clip", _slice_caption(corners, len(walk.clipped), len(labels)), call,
                        data=_slice_data(corners, labels, points, walk.clipped), **kw)
        return
    gone = {c[1] for c in walk.clipped}
    corners = [x for x in labels if x not in gone]
    if len(corners) == 3:
        walk.clipped.append(corners)
        yield walk.beat("last-slice", _slice_caption(corners, len(walk.clipped), len(labels)),
                        call, data=_slice_data(corners, labels, points, walk.clipped), **kw)


def _slice_caption(corners: list[str], k: int, n: int) -> str:
    return f"Slice {''.join(corners)}: {k} / {n - 2} slices"


def _slice_data(corners, labels, points, clipped) -> dict:
    where = dict(zip(labels, points, strict=True))
    gone = {c[1] for c in clipped[:-1]}
    return {
        "corners": corners,
        "points": [where[c] for c in corners],
        "k": len(clipped),
        "total": len(labels) - 2,
        # what is left of the fruit once this slice is off (empty after the last one)
        "rest": [where[x] for x in labels if x not in gone | {corners[1]}]
        if len(clipped) < len(labels) - 2 else [],
    }


# --- monotone: the sweep, the partition, the stack ------------------------------------------------

SWEEP_STEPS = {"classify_vertex", "add_diagonal", "monotone_pieces", "triangulate_monotone_piece"}
KINDS = {
    "start": "both neighbours below, interior below: a start vertex",
    "end": "both neighbours above, interior above: an end vertex",
    "split": "both neighbours below, interior above: a split vertex needs a diagonal up",
    "merge": "both neighbours above, interior below: a merge vertex needs a diagonal down",
    "regular": "one neighbour above, one below: a regular vertex",
}


def _monotone_beats(walk: _Walk, call: Event, ret: Event, kw: dict) -> Iterator[Beat]:
    where = walk.root_points()
    labels = list(where)
    if ret.name == "classify_vertex":
        v, kind = show(call.args["v"]), ret.result
        kw["roles"] = {v: "rejected" if kind in ("split", "merge") else "called"}
        yield walk.beat("classify", f"{v}: {KINDS.get(kind, kind)}", call,
                        data={"vertex": v, "kind": kind, "at": where[v]}, **kw)
    elif ret.name == "add_diagonal":
        u, w = (labels[k] for k in ret.result)
        walk.claims += 1
        yield walk.beat("monotone-diagonal", f"Diagonal {u}{w} removes a split or merge vertex",
                        call, data={"labels": [u, w], "points": [where[u], where[w]]}, **kw)
    elif ret.name == "monotone_pieces":
        pieces = [walk.entered_after(call, r["ref"]) for r in ret.result]
        yield walk.beat("pieces", f"The diagonals cut the polygon into {len(pieces)} y-monotone "
                        "pieces", call, data={"pieces": [p.get("points", []) for p in pieces]},
                        **kw)
    else:
        triangles = [[where[labels[k]] for k in t] for t in ret.result]
        yield walk.beat("stack", f"The stack triangulates a monotone piece: "
                        f"{len(triangles)} triangle{'s' if len(triangles) != 1 else ''}", call,
                        data={"triangles": triangles}, **kw)
