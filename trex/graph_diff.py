"""How two scene graphs differ, in words, play by play (``trex snapshot --check``, the pytest
plugin). Plain data in, lines of text out: no manim.

The plays of the two graphs are first lined up by what they animate (each animation's class
and mobject name), so a play added or removed shows as such and the plays after it are still
compared with their counterparts. Then each pair of plays is compared field by field, and the
mobjects of each animation (and its target) part by part. A change seen in several plays is
said once, with the list of plays. Plays are numbered from 1, as in the stored graph
("expected"); a play that moved says where it is now.

>>> def play(name, colour="#83C167", run_time=1.0):
...     line = {"type": "Line", "role": "result", "name": name, "stroke": colour, "points": []}
...     return {"run_time": run_time, "subcaption": None,
...             "animations": [{"type": "Create", "run_time": run_time, "mobject": line}]}
>>> old = {"plays": [play("claim"), play("claim")], "final": []}
>>> new = {"plays": [play("claim", run_time=1.5), play("claim", "#FC6255")], "final": []}
>>> for line in differences(old, new):
...     print(line)
play 1 (Create claim): run_time 1.0 → 1.5
play 2 (Create claim): mobject "claim" stroke #83C167 → #FC6255
>>> new["plays"] += [play("x"), play("y"), play("z")]
>>> differences(old, new)[-1]
'3 plays added after play 2: Create x, Create y, Create z'
>>> differences(old, old)
[]
"""

from __future__ import annotations

import difflib
import json
from collections.abc import Iterable, Iterator, Sequence
from dataclasses import dataclass
from typing import Any, cast

#: How many lines :func:`report` shows before it only counts the rest.
LIMIT = 40
#: How many plays (or mobjects) an added or removed run names before "…".
NAMED = 3

# The fields of a mobject node in the order they are reported; any other field comes after.
_MOBJECT_FIELDS = ("type", "name", "role", "stroke", "fill", "color", "stroke_opacity",
                   "fill_opacity", "stroke_width", "halo", "text", "box", "points")
_PLAY_FIELDS = ("run_time", "subcaption")


# --- naming things -----------------------------------------------------------------------------


def _named(node: dict) -> str | None:
    """A mobject's own name, if it has one (manim names an unnamed mobject after its class)."""
    name = node.get("name")
    return name if isinstance(name, str) and name and name != node.get("type") else None


def _short(node: dict) -> str:
    """A mobject as a word: its name, else its text in quotes, else its class."""
    name = _named(node)
    if name is not None:
        return name
    if isinstance(node.get("text"), str):
        return json.dumps(node["text"], ensure_ascii=False)
    return str(node.get("type", "?"))


def _kind(kind: Any) -> str:
    """An animation's class as said: manim's ``.animate`` builds a ``_MethodAnimation``."""
    return "animate" if kind == "_MethodAnimation" else str(kind)


def _animation_label(animation: dict) -> str:
    kind = _kind(animation.get("type", "?"))
    if "mobject" in animation:
        mobject = animation["mobject"]
        if isinstance(mobject, dict) and (_named(mobject) or "text" in mobject):
            return f"{kind} {_short(mobject)}"
    return kind


def play_label(play: dict) -> str:
    """What a play animates, in a few words: ``Create claim``, ``FadeIn title and 2 more``.

    >>> play_label({"animations": [{"type": "Wait", "mobject": {"type": "Mobject",
    ...                                                         "name": "Mobject"}}]})
    'Wait'
    """
    animations = play.get("animations") or []
    if not animations:
        return "nothing"
    first = _animation_label(animations[0])
    return first if len(animations) == 1 else f"{first} and {len(animations) - 1} more"


#: Values longer than this are cut (with "…"): a difference stays one readable line.
WIDEST = 120


def _value(value: Any) -> str:
    """A field's value as it is written in a difference."""
    text = _plain(value)
    return text if len(text) <= WIDEST else text[:WIDEST - 1] + "…"


def _plain(value: Any) -> str:
    if value is None:
        return "none"
    if isinstance(value, str):
        return value if value.startswith("#") or value.isidentifier() else json.dumps(
            value, ensure_ascii=False)
    if isinstance(value, list) and all(isinstance(v, str) for v in value):
        return "[" + ", ".join(value) + "]"
    return json.dumps(value, ensure_ascii=False)


def _key(value: Any) -> Any:
    """A value that can be hashed (a list, in a graph written by hand, as its JSON)."""
    if value is None or isinstance(value, str | int | float):
        return value
    return json.dumps(value, sort_keys=True, default=str)


def _signature(node: Any) -> Any:
    """What an animation or mobject is, for lining lists up: its class and name, recursively for
    groups."""
    if not isinstance(node, dict):
        return json.dumps(node, sort_keys=True)
    members = node.get("animations")
    inner = tuple(_signature(a) for a in members) if isinstance(members, list) else ()
    mobject = node.get("mobject")
    name = ((_key(mobject.get("name")), _key(mobject.get("type")))
            if isinstance(mobject, dict) else None)
    return (_key(node.get("type")), _key(node.get("name")), name, inner)


def _plays_text(numbers: list[int]) -> str:
    """``play 4``; ``plays 4–6, 9 (4 plays)``."""
    numbers = sorted(set(numbers))
    if len(numbers) == 1:
        return f"play {numbers[0]}"
    runs: list[list[int]] = []
    for n in numbers:
        if runs and n == runs[-1][-1] + 1:
            runs[-1].append(n)
        else:
            runs.append([n])
    shown = [f"{r[0]}" if len(r) == 1 else f"{r[0]}–{r[-1]}" for r in runs]
    if len(shown) > 6:
        shown = [*shown[:6], "…"]
    return f"plays {', '.join(shown)} ({len(numbers)} plays)"


# --- comparing ---------------------------------------------------------------------------------


@dataclass(frozen=True)
class Difference:
    """One thing that changed: in which play (``None``: the final picture, or the document),
    and what, in words."""

    play: int | None  # the play's number in the stored graph, from 1
    now: int | None  # its number in the new graph, when that is another
    label: str  # what the play animates
    what: str


def _points_change(old: list, new: list) -> str:
    if len(old) != len(new):
        return f"{len(old)} → {len(new)} points"
    moved = max((abs(a - b) for p, q in zip(old, new, strict=True)
                 for a, b in zip(p, q, strict=True)), default=0.0)
    return f"points moved by up to {moved:.3g}"


def _box_change(old: Any, new: Any) -> str:
    if old is None or new is None:  # a text-like mobject has a box (malformed() checks it)
        return f"box {_value(old)} → {_value(new)}"
    moved = max(abs(a - b) for a, b in zip(old, new, strict=True))
    return f"box moved by up to {moved:.3g}"


_TOP = ("mobject", "target", "final: mobject")


@dataclass(frozen=True)
class _Delta:
    """What changed in one mobject node: its own fields (``stroke #A → #B``), its paired parts
    that changed, and its parts added or removed (whole lines)."""

    where: str
    own: tuple[str, ...]
    parts: tuple[_Delta, ...]
    extra: tuple[str, ...]

    def uniform(self, own: tuple[str, ...]) -> bool:
        """Whether this node and all its changed parts changed exactly as ``own`` says."""
        return self.own == own and not self.extra and all(p.uniform(own) for p in self.parts)

    def size(self) -> int:
        return 1 + sum(p.size() for p in self.parts)

    def lines(self) -> Iterator[str]:
        """The node's changes in words; parts that changed just as it did are counted, not
        repeated."""
        if self.own:
            folded = [p for p in self.parts if p.uniform(self.own)]
            count = sum(p.size() for p in folded)
            also = (f" (its {count} parts too)" if count > 1 else " (its part too)") if count else ""
            yield f"{self.where} {', '.join(self.own)}{also}"
            rest: Sequence[_Delta] = [p for p in self.parts if p not in folded]
        elif len(self.parts) > 1 and all(p.uniform(self.parts[0].own) for p in self.parts):
            count = sum(p.size() for p in self.parts)
            yield f"{self.where}: {count} parts {', '.join(self.parts[0].own)}"
            rest = []
        else:
            rest = self.parts
        for part in rest:
            yield from part.lines()
        yield from self.extra


def _own_changes(old: dict, new: dict) -> list[str]:
    changes = []
    fields = [*_MOBJECT_FIELDS,
              *sorted((set(old) | set(new)) - {*_MOBJECT_FIELDS, "submobjects"})]
    for field in fields:
        a, b = old.get(field), new.get(field)
        if a == b:
            continue
        if field == "points" and isinstance(a, list) and isinstance(b, list):
            changes.append(_points_change(a, b))
        elif field == "box":
            changes.append(_box_change(a, b))
        elif field == "name":
            changes.append(f"renamed {json.dumps(b, ensure_ascii=False)}")
        elif field == "text":
            changes.append(f"text {json.dumps(a, ensure_ascii=False)} → "
                           f"{json.dumps(b, ensure_ascii=False)}")
        elif field == "type":
            changes.append(f"{_value(a)} → {_value(b)}")
        else:
            changes.append(f"{field} {_value(a)} → {_value(b)}")
    return changes


def _delta(old: dict, new: dict, parent: str, index: int, siblings: list) -> _Delta | None:
    """The changes from one mobject node to another (None: none). ``parent`` says where it
    sits: a word (``mobject``, ``target``, ``final: mobject``) for an animation's or the
    final picture's own mobject, else the path of the mobject it is part of."""
    if old == new:
        return None
    step = _place(old, index, siblings)
    where = f"{parent} {step}" if parent in _TOP else f"{parent} › {step}"
    parts, extra = _children(old.get("submobjects") or [], new.get("submobjects") or [], where)
    return _Delta(where, tuple(_own_changes(old, new)), tuple(parts), tuple(extra))


def _children(old: list, new: list, where: str) -> tuple[list[_Delta], list[str]]:
    """Submobjects (or the final mobjects, ``where`` = ``final: mobject``) lined up by class
    and name: the changes of the pairs, and lines for those added or removed."""
    key = [(_key(n.get("type")), _key(n.get("name"))) if isinstance(n, dict) else _key(n)
           for n in old]
    key_new = [(_key(n.get("type")), _key(n.get("name"))) if isinstance(n, dict) else _key(n)
               for n in new]
    matcher = difflib.SequenceMatcher(None, key, key_new, autojunk=False)
    parts: list[_Delta] = []
    extra: list[str] = []
    for tag, i0, i1, j0, j1 in matcher.get_opcodes():
        if tag in ("equal", "replace"):
            pairs = min(i1 - i0, j1 - j0)
            for k in range(pairs):
                a, b = old[i0 + k], new[j0 + k]
                if isinstance(a, dict) and isinstance(b, dict):
                    delta = _delta(a, b, where, i0 + k, old)
                    if delta is not None:
                        parts.append(delta)
                elif a != b:
                    extra.append(f"{where}: {_value(a)} → {_value(b)}")
            i0, j0 = i0 + pairs, j0 + pairs
        if j1 > j0:
            extra.append(_counted(new[j0:j1], "added", where))
        if i1 > i0:
            extra.append(_counted(old[i0:i1], "removed", where))
    return parts, extra


def _mobject_changes(old: Any, new: Any, parent: str) -> Iterator[str]:
    """An animation's mobject (or target) compared, in lines."""
    if isinstance(old, dict) and isinstance(new, dict):
        delta = _delta(old, new, parent, 0, [old])
        if delta is not None:
            yield from delta.lines()
    elif old != new:
        yield f"{parent} {_value(old)} → {_value(new)}"


def _counted(nodes: list, verb: str, where: str) -> str:
    words = [_short(n) if isinstance(n, dict) else _value(n) for n in nodes[:NAMED]]
    if len(nodes) > NAMED:
        words.append("…")
    top = where == "final: mobject"
    noun = "mobject" if top else "part"
    noun += "" if len(nodes) == 1 else "s"
    return f"{'final' if top else where}: {len(nodes)} {noun} {verb} ({', '.join(words)})"


def _place(node: dict, index: int, siblings: list) -> str:
    """A node's step in a path: its name, or its class (with its place when not unique)."""
    name = _named(node)
    if name is not None:
        return json.dumps(name, ensure_ascii=False)
    kind = str(node.get("type", "?"))
    if isinstance(node.get("text"), str):
        return f"{kind} {json.dumps(node['text'], ensure_ascii=False)}"
    same = [k for k, s in enumerate(siblings) if isinstance(s, dict) and s.get("type") == kind]
    return kind if len(same) <= 1 or index not in same else f"{kind} {same.index(index) + 1}"


def _animation_changes(old: dict, new: dict, where: str, play_times: tuple) -> Iterator[str]:
    """``where`` is empty for a play's only animation, else ``animation 2 (FadeIn x)``: it
    prefixes the animation's own fields; its mobjects' changes name the mobjects."""
    prefix = f"{where} " if where else ""
    if old.get("type") != new.get("type"):
        yield f"{prefix}{_kind(old.get('type'))} → {_kind(new.get('type'))}"
    a, b = old.get("run_time"), new.get("run_time")
    if a != b and (a, b) != play_times:
        yield f"{prefix}run_time {_value(a)} → {_value(b)}"
    for part in ("mobject", "target"):
        if part in old and part in new:
            yield from _mobject_changes(old[part], new[part], part)
        elif part in old or part in new:
            node = old.get(part, new.get(part))
            verb = "removed" if part in old else "added"
            shown = _short(node) if isinstance(node, dict) else _value(node)
            yield f"{prefix}{part} {verb} ({shown})"
    yield from _list_changes(old.get("animations"), new.get("animations"), prefix.strip(),
                             play_times)
    for field in sorted((set(old) | set(new)) - {"type", "run_time", "mobject", "target",
                                                 "animations"}):
        if old.get(field) != new.get(field):
            yield f"{prefix}{field} {_value(old.get(field))} → {_value(new.get(field))}"


def _list_changes(old: Any, new: Any, where: str, play_times: tuple) -> Iterator[str]:
    """Animations (of a play, or of a group) lined up and compared."""
    if old is None and new is None:
        return
    old, new = list(old or []), list(new or [])
    single = len(old) == len(new) == 1 and not where
    matcher = difflib.SequenceMatcher(None, [_signature(a) for a in old],
                                      [_signature(a) for a in new], autojunk=False)
    within = f"{where} " if where else ""
    for tag, i0, i1, j0, j1 in matcher.get_opcodes():
        if tag in ("equal", "replace"):
            pairs = min(i1 - i0, j1 - j0)
            for k in range(pairs):
                a = old[i0 + k]
                name = "" if single else (f"{within}animation {i0 + k + 1} "
                                          f"({_animation_label(a)})")
                yield from _animation_changes(a, new[j0 + k], name, play_times)
            i0, j0 = i0 + pairs, j0 + pairs
        for nodes, verb, at in ((new[j0:j1], "added", j0), (old[i0:i1], "removed", i0)):
            if nodes:
                words = [_animation_label(a) for a in nodes[:NAMED]] + (
                    ["…"] if len(nodes) > NAMED else [])
                noun = "animation" if len(nodes) == 1 else "animations"
                yield (f"{within}{len(nodes)} {noun} {verb} at {at + 1}: "
                       f"{', '.join(words)}")


def _play_changes(old: dict, new: dict) -> Iterator[str]:
    times = (old.get("run_time"), new.get("run_time"))
    for field in _PLAY_FIELDS:
        if old.get(field) != new.get(field):
            yield f"{field} {_value(old.get(field))} → {_value(new.get(field))}"
    yield from _list_changes(old.get("animations"), new.get("animations"), "", times)
    for field in sorted((set(old) | set(new)) - {*_PLAY_FIELDS, "animations"}):
        if old.get(field) != new.get(field):
            yield f"{field} {_value(old.get(field))} → {_value(new.get(field))}"


def _plays_run(plays: list) -> str:
    words = [play_label(p) for p in plays[:NAMED]] + (["…"] if len(plays) > NAMED else [])
    return ", ".join(words)


def _play_differences(old: list, new: list) -> Iterator[Difference]:
    matcher = difflib.SequenceMatcher(None, [_signature({"animations": p.get("animations")})
                                             for p in old],
                                      [_signature({"animations": p.get("animations")})
                                       for p in new], autojunk=False)
    for tag, i0, i1, j0, j1 in matcher.get_opcodes():
        if tag in ("equal", "replace"):
            pairs = min(i1 - i0, j1 - j0)
            for k in range(pairs):
                a, b = old[i0 + k], new[j0 + k]
                if a == b:
                    continue
                number, now = i0 + k + 1, j0 + k + 1
                for what in _play_changes(a, b):
                    yield Difference(number, now if now != number else None, play_label(a),
                                     what)
            i0, j0 = i0 + pairs, j0 + pairs
        if j1 > j0:
            count = j1 - j0
            where = f"after play {i0}" if i0 else "before play 1"
            noun = "play" if count == 1 else "plays"
            yield Difference(None, None, "",
                             f"{count} {noun} added {where}: {_plays_run(new[j0:j1])}")
        if i1 > i0:
            first, last = i0 + 1, i1
            span = f"play {first}" if first == last else f"plays {first}–{last}"
            yield Difference(None, None, "",
                             f"{span} removed: {_plays_run(old[i0:i1])}")


def _grouped(found: Iterable[Difference]) -> list[str]:
    """One line per distinct change, in the order first seen, naming every play it is in."""
    groups: dict[str, list[Difference]] = {}
    for difference in found:
        if difference.play is None:
            groups.setdefault(f"\0{len(groups)}", []).append(difference)
        elif difference.what in groups and difference in groups[difference.what]:
            continue  # the same change twice in one play (two animations of one mobject)
        else:
            groups.setdefault(difference.what, []).append(difference)
    lines = []
    for group in groups.values():
        first = group[0]
        if first.play is None:
            lines.append(first.what)
        elif len(group) == 1:
            now = f", now play {first.now}" if first.now else ""
            lines.append(f"play {first.play} ({first.label}{now}): {first.what}")
        else:
            plays = cast("list[int]", [d.play for d in group])  # grouped: only a play's have a group
            lines.append(f"{_plays_text(plays)}: {first.what}")
    return lines


def differences(old: dict, new: dict) -> list[str]:
    """Every difference from the graph ``old`` (stored, expected) to ``new`` (built), in words;
    empty when they are equal. A graph not shaped as docs/scene-graph.md says (a file edited by
    hand; :func:`malformed`) is compared field by field instead, after a first line saying so:
    ``plays[3].run_time: 1.0 → 1.5``. Any other failure here is a bug, and raises."""
    if old == new:
        return []
    for which, graph in (("stored", old), ("new", new)):
        problem = malformed(graph)
        if problem is not None:
            return [f"the {which} graph is not a scene graph ({problem}): compared field by "
                    "field", *_paths(old, new, "")]
    lines = _grouped(_differences(old, new))
    if not lines:
        raise RuntimeError("trex.graph_diff named no difference between unequal graphs (a bug)")
    return lines


# --- the shape the comparison reads (docs/scene-graph.md) -------------------------------------


def malformed(graph: Any) -> str | None:
    """Where ``graph`` is not shaped as docs/scene-graph.md says, in a few words; None when it
    is. Only the parts the comparison reads are checked: the lists of plays, animations and
    mobjects, and the numbers of points and boxes.

    >>> malformed({"plays": [{"animations": [{"mobject": {"points": [[0, 1]]}}]}]})
    'plays[0].animations[0].mobject.points is not a list of [x, y, z]'
    >>> malformed({"plays": [], "final": [{"type": "Dot", "box": None, "points": []}]}) is None
    True
    """
    if not isinstance(graph, dict):
        return "not an object"
    return (_listed(graph, "plays", "", _play_shape)
            or _listed(graph, "final", "", _mobject_shape))


def _listed(node: dict, key: str, where: str, shape: Any) -> str | None:
    """``node[key]``, if there, as a list whose items have ``shape``."""
    if key not in node:
        return None
    at = f"{where}.{key}" if where else key
    if not isinstance(node[key], list):
        return f"{at} is not a list"
    return next((p for k, item in enumerate(node[key])
                 if (p := shape(item, f"{at}[{k}]")) is not None), None)


def _play_shape(node: Any, where: str) -> str | None:
    if not isinstance(node, dict):
        return f"{where} is not an object"
    return _listed(node, "animations", where, _animation_shape)


def _animation_shape(node: Any, where: str) -> str | None:
    if not isinstance(node, dict):
        return f"{where} is not an object"
    for part in ("mobject", "target"):
        if part in node and (problem := _mobject_shape(node[part], f"{where}.{part}")):
            return problem
    return _listed(node, "animations", where, _animation_shape)


def _numbers(value: Any, count: int) -> bool:
    return (isinstance(value, list) and len(value) == count
            and all(isinstance(v, int | float) and not isinstance(v, bool) for v in value))


def _mobject_shape(node: Any, where: str) -> str | None:
    if not isinstance(node, dict):
        return f"{where} is not an object"
    points = node.get("points", [])
    if not (isinstance(points, list) and all(_numbers(p, 3) for p in points)):
        return f"{where}.points is not a list of [x, y, z]"
    if node.get("box") is not None and not _numbers(node["box"], 4):
        return f"{where}.box is not [x0, y0, x1, y1]"
    return _listed(node, "submobjects", where, _mobject_shape)


def _differences(old: dict, new: dict) -> list[Difference]:
    found: list[Difference] = []
    for key in sorted((set(old) | set(new)) - {"plays", "final"}):
        if old.get(key) != new.get(key):
            found.append(Difference(None, None, "",
                                    f"{key} {_value(old.get(key))} → {_value(new.get(key))}"))
    found.extend(_play_differences(list(old.get("plays") or []), list(new.get("plays") or [])))
    final_old, final_new = list(old.get("final") or []), list(new.get("final") or [])
    if final_old != final_new:
        parts, extra = _children(final_old, final_new, "final: mobject")
        found.extend(Difference(None, None, "", what)
                     for what in [*(line for p in parts for line in p.lines()), *extra])
    return found


def _paths(old: Any, new: Any, path: str) -> Iterator[str]:
    """The plain differences of two JSON values, by path."""
    if isinstance(old, dict) and isinstance(new, dict):
        for key in sorted(set(old) | set(new), key=str):
            if old.get(key) != new.get(key):
                yield from _paths(old.get(key), new.get(key), f"{path}.{key}" if path else key)
    elif isinstance(old, list) and isinstance(new, list) and len(old) == len(new):
        for k, (a, b) in enumerate(zip(old, new, strict=True)):
            if a != b:
                yield from _paths(a, b, f"{path}[{k}]")
    elif old != new:
        yield f"{path or 'the graph'}: {_value(old)} → {_value(new)}"


def report(old: dict, new: dict, limit: int = LIMIT) -> list[str]:
    """:func:`differences`, at most ``limit`` lines and then how many more there are."""
    lines = differences(old, new)
    if len(lines) > limit:
        rest = len(lines) - limit
        lines = [*lines[:limit], f"… and {rest} more difference{'s' if rest > 1 else ''}"]
    return lines
