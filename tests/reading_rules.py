"""Issue 12's rules for what a viewer reads, checked on a scene graph (dry run, no timing):
every cue of the ``.srt`` at least 0.83 s and at most 17 characters per second
(:func:`story.reading.readable`), every visible text's letters at least 2.5 % of the frame's
height (:data:`LEAST_LINE`, by their capitals). The test modules of the scenes and of the
lecture apply them."""

from __future__ import annotations

import ast
import itertools
import json
import math
import re
from collections.abc import Iterator
from itertools import pairwise
from typing import Any

from story.reading import readable

#: 2.5 % of the frame's height (8 units): the least a text's letters may stand, measured by its
#: capitals (:func:`letter_height`; 27 px at 1080p, 12 px at 480p)
LEAST_LINE = 0.2


def mobject_nodes(node: dict) -> Iterator[dict]:
    """A mobject node and all its parts."""
    yield node
    for child in node.get("submobjects", ()):
        yield from mobject_nodes(child)


def animation_nodes(node: dict) -> Iterator[dict]:
    """Every mobject node of an animation's graph: its mobject, its target, its members'."""
    for key in ("mobject", "target"):
        if key in node:
            yield from mobject_nodes(node[key])
    for child in node.get("animations", ()):
        yield from animation_nodes(child)


def graph_nodes(data: dict, *, final_only: bool = False) -> Iterator[dict]:
    """Every mobject node of a graph's data: the animations' mobjects and targets, then the
    mobjects on screen at the end."""
    if not final_only:
        for play in data["plays"]:
            for anim in play["animations"]:
                yield from animation_nodes(anim)
    for mobject in data.get("final", ()):
        yield from mobject_nodes(mobject)


def drawn(node: dict) -> bool:
    """Whether a text node is drawn: filled, or a written text (``GlyphText``: a title, whose
    fill is its glyphs', which the graph does not list, not the group's)."""
    return (node.get("fill_opacity") or 0) > 0 or node.get("type") == "GlyphText"


def unreadable_cues(data: dict) -> list[str]:
    """The cues too short or too fast to read, as ``"1.20 s, 41 cps: …"``."""
    bad = []
    for cue in data["cues"]:
        seconds = cue["end"] - cue["start"]
        if not readable(cue["text"], seconds):
            cps = len(cue["text"]) / seconds if seconds > 0 else float("inf")
            bad.append(f"{seconds:.2f} s, {cps:.0f} cps: {cue['text']}")
    return bad


def letter_height(node: dict) -> float | None:
    """How tall a text node's letters stand as drawn: its capitals, or its tallest glyphs where
    they are shorter (``cap``: :func:`rendering.typeset.letter_height`), None where the graph
    does not say. Not its box: a box holds descenders, brackets above the capitals, and for a
    text of several lines the gaps between them (a box over its lines passed rows whose
    capitals were 2.3 % of the frame)."""
    return node.get("cap")


def small_texts(data: dict) -> list[str]:
    """The visible texts whose letters stand under :data:`LEAST_LINE`, as ``"name 'text'
    0.150"``, and those whose letters the graph does not measure (``"… no cap"``: a size
    unread is no size checked)."""
    small: dict[tuple[str, str], float] = {}
    unmeasured: set[tuple[str, str]] = set()
    for node in graph_nodes(data):
        if node.get("box") is None or not node.get("text", "").strip():
            continue
        if not drawn(node):
            continue
        height, key = letter_height(node), (node["name"], node["text"])
        if height is None:
            unmeasured.add(key)
        elif height < LEAST_LINE:  # the smallest it is drawn at
            small[key] = min(height, small.get(key, height))
    return ([f"{name} {text!r} {h:.3f}" for (name, text), h in sorted(small.items())]
            + [f"{name} {text!r} no cap" for name, text in sorted(unmeasured)])


#: the animations that take a mobject off the screen, and those that put one on
OUTGOING = {"FadeOut", "Uncreate", "Unwrite", "ShrinkToCenter"}
#: ``Add``, ``Replace`` (:class:`metaphors.fruit.Replace`: the one it replaces goes in the
#: same frame): a cut, the mobject on screen from the play's first frame (ear clipping's counts)
INCOMING = {"FadeIn", "Write", "Create", "AddTextLetterByLetter", "GrowFromCenter", "Add",
            "Replace"}


def _text_of(node: dict) -> str:
    """A text node's text, or its lines' joined (a text wrapped to two lines is a group of
    them, with no text of its own)."""
    if node.get("text") is not None:
        return node["text"]
    return " ".join(t for part in node.get("submobjects", ()) if (t := _text_of(part)))


def _played_texts(anim: dict, name: str) -> Iterator[tuple[str, str]]:
    """(animation type, text) of every text named ``name`` an animation (or its members)
    plays (a wrapped one's lines joined)."""
    mobject = anim.get("mobject") or {}
    if mobject.get("name") == name and _text_of(mobject).strip():
        yield anim["type"], _text_of(mobject)
    for child in anim.get("animations", ()):
        yield from _played_texts(child, name)


def crossfaded_texts(data: dict, name: str) -> list[str]:
    """The plays that take one text named ``name`` off while putting the next on (the two on
    screen at once, one over the other), as ``"play 12: 'old' → 'new'"``."""
    found = []
    for k, play in enumerate(data["plays"]):
        played = [pair for anim in play["animations"] for pair in _played_texts(anim, name)]
        gone = [text for kind, text in played if kind in OUTGOING]
        come = [text for kind, text in played if kind in INCOMING]
        if gone and come:
            found.append(f"play {k}: {gone[0]!r} → {come[0]!r}")
    return found


def refaded_texts(data: dict, name: str) -> list[str]:
    """The plays that fade in a text named ``name`` saying what the one on screen says, as
    ``"play 14: 'nearest_to(B, [D, E]) → D'"``: the line is cut and comes again, a flicker
    (each of the water's, the hand's and the line's beats of one call did so with the call
    line). A text faded out since may come back."""
    found = []
    shown: str | None = None
    for k, play in enumerate(data["plays"]):
        for kind, text in (pair for anim in play["animations"]
                           for pair in _played_texts(anim, name)):
            if kind in OUTGOING:
                shown = None
            elif kind in INCOMING:
                if text == shown:
                    found.append(f"play {k}: {text!r}")
                shown = text
    return found


def crossfaded_subtitles(data: dict) -> list[str]:
    """Issue 22 item 9: the plays that take one subtitle off while putting the next on (two
    subtitles on screen at once), as ``"play 12: 'old' → 'new'"``. A caption goes before the
    next comes: a cut, or a play that takes it off and then one that puts the next on."""
    return crossfaded_texts(data, "subtitle")


def _text_boxes(anim: dict, kinds: set[str]) -> Iterator[tuple[str, tuple[float, ...]]]:
    """(text, box) of every drawn text an animation of one of ``kinds`` (or its members')
    plays, its parts' too."""
    if anim["type"] in kinds:
        for node in mobject_nodes(anim.get("mobject") or {}):
            if (node.get("text") or "").strip() and node.get("box") and (
                    drawn(node) or node.get("type") == "FlatText"):
                yield node["text"], tuple(node["box"])
    for child in anim.get("animations", ()):
        yield from _text_boxes(child, kinds)


def crossfaded_overlaps(data: dict) -> list[str]:
    """The plays that fade a text out while fading another in over it (the two read as one,
    as a count coming where the black box's question goes), as
    ``"play 80: 'an inner' under 'n − 2 = 13 − 2'"``: a text goes before the next comes."""
    found = []
    for k, play in enumerate(data["plays"]):
        gone = [t for a in play["animations"] for t in _text_boxes(a, OUTGOING)]
        come = [t for a in play["animations"] for t in _text_boxes(a, INCOMING)]
        found += [f"play {k}: {old!r} under {new!r}" for old, a in gone for new, b in come
                  if old != new and a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]]
    return found


def words_before_pictures(data: dict) -> list[str]:
    """Issue 22: the runs whose first subtitle comes up in a play before the one that writes
    their title and draws their picture (the words a second ahead of what they speak of), as
    ``"play 71: 'The frame as before: …' before 'Rotation on …'"``: since the screen was last
    cleared (a play of fades out only), no subtitle before the title."""
    found, said = [], None
    for k, play in enumerate(data["plays"]):
        kinds = {a["type"] for a in play["animations"]}
        if kinds and kinds <= OUTGOING:
            said = None
            continue
        titles = [t for a in play["animations"] for t in _played_texts(a, "title")]
        if titles and said is not None:
            found.append(f"play {said[0]}: {said[1]!r} before {titles[0][1]!r}")
        if titles:
            said = None
        elif said is None:
            subtitles = [t for a in play["animations"] for _, t in _played_texts(a, "subtitle")]
            if subtitles:
                said = (k, subtitles[0])
    return found


# --- issue 22 item 10: the words ------------------------------------------------------------------

#: the command line's names that are no English word: every hyphenated registry name, and
#: the lower-case names of the heuristics the thesis capitalises (``gravity`` and
#: ``monotone`` are words a caption may use: "gravity points down", "y-monotone")
_SLUG_WORDS = ("scaling", "rotation", "translation", "cdt")
#: code on screen: an identifier with an underscore, a call, an arrow to a result, an index
#: list, an elided dict, a Python truth value, the command's name
_CODE = re.compile(r"\b[A-Za-z]\w*_\w+|\b[a-z]\w*\(|→|\[\s*\[?\s*-?\d|\{…\}|\b(?:True|False|None)\b"
                   r"|\btrex\b")
#: a number with more than one decimal
_LONG_NUMBER = re.compile(r"\d\.\d\d")


def _slug_pattern() -> re.Pattern:
    from story.registry import names

    slugs = sorted({n for n in names() if "-" in n} | set(_SLUG_WORDS), key=len, reverse=True)
    return re.compile(r"(?<![\w-])(?:" + "|".join(map(re.escape, slugs)) + r")(?![\w-])")


def _shown_texts(node: dict, skip: frozenset[str]) -> Iterator[str]:
    """The drawn texts of a node and its parts, leaving out the subtrees named in ``skip``."""
    if node.get("name") in skip:
        return
    if (node.get("text") or "").strip() and drawn(node):
        yield node["text"]
    for child in node.get("submobjects", ()):
        yield from _shown_texts(child, skip)


def _all_shown_texts(data: dict, skip: frozenset[str]) -> Iterator[str]:
    def tops(anim: dict) -> Iterator[dict]:
        for key in ("mobject", "target"):
            if key in anim:
                yield anim[key]
        for child in anim.get("animations", ()):
            yield from tops(child)

    for play in data["plays"]:
        for anim in play["animations"]:
            for top in tops(anim):
                yield from _shown_texts(top, skip)
    for mobject in data.get("final", ()):
        yield from _shown_texts(mobject, skip)
    for cue in data.get("cues", ()):
        yield cue["text"]
    for play in data["plays"]:
        if play.get("subcaption"):
            yield play["subcaption"]


def unspoken_words(data: dict, *, call_line: bool = False) -> list[str]:
    """Issue 22 item 10: the texts on screen (and the cues) that use the command line's
    slugs, show code, or a number with two decimals, as ``"slug: 'scaling on …'"``.
    ``call_line``: the panel's call line is allowed (``trex render`` and the player keep it,
    a programmer wants the real call) and not read."""
    skip = frozenset({"panel:call"} if call_line else ())
    slug, found = _slug_pattern(), {}
    for text in _all_shown_texts(data, skip):
        for kind, pattern in (("slug", slug), ("code", _CODE), ("number", _LONG_NUMBER)):
            if pattern.search(text):
                found.setdefault(f"{kind}: {text!r}", None)
    return sorted(found)


#: 4 % of the frame's height: the least of a wrong claim that must be seen outside P
LEAST_OUTSIDE = 0.32
#: 3 % of the frame's height: the least gap between a red claim and a vertex not its own, so
#: that it is seen to cross an edge, not to pass through the vertex
LEAST_CLEARANCE = 0.24
#: the colour of what is rejected (metaphors.theme.THEME.rejected), as the graph writes it
_REJECTED = "#EF4B4B"
#: the names of the claims drawn (a run's, an analysis's, an exercise's answer) and of the
#: polygons they are drawn on
_CLAIMS = ("claim", "analysis:claim", "answer:diagonal")
_POLYGONS = ("polygon", "analysis:polygon")


def _corners(node: dict) -> list[tuple[float, float]]:
    """The corners of a polygon node: the first point of every cubic segment."""
    return [(x, y) for x, y, _ in node["points"][::4]]


def _near(p: tuple[float, float], corners: list[tuple[float, float]], within: float = 1e-3) -> bool:
    return any(abs(p[0] - x) < within and abs(p[1] - y) < within for x, y in corners)


def hidden_failures(data: dict) -> list[str]:
    """Issue 22 items 3 and 6: the red (rejected) claims (a run's, an analysis's, a card's
    figure's: the recap's BD was not measured), and exercises' rejected diagonals, whose part
    outside their polygon is under
    :data:`LEAST_OUTSIDE` on screen, as ``"claim (x, y)–(x, y): 0.14 outside"``, or which
    pass nearer than :data:`LEAST_CLEARANCE` to a vertex not their own. A claim is
    matched to the drawn polygon that has both its ends as corners; one with no such polygon
    is reported too, so that a claim drawn elsewhere cannot pass unmeasured."""
    from shapely.geometry import LineString
    from shapely.geometry import Point as ShapelyPoint
    from shapely.geometry import Polygon as Region

    nodes = list(graph_nodes(data))
    polygons = [_corners(n) for n in nodes if n.get("points") and (
        n.get("name") in (*_POLYGONS, "figure:polygon")
        or (n.get("name"), n["type"]) == ("exercise", "Polygon"))]
    found = {}
    for node in nodes:
        # a card's figure's too: the overview's "DI leaves P" is seen to leave it
        if node.get("name") not in (*_CLAIMS, "figure:claim"):
            continue
        # a card's claim is a line on a dark casing: the line is its last part
        line = node if node.get("points") else next(
            (c for c in reversed(node.get("submobjects", ())) if c.get("points")), {})
        if (line.get("stroke") or "").upper() != _REJECTED:
            continue
        a, b = (tuple(line["points"][k][:2]) for k in (0, -1))
        # the polygon itself, not an exercise's triangle T drawn on it
        home = sorted((c for c in polygons if _near(a, c) and _near(b, c)), key=len,
                      reverse=True)
        where = f"claim ({a[0]:g}, {a[1]:g})–({b[0]:g}, {b[1]:g})"
        if not home:
            found[where] = "no polygon has both its ends"
            continue
        outside = LineString([a, b]).difference(Region(home[0])).length
        gap = min((LineString([a, b]).distance(ShapelyPoint(q)) for q in home[0]
                   if not (_near(q, [a]) or _near(q, [b]))), default=float("inf"))
        if outside < LEAST_OUTSIDE:
            found[where] = f"{outside:.2f} outside"
        elif gap < LEAST_CLEARANCE:
            found[where] = f"{gap:.2f} from a vertex: it looks as if it passes through"
    return [f"{where}: {what}" for where, what in sorted(found.items())]


#: issue 22 item 6: the least time a question stays up, counted down, before its answer
LEAST_THINKING = 15.0


def rushed_questions(data: dict) -> list[str]:
    """The exercise questions whose answer's cue starts under :data:`LEAST_THINKING` after
    the question's own, as ``"3.2 s: Which vertex …"``; the cues are what the ``.srt`` says
    (the question's cue is the question, the next cue its answer)."""
    cues = data["cues"]
    questions = {n["text"].split(". ", 1)[-1] for n in graph_nodes(data)
                 if n.get("name") == "exercise" and n.get("text")}
    found = []
    for cue, after in pairwise(cues):
        if cue["text"] in questions and after["start"] - cue["start"] < LEAST_THINKING:
            found.append(f"{after['start'] - cue['start']:.1f} s: {cue['text']}")
    return found


def _box_of(node: dict) -> tuple[float, float, float, float] | None:
    """A node's box on screen with all its parts: ``(left, bottom, right, top)``."""
    boxes = [n["box"] for n in mobject_nodes(node) if n.get("box")]
    boxes += [(x, y, x, y) for n in mobject_nodes(node) for x, y, _ in n.get("points", ())]
    if not boxes:
        return None
    return (min(b[0] for b in boxes), min(b[1] for b in boxes),
            max(b[2] for b in boxes), max(b[3] for b in boxes))


def _overlap(a: tuple[float, ...], b: tuple[float, ...]) -> bool:
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def answers_over_pictures(data: dict) -> list[str]:
    """Issue 22 item 6: the answers written over their exercise's polygon (its outline and
    vertex labels, not the title and legend lines), as ``"Answer: G — …"``."""
    found = []
    picture: list[tuple[float, ...]] = []
    for play in data["plays"]:
        for anim in play["animations"]:
            node = anim.get("mobject", {})
            if anim.get("type") in OUTGOING:
                continue  # the screen cleared: what leaves is not drawn over
            if node.get("name") == "exercise" and node.get("text"):
                continue  # the title and the legend: lines of their own, above and below
            if node.get("name") == "exercise" and (box := _box_of(node)):
                picture.append(box)
            elif node.get("name") == "answer" and (box := _box_of(node)):
                text = " ".join(n["text"] for n in mobject_nodes(node) if n.get("text"))
                if any(_overlap(box, p) for p in picture):
                    found.append(text)
                picture = []
    return found


_SLICES = re.compile(r"(\d+) / (\d+) slices$")
_RESULT = re.compile(r"= (\d+) triangles$")


def broken_counts(data: dict) -> list[str]:
    """Issue 22 item 5: the slice counts that do not run 0, 1 … n − 2 one by one, or that end
    without the whole triangulation drawn and its ``… = n − 2 triangles``, as
    ``"0 1 3 … / 11 → 11"``; and a count said (``… = 11 triangles``) that is not the number of
    triangles drawn. A count is each counter shown, in order (a new run starts at 0)."""
    shown = [n["text"] for play in data["plays"] for anim in play["animations"]
             if anim["type"] in INCOMING and (n := anim.get("mobject", {})).get("name")
             == "counter"]
    runs: list[tuple[list[int], int, str | None]] = []
    for text in shown:
        if (m := _SLICES.search(text)) is not None:
            k, total = int(m[1]), int(m[2])
            if k == 0 or not runs or runs[-1][2] is not None:
                runs.append(([], total, None))
            runs[-1][0].append(k)
        elif (m := _RESULT.search(text)) is not None and runs:
            runs[-1] = (runs[-1][0], runs[-1][1], m[1])
    drawn = sum(1 for play in data["plays"] for anim in play["animations"]
                if anim["type"] in INCOMING
                and anim.get("mobject", {}).get("name") == "triangulation")
    found = []
    for ks, total, result in runs:
        if ks != list(range(total + 1)) or result != str(total):
            found.append(f"{' '.join(map(str, ks))} / {total} → {result}")
    said = sum(int(m[1]) for text in shown if (m := _RESULT.search(text)) is not None)
    if drawn != said or drawn < sum(total for _, total, _ in runs):
        found.append(f"{drawn} triangles drawn, {said} said")
    return found


def flickering_counts(data: dict) -> list[str]:
    """The counts (``"3 / 11 slices"``, the whole count after them) that come in otherwise
    than by a cut from the count of their run before them, as ``"play 134: FadeIn '2 / 11
    slices' after '1 / 11 slices'"``: a fade starts from nothing, so for its first frames no
    count is on screen (at the fast steps' pace, two frames of three at -ql: the count
    flickered and was gone at 98 s in chapter 4), and an ``Add`` comes after the one before
    was taken off unseen by the graph, maybe plays before (11 / 11 was taken off before the
    wait that held its caption, gone for 1.6 s). A count replacing a count comes by
    ``Replace`` (:class:`metaphors.fruit.Replace`: the old one off in the same frame); a
    run's first count may fade in. A run starts where its polygon is drawn (``Create``) or
    its count starts again at 0."""
    found = []
    before: str | None = None
    for k, play in enumerate(data["plays"]):
        for anim in play["animations"]:
            node = anim.get("mobject") or {}
            if node.get("name") == "polygon" and anim["type"] == "Create":
                before = None
            if node.get("name") != "counter" or anim["type"] not in INCOMING:
                continue
            text = _text_of(node)
            if (m := _SLICES.search(text)) is not None and int(m[1]) == 0:
                before = None
            if before is not None and anim["type"] != "Replace":
                found.append(f"play {k}: {anim['type']} {text!r} after {before!r}")
            before = text
    return found


#: the most of a good sub-polygon's tint that may lie off the fruit (square units: rounding)
MOST_GOOD_OFF = 0.02
#: the names of ear clipping's keyhole cuts (:func:`metaphors.fruit.keyhole`)
_KEYHOLE = "keyhole:"


def _region(node: dict):
    """A drawn polygon's region (its rings: the largest, less the others)."""
    from shapely.geometry import Polygon as Region

    rings = sorted((Region(c).buffer(0) for c in _paths(node)), key=lambda r: -r.area)
    if not rings:
        return None
    region = rings[0]
    for hole in rings[1:]:
        region = region.difference(hole)
    return region


def stale_good_parts(data: dict) -> list[str]:
    """Prune and search's good sub-polygon (its tint, named ``good``) lying over no fruit
    (the polygon as it stands: ear clipping's fruit shrinks as slices are cut), as ``"play
    177: 1.23 off the fruit"`` or ``"play 177: over no fruit"``: the good part shrinks with
    the fruit (the slices are cut from it) and goes when only its cutting edge is left; in
    chapter 4 the tint A-B-G-H stayed while its slices lay on the plate and the fruit was
    gone. Judged after each play where both were last seen the same way (a turn of the
    picture leaves their places unknown until each is drawn again). Likewise a keyhole cut
    (``keyhole:1``) left with no fruit round it, as ``"play 280: keyhole:1 over no fruit"``:
    chapter 4's green c₁–F floated alone after the last slice."""
    unknown = object()
    fruit: object = None
    good: object = None
    found, said = [], ""  # each stale span once, at its first play
    cuts: set[str] = set()  # the keyhole cuts shown
    for k, play in enumerate(data["plays"]):
        for anim in play["animations"]:
            node = anim.get("mobject") or {}
            name = node.get("name")
            if (name or "").startswith(_KEYHOLE):
                (cuts.discard if anim["type"] in OUTGOING else cuts.add)(name)
            if name not in ("polygon", "good"):
                continue
            if name == "polygon" and anim["type"] == "Create":  # a run starts
                good, cuts = None, set()
            if anim["type"] in OUTGOING:
                shape = None
            elif anim["type"] == "Turn":
                shape = unknown
            else:
                shape = _region(anim.get("target") or node)
            if name == "polygon":
                fruit = shape
            else:
                good = shape
        if fruit is None and cuts:
            found.append(f"play {k}: {', '.join(sorted(cuts))} over no fruit")
            cuts = set()  # each cut once
        if good is None or good is unknown or fruit is unknown:
            said = ""
            continue
        words = ""
        if fruit is None:
            words = "over no fruit"
        elif (off := good.difference(fruit).area) > MOST_GOOD_OFF:  # type: ignore[attr-defined]
            words = f"{off:.2f} off the fruit"
        if words and words != said:
            found.append(f"play {k}: {words}")
        said = words
    return found


#: issue 22 item 7: the most of a lecture's time its screen may be text alone (cards)
MOST_TEXT_ONLY = 0.10


def text_only_seconds(data: dict) -> tuple[float, float]:
    """The seconds a graph shows a card of text alone (text on black: from its title's coming
    to its going; not a card with a figure) and its whole length."""
    total = text_only = 0.0
    showing = False
    for play in data["plays"]:
        names = {(a["type"], a.get("mobject", {}).get("name")) for a in play["animations"]}
        if any(kind in INCOMING and name == "card:title" for kind, name in names):
            # a card that draws its idea beside its words is not text alone
            showing = not any(kind in INCOMING and (name or "").startswith("figure:")
                              for kind, name in names)
        if any(kind in OUTGOING and name == "card:title" for kind, name in names):
            showing = False
        total += play["run_time"]
        text_only += play["run_time"] if showing else 0.0
    return text_only, total


def _card_text(node: dict) -> str:
    return " ".join(t for part in mobject_nodes(node) if (t := (part.get("text") or "").strip()))


def unreadable_cards(data: dict) -> list[str]:
    """The cards of a scene (``card``: a run's number and title on black) up for less than
    their words take to read (:func:`story.reading.readable`: 17 characters a second, 0.83 s
    at least), from the play that brings one in to the one that takes it off, as ``"0.80 s,
    60 cps: '1 / 8 Scaling fails: …'"``: the counterexample scene's cards of 34–48
    characters stood 0.6–0.8 s."""
    found, shown = [], None
    clock = 0.0
    for play in data["plays"]:
        for anim in play["animations"]:
            node = anim.get("mobject") or {}
            if node.get("name") != "card":
                continue
            if anim["type"] in INCOMING:
                shown = (clock, _card_text(node))
            elif anim["type"] in OUTGOING and shown is not None:
                seconds = clock + play["run_time"] - shown[0]
                if not readable(shown[1], seconds):
                    found.append(f"{seconds:.2f} s, {len(shown[1]) / seconds:.0f} cps: "
                                 f"{shown[1]!r}")
                shown = None
        clock += play["run_time"]
    return found


def captions_said_again(data: dict) -> list[str]:
    """The captions a graph says more than once, as ``"3 × '✗ BD is not an inner diagonal:
    BD crosses edge E–A'"``: the counterexample scene said its ✗ ending three times and "The
    frame as before" seven, over other runs each time."""
    counts: dict[str, int] = {}
    for cue in data["cues"]:
        counts[cue["text"]] = counts.get(cue["text"], 0) + 1
    return [f"{n} × {text!r}" for text, n in counts.items() if n > 1]


#: what a caption says to speak of the picture the viewer saw just before
_AS_BEFORE = re.compile(r"\bas before\b|\bthe same (?:polygon|frame|picture)\b", re.IGNORECASE)


def false_as_before(data: dict) -> list[str]:
    """The captions that speak of the picture shown before ("The frame as before", "on the
    same polygon") said over a polygon just drawn that is not the one drawn before it, as
    ``"'The frame as before: candidates D, E' over another polygon"``: the counterexample
    scene said it as the mirror image gave way to the polygon (62 s), and the polygon to the
    mirror image (96 s)."""
    found, drawn, fresh = [], [], False
    for play in data["plays"]:
        for anim in play["animations"]:
            node = anim.get("mobject") or {}
            if anim["type"] in INCOMING and node.get("name") in _RUN_POLYGONS and node.get("points"):
                drawn.append([tuple(round(c, 3) for c in p[:2]) for p in node["points"]])
                fresh = True
        caption = play.get("subcaption")
        if caption:
            if _AS_BEFORE.search(caption) and fresh and (len(drawn) < 2 or drawn[-1] != drawn[-2]):
                found.append(f"{caption!r} over another polygon")
            fresh = False
    return found


#: the tools that move to their pick, by the names of their drawings, and the animations that
#: move them (a play of waits only is the picture standing still)
_MOVING_TOOLS = ("water", "flood", "hand", "sweep")
_MOVES = ("UpdateFromAlphaFunc", "Rotate", "_MethodAnimation", "Transform")


def rushed_tools(data: dict) -> list[str]:
    """The captions under which a tool moves to its pick for less time than the picture then
    stands still, as ``"'Water spilled …': moves 0.77 s, still 2.47 s"``: the counterexample
    scene's water covered all of T in 0.8 s and stood still 2.5 s (8.7–9.5 s), its clock hand
    likewise (21.3–22.9 s)."""
    found: list[str] = []
    spans: list[tuple[str, float, float]] = []
    caption, moving, still = None, 0.0, 0.0
    for play in data["plays"]:
        if play.get("subcaption"):
            if caption is not None:
                spans.append((caption, moving, still))
            caption, moving, still = play["subcaption"], 0.0, 0.0
        kinds = [(a["type"], (a.get("mobject") or {}).get("name")) for a in play["animations"]]
        if any(kind in _MOVES and name in _MOVING_TOOLS for kind, name in kinds):
            moving += play["run_time"]
        elif kinds and all(kind == "Wait" for kind, _ in kinds):
            still += play["run_time"]
    if caption is not None:
        spans.append((caption, moving, still))
    for caption, moving, still in spans:
        if moving > 0 and still > moving:
            found.append(f"{caption!r}: moves {moving:.2f} s, still {still:.2f} s")
    return found


# --- issue 22 item 4: one picture per idea ----------------------------------------------------

#: the polygons a run or an analysis draws its steps on (a card's figure is no run)
_RUN_POLYGONS = ("polygon", "analysis:polygon")


def _shape(node: dict) -> tuple[tuple[float, float], ...]:
    """A drawn polygon's shape wherever, however large and however turned it is drawn: each
    corner's edge over the perimeter and its turn (degrees), rounded, from the corner that
    makes the least tuple (a run and an analysis draw one polygon in different boxes, and
    gravity's analysis draws it turned as its run left it)."""
    corners = _corners(node)
    n = len(corners)
    edges = [math.dist(corners[k], corners[(k + 1) % n]) for k in range(n)]
    perimeter = max(sum(edges), 1e-9)

    def turn(k: int) -> float:
        (ax, ay), (bx, by), (cx, cy) = corners[k - 1], corners[k], corners[(k + 1) % n]
        return math.degrees(math.atan2((bx - ax) * (cy - by) - (by - ay) * (cx - bx),
                                       (bx - ax) * (cx - bx) + (by - ay) * (cy - by)))

    form = [(round(edges[k] / perimeter, 2), round(turn(k))) for k in range(n)]
    return min(tuple(form[k:] + form[:k]) for k in range(n))


#: a step's picture is what it brings on screen, wherever its run is drawn: an analysis that
#: plays a run again names its copies ``analysis:…``
_COPY = "analysis:"


def _box_of_polygon(node: dict) -> tuple[float, float, float]:
    corners = _corners(node)
    x0, y0 = min(x for x, _ in corners), min(y for _, y in corners)
    return x0, y0, max(max(x for x, _ in corners) - x0, max(y for _, y in corners) - y0, 1e-9)


def _drawn(node: dict, box: tuple[float, float, float] | None) -> tuple:
    """What a mobject shows, wherever its run is drawn: its name (an analysis's copy named as
    the original), its text and its points over its run's polygon's box, rounded."""
    x0, y0, size = box or (0.0, 0.0, 1.0)
    points = tuple((round((x - x0) / size, 2), round((y - y0) / size, 2))
                   for n in mobject_nodes(node) for x, y, _ in n.get("points", ()))
    texts = tuple(n["text"] for n in mobject_nodes(node) if n.get("text"))
    return (node.get("name") or "").removeprefix(_COPY), texts, points


def _raw(node: dict) -> str:
    return json.dumps([node.get("name"), node.get("text"), node.get("points"),
                       [_raw(n) for n in node.get("submobjects", ())]])


def _changes(anim: dict) -> Iterator[tuple[dict | None, dict | None]]:
    """(what leaves the screen, what comes on) for an animation and its members: a mobject
    that comes in, one that goes, one a transform (or ``.animate``) turns into its target."""
    node = anim.get("mobject") or None
    if "target" in anim:
        yield node, anim["target"]
    elif anim.get("type") in INCOMING and node:
        yield None, node
    elif anim.get("type") in OUTGOING and node:
        yield node, None
    for child in anim.get("animations", ()):
        yield from _changes(child)


Step = tuple[str, tuple | None, str, frozenset]


def shown_steps(data: dict) -> list[Step]:
    """Each caption of a graph as ``(section, shape, caption, picture)``: the card whose
    title opened the section it is said in (a chapter's heuristic is its card and what
    follows, up to the next card; in a scene with no card, a run's title opens one), the shape of the run's polygon it is said over — the last
    one drawn by the end of its step (a step's polygon may be drawn just after its caption) —
    and what is on screen at the end of its step (each mobject as :func:`_drawn`, placed on
    its run's polygon's box; the subtitle left out: the caption is the step)."""
    steps: list[Step] = []
    section, shape, box, open_step, carded = "", None, None, None, False
    screen: dict[str, tuple] = {}  # each mobject on screen, by what it is: as it is drawn

    def close() -> None:
        if open_step is not None:
            steps.append((open_step[0], shape, open_step[1], frozenset(screen.values())))

    for play in data["plays"]:
        tops = [(a["type"], a.get("mobject", {})) for a in play["animations"]]
        if play.get("subcaption"):  # the step before ends
            close()
        if any(kind in INCOMING and node.get("name") == "card:title" for kind, node in tops):
            section, shape, box, carded = play.get("subcaption") or "", None, None, True
        titles = [node["text"] for kind, node in tops
                  if kind in INCOMING and node.get("name") == "title" and node.get("text")]
        if titles and not carded:  # a scene of several runs: each run's title opens one
            section = titles[0]
        if play.get("subcaption"):
            open_step = (section, play["subcaption"])
        for kind, node in tops:
            if kind in INCOMING and node.get("name") in _RUN_POLYGONS and node.get("points"):
                shape, box = _shape(node), _box_of_polygon(node)
        for anim in play["animations"]:
            for gone, come in _changes(anim):
                if gone is not None:
                    screen.pop(_raw(gone), None)
                if come is not None and come.get("name") != "subtitle":
                    screen[_raw(come)] = _drawn(come, box)
    close()
    return steps


#: how many beats in a row, said again in order over one polygon, are its run told again
#: (two are not: divide and conquer says "Split …" then "Find an inner diagonal …" per piece)
TOLD_AGAIN = 3


def replayed_beats(data: dict) -> list[str]:
    """Issue 22 item 4: the runs' beats shown twice, as ``"'caption' (section)"``. A run is a
    polygon drawn in a card's section; its beats are the captions said over it
    (:func:`shown_steps`). A beat is replayed when the same caption is said again over a
    polygon of the same shape in one section *and* the same picture is on screen at its
    end (the run, or an analysis that plays it again) — or when it ends
    :data:`TOLD_AGAIN` captions in a row said again in that order over the same shape in
    that section, however they are drawn: the run told again (review r34: gravity's "why
    the band is always right" retold turn, fall, slide and snag word for word over its own
    drawing of the polygon). One step's caption said over each
    piece of divide and conquer, each batch of a fast summary, or one claim of several
    heuristics on one polygon, is no replay: each time something else is on screen (another
    piece, another diagonal, another metaphor)."""
    seen: set[Step] = set()
    told: set[tuple] = set()  # (section, shape, TOLD_AGAIN captions in a row)
    found: list[str] = []
    said: list[str] = []
    for step in shown_steps(data):
        section, shape, caption, _ = step
        said = [*said, caption][-TOLD_AGAIN:]
        run = (section, shape, *said) if len(said) == TOLD_AGAIN else None
        if shape is not None and (step in seen or run in told):
            found.append(f"{caption!r} ({section})")
        seen.add(step)
        if run is not None:
            told.add(run)
    return found


def repeated_verdicts(data: dict) -> list[str]:
    """Issue 22 item 4: the ✗ captions said more than once in a section (a heuristic's card
    and what follows; in a scene, a run's title and what follows), as ``"2 × '✗ BD …' (section)"``."""
    counts: dict[tuple[str, str], int] = {}
    for section, _, caption, _ in shown_steps(data):
        if caption.startswith("✗"):
            counts[(section, caption)] = counts.get((section, caption), 0) + 1
    return [f"{n} × {caption!r} ({section})" for (section, caption), n in counts.items()
            if n > 1]


# --- issue 22: the caption says what is on screen -----------------------------------------------

#: what a beat's words play animates besides the picture: the subtitle, the panel's text
_WORDS = ("subtitle", "title", "panel:", "code:")


def _draws_picture(play: dict) -> bool:
    """Whether a play changes more than words (subtitle, panel text) or waits."""
    def picture(anim: dict) -> bool:
        if anim.get("animations"):
            return any(picture(a) for a in anim["animations"])
        name = (anim.get("mobject") or {}).get("name") or ""
        return anim["type"] != "Wait" and not name.startswith(_WORDS)
    return any(picture(a) for a in play["animations"])


def stale_endings(data: dict) -> list[str]:
    """The plays that draw a run's whole triangulation while the caption on screen is a step
    caption of an earlier beat, as ``"play 40: 'Split along …'"``: a caption said before in
    the run (since its polygon was drawn), or one that was up while an earlier beat's picture
    changed (from its own play to the triangulation's)."""
    found = []
    plays = data["plays"]
    run_start, said_at = 0, -1
    for k, play in enumerate(plays):
        tops = [(a["type"], (a.get("mobject") or {}).get("name")) for a in play["animations"]]
        if any(kind in INCOMING and name == "polygon" for kind, name in tops):
            run_start = k
        if play.get("subcaption"):
            said_at = k
        if not any(kind in INCOMING and name == "triangulation" for kind, name in tops):
            continue
        if said_at < 0:
            continue
        caption = plays[said_at]["subcaption"]
        earlier = any(p.get("subcaption") == caption for p in plays[run_start:said_at])
        over = any(_draws_picture(p) for p in plays[said_at:k])
        if earlier or over:
            found.append(f"play {k}: {caption!r}")
    return found


def _call_text(node: dict) -> str:
    """The words of a call line's node (its lines' texts, joined)."""
    return " ".join(t for part in mobject_nodes(node) if (t := part.get("text", "").strip()))


def stale_call_lines(data: dict) -> list[str]:
    """The plays that draw a run's whole triangulation while the panel's call line is a step's
    call, as ``"play 177: 'split(P, 3, 1) → [P, P]'"``: the call line on screen then (the
    last one brought in since the run's polygon was drawn) is of a function the run called
    with other call lines too (a split, a piece's triangles), where the run's own call, made
    once, says what the picture shows (``divide_and_conquer(P, gravity) → 11 triangles``);
    and a call line there whose result is not the triangles counted (ear clipping's run
    ended on ``triangulate(P, "ear-clipping-naive") → [[12, 7, 8], [0, 1, 12], …]``: index
    triples, code a class does not read, where the picture shows the triangles)."""
    found = []
    said: list[str] = []
    for k, play in enumerate(data["plays"]):
        tops = [(a["type"], a.get("mobject") or {}) for a in play["animations"]]
        if any(kind in INCOMING and node.get("name") == "polygon" for kind, node in tops):
            said = []
        said += [_call_text(node) for kind, node in tops
                 if kind in INCOMING and node.get("name") == "panel:call"]
        if not said or not any(kind in INCOMING and node.get("name") == "triangulation"
                               for kind, node in tops):
            continue
        name = said[-1].split("(")[0]
        # a call said again with its result is the same call
        if (len({c.split(" →")[0] for c in said if c.split("(")[0] == name}) > 1
                or not _COUNTED_CALL.search(said[-1])):
            found.append(f"play {k}: {said[-1]!r}")
    return found


_SUBSCRIPTS = str.maketrans({**{c: str(k) for k, c in enumerate("₀₁₂₃₄₅₆₇₈₉")}, "′": "_",
                             "″": "__"})


def _depth(text: str) -> int:
    """How many brackets are open at the end of ``text``."""
    return sum(text.count(c) for c in "([{") - sum(text.count(c) for c in ")]}")


def unreal_call_lines(data: dict) -> list[str]:
    """Issue 22 item 1, a programmer's call line: the call lines (the part before the
    result's arrow) Python could not read as a call, and those broken into lines anywhere
    but after an argument's comma or before the arrow, as ``"'first_hit_sweeping(B, [0,
    1], [D, E], —) → D': not Python"`` or ``"'…[D, | E], T(ABC)) → E': broken inside an
    argument"`` (the vertical sweep's unset shore was a dash, and TranslationCorrect's list
    [D, E] broke over two lines)."""
    found: list[str] = []
    for node in graph_nodes(data):
        if node.get("name") != "panel:call":
            continue
        lines = [t for part in mobject_nodes(node) if (t := (part.get("text") or "").strip())]
        whole = " ".join(lines)
        if not whole:
            continue
        # a label's subscript (c₁) is its name's digit, its prime (c₁′) a letter, an elision (``{…}``, a cut line's
        # end) Python's ``...``
        call = whole.split(" →")[0].translate(_SUBSCRIPTS).replace("…", "...")
        try:
            parsed = ast.parse(call, mode="eval").body
        except SyntaxError:
            parsed = None
        if not isinstance(parsed, ast.Call) and not call.endswith("..."):  # a cut one: its start
            found.append(f"{whole!r}: not Python")
        for k in range(1, len(lines)):
            before = " ".join(lines[:k])
            if not (lines[k].startswith("→") or (before.endswith(",") and _depth(before) == 1
                                                 and "→" not in before)):
                found.append(f"{' | '.join(lines)!r}: broken inside an argument")
    return sorted(set(found))


#: the end of a run's call line under its whole triangulation: the triangles it gives,
#: counted (``→ 11 triangles``), not their index triples (``→ [[12, 7, 8], [0, 1, 12], …]``)
_COUNTED_CALL = re.compile(r"→\s*\d+\s*triangles$")


def _result_rows() -> frozenset[str]:
    """The texts of the pseudocode rows that say a run's result (:data:`story.pseudocode.RESULT`)."""
    from story.pseudocode import RESULT
    from story.registry import entry, names

    return frozenset(row.text.strip() for name in names() for row in entry(name).pseudocode
                     if RESULT in row.calls)


def _lit_rows(anim: dict) -> Iterator[str]:
    """The texts of the lit pseudocode rows (a ``code:`` row's copy in ink) an animation
    (or its members) puts on the screen."""
    mobject = anim.get("mobject") or {}
    if (anim["type"] in INCOMING and (mobject.get("name") or "").startswith("code:")
            and mobject.get("role") == "called" and (mobject.get("text") or "").strip()):
        yield mobject["text"].strip()
    for child in anim.get("animations", ()):
        yield from _lit_rows(child)


def stale_lit_rows(data: dict) -> list[str]:
    """The plays that draw a run's whole triangulation while the pseudocode's lit row is
    not the one saying the result ("their union is the triangulation of P"), as
    ``"play 40: 'divide P along it into P1 and P2'"``: the last step's row no longer says what
    the picture shows. A run without pseudocode rows lit (no panel, or its source) is not
    judged."""
    results = _result_rows()
    found, lit = [], None
    for k, play in enumerate(data["plays"]):
        tops = [(a["type"], (a.get("mobject") or {}).get("name")) for a in play["animations"]]
        for anim in play["animations"]:
            for text in _lit_rows(anim):
                lit = text
        if lit is not None and lit not in results and any(
                kind in INCOMING and name == "triangulation" for kind, name in tops):
            found.append(f"play {k}: {lit!r}")
    return found


#: the diagonals a ✗ caption refutes: "✗ BD is not an inner diagonal: …", "✗ Scaling
#: fails: BD crosses edge E–A"
_REFUTED = re.compile(r"\b([A-Z][a-z₀-₉]*[A-Z][a-z₀-₉]*) (?:is not an inner diagonal|crosses)")


def refuted_lit_rows(data: dict) -> list[str]:
    """The plays whose lit pseudocode row states as a fact what the caption on screen then
    refutes, as ``"play 31: 'BD is an inner diagonal' under '✗ BD is not an inner
    diagonal: …'"``: the rule's row said "BD is an inner diagonal", lit while the ✗ said it
    was not (Scaling, Rotation and Translation at 13–18 s). A row saying it as the rule's
    claim ("claim BD is an inner diagonal") is what the rule does, not a fact."""
    found, lit, caption = [], None, ""
    for k, play in enumerate(data["plays"]):
        caption = play.get("subcaption") or caption
        for anim in play["animations"]:
            for text in _lit_rows(anim):
                lit = text
        if lit is None or not caption.startswith("✗"):
            continue
        if any(re.search(rf"(?<!claim )\b{name} is an inner diagonal", lit)
               for name in _REFUTED.findall(caption)):
            found.append(f"play {k}: {lit!r} under {caption!r}")
    return found


def flashes_against_roles(data: dict) -> list[str]:
    """The vertices a run's picture flashes (``Indicate``) in another colour than the role
    it has then — the colour the panel shows it in, and the legend's — as ``"play 12:
    vertex:D flashes #EF4B4B, idle"``: Scaling with walls flashed D red (no failure: B does
    not see it, unsaid) while the panel kept it white, and E green (no verdict yet) while
    the panel showed it amber."""
    from metaphors.theme import THEME

    found = []
    for k, play in enumerate(data["plays"]):
        for anim in play["animations"]:
            node = anim.get("mobject") or {}
            name, role = node.get("name") or "", node.get("role") or "idle"
            if anim["type"] != "Indicate" or not name.startswith("vertex:"):
                continue
            if str(anim.get("color", "")).upper() != THEME.role_colour(role).upper():
                found.append(f"play {k}: {name} flashes {anim.get('color')}, {role}")
    return found


#: a verdict's marks on a run's picture (:mod:`metaphors.basics`)
_VERDICT_MARKS = ("tick", "cross")


def leftover_verdicts(data: dict) -> list[str]:
    """The plays that draw a run's whole triangulation while a verdict's ✓ or ✗ of one of
    its steps is still on screen, as ``"play 90: 2 ✓/✗ left"``: the diagonal it judged is
    an edge of the result now, and a mark left over (or left behind, unturned, when a later
    claim took its place) reads as a claim on the triangulation. And the red test triangles
    left past their step (:func:`stale_test_triangles`)."""
    found = []
    shown = 0
    for k, play in enumerate(data["plays"]):
        tops = [(a["type"], (a.get("mobject") or {}).get("name")) for a in play["animations"]]
        if any(kind in INCOMING and name in _POLYGONS for kind, name in tops):
            shown = 0  # a new run: the screen was cleared for it
        shown += sum(1 for kind, name in tops if kind in INCOMING and name in _VERDICT_MARKS)
        shown -= sum(1 for kind, name in tops if kind in OUTGOING and name in _VERDICT_MARKS)
        if shown > 0 and any(kind in INCOMING and name == "triangulation" for kind, name in tops):
            found.append(f"play {k}: {shown} ✓/✗ left")
    return found + stale_test_triangles(data)


#: ear clipping's test triangle (:func:`metaphors.fruit.ear_test`), red for a vertex that is no ear
_TEST_TRIANGLE = "ear-triangle"


def stale_test_triangles(data: dict) -> list[str]:
    """The red test triangles of ear clipping ("Is G an ear? no") still on screen when a
    later step's picture changes, as ``"play 95: red ear-triangle of play 93"``: the verdict
    of its own step only, it is stale once the next caption is up and the picture moves on
    (prune and search's H-G-F stayed red through the whole gravity step after it, under the
    green ✓ for GB). A part of :func:`leftover_verdicts`."""
    found = []
    since, moved_on = -1, False  # the play the red triangle came in; a caption after it
    for k, play in enumerate(data["plays"]):
        if since >= 0 and play.get("subcaption"):
            moved_on = True
        for anim in play["animations"]:
            for kind, node in _recorded(anim):
                if node.get("name") not in (_TEST_TRIANGLE, _TEST_ANGLE):
                    continue
                if kind in OUTGOING:
                    since, moved_on = -1, False
                elif since < 0 and node.get("role") == "rejected":
                    since = k
        if since >= 0 and moved_on and not play.get("subcaption") and _draws_picture(play):
            found.append(f"play {k}: red {_TEST_TRIANGLE} of play {since}")
            since, moved_on = -1, False  # each triangle once
    return found


# --- issue 22: an ear test answered no shows why --------------------------------------------------

#: what a not-convex vertex's test shows (:func:`metaphors.fruit.angle_wedge`): its angle
_TEST_ANGLE = "ear-angle"
#: the least height of a red test triangle, and the least radius of a test's angle: 1.5 %
#: of the frame's height (a line, or a sliver, shows no inside)
LEAST_TEST_HEIGHT = 0.12


def _pulsed(play: dict) -> dict[str, tuple[float, float]]:
    """The vertices a play pulses (``Indicate``), by label: where their dots stand."""
    dots = {}
    for anim in play["animations"]:
        node = anim.get("mobject") or {}
        if anim.get("type") == "Indicate" and (node.get("name") or "").startswith("vertex:"):
            dot = _dot_centre(node)
            if dot is not None:
                dots[node["name"].removeprefix("vertex:")] = dot
    return dots


def _strictly_inside(p: tuple[float, float], corners: list[tuple[float, float]]) -> bool:
    """Whether ``p`` lies in the triangle ``corners`` (closed), and is none of its corners."""
    if _near(p, corners, within=MARKER_AT_CORNER):
        return False
    sides = [(b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
             for a, b in zip(corners, corners[1:] + corners[:1], strict=True)]
    return all(x >= -1e-9 for x in sides) or all(x <= 1e-9 for x in sides)


def _shoelace(corners: list[tuple[float, float]]) -> float:
    return abs(sum(a[0] * b[1] - b[0] * a[1]
                   for a, b in zip(corners, corners[1:] + corners[:1], strict=True))) / 2


def unseen_ear_tests(data: dict) -> list[str]:
    """The ear tests answered no whose picture does not show why, as ``"play 151 H: red
    triangle 0.00 high"``, ``"play 93 G: red triangle, no vertex inside"`` or ``"play 9 G: angle
    0.010 wide"``. An ear is a convex vertex whose triangle holds no other vertex (the thesis,
    Meisters), so a vertex is no ear for one of two reasons, each drawn: a vertex inside its
    triangle (red, at least :data:`LEAST_TEST_HEIGHT` high, that vertex pulsing inside it),
    or its angle, 180° or more (a red wedge round it, :data:`_TEST_ANGLE`, at least as large
    as half a disc of radius :data:`LEAST_TEST_HEIGHT`). Prune and search's "is H an ear? no" (chapter 4 at
    96 s) drew the straight G-H-K, a red line with no inside, and its reflex G, the holes'
    a₁, b₁, a₂ and b₂ a red triangle holding nothing, mostly outside the fruit."""
    found = []
    for k, play in enumerate(data["plays"]):
        pulsed = _pulsed(play)
        for anim in play["animations"]:
            if anim.get("type") in OUTGOING:
                continue
            node = anim.get("target") or anim.get("mobject") or {}
            name = node.get("name")
            if node.get("role") != "rejected" or name not in (_TEST_TRIANGLE, _TEST_ANGLE):
                continue
            corners = _corners(node)
            # the vertex at a corner of its triangle, or the one pulsing with its angle
            tested = next((v for v, dot in pulsed.items()
                           if _near(dot, corners, MARKER_AT_CORNER) or name == _TEST_ANGLE), "?")
            if name == _TEST_ANGLE:
                if _shoelace(corners) < math.pi * LEAST_TEST_HEIGHT ** 2 / 2:
                    found.append(f"play {k} {tested}: angle {_shoelace(corners):.3f} wide")
                continue
            height = _altitude(*corners[:3])
            if height < LEAST_TEST_HEIGHT:
                found.append(f"play {k} {tested}: red triangle {height:.2f} high")
            elif not any(_strictly_inside(dot, corners[:3]) for dot in pulsed.values()):
                found.append(f"play {k} {tested}: red triangle, no vertex inside")
    return found


# --- issue 22: a verdict's mark reads -------------------------------------------------------------

#: 2 % of the frame's height: the least gap between a verdict's ✓ or ✗ and an edge or label
LEAST_MARK_GAP = 0.16
#: the names of the verdicts' marks (a run's, an analysis's)
_MARKS = ("tick", "cross", "analysis:tick", "analysis:cross")


def _recorded(anim: dict) -> Iterator[tuple[str, dict]]:
    """(the animation's type, node) of every top mobject an animation (or its members) has:
    its mobject and its target, the state it ends in."""
    for key in ("mobject", "target"):
        if key in anim:
            yield anim["type"], anim[key]
    for child in anim.get("animations", ()):
        yield from _recorded(child)


def _label_boxes(marker: dict, *, direct: bool = False
                 ) -> Iterator[tuple[float, float, float, float]]:
    """The box of each text a vertex's marker shows (its label): among all its parts, or,
    ``direct``, among its own children only (a marker's dot and label, not what a group
    holding markers holds further down)."""
    parts = marker.get("submobjects", ()) if direct else mobject_nodes(marker)
    for node in parts:
        if node.get("box") and (node.get("text") or "").strip():
            x0, y0, x1, y1 = node["box"]
            yield (x0, y0, x1, y1)


def _state_then(data: dict, last: dict[str, tuple[int, str, dict]], k: int,
                name: str) -> dict | None:
    """The node ``name`` as play ``k`` shows it: its last record, or, when that record is a
    turn's start (a turn records where it starts), its next record after ``k`` where that
    shows where it starts (a turn's, a transform's, a fade out's), or, never recorded again,
    as the graph's end has it."""
    if name not in last:
        return None
    _, kind, node = last[name]
    if kind != "Turn":
        return node
    for play in data["plays"][k + 1:]:
        for later, then in (r for a in play["animations"] for r in _recorded(a)):
            if then.get("name") == name:
                return then if later not in INCOMING else None
    ends = [n for top in data.get("final", ()) for n in mobject_nodes(top) if n.get("name") == name]
    return ends[0] if ends else None


def _marks_on_polygons(data: dict, names: tuple[str, ...], *, settled: bool = False
                       ) -> Iterator[tuple[int, dict, dict | None, dict[str, tuple[int, str, dict]]]]:
    """(play, mark node, its polygon as the play shows it, the last records of the polygons
    and vertex markers) of each mark named in ``names`` coming in: the polygon is the last
    drawn before the mark (a turned picture's: as the turn back starts from it), the
    analysis's for an analysis's mark. ``settled``: also each later record of the mark that
    shows where it stands (not a turn's, which records where the turn starts), each place
    once: a turned picture's mark, placed again for the picture upright, as it leaves."""
    last: dict[str, tuple[int, str, dict]] = {}  # name: (play, animation type, node)
    seen: set[tuple[str, tuple | None]] = set()
    close = False  # a close-up is on: its window drawn (gravity's, from the fall to the ✓)
    for k, play in enumerate(data["plays"]):
        marks = []
        for kind, node in (r for a in play["animations"] for r in _recorded(a)):
            name = node.get("name") or ""
            if name == _CLOSE_UP + ":window":
                close = kind in INCOMING
            if name in names and (kind in INCOMING or (settled and kind != "Turn")):
                place = (name, _box_of(node))
                if kind in INCOMING or place not in seen:
                    marks.append(node)
                seen.add(place)
            elif name in _POLYGONS or name.startswith("vertex:"):
                last[name] = (k, kind, node)
        for mark in marks:
            home = "analysis:polygon" if mark["name"].startswith("analysis:") else "polygon"
            yield k, mark, (_close_up_then(data, k) if close else
                            _state_then(data, last, k, home)), last


def _close_up_then(data: dict, k: int) -> dict | None:
    """P as a close-up shows it at play ``k``: its fill, cut at the board's box, as the zoom
    back out records it when it starts (a zoom records where it starts), None if never."""
    for play in data["plays"][k + 1:]:
        for _, node in (r for a in play["animations"] for r in _recorded(a)):
            if node.get("name") == _CLOSE_UP:
                return next((part for part in node.get("submobjects", ())
                             if part.get("type") == "Polygon"), None)
    return None


def crowded_verdicts(data: dict) -> list[str]:
    """The verdicts' marks (✓, ✗) that come nearer than :data:`LEAST_MARK_GAP` to an edge of
    their polygon or to one of its vertex labels, as ``"play 38 tick: 0.05 from edge …"``;
    a mark whose polygon cannot be found is reported too. The polygon and the labels are the
    last drawn before the mark (a turned picture's: as the turn back starts from it); a mark
    on a turned picture is judged again where it stands once the picture is upright."""
    import numpy as np
    from shapely.geometry import LineString
    from shapely.geometry import box as area

    found = []
    for k, mark, polygon, last in _marks_on_polygons(data, _MARKS, settled=True):
        box = _box_of(mark)
        if polygon is None or box is None:
            found.append(f"play {k} {mark['name']}: no polygon drawn")
            continue
        shape, corners = area(*box), _corners(polygon)
        gaps = {f"edge ({a[0]:g}, {a[1]:g})–({b[0]:g}, {b[1]:g})":
                shape.distance(LineString([a, b]))
                for a, b in zip(corners, corners[1:] + corners[:1], strict=True)}
        for name in [n for n in last if n.startswith("vertex:")]:
            marker = _state_then(data, last, k, name)
            dots = [n for n in mobject_nodes(marker or {}) if n.get("points")]
            if not dots:
                continue
            centre = tuple(np.mean([q[:2] for q in dots[0]["points"]], axis=0))
            if _near(centre, corners, 0.05):  # a vertex of this polygon
                for label in _label_boxes(marker or {}):
                    gaps[name] = min(gaps.get(name, np.inf), shape.distance(area(*label)))
        where, gap = min(gaps.items(), key=lambda item: item[1])
        if gap < LEAST_MARK_GAP:
            found.append(f"play {k} {mark['name']}: {gap:.2f} from {where}")
    return found


# --- issue 22 item 5: a summary covers one unbroken run of fast beats ----------------------------

#: a summary caption of beats played fast (story.reading.summarised): its first and last claim
_SUMMARY = re.compile(r"^\w+ (\d+)(?:–(\d+))?: the same steps, faster$")
#: a summary naming its claims by their labels on screen (the monotone sweep's vertices):
#: ``"Vertices H, B, G and F: …"``, ``"Vertices H–K: …"``, ``"Vertex H: …"``
_NAMED_SUMMARY = re.compile(r"^(?:Vertex|Vertices) (.+): the same steps, faster$")


def _claims_made(play: dict, made: int) -> int:
    """The claims made by the end of ``play``, ``made`` before it: a claim drawn (divide and
    conquer's diagonals), a vertex classified (the monotone sweep's kind), a slice counted
    (ear clipping's ``k / n slices`` says k itself)."""
    for anim in play["animations"]:
        node = anim.get("mobject") or {}
        if anim["type"] not in INCOMING:
            continue
        if node.get("name") in ("claim", "kind"):
            made += 1
        elif node.get("name") == "counter" and (m := _SLICES.search(node.get("text", ""))):
            made = int(m[1])
    return made


def _classified(play: dict) -> list[str]:
    """The vertices a play shows the kind of (the monotone sweep: a kind comes in beside the
    vertex it indicates, or, where no place beside it is its own, the sweep line moves to the
    vertex it indicates), by their labels."""
    names = [(a["type"], (a.get("mobject") or {}).get("name") or "") for a in play["animations"]]
    if not any(kind in INCOMING and name == "kind" for kind, name in names) and not any(
            kind in ("Transform", "Create") and name == "sweep" for kind, name in names):
        return []
    return [name.removeprefix("vertex:") for kind, name in names
            if kind == "Indicate" and name.startswith("vertex:")]


def _summary_spans(data: dict) -> Iterator[tuple[int, str, set[int], list[str]]]:
    """Each subtitle said in a run, as ``(run, caption, claims, vertices)``: the run it is said
    in (a new one begins where a polygon is drawn), the claims whose marks appear while it is
    up, and the labels of the vertices classified meanwhile, in order."""
    run, made, caption, claims, vertices = 0, 0, None, set(), []
    for play in data["plays"]:
        if any(a["type"] in INCOMING and (a.get("mobject") or {}).get("name") == "polygon"
               for a in play["animations"]):
            if caption is not None:
                yield run, caption, claims, vertices
            run, made, caption, claims, vertices = run + 1, 0, None, set(), []
        said = play.get("subcaption")
        if said and said != caption:
            if caption is not None:
                yield run, caption, claims, vertices
            caption, claims, vertices = said, set(), []
        now = _claims_made(play, made)
        claims |= set(range(made + 1, now + 1))
        vertices += _classified(play)
        made = now
    if caption is not None:
        yield run, caption, claims, vertices


def _named(listed: str) -> list[str]:
    """The labels a named summary lists: ``"H, B, G and F"`` → ``["H", "B", "G", "F"]``; a
    range ``"H–K"`` stays one item (its ends checked by the caller)."""
    return [x for x in re.split(r", | and ", listed) if x]


def broken_summaries(data: dict) -> list[str]:
    """Issue 22 item 5: the summary captions (``"Vertices 3–7: the same steps, faster"``) that
    come back in their run after another caption (a key step must end a summary, not
    interrupt it), or whose range is not the claims made while they are up, as
    ``"'Diagonals 3–7: …' again"`` or ``"'Diagonals 3–7: …' over 3–4"``. A summary of vertices
    names them by their labels, the vertices classified while it is up (``"'Vertices H and
    B: …' over H, B, G"``); one that numbers them names what the picture never shows."""
    found = []
    said: set[tuple[int, str]] = set()
    for run, caption, claims, vertices in _summary_spans(data):
        if (named := _NAMED_SUMMARY.match(caption)) is not None and (
                _SUMMARY.match(caption) is None):
            if (run, caption) in said:
                found.append(f"{caption!r} again")
            said.add((run, caption))
            listed = _named(named[1])
            ends = listed[0].split("–") if len(listed) == 1 else listed
            if len(ends) == 2 and len(listed) == 1:  # a range: its ends, and at least three
                ok = len(vertices) > 2 and [vertices[0], vertices[-1]] == ends
            else:
                ok = listed == vertices
            if not ok:
                found.append(f"{caption!r} over {', '.join(vertices) or 'nothing'}")
            continue
        if (m := _SUMMARY.match(caption)) is None:
            continue
        if m[0].startswith("Vert"):  # the picture shows a vertex by its label, never a number
            found.append(f"{caption!r} numbers vertices")
        if (run, caption) in said:
            found.append(f"{caption!r} again")
        said.add((run, caption))
        first, last = int(m[1]), int(m[2] or m[1])
        if claims != set(range(first, last + 1)):
            shown = f"{min(claims)}–{max(claims)}" if claims else "nothing"
            found.append(f"{caption!r} over {shown}")
    return found


# --- issue 22: the panel's small polygon keeps its labels readable --------------------------------

#: the least a label of the panel's polygon keeps from its outline and from another label
LABEL_ROOM = 0.03
#: how much nearer its own dot a panel label's centre stands than any other's (the keyhole's
#: b₂, midway between the dots a₂ and b₂, named neither)
LABEL_OWN = 1.2


#: the least gap between two labels side by side (a space and more): nearer, they read as
#: one word (the keyhole's a₂ and b₂, 0.05 apart: "a₂b₂")
LABEL_WORDS = 0.1


def _one_word(a: tuple[float, ...], b: tuple[float, ...]) -> bool:
    """Whether box ``b`` stands just right of box ``a`` on its line (their heights overlap
    by half the lower one's), less than :data:`LABEL_WORDS` from it."""
    beside = min(a[3], b[3]) - max(a[1], b[1]) > min(a[3] - a[1], b[3] - b[1]) / 2
    return beside and 0 <= b[0] - a[2] < LABEL_WORDS


def crowded_panel_labels(data: dict) -> list[str]:
    """The labels of the panel's polygon that overlap another label or come within
    :data:`LABEL_ROOM` of its outline (an edge through a label misreads it), or that stand
    nearer another vertex's dot than their own (their box, or their centre by
    :data:`LABEL_OWN`), as ``"K × M"``, ``"K × edge"``, ``"K ~ J"``; or that stand side by
    side with another nearer than :data:`LABEL_WORDS` (``"a₂ b₂ one word"``: "a₂b₂");
    and the vertices left without a label (no room for one: ``"K unlabelled"``). Each run's
    panel (from its polygon's coming in) is judged alone."""
    found: list[str] = []
    for outline, markers in _panels(data):
        found += _crowded(outline, markers)
    return found


def _panels(data: dict) -> Iterator[tuple[dict, dict[str, dict]]]:
    """Each run's panel polygon and the first node of each of its markers (``panel:K``) the
    graph shows: a run begins where its polygon is drawn (the panel comes in with it, added,
    not played: its nodes are those a play recolours, and the last run's those on screen at
    the end). A run whose panel polygon the graph never shows is left out."""
    runs: list[tuple[dict | None, dict[str, dict]]] = [(None, {})]

    def seen(node: dict) -> None:
        name = node.get("name") or ""
        outline, markers = runs[-1]
        if name == "panel:polygon" and node.get("points") and outline is None:
            runs[-1] = (node, markers)
        elif name.startswith("panel:") and name not in _PANEL_PARTS:
            markers.setdefault(name[6:], node)

    for play in data["plays"]:
        if any(a["type"] in INCOMING and (a.get("mobject") or {}).get("name") == "polygon"
               for a in play["animations"]):
            runs.append((None, {}))
        for anim in play["animations"]:
            for node in animation_nodes(anim):
                seen(node)
    for mobject in data.get("final", ()):
        for node in mobject_nodes(mobject):
            seen(node)
    for outline, markers in runs:
        if outline is not None and markers:
            yield outline, markers


#: the panel's nodes that are no vertex's marker
_PANEL_PARTS = {"panel:polygon", "panel:lit", "panel:call"}


def _crowded(outline_node: dict, markers: dict[str, dict]) -> list[str]:
    from shapely.geometry import MultiLineString, Point, box

    # manim's points: four a curve, its first and last the ends of an edge (several rings,
    # with holes, are not joined end to start)
    points = outline_node["points"]
    outline = MultiLineString([(points[k][:2], points[k + 3][:2])
                               for k in range(0, len(points) - 3, 4)])
    labels, dots, found = {}, {}, []
    for label, node in markers.items():
        parts = list(mobject_nodes(node))
        texts = [p for p in parts if p.get("text") and p.get("box")]
        dot = next((p for p in parts if p.get("type") == "Dot" and p.get("points")), None)
        if dot is None:
            continue
        xs, ys = zip(*[q[:2] for q in dot["points"]], strict=True)
        dots[label] = Point(sum(xs) / len(xs), sum(ys) / len(ys))
        if texts:
            labels[label] = box(*texts[0]["box"])
        else:
            found.append(f"{label} unlabelled")
    for label, shape in sorted(labels.items()):
        if shape.distance(outline) < LABEL_ROOM:
            found.append(f"{label} × edge")
        found += [f"{label} × {other}" for other, there in sorted(labels.items())
                  if other > label and shape.distance(there) < LABEL_ROOM]
        found += [f"{label} {other} one word" for other, there in sorted(labels.items())
                  if other != label and _one_word(shape.bounds, there.bounds)]
        nearest = min(dots, key=lambda k: (shape.distance(dots[k]), k))
        centre = shape.centroid
        closest = min(dots, key=lambda k: (centre.distance(dots[k]) * (
            LABEL_OWN if k == label else 1), k != label))
        if nearest != label and shape.distance(dots[nearest]) < shape.distance(dots[label]):
            found.append(f"{label} ~ {nearest}")
        elif closest != label:  # midway between two dots: it names neither
            found.append(f"{label} ~ {closest}")
    return found


# --- issue 22: no text over the picture -------------------------------------------------------

#: the least gap between a note drawn on the picture and a vertex's label (1.5 % of the
#: frame's height): nearer, the two read as one text ("Doutside P, inside T")
LEAST_NOTE_GAP = 0.12
#: the notes a metaphor writes beside what it points at, on the picture
_NOTES = ("astray:note",)
#: a legend's entries (a swatch and its words): a run's or an analysis's
_LEGEND = "legend:"


def _notes(node: dict) -> Iterator[tuple[str, tuple[float, float, float, float]]]:
    """(text, box) of each note (:data:`_NOTES`) and legend entry (:data:`_LEGEND`, its
    swatch and words) in a node and its parts."""
    for part in mobject_nodes(node):
        name = part.get("name") or ""
        if name in _NOTES and part.get("box"):
            yield part["text"], tuple(part["box"])
        elif name.startswith(_LEGEND) and (box := _box_of(part)) is not None:
            yield _text_of(part), box


def _named_label_boxes(node: dict) -> Iterator[tuple[str, tuple[float, float, float, float]]]:
    """(vertex, box) of each vertex label in a node and its parts."""
    for part in mobject_nodes(node):
        if (part.get("name") or "").startswith("vertex:"):
            for box in _label_boxes(part, direct=True):
                yield part["name"].removeprefix("vertex:"), box


def _touching(part: dict, labels: dict[str, tuple[float, float, float, float]]) -> list[str]:
    """``part``'s text nearer than :data:`LEAST_NOTE_GAP` to each of the ``labels`` it
    touches, as ``"'outside P, inside T' touches D"``."""
    x0, y0, x1, y1 = part["box"]
    grown = (x0 - LEAST_NOTE_GAP, y0 - LEAST_NOTE_GAP, x1 + LEAST_NOTE_GAP, y1 + LEAST_NOTE_GAP)
    return [f"{part['text']!r} touches {v}" for v, box in sorted(labels.items())
            if _overlap(grown, box)]


def crowded_notes(data: dict) -> list[str]:
    """The notes on the picture (:data:`_NOTES`) nearer than :data:`LEAST_NOTE_GAP` to a
    vertex label shown with them, as ``"'outside P, inside T' touches D"``. The labels are
    those of the polygon drawn last before the note (a scene of several runs draws several)."""
    found = []
    for anim, labels in _with_labels(data):
        for words, box in _notes(anim.get("mobject", {})):
            found += _touching({"text": words, "box": box}, labels)
    return sorted(set(found))


#: the word a vertex gets as the monotone partition's sweep reaches it ("split", "merge" …)
_KIND_WORDS = ("kind",)


def crowded_kind_words(data: dict) -> list[str]:
    """Issue 22: the monotone partition's kind words (:data:`_KIND_WORDS`) nearer than
    :data:`LEAST_NOTE_GAP` to a vertex label shown with them, as ``"'split' touches B"``, or
    on an edge of the polygon drawn last, as ``"'split' on an edge"``: beside a label the
    word reads with it (B's label read "Bregular"), on an edge it is crossed out."""
    from shapely.geometry import LineString
    from shapely.geometry import box as rectangle

    found = []
    edges: list = []
    for anim, labels in _with_labels(data):
        node = anim.get("mobject", {})
        if anim.get("type") in INCOMING and node.get("name") in _POLYGONS and node.get("points"):
            edges = [LineString(s) for s in _segments(node)]
        if anim.get("type") not in INCOMING:
            continue
        for part in mobject_nodes(node):
            if part.get("name") not in _KIND_WORDS or not part.get("box"):
                continue
            found += _touching(part, labels)
            if any(rectangle(*part["box"]).intersects(e) for e in edges):
                found.append(f"{part['text']!r} on an edge")
    return sorted(set(found))


#: the farthest a kind word's box may stand from its vertex's dot (12.5 % of the frame's
#: height): farther, it is read as nobody's ("regular" stood up-left, a way from its vertex)
KIND_FARTHEST = 1.0
#: how many times farther than its own vertex every other vertex's dot must be from a kind
#: word: nearer, the word reads as the other's ("start" between A and L)
KIND_OWN = 1.5
#: the farthest a kind word's box may stand from its vertex as drawn, its dot or its label
#: (3.75 % of the frame's height, 18 px at 480p): "regular" stood in the slot left of I,
#: 0.35 from I's label and 0.45 from its dot, read as the slot's, not I's
KIND_BESIDE = 0.3


def _dot_centres(node: dict) -> Iterator[tuple[str, tuple[float, float]]]:
    """(vertex, centre) of each vertex marker's dot in a node and its parts."""
    for part in mobject_nodes(node):
        if (part.get("name") or "").startswith("vertex:"):
            for dot in part.get("submobjects", ()):
                if dot.get("type") == "Dot" and dot.get("points"):
                    xs = [q[0] for q in dot["points"]]
                    ys = [q[1] for q in dot["points"]]
                    yield (part["name"].removeprefix("vertex:"),
                           ((min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2))


def stray_kind_words(data: dict) -> list[str]:
    """Issue 22: the monotone partition's kind words not beside their own vertex (the one the
    play flashes, Indicate): farther than :data:`KIND_FARTHEST` from its dot, as
    ``"'regular' for B 1.4 away"``, farther than :data:`KIND_BESIDE` from both its dot and
    its label, as ``"'regular' for I 0.35 from it"``, or with another vertex's dot or label
    nearer than :data:`KIND_OWN` times its own (dot or label), as ``"'start' for A nearer
    L"``. The dots and labels are those of the polygon drawn last, where they were last
    drawn."""
    from shapely.geometry import Point
    from shapely.geometry import box as rectangle

    dots: dict[str, tuple[float, float]] = {}
    labels: dict[str, tuple[float, float, float, float]] = {}
    found = []
    for play in data["plays"]:
        words, own = [], set()
        for anim in play["animations"]:
            node = anim.get("mobject", {})
            if anim.get("type") in INCOMING and node.get("name") in _POLYGONS:
                dots, labels = {}, {}
            for key in ("mobject", "target"):
                dots.update(dict(_dot_centres(anim.get(key, {}))))
                labels.update(dict(_named_label_boxes(anim.get(key, {}))))
            if anim.get("type") == "Indicate" and (node.get("name") or "").startswith("vertex:"):
                own.add(node["name"].removeprefix("vertex:"))
            if anim.get("type") in INCOMING:
                words += [p for p in mobject_nodes(node)
                          if p.get("name") in _KIND_WORDS and p.get("box")]
        for word in words:
            shape = rectangle(*word["box"])
            for v in sorted(own & set(dots)):
                gap = shape.distance(Point(dots[v]))
                if gap > KIND_FARTHEST + 0.01:  # the graph rounds boxes to 0.001
                    found.append(f"{word['text']!r} for {v} {gap:.1f} away")
                beside = min(gap, shape.distance(rectangle(*labels[v])) if v in labels else gap)
                if beside > KIND_BESIDE + 0.01:
                    found.append(f"{word['text']!r} for {v} {beside:.2f} from it")
                marks = [(w, Point(at)) for w, at in dots.items()]
                marks += [(w, rectangle(*b)) for w, b in labels.items()]
                found += [f"{word['text']!r} for {v} nearer {w}" for w, mark in sorted(
                    marks, key=lambda m: m[0])
                    if w != v and shape.distance(mark) < KIND_OWN * beside]
    return sorted(set(found))


def fleeting_kind_words(data: dict) -> list[str]:
    """Issue 22: the monotone partition's kind words gone before their caption (the one
    that names their vertex, ``"L: … a start vertex"``) has been read: up less than
    :data:`story.reading.LEAST_CUE` seconds, as ``"'start' up 0.28 s"`` (it faded out at
    once, while its caption stayed three seconds); or left over when the next comes in, as
    ``"'start' left over"`` (one word at a time). A summary's fast steps, whose caption
    names no vertex, show no words: each would flash by in a fifth of a second. A word is
    known by its text and box."""
    from story.reading import LEAST_CUE

    found, now = [], 0.0
    up: dict[tuple, float] = {}  # (word, box) -> since
    for play in data["plays"]:
        for going in (True, False):  # what goes, then what comes
            for anim in play["animations"]:
                if anim.get("type") not in (OUTGOING if going else INCOMING):
                    continue
                for p in mobject_nodes(anim.get("mobject", {})):
                    if p.get("name") not in _KIND_WORDS or not p.get("box"):
                        continue
                    key = (p.get("text"), tuple(p["box"]))
                    if going and key in up:
                        since = up.pop(key)
                        if now - since < LEAST_CUE - 1e-6:
                            found.append(f"{key[0]!r} up {now - since:.2f} s")
                    elif not going:
                        found += [f"{k[0]!r} left over" for k in up]
                        up[key] = now
        now += play.get("run_time") or 0.0
    return found


def _stack_labels(node: dict) -> list[str]:
    """The labels the monotone stack's column shows, the top first ("stack" over them; the
    mark of its top, ``stack:top``, is no label)."""
    return [t for p in mobject_nodes(node) if (t := (p.get("text") or "").strip())
            and p.get("name") != "stack:top"][1:]


def jumping_stacks(data: dict) -> list[str]:
    """Issue 22: the monotone stack's column changing by labels its caption does not name,
    as ``"'B waits on the stack': A went, b₁ came"``: the stack is read from its column,
    and a vertex that leaves or comes back unsaid makes it jump (after a vertex met the
    other chain, the bottom went and the old top came back under a caption that named only
    the new one)."""
    found, caption = [], ""
    shown: list[str] = []
    for play in data["plays"]:
        caption = play.get("subcaption") or caption
        for anim in play["animations"]:
            node = anim.get("mobject", {})
            if node.get("name") != "stack:column":
                continue
            if anim.get("type") in OUTGOING:
                shown = []
                continue
            new = _stack_labels(anim.get("target", node))
            said = set(re.findall(r"\w+", caption))
            went = [v for v in shown if v not in new and v not in said]
            came = [v for v in new if v not in shown and v not in said]
            if went or came:
                found.append(f"{caption!r}: " + ", ".join(
                    [*(f"{v} went" for v in went), *(f"{v} came" for v in came)]))
            shown = new
    return found


def crowded_counts(data: dict) -> list[str]:
    """The counters (``"n − 2 = 13 − 2 = 11 triangles"``, ``"3 / 11 slices"``) nearer than
    :data:`LEAST_NOTE_GAP` to a vertex label or to the subtitle on screen with them, as
    ``"'n − 2 = …' touches C"``, ``"'n − 2 = …' touches the subtitle"``: text over text (the
    monotone count stood under P, on the bottom vertex's label and the subtitle)."""
    subtitle: tuple[float, ...] | None = None
    found = []
    for anim, labels in _with_labels(data):
        node = anim.get("mobject", {})
        if node.get("name") == "subtitle" and node.get("box"):
            subtitle = None if anim.get("type") in OUTGOING else tuple(node["box"])
        if anim.get("type") not in INCOMING:
            continue
        for part in mobject_nodes(node):
            if part.get("name") != "counter" or not part.get("box"):
                continue
            found += _touching(part, labels)
            x0, y0, x1, y1 = part["box"]
            grown = (x0 - LEAST_NOTE_GAP, y0 - LEAST_NOTE_GAP, x1 + LEAST_NOTE_GAP,
                     y1 + LEAST_NOTE_GAP)
            if subtitle is not None and _overlap(grown, subtitle):
                found.append(f"{part['text']!r} touches the subtitle")
    return sorted(set(found))


def calls_over_code(data: dict) -> list[str]:
    """The panel's call lines that run over its pseudocode rows (a long result wrapped to
    four lines reached up into them), as ``"'triangulate_monotone_piece(…' over 'their …'"``."""
    rows, calls = {}, {}
    for node in graph_nodes(data):
        name, box, said = node.get("name") or "", node.get("box"), (node.get("text") or "").strip()
        if box and said and name.startswith("code:"):
            rows[said] = box
        elif name == "panel:call":  # one text, or a group of its wrapped lines
            said = " ".join(t for n in mobject_nodes(node) if (t := (n.get("text") or "").strip()))
            whole = _box_of(node)
            if said and whole is not None:
                calls[said] = whole
    return sorted(f"{c[:30]!r} over {r!r}" for c, a in calls.items() for r, b in rows.items()
                  if _overlap(a, b))


#: the metaphors' shapes that grow as the run goes (and may outgrow the picture)
_GROWING = ("water",)


#: the picture's fills a note or a legend must not stand over: P's and T's (a run's, an
#: analysis's)
_FILLS = ("polygon", "analysis:polygon", "T", "analysis:T")
#: the most of a note's or a legend entry's box that may lie over the picture's fills (square
#: units: a corner touching an edge's stroke, no more)
MOST_TEXT_OVER_FILL = 1e-3


def notes_over_fills(data: dict) -> list[str]:
    """The notes (:data:`_NOTES`) and legend entries (:data:`_LEGEND`) that come in over P's
    or T's fill (:data:`_FILLS`, the ones drawn last before them), as ``"play 13 'outside P,
    inside T': 0.48 over the picture"``: issue 22, no text over the picture (the run's
    "outside P, inside T" stood inside P, over its fill, beside the red piece it named)."""
    from shapely.geometry import box as rectangle
    from shapely.ops import unary_union

    fills: dict[str, object] = {}
    found = []
    for k, play in enumerate(data["plays"]):
        for anim in play["animations"]:
            node = anim.get("mobject", {})
            if anim.get("type") in INCOMING and node.get("name") in _FILLS \
                    and node.get("points"):
                if node["name"] in _POLYGONS:
                    fills = {}
                fills[node["name"]] = _outline(node)
            if anim.get("type") in OUTGOING or not fills:
                continue
            picture = unary_union([f for f in fills.values() if f is not None])
            for words, box in _notes(node):
                over = rectangle(*box).intersection(picture).area
                if over > MOST_TEXT_OVER_FILL:
                    found.append(f"play {k} {words!r}: {over:.2f} over the picture")
    return found


def shapes_under_text(data: dict) -> list[str]:
    """The growing shapes (:data:`_GROWING`) drawn under a subtitle or a title, or off the
    screen's edge, as ``"water under the subtitle"``: the picture keeps to its part of the
    screen, so that no text is read over it; and the picture's fills under a note or a
    legend (:func:`notes_over_fills`)."""
    texts = {(n["name"], tuple(n["box"])) for n in graph_nodes(data)
             if n.get("name") in ("subtitle", "title") and n.get("box")
             and (n.get("text") or "").strip()}
    found = set()
    for node in graph_nodes(data):
        if node.get("name") not in _GROWING or not node.get("points"):
            continue
        box = _box_of(node)
        if box is None:
            continue
        found |= {f"{node['name']} under the {name}" for name, where in texts
                  if _overlap(box, where)}
        if box[0] < -7.12 or box[2] > 7.12:
            found.add(f"{node['name']} off the screen")
    return [*sorted(found), *notes_over_fills(data)]


#: the pieces of a moving tool's drawn line (:func:`metaphors.sweep.drawn_segment`)
_TOOL_DRAWINGS = ("hand:", "sweep:")
#: the unseen lines a tool's drawing follows, moved by a play (:func:`metaphors.clock.clock`)
_TOOL_AXES = ("hand", "sweep")


def moved_after_the_pick(data: dict) -> list[str]:
    """The tools (the clock hand, the sweep line) moved on after their pick lit, as
    ``"play 14: hand"``: a tool stops at its pick, its decisive moment. Moved on, it rang a
    candidate that decides nothing (the water wetted E after D, chapter 2), and red on its
    line said "fails" where nothing was judged (Correct Rotation's hand drew C–E red across
    the notch of the mirror image as it turned on from its pick D). The red of the part that
    reached the pick from outside P, said by its legend, is the failure, and stays."""
    found = []
    lit = False
    for k, play in enumerate(data["plays"]):
        for anim in play["animations"]:
            node = anim.get("mobject") or {}
            name = node.get("name") or ""
            if name.startswith("lit:") and anim["type"] in INCOMING:
                lit = True
            elif any((c.get("name") or "").startswith(_TOOL_DRAWINGS)
                     for c in node.get("submobjects", ())) and anim["type"] in INCOMING:
                lit = False  # a new tool, not yet at its pick
            elif lit and name in _TOOL_AXES and anim["type"] not in (*INCOMING, *OUTGOING):
                found.append(f"play {k}: {name}")
    return found


#: a tool's dashed tail shorter than this from a vertex reads as a mark on its label ("A′")
SHORTEST_TAIL = 0.4


def tails_beside_labels(data: dict) -> list[str]:
    """The tools (the clock hand, the sweep line) whose dashed line ends in a tail shorter
    than :data:`SHORTEST_TAIL` from a vertex, as ``"play 11: hand beside A"``: one or two
    dashes beyond the vertex, next to its label, read as a prime ("A′", Rotation at 9 s,
    the hand set to A). The line as it comes in, each piece's dashes told by its children."""
    found = []
    for k, shown in _shown_after_plays(data, ("vertex:",)):
        play = data["plays"][k]
        for anim in play["animations"]:
            node = anim.get("mobject") or {}
            parts = node.get("submobjects", ())
            if anim["type"] not in INCOMING or not any(
                    (c.get("name") or "").startswith(_TOOL_DRAWINGS) for c in parts):
                continue
            dots = {name.removeprefix("vertex:"): _centre(dot) for name, marker in shown.items()
                    for dot in marker.get("submobjects", ())[:1] if dot.get("points")}
            for piece in parts:
                if not (piece.get("name") or "").endswith(":outside"):
                    continue
                points = [p[:2] for n in mobject_nodes(piece) for p in n.get("points") or ()]
                if not points:
                    continue
                ends = (points[0], points[-1])
                if math.dist(*ends) >= SHORTEST_TAIL:
                    continue
                for label, at in dots.items():
                    if min(math.dist(e, at) for e in ends) < 0.1:
                        found.append(f"play {k}: {piece['name'].split(':')[0]} beside {label}")
    return found


#: the water's shapes that fill a region cut anew at each step (the walls', the shore's band)
_FILLING = ("water", "flood")
#: the animations that morph one shape into another corner to corner
_MORPHS = {"Transform", "ReplacementTransform", "TransformFromCopy"}


def morphed_water(data: dict) -> list[str]:
    """The plays that take the water (:data:`_FILLING`) from one region to the next by a
    morph, as ``"play 14: water"``: a Transform moves each corner of the first region to a
    corner of the next, so that between two clipped regions it opens dry holes where both
    are wet (Scaling with walls at 10.3 s: a dark box at B) and bends a rising band's
    edge. Water that grows is cut anew in every frame."""
    found = []
    for k, play in enumerate(data["plays"]):
        for anim in play["animations"]:
            name = (anim.get("mobject") or {}).get("name")
            if anim.get("type") in _MORPHS and name in _FILLING:
                found.append(f"play {k}: {name}")
    return found


# --- issue 22 item 5 for the exercises: polygons a class can read --------------------------------

#: the least angle at a vertex, inside or out, as drawn (degrees)
LEAST_ANGLE = 15.0
#: the least gap between a vertex label and an edge or another label (touching is crowding)
LEAST_LABEL_GAP = 0.02


def _exercise_pictures(data: dict) -> Iterator[tuple[list[tuple[float, float]], list[tuple],
                                                      list[tuple[float, float]]]]:
    """Each exercise picture coming on screen: its polygon's corners, its labels, as
    ``(text, box)`` in the order of the corners, and its triangle T's corners."""
    corners: list[tuple[float, float]] | None = None
    triangle: list[tuple[float, float]] = []
    for play in data["plays"]:
        for anim in play["animations"]:
            node = anim.get("mobject") or {}
            if anim.get("type") not in INCOMING or node.get("name") != "exercise":
                continue
            if node["type"] == "Polygon" and node.get("points"):
                shape = _corners(node)
                if corners is None or len(shape) > len(corners):  # P, not its triangle T
                    if corners is not None:
                        triangle = corners
                    corners = shape
                else:
                    triangle = shape
            markers = [m for m in node.get("submobjects", ()) if [c["type"] for c in
                       m.get("submobjects", ())] == ["Dot", "FlatText"]]
            if markers and corners is not None:
                yield corners, [(m["submobjects"][1]["text"], m["submobjects"][1]["box"])
                                for m in markers], triangle
                corners, triangle = None, []


def _inner_angle(p, q, r) -> float:
    import math

    u, v = (p[0] - q[0], p[1] - q[1]), (r[0] - q[0], r[1] - q[1])
    return math.degrees(math.atan2(v[0] * u[1] - v[1] * u[0], v[0] * u[0] + v[1] * u[1])) % 360


def crowded_exercises(data: dict) -> list[str]:
    """Issue 22 items 5 and 6: the exercise pictures a class cannot read, as drawn on screen:
    an angle under :data:`LEAST_ANGLE` (a needle) or over 360° minus it (a notch), a vertex
    nearer than :data:`LEAST_CLEARANCE` to an edge it is not on or to a side of T (its AC:
    is the vertex a candidate or not?), and two vertex labels, or a label and an edge, nearer
    than :data:`LEAST_LABEL_GAP`; as ``"angle at E: 2°"``, ``"H 0.03 from T's side"``."""
    from shapely.geometry import LineString, box
    from shapely.geometry import Point as ShapelyPoint

    found = []
    for corners, labels, triangle in _exercise_pictures(data):
        n = len(corners)
        names = [text for text, _ in labels] if len(labels) == n else [str(k) for k in range(n)]
        if corners[0] == corners[-1]:
            corners = corners[:-1]
            n -= 1
        edges = [LineString([corners[k], corners[(k + 1) % n]]) for k in range(n)]
        t = list(dict.fromkeys(triangle))
        sides = [LineString([t[k], t[(k + 1) % len(t)]]) for k in range(len(t))]
        for v in range(n):
            if not _near(corners[v], t, 1e-3) and sides:
                near = min(side.distance(ShapelyPoint(corners[v])) for side in sides)
                if near < LEAST_CLEARANCE:
                    found.append(f"{names[v]} {near:.2f} from T's side")
        for v in range(n):
            a = _inner_angle(corners[v - 1], corners[v], corners[(v + 1) % n])
            if a < LEAST_ANGLE or a > 360 - LEAST_ANGLE:
                found.append(f"angle at {names[v]}: {a:.0f}°")
            near = min(edges[e].distance(ShapelyPoint(corners[v])) for e in range(n)
                       if v not in (e, (e + 1) % n))
            if near < LEAST_CLEARANCE:
                found.append(f"{names[v]} {near:.2f} from an edge")
        boxes = [(text, box(*b)) for text, b in labels]
        for (t1, b1), (t2, b2) in itertools.combinations(boxes, 2):
            if b1.distance(b2) < LEAST_LABEL_GAP:
                found.append(f"labels {t1} and {t2} touch")
        for text, b in boxes:
            if any(e.distance(b) < LEAST_LABEL_GAP for e in edges):
                found.append(f"label {text} on an edge")
    return found


# --- issue 22: no text under a moving shape --------------------------------------------------------

#: the margin round the polygon's box that a sweeping line is drawn in
#: (:func:`metaphors.sweep._long_line`): the long invisible axis is cut to it on screen
SWEEP_MARGIN = 0.35


def _segment(node: dict) -> tuple[tuple[float, float], tuple[float, float]]:
    """A line node's ends."""
    (x0, y0, _), (x1, y1, _) = node["points"][0], node["points"][-1]
    return (x0, y0), (x1, y1)


def _fan(hub, tip, towards):
    """The fan a hand from ``hub`` to ``tip`` sweeps turning (the short way) until it points
    at ``towards``."""
    import math

    from shapely.geometry import Polygon as Region

    start = math.atan2(tip[1] - hub[1], tip[0] - hub[0])
    turn = (math.atan2(towards[1] - hub[1], towards[0] - hub[0]) - start + math.pi) \
        % (2 * math.pi) - math.pi
    r = math.dist(hub, tip)
    steps = max(2, math.ceil(abs(math.degrees(turn)) / 3) + 1)
    return Region([hub, *((hub[0] + r * math.cos(start + turn * k / (steps - 1)),
                           hub[1] + r * math.sin(start + turn * k / (steps - 1)))
                          for k in range(steps))]).buffer(0)


def _centre(node: dict) -> tuple[float, float]:
    points = node["points"]
    return (sum(p[0] for p in points) / len(points), sum(p[1] for p in points) / len(points))


def notes_under_moving_tools(data: dict) -> list[str]:
    """The notes on the picture (:data:`_NOTES`) that a tool moving after them sweeps over
    while they are up, as ``"'outside P, inside T' under the sweep"``: the sweeping line's
    path from where it starts to where it stops (cut to the picture as it is drawn), or the
    clock hand's fan up to the candidate it lights next. Only the moves' ends are recorded,
    so the path between them is the one the tool takes: a translation, a turn about the hub."""
    from shapely.geometry import MultiPoint
    from shapely.geometry import box as rectangle

    plays = data["plays"]
    notes: dict[str, tuple[str, tuple]] = {}
    picture = None
    found = set()
    for k, play in enumerate(plays):
        for anim in play["animations"]:
            node = anim.get("mobject", {})
            name = node.get("name")
            if name in _POLYGONS and anim.get("type") in INCOMING and node.get("points"):
                x0, y0, x1, y1 = _box_of(node)
                picture = rectangle(x0 - SWEEP_MARGIN, y0 - SWEEP_MARGIN, x1 + SWEEP_MARGIN,
                                    y1 + SWEEP_MARGIN)
            for words, box in _notes(node):
                if anim.get("type") in OUTGOING:
                    notes.pop(words, None)
                else:
                    notes[words] = (words, box)
            swept = None
            if name == "sweep" and "target" in anim and node.get("points"):
                ends = [*_segment(node), *_segment(anim["target"])]
                swept = MultiPoint(ends).convex_hull
                swept = swept.intersection(picture) if picture is not None else swept
            elif name == "hand" and anim.get("type") == "Rotate" and node.get("points"):
                lit = next((a["mobject"] for later in plays[k + 1:k + 2]
                            for a in later["animations"]
                            if (a.get("mobject", {}).get("name") or "").startswith("lit:")), None)
                if lit is not None:
                    hub, tip = _segment(node)
                    swept = _fan(hub, tip, _centre(lit))
            if swept is None or swept.is_empty:
                continue
            for text, (x0, y0, x1, y1) in notes.values():
                if rectangle(x0, y0, x1, y1).intersects(swept):
                    found.add(f"{text!r} under the {name}")
    return sorted(found)


#: the metaphors' faces drawn round a vertex (the clock's dial): a vertex label under one is
#: read through its fill and rim
_FACES = ("dial",)


def _outline(node: dict):
    """A closed node's outline as a shapely polygon: its curves' anchor points."""
    from shapely.geometry import Polygon as Region

    corners = [(x, y) for x, y, _ in node["points"][::4]]
    return Region(corners).buffer(0) if len(corners) >= 3 else None


def _with_labels(data: dict) -> Iterator[tuple[dict, dict[str, tuple[float, float, float, float]]]]:
    """Every animation of the graph with the vertex labels on screen once it has played: those
    of the polygon drawn last, each at the place it was last drawn (a polygon coming in
    begins a new picture)."""
    labels: dict[str, tuple[float, float, float, float]] = {}
    for play in data["plays"]:
        for anim in play["animations"]:
            node = anim.get("mobject", {})
            if anim.get("type") in INCOMING and node.get("name") in _POLYGONS:
                labels = {}
            for key in ("mobject", "target"):
                labels.update(dict(_named_label_boxes(anim.get(key, {}))))
            yield anim, labels


#: the parts of a tool's drawing only a word on screen could explain: a face round its hub,
#: its hour marks
_UNSAID_PARTS = ("dial", "mark:")
#: the words that would say what they are
_FACE_WORDS = re.compile(r"\b(?:dial|face|hour marks?)\b", re.IGNORECASE)


def unexplained_tool_parts(data: dict) -> list[str]:
    """The parts of a tool drawn (:data:`_UNSAID_PARTS`) that no caption, title or legend
    says anything of, as ``"dial"``, ``"mark:D"``: the clock's grey wedge at its hub (33 px
    at B, 15–25 px at C) and the amber tick it lit on the hand at the pick read as nothing
    (review of the rotation scenes)."""
    said = any(_FACE_WORDS.search(text) for text in _all_shown_texts(data, frozenset()))
    if said:
        return []
    found = set()
    for play in data["plays"]:
        for anim in play["animations"]:
            for node in animation_nodes(anim):
                name = node.get("name") or ""
                if anim.get("type") in INCOMING and name.startswith(_UNSAID_PARTS):
                    found.add(name)
    return sorted(found)


def labels_under_faces(data: dict) -> list[str]:
    """The vertex labels a face (:data:`_FACES`) covers, as ``"the dial covers B"``; the labels
    are those of the polygon drawn last before the face, at the places they were last
    drawn."""
    from shapely.geometry import box as rectangle

    found = set()
    for anim, labels in _with_labels(data):
        node = anim.get("mobject", {})
        if anim.get("type") not in INCOMING:
            continue
        for part in mobject_nodes(node):
            if part.get("name") not in _FACES or not part.get("points"):
                continue
            face = _outline(part)
            if face is None:
                continue
            found |= {f"the {part['name']} covers {v}" for v, box in labels.items()
                      if face.intersects(rectangle(*box))}
    return sorted(found)


# --- issue 22 item 4: the correction stays inside P ------------------------------------------------

#: how much of the water may lie outside its polygon on screen (float clipping's slivers)
MOST_WATER_OUTSIDE = 1e-3
#: the polygons a metaphor's shading is drawn on: a run's, an analysis's, a card's figure's
_PICTURES = (*_POLYGONS, "figure:polygon")
#: the least corners of a water shape on one circle round a vertex for it to be spilt water
_DISK_CORNERS = 12


def _colour(name: str) -> str:
    """A colour of the legend (:data:`metaphors.theme.THEME`) as the graph writes it."""
    from metaphors.theme import THEME

    return str(getattr(THEME, name)).upper()


def _paths(node: dict) -> list[list[tuple[float, float]]]:
    """A node's closed paths as lists of corners: a path ends where the next curve does not
    start at the last one's end."""
    points = [tuple(p[:2]) for p in node.get("points", ())]
    paths: list[list[tuple[float, float]]] = []
    for k in range(0, len(points) - 3, 4):
        a, b = points[k], points[k + 3]
        if not paths or paths[-1][-1] != a:
            paths.append([a])
        paths[-1].append(b)
    return [p for p in paths if len(p) >= 4]


def _filled_in(node: dict, colours: set[str]) -> bool:
    return (node.get("fill") or "").upper() in colours and (node.get("fill_opacity") or 0) > 0 \
        and bool(node.get("points"))


def _shaded(anim: dict, colours: set[str]) -> Iterator[dict]:
    """The parts of an animation's mobjects (and targets) filled in one of ``colours``, but
    the legend's swatches (beside the picture, not on it)."""
    def walk(node: dict) -> Iterator[dict]:
        if (node.get("name") or "").startswith("legend:"):
            return
        if _filled_in(node, colours):
            yield node
        for child in node.get("submobjects", ()):
            yield from walk(child)

    for _kind, node in _recorded(anim):
        yield from walk(node)


def _spilt(corners: list[tuple[float, float]], polygon: list[tuple[float, float]]) -> bool:
    """Whether a water shape is water spilt at a vertex (Scaling's): a disk round one of the
    polygon's corners, cut only by straight lines (where the picture's part of the screen
    ends): at least :data:`_DISK_CORNERS` of its corners on one circle round it, none
    beyond."""
    import math

    for x, y in polygon:
        far = [math.hypot(px - x, py - y) for px, py in corners]
        radius = max(far)
        if radius > 1e-6 and sum(r > radius * 0.995 for r in far) >= _DISK_CORNERS:
            return True
    return False


def water_outside_polygon(data: dict) -> list[str]:
    """The water (any shape filled in the legend's water colour, whatever its name: the
    rising water of Correct Scaling, a run's and an analysis's) drawn outside the polygon it
    is drawn on (the last drawn, :data:`_PICTURES`), as ``"play 62 FadeOut Line: 0.42
    outside P"`` (square units on screen, the most of each shape name): the corrections'
    water is shown inside P, or the blue would say "inside" where the legend's red says
    "outside P". Not judged: water spilt at a vertex (:func:`_spilt`), Scaling's disk, which
    spreads over P's edges by design (its metaphor; the analysis turns the part outside P
    red), and the legend's swatches."""
    from shapely.geometry import Polygon as Region

    water = {_colour("water")}
    polygon = corners = None
    found: dict[str, tuple[float, str]] = {}
    for k, play in enumerate(data["plays"]):
        for anim in play["animations"]:
            node = anim.get("mobject", {})
            if node.get("name") in _PICTURES and anim.get("type") in INCOMING \
                    and node.get("points"):
                corners = _corners(node)
                polygon = Region(corners).buffer(0)
            if polygon is None:
                continue
            for part in _shaded(anim, water):
                for piece in (c for n in mobject_nodes(part) for c in _paths(n)):
                    if _spilt(piece, corners):
                        continue
                    spilt = Region(piece).buffer(0).difference(polygon).area
                    name = part.get("name") or part.get("type") or "?"
                    if spilt > MOST_WATER_OUTSIDE and spilt > found.get(name, (0.0, ""))[0]:
                        found[name] = (spilt, f"play {k} {anim['type']} {name}")
    return [f"{where}: {area:.2f} outside P" for area, where in sorted(found.values(),
                                                                         key=lambda f: f[1])]


#: how much of a swept region may lie outside its polygon, not turned red (slivers)
MOST_SWEPT_OUTSIDE = 1e-2


def swept_outside_polygon(data: dict) -> list[str]:
    """The swept regions (filled in the legend's swept colour, whatever their name: what the
    water, the hand or the line swept) whose part outside the polygon they are drawn on
    (:data:`_PICTURES`: a run's, an analysis's, a card's figure's) is never shown red in that
    picture, as ``"play 63 figure:polygon: 1.20 outside P"`` (square units on screen, for
    each picture): the legend's swept blue means inside, red outside P. The wrong
    heuristic's pass shows the swept part outside P pale blue while the tool moves and red
    once it stops (a red shape over it); a card's figure comes before that pass and shows
    the swept region inside P only. A picture ends when the next polygon comes in."""
    from shapely.geometry import Polygon as Region
    from shapely.ops import unary_union

    swept, red = {_colour("swept")}, {_colour("rejected")}
    found = []
    picture: tuple[int, str] | None = None
    polygon = None
    outside: list = []
    shown_red: list = []

    def close() -> None:
        if picture is not None and outside:
            left = unary_union(outside).difference(unary_union(shown_red)).area if shown_red \
                else unary_union(outside).area
            if left > MOST_SWEPT_OUTSIDE:
                found.append(f"play {picture[0]} {picture[1]}: {left:.2f} outside P")

    for k, play in enumerate(data["plays"]):
        for anim in play["animations"]:
            node = anim.get("mobject", {})
            if node.get("name") in _PICTURES and anim.get("type") in INCOMING \
                    and node.get("points"):
                close()
                picture, polygon, outside, shown_red = (k, node["name"]), \
                    Region(_corners(node)).buffer(0), [], []
            if polygon is None:
                continue
            for part in _shaded(anim, swept):
                outside += [Region(c).buffer(0).difference(polygon) for c in _paths(part)]
            for part in _shaded(anim, red):
                shown_red += [Region(c).buffer(0) for c in _paths(part)]
    close()
    return found


#: the drawn pieces of a moving tool's line (:func:`metaphors.sweep.drawn_segment`)
_TOOL_PIECES = ("sweep:", "hand:")
#: a tool's line drawn whole, under its own name: the monotone partition's sweep line was
#: one dashed line ("sweep"), through every label at its height
_TOOL_LINES = ("sweep",)


def labels_under_tools(data: dict) -> list[str]:
    """The vertex labels a tool's drawn line runs through where it is recorded (as it
    appears and as it is cleared away: where it stopped), as ``"the sweep runs through A"``;
    the labels are those of the polygon drawn last."""
    from shapely.geometry import LineString
    from shapely.geometry import box as rectangle

    found = set()
    for anim, labels in _with_labels(data):
        node = anim.get("mobject", {})
        for piece in mobject_nodes(node):
            name = piece.get("name") or ""
            if not name.startswith(_TOOL_PIECES) and name not in _TOOL_LINES:
                continue
            for part in mobject_nodes(piece):  # a dashed line's dashes
                if len(part.get("points", ())) < 2 or (part.get("stroke_opacity") or 0) == 0:
                    continue
                line = LineString([p[:2] for p in part["points"]])
                found |= {f"the {name.split(':')[0]} runs through {v}"
                          for v, (x0, y0, x1, y1) in labels.items()
                          if line.intersects(rectangle(x0 + 0.005, y0 + 0.005, x1 - 0.005,
                                                       y1 - 0.005))}
    return sorted(found)


# --- issue 22: a vertex label is read clear of the lines drawn ------------------------------------

#: the board's drawn segments a vertex label must not meet: its outline's edges, the
#: diagonals drawn on it, the triangles' edges (a piece done, the whole triangulation) and a
#: run's claim (Correct Scaling's BE ran through E's label)
_SEGMENT_OWNERS = ("polygon", "analysis:polygon", "diagonal:", "triangle", "triangulation",
                   "ear-triangle", "claim")
#: the owners of which several are shown under one name (each piece's triangles)
_MANY = ("triangle", "triangulation")


def _segments(node: dict) -> list[tuple[tuple[float, float], tuple[float, float]]]:
    """The straight pieces of a drawn outline or line: manim's points come four a curve,
    the first and the last the ends of an edge (several rings, with holes, are not joined)."""
    points = node.get("points") or []
    return [(tuple(points[k][:2]), tuple(points[k + 3][:2])) for k in range(0, len(points) - 3, 4)
            if points[k][:2] != points[k + 3][:2]]


def _ends(anim: dict) -> Iterator[tuple[str, dict, str]]:
    """(the animation's type, node, name) of every top mobject an animation (or its members)
    has: its mobject, then its target, the state the mobject ends in, under the mobject's
    name (a transform into a new shape: the fruit's outline as its slices go)."""
    own = (anim.get("mobject") or {}).get("name") or ""
    for key in ("mobject", "target"):
        if key in anim:
            yield anim["type"], anim[key], own or anim[key].get("name") or ""
    for child in anim.get("animations", ()):
        yield from _ends(child)


def _shown_after_plays(data: dict, names: tuple[str, ...], many: tuple[str, ...] = (),
                       by_corners: bool = False) -> Iterator[tuple[int, dict[str, dict]]]:
    """After each play ``k``, the things on screen whose names start with one of ``names``,
    by name, as the play leaves them: a thing faded out is gone, and one a turn moves is
    unknown until it is recorded again (a turn records where it starts, not where it leaves
    the thing). A polygon coming in begins a new picture. Of the ``many`` shown under one
    name (each piece's triangles), each is told by where it starts, or ``by_corners``, by
    all its points (two triangles of a fan start at one corner)."""
    shown: dict[str, dict] = {}
    for k, play in enumerate(data["plays"]):
        for anim in play["animations"]:
            top = anim.get("mobject") or {}
            if anim.get("type") in INCOMING and top.get("name") in _POLYGONS:
                shown = {}
            for kind, node, named in _ends(anim):
                for part in mobject_nodes(node):
                    name = named if part is node else part.get("name") or ""
                    if many and name.startswith(many) and part.get("points"):
                        name += f"@{part['points'] if by_corners else part['points'][0]}"
                    if name.startswith(names):
                        if kind in OUTGOING or kind == "Turn":
                            shown.pop(name, None)
                        else:
                            shown[name] = part
        yield k, shown


def crossed_vertex_labels(data: dict) -> list[str]:
    """The board's vertex labels that a drawn segment meets, as ``"play 93 K × diagonal:IM"``
    or ``"play 12 K × polygon"`` (each label and segment once, at the first play it shows):
    a label an edge or a diagonal runs through reads as part of the line, or names the wrong
    vertex. The label, the outline and the diagonals are as the play leaves them; a thing
    faded out is gone, and one a turn moves is unknown until it is recorded again (a turn
    records where it starts). A polygon coming in begins a new picture."""
    from shapely.geometry import LineString
    from shapely.geometry import box as area

    found: dict[tuple[str, str], str] = {}
    for k, shown in _shown_after_plays(data, ("vertex:", *_SEGMENT_OWNERS), many=_MANY):
        lines = {name: [LineString(s) for s in _segments(node)] for name, node in shown.items()
                 if name.startswith(_SEGMENT_OWNERS)}
        for name, marker in shown.items():
            if not name.startswith("vertex:"):
                continue
            for label in _label_boxes(marker, direct=True):
                shape = area(*label)
                for owner, segments in lines.items():
                    if any(shape.intersects(s) for s in segments):
                        drawn = owner.partition("@")[0]
                        found.setdefault((name, drawn),
                                         f"play {k} {name.removeprefix('vertex:')} × {drawn}")
    return sorted(found.values(), key=lambda s: int(s.split()[1]))


def labels_on_claims(data: dict, margin: float = 0.05) -> list[str]:
    """Issue 22: the analyses' vertex labels nearer than ``margin`` (the labels' own margin
    from an edge, :data:`metaphors.labels.MARGIN`) to a claim the analysis draws, as
    ``"play 60 E: 0.00 from analysis:claim"``: a label on the claim reads as part of it. The
    labels as the analysis's picture last put them up."""
    from shapely.geometry import LineString
    from shapely.geometry import box as area

    shown: dict[str, dict] = {}
    found = []
    for k, play in enumerate(data["plays"]):
        for anim in play["animations"]:
            node = anim.get("mobject") or {}
            name = node.get("name") or ""
            if name.startswith("vertex:") and anim["type"] in INCOMING:
                shown[name] = node
            if name == "analysis:claim" and anim["type"] in INCOMING and node.get("points"):
                points = node["points"]
                claim = LineString([points[0][:2], points[-1][:2]])
                for vertex, marker in shown.items():
                    near = min((area(*b).distance(claim) for b in _label_boxes(marker,
                                                                                  direct=True)),
                               default=margin)
                    if near < margin:
                        found.append(f"play {k} {vertex.removeprefix('vertex:')}: {near:.2f} "
                                     f"from {name}")
    return found


# --- issue 22: a ✓ stands beside its claim inside P ---------------------------------------------

#: the marks of a correct claim: an analysis's and a run's (:mod:`metaphors.basics`, placed
#: by :mod:`metaphors.marks`). Not judged: the ✓ that begins a caption ("✓ BE is an inner
#: diagonal"), which is the subtitle's, under the picture
_TICKS = ("analysis:tick", "tick")


def _luminance(colour: str) -> float:
    """The relative luminance (0 black, 1 white) of a ``#rrggbb`` colour."""
    r, g, b = (int(colour.lstrip("#")[k:k + 2], 16) / 255 for k in (0, 2, 4))
    return 0.2126 * r + 0.7152 * g + 0.0722 * b


def bare_ticks(data: dict) -> list[str]:
    """Issue 22: the analyses' green ✓ marks that come in without their dark halo (a filled,
    thickly stroked silhouette in a dark colour, in the same play), as ``"play 61"``: green on
    the green witness shading does not read. (A run's ✓ comes once its shading is gone.)"""
    found = []
    for k, play in enumerate(data["plays"]):
        came = [node for a in play["animations"] for kind, node in _recorded(a)
                if kind in INCOMING]
        ticks = [n for n in came if n.get("name") == "analysis:tick"]
        halos = [n for n in came if n.get("name") == "analysis:tick:halo"
                 and (n.get("fill_opacity") or 0) >= 0.99 and (n.get("stroke_width") or 0) >= 4
                 and _luminance(n["fill"]) < 0.15 and _luminance(n["stroke"]) < 0.15]
        if ticks and len(halos) < len(ticks):
            found.append(f"play {k}")
    return found


def ticks_outside(data: dict) -> list[str]:
    """The ✓ marks (:data:`_TICKS`) not wholly inside their polygon, as ``"play 60
    analysis:tick: 0.83 outside P"`` (how far its box reaches out): a ✓ past an edge seems
    to judge that edge, and a correct claim lies inside P, where there is room for its mark.
    The polygon is as the play shows it (:func:`_marks_on_polygons`): the last drawn before
    the mark, or the ear clipping's fruit as it has shrunk; a ✓ on a turned picture is
    judged as it comes in and again as it leaves, once the picture is upright."""
    from shapely.geometry import Point, Polygon
    from shapely.geometry import box as area

    found = []
    boxed = ticks_by_the_box(data)  # the black box's answer, beside it: off P on purpose
    for k, tick, polygon, _ in _marks_on_polygons(data, _TICKS, settled=True):
        box = _box_of(tick)
        if box is not None and tuple(box) in boxed:
            continue
        if polygon is None or box is None:
            found.append(f"play {k} {tick['name']}: no polygon drawn")
            continue
        shape = area(*box)
        region = Polygon(_corners(polygon))
        if not region.buffer(1e-6).contains(shape):
            reach = max(region.distance(Point(p)) for p in shape.exterior.coords)
            found.append(f"play {k} {tick['name']}: {reach:.2f} outside P")
    return found


# --- issue 22: the ball's fall is seen, no label under it -------------------------------------

#: the least gap (scene units) a vertex label keeps from the hit ring and from the ball's path
FALL_GAP = 0.08
#: the ball's radius (:func:`metaphors.gravity._ball`): its path is that wide either side
BALL_RADIUS = 0.12


def labels_under_the_fall(data: dict) -> list[str]:
    """The vertex labels within :data:`FALL_GAP` of gravity's hit ring, or of the ball's path
    down to it, while the ring is up, as ``"play 14 E under the fall"``: a label the ring
    circles hides where the ball hit, the decisive moment. The path is the band's straight
    drop (its shape when the ring comes in), as wide as the ball and cut square at V (V's own
    label stands beside the ball hanging there); a label counts where it was recorded since
    the last turn (a turn records where it starts)."""
    from shapely.geometry import LineString, Point
    from shapely.geometry import box as rectangle

    fresh: dict[str, tuple[float, float, float, float]] = {}
    band: list = []
    fall = None
    radius: float | None = None  # the ring's, while it turns with the picture (a close-up)
    found: dict[str, str] = {}
    for k, play in enumerate(data["plays"]):
        for anim in play["animations"]:
            node = anim.get("mobject") or {}
            if anim.get("type") == "Turn" or (anim.get("type") in INCOMING
                                              and node.get("name") in _POLYGONS):
                fresh = {}
                if node.get("name") == "hit" and fall is not None:
                    # the ring turns (a close-up zooms back): where it ends is not recorded,
                    # but the band's next shape is, still straight down to it
                    pts = [p[:2] for p in node["points"]]
                    radius, fall = (max(p[0] for p in pts) - min(p[0] for p in pts)) / 2, None
                continue
            for key in ("mobject", "target"):
                part = anim.get(key) or {}
                fresh.update(dict(_named_label_boxes(part)))
                if part.get("name") == "band" and part.get("points"):
                    band = part["points"]
                    if radius is not None and band[0][:2] != band[-1][:2]:
                        fall = Point(band[-1][:2]).buffer(radius).union(
                            LineString([band[0][:2], band[-1][:2]]).buffer(BALL_RADIUS,
                                                                           cap_style=2))
                        radius = None
            if node.get("name") == "hit" and node.get("points"):
                if anim.get("type") in OUTGOING:
                    fall, radius = None, None
                elif anim.get("type") in INCOMING:
                    pts = [p[:2] for p in node["points"]]
                    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
                    centre = ((min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2)
                    ring = Point(centre).buffer((max(xs) - min(xs)) / 2)
                    path = (LineString([band[0][:2], band[-1][:2]]).buffer(BALL_RADIUS, cap_style=2)
                            if len(band) >= 2 and band[0][:2] != band[-1][:2] else ring)
                    fall = ring.union(path)
        if fall is not None:
            for v, box in fresh.items():
                if fall.distance(rectangle(*box)) < FALL_GAP:
                    found.setdefault(v, f"play {k} {v} under the fall")
    return sorted(found.values(), key=lambda s: int(s.split()[1]))


# --- issue 22: a label is read clear of ear clipping's red test triangle ------------------------

#: the red triangle of a vertex that is not an ear (:func:`metaphors.fruit.ear_test`)
_TEST_TRIANGLES = ("ear-triangle", "ear-angle")
#: a dark card under a label the triangle could not be kept off (its vertex inside it)
_BACKINGS = "backing:"
#: how opaque a card must be to read a label on it
LEAST_BACKING = 0.6
#: the least gap between a haloed label inside a test triangle and the triangle's edges
#: (:func:`labels_under_test_triangles`)
LEAST_EDGE_GAP = 0.03


def labels_under_test_triangles(data: dict) -> list[str]:
    """The vertex labels that a red test triangle lies over, as ``"play 60 c₂ under the
    ear-triangle"``: a label on its red over the fruit's orange is hard to read (a red label
    all but vanishes), and an edge through it reads as part of the line. The labels and the
    triangle are as :func:`crossed_vertex_labels` follows them; a triangle counts once it is
    drawn (its fill or its edge up). A label on a dark card (``backing:V``, at least
    :data:`LEAST_BACKING` opaque, covering the label) reads, its vertex inside the triangle;
    so does a label with a dark halo (:func:`_haloed`, as every label on the fruit has) that
    no edge of the triangle comes within :data:`LEAST_EDGE_GAP` of: a card under it was a
    box no other label had (ear clipping's G)."""
    from shapely.geometry import Polygon
    from shapely.geometry import box as area

    found: dict[str, str] = {}
    for k, shown in _shown_after_plays(data, ("vertex:", _BACKINGS, *_TEST_TRIANGLES)):
        triangles = [(name, Polygon(_corners(node))) for name, node in shown.items()
                     if name.startswith(_TEST_TRIANGLES) and len(node.get("points") or []) >= 12
                     and ((node.get("fill_opacity") or 0) > 0
                          or (node.get("stroke_opacity") or 0) > 0)]
        for name, marker in shown.items():
            if not name.startswith("vertex:"):
                continue
            vertex = name.removeprefix("vertex:")
            card = shown.get(_BACKINGS + vertex)
            backed = (None if card is None or (card.get("fill_opacity") or 0) < LEAST_BACKING
                      or _box_of(card) is None else area(*_box_of(card)))
            haloed = any(_haloed(part) for part in marker.get("submobjects", ())
                         if (part.get("text") or "").strip())
            for label in _label_boxes(marker, direct=True):
                if backed is not None and backed.buffer(1e-6).contains(area(*label)):
                    continue
                for owner, triangle in triangles:
                    if haloed and triangle.exterior.distance(area(*label)) >= LEAST_EDGE_GAP:
                        continue
                    if triangle.intersects(area(*label)):
                        found.setdefault(f"{vertex} {owner}",
                                         f"play {k} {vertex} under the {owner}")
    return sorted(found.values(), key=lambda s: int(s.split()[1]))


# --- issue 22: gravity's fall is seen ------------------------------------------------------------

#: the least a ball's drawn fall may be: 4 % of the frame's height (8 units)
LEAST_FALL = 0.32


def short_falls(data: dict) -> list[str]:
    """The balls whose drawn fall, from V down to where they hit, is under
    :data:`LEAST_FALL`, as ``"play 61 fall 0.26"``: Gravity is correct, but its metaphor
    must be seen, the ball falling and hitting (on the counterexample it fell 16 px at 480p,
    under its own size). A fall is the band stretching from a point (the ball hanging at V)
    to the hit, as it is drawn then (a close-up zooms it)."""
    def transforms(anim: dict) -> Iterator[dict]:
        if anim.get("type") == "Transform":
            yield anim
        for child in anim.get("animations", ()):
            yield from transforms(child)

    found = []
    for k, play in enumerate(data["plays"]):
        for anim in (t for top in play["animations"] for t in transforms(top)):
            start = (anim.get("mobject") or {}).get("points") or []
            end = (anim.get("target") or {}).get("points") or []
            if (anim["mobject"].get("name") != "band" or not start or not end
                    or start[0][:2] != start[-1][:2]):
                continue  # not the drop: the band already stretched (the slide, the snag)
            fall = ((end[-1][0] - start[0][0]) ** 2 + (end[-1][1] - start[0][1]) ** 2) ** 0.5
            if fall < LEAST_FALL:
                found.append(f"play {k} fall {fall:.2f}")
    return found


# --- issue 22: a finished run's labels in one colour ------------------------------------------


def mixed_ending_labels(data: dict) -> list[str]:
    """The colours of the vertex labels, on the board and in the panel, of a scene that ends
    on its whole triangulation, as ``["#8A93A3 A, B", "#E8ECF2 E"]``, when they are not all
    the ink the labels are drawn in: once no call runs, grey ("not in the current call")
    means nothing, and two colours of label would seem to sort the vertices in two kinds.
    Judged on the scene's last picture (``final``); an empty list when it shows no
    triangulation, or all its labels are in ink."""
    final = data.get("final") or []
    if not any(top.get("name") == "triangulation" for top in final):
        return []
    colours: dict[str, list[str]] = {}
    for top in final:
        name = top.get("name") or ""
        parts = top.get("submobjects", ())
        if not (name.startswith(("vertex:", "panel:")) and any(
                part.get("type") == "Dot" for part in parts)):  # a marker: its dot, its label
            continue
        for part in parts:
            if part.get("text"):
                colours.setdefault(str(part.get("fill")).upper(), []).append(part["text"])
    if set(colours) <= {_colour("ink")}:
        return []
    return [f"{colour} {', '.join(sorted(set(labels)))}" for colour, labels in sorted(colours.items())]


# --- issue 22: a label reads on whatever it stands over ---------------------------------------

#: the least contrast (WCAG's ratio, 1 to 21) between a vertex label's colour and a fill it
#: stands over: 3 : 1, WCAG's least for large text (a grey, red or green label on ear
#: clipping's orange fruit is about 1.1 : 1, white on it 2.9 : 1)
LEAST_CONTRAST = 3.0
#: a halo behind a label's glyphs that lets it read on any fill: dark, opaque, this wide
HALO_WIDTH = 4.0
#: the filled things a label may stand over: the polygon (ear clipping's fruit), the slices.
#: Not yet a whole triangulation's triangles: grey labels on their tints are 2.8 : 1 at the
#: end of DivideAndConquer (G) and HolesSweep (c₁)
_FILLED = ("polygon", "slice:")


def _relative_luminance(colour: str) -> float:
    """WCAG's relative luminance of a ``#rrggbb`` colour (its channels made linear)."""
    def linear(c: float) -> float:
        return c / 12.92 if c <= 0.03928 else ((c + 0.055) / 1.055) ** 2.4

    r, g, b = (linear(int(colour.lstrip("#")[k:k + 2], 16) / 255) for k in (0, 2, 4))
    return 0.2126 * r + 0.7152 * g + 0.0722 * b


def contrast(a: str, b: str) -> float:
    """WCAG's contrast ratio of two ``#rrggbb`` colours (1: the same; 21: black and white).

    >>> round(contrast("#000000", "#ffffff"), 1), contrast("#8a93a3", "#8a93a3")
    (21.0, 1.0)
    """
    light, dark = sorted((_relative_luminance(a), _relative_luminance(b)), reverse=True)
    return (light + 0.05) / (dark + 0.05)


def _over(fill: str, opacity: float, background: str) -> str:
    """``fill`` at ``opacity`` over ``background``, as the screen shows it."""
    return "#" + "".join(
        f"{round(opacity * int(fill.lstrip('#')[k:k + 2], 16) + (1 - opacity) * int(background.lstrip('#')[k:k + 2], 16)):02x}"
        for k in (0, 2, 4))


def _one_colour(value) -> str | None:
    return value if isinstance(value, str) else (value[0] if value else None)


def _haloed(node: dict) -> bool:
    """Whether a text node has a dark, opaque halo at least :data:`HALO_WIDTH` wide."""
    halo = node.get("halo") or {}
    colour = _one_colour(halo.get("stroke"))
    return (colour is not None and _luminance(colour) < 0.15
            and (halo.get("stroke_opacity") or 0) >= 0.99
            and (halo.get("stroke_width") or 0) >= HALO_WIDTH)


def labels_without_contrast(data: dict) -> list[str]:
    """The vertex labels that stand over a fill (:data:`_FILLED`) they do not read on, as
    ``"play 12 M on polygon 1.1 : 1"``: the contrast between the label's colour and the fill
    as the screen shows it (over the background) is under :data:`LEAST_CONTRAST`, and the
    label has no dark halo (:func:`_haloed`). A grey M, a red G or a green C on ear
    clipping's orange fruit all but vanish. And the labels a fill is drawn over (it came in
    after them, :func:`_layers`), as ``"play 105 M under polygon 1.4 : 1"``: seen through the
    fill (a halo under it too), the label against the fill (chapter 4's M, H and G light
    orange on the fruit faded back in after gravity's close-up). Each label and fill as
    :func:`_shown_after_plays` follows them; each vertex is named once, where it first fails."""
    from shapely.geometry import box as area

    found: dict[str, str] = {}
    layers = _layers(data)
    for k, shown in _shown_after_plays(data, ("vertex:", *_FILLED)):
        fills = _fills(shown)
        layer = next(layers)
        for name, marker in shown.items():
            if not name.startswith("vertex:"):
                continue
            vertex = name.removeprefix("vertex:")
            for part in marker.get("submobjects", ()):
                colour = _one_colour(part.get("fill"))
                if (not part.get("box") or not (part.get("text") or "").strip()
                        or colour is None or not drawn(part)):
                    continue
                for owner, shape, fill, under in fills:
                    if not shape.intersects(area(*part["box"])):
                        continue
                    if layer.get(owner, 0) > layer.get(name, 0):  # the fill drawn over it
                        ratio = contrast(_over(*fill, colour), under)
                        words = f"{vertex} under {owner}"
                    elif _haloed(part):
                        continue
                    else:
                        ratio, words = contrast(colour, under), f"{vertex} on {owner}"
                    if ratio < LEAST_CONTRAST:
                        found.setdefault(vertex, f"play {k} {words} {ratio:.1f} : 1")
    return sorted(found.values(), key=lambda s: int(s.split()[1]))


def _fills(shown: dict[str, dict]) -> list[tuple[str, Any, tuple[str, float], str]]:
    """The fills (:data:`_FILLED`) of what is shown: their names, shapes, colours and
    opacities, and colours as the screen shows them over the background."""
    from shapely.geometry import Polygon

    from metaphors.theme import THEME

    fills = []
    for name, node in shown.items():
        colour = _one_colour(node.get("fill"))
        if not name.startswith(_FILLED) or colour is None or (node.get("fill_opacity") or 0) <= 0:
            continue
        rings = sorted((Polygon(p) for p in _paths(node) if Polygon(p).is_valid),
                       key=lambda r: -r.area)
        if not rings:
            continue
        shape = Polygon(rings[0].exterior, [r.exterior for r in rings[1:]])
        opacity = float(node["fill_opacity"])
        fills.append((name.split("@")[0], shape, (colour, opacity),
                      _over(colour, opacity, THEME.background)))
    return fills


def _layers(data: dict) -> Iterator[dict[str, int]]:
    """After each play, where each top mobject shown stands in the drawing order, by name
    (higher: drawn over lower): a mobject coming in, or first recorded, goes over all there
    are (as manim adds it); one going leaves."""
    layer: dict[str, int] = {}
    high = 0
    for play in data["plays"]:
        for anim in play["animations"]:
            for kind, _, name in _ends(anim):
                if kind in OUTGOING:
                    layer.pop(name, None)
                elif kind in INCOMING or name not in layer:
                    high += 1
                    layer[name] = high
        yield layer


# --- issue 22: labels named together read as labels ------------------------------------------

#: a subscripted label run into a lower-case one (``a₂b₂``): it reads as one word
_RUN_TOGETHER = re.compile(r"[a-z][₀-₉′″]+[a-z][₀-₉′″]*")


def run_together_labels(data: dict) -> list[str]:
    """The captions and texts on screen (not the call line: code) that write a subscripted
    label straight before a lower-case one, as ``"'Slice a₂b₂H: 17 / 17 slices': a₂b₂"``:
    "a₂b₂H" reads as one word, where "MAB" or "c₂F" read as the letters they are."""
    found: dict[str, str] = {}
    for text in _all_shown_texts(data, frozenset({"panel:call"})):
        for match in _RUN_TOGETHER.finditer(text):
            found.setdefault(text, f"{text!r}: {match[0]}")
    return sorted(found.values())


# --- issue 22: the picture's labels stand apart ------------------------------------------------

#: the least gap between the labels of two vertices on the picture (1 % of the frame's
#: height): nearer, they read as one (K stacked 0.07 over M on ear clipping's fruit)
LEAST_LABELS_APART = 0.08


def crowded_vertex_labels(data: dict) -> list[str]:
    """The pairs of vertex labels on the picture nearer than :data:`LEAST_LABELS_APART`, as
    ``"play 6 K M 0.07"``: each pair once, where it first is, the labels as
    :func:`_shown_after_plays` follows them (a polygon coming in begins a new picture)."""
    from shapely.geometry import box as area

    found: dict[tuple[str, str], str] = {}
    for k, shown in _shown_after_plays(data, ("vertex:",)):
        labels = {name.removeprefix("vertex:"): area(*boxes[0]) for name, marker in shown.items()
                  if (boxes := list(_label_boxes(marker, direct=True)))}
        for (v, a), (w, b) in itertools.combinations(sorted(labels.items()), 2):
            gap = a.distance(b)
            if gap < LEAST_LABELS_APART:
                found.setdefault((v, w), f"play {k} {v} {w} {gap:.2f}")
    return sorted(found.values(), key=lambda s: int(s.split()[1]))


# --- issue 22: a run's verdict stands by its claim -------------------------------------------

#: the farthest a run's ✓ or ✗ may stand from the claim it judges (5 % of the frame's
#: height, 24 px at 480p): at 0.73 (44 px), prune and search's ✓ for GB stood over the fruit
#: by H's label, read as judging nothing near it
FARTHEST_MARK = 0.4
#: the names of a run's marks and of its claim
_RUN_MARKS, _CLAIM = ("tick", "cross"), "claim"


def far_verdicts(data: dict) -> list[str]:
    """A run's ✓ or ✗ standing farther than :data:`FARTHEST_MARK` from the claim it judges
    (the last claim drawn before it), as ``"play 115 tick 1.80 from its claim"``: so far
    off, it seems to judge what it stands by (prune and search's ✓ for GB stood outside P
    beside edge AB, then 0.73 off over the fruit)."""
    found = []
    boxed = ticks_by_the_box(data)  # the black box's answer stands by the box, not the claim
    for k, kind, name, mark, claim in _marks_by_claims(data):
        if tuple(mark.bounds) in boxed:
            continue
        if kind in INCOMING and (far := claim.distance(mark)) > FARTHEST_MARK:
            found.append(f"play {k} {name} {far:.2f} from its claim")
    return found


def _marks_by_claims(data: dict) -> Iterator[tuple[int, str, str, Any, Any]]:
    """Each run's ✓ or ✗ a play records, with the claim it judges (the last claim recorded,
    in that play or before): (play, how it is recorded, its name, its box and the claim as
    shapely geometry)."""
    from shapely.geometry import LineString
    from shapely.geometry import box as area

    claim = None
    for k, play in enumerate(data["plays"]):
        records = [(kind, node) for a in play["animations"] for kind, node in _recorded(a)]
        for _, node in records:
            if node.get("name") == _CLAIM and len(node.get("points") or []) >= 2:
                claim = LineString([node["points"][0][:2], node["points"][-1][:2]])
        for kind, node in records:
            box = _box_of(node) if node.get("name") in _RUN_MARKS else None
            if box is not None and claim is not None:
                yield k, kind, node["name"], area(*box), claim


def verdicts_on_claims(data: dict) -> list[str]:
    """A run's ✓ or ✗ whose box crosses the claim it judges (the last claim recorded), as
    ``"play 84 tick over its claim"``, wherever a play records it: as it comes in, and where
    a later play finds it (a turn records where it starts). Chapter 3's ✓ for EC, beside EC
    up close, zoomed back out with the picture onto EC itself (76-78 s): the needle of P it
    stood in shrank under it."""
    found = [f"play {k} {name} over its claim" for k, kind, name, mark, claim
             in _marks_by_claims(data) if kind not in OUTGOING and claim.intersects(mark)]
    return list(dict.fromkeys(found))


# --- r567 item 1: a vertex's colour keeps its meaning ---------------------------------------------

#: the marker names of a vertex: on the picture and on the panel's small map
_VERTEX_MARKERS = ("vertex:", "panel:")
#: the panel's parts that are no vertex: its call line (what it draws is "panel/…")
_PANEL_NOT_VERTICES = ("panel:call",)


def _vertex_label(node: dict) -> str | None:
    """The label of a vertex marker node (``vertex:K``, ``panel:K``), else None."""
    name = node.get("name") or ""
    if name in _PANEL_NOT_VERTICES or not name.startswith(_VERTEX_MARKERS):
        return None
    return name.split(":", 1)[1]


def _given_colours(anim: dict) -> Iterator[tuple[str, str, str]]:
    """(label, colour, how) for each colour an animation gives a vertex marker: the colour
    of a pulse (``Indicate``: it shows while the pulse plays) or of a target's stroke."""
    for child in anim.get("animations", ()):
        yield from _given_colours(child)
    label = _vertex_label(anim.get("mobject") or {})
    if label is None:
        return
    if anim.get("color"):
        yield label, anim["color"].upper(), anim["type"]
    stroke = (anim.get("target") or {}).get("stroke")
    if isinstance(stroke, str):
        yield label, stroke.upper(), "target"


def shifting_vertex_colours(data: dict, legend: dict[str, str], kinds: tuple[str, ...],
                            called: str) -> list[str]:
    """The colours a vertex is given against the one legend, as ``"play 33 B Indicate
    #FFFF00: in no legend"`` or ``"play 27 K #4F8FF7: merge, then called"``: every colour
    a vertex is given (a pulse's too) is one of ``legend``'s (name → colour, the theme's),
    and a vertex shown as one of ``kinds`` (split, merge) is never given the ``called``
    colour after it: it would seem another kind (K, a merge vertex, turned the blue of a
    start vertex as it took over from M). A polygon coming in (its markers faded in) starts
    afresh."""
    colours = {c.upper(): name for name, c in legend.items()}
    kind_colours = {legend[k].upper(): k for k in kinds}
    found: list[str] = []
    shown: dict[str, str] = {}  # vertex label -> the kind it was shown as
    for k, play in enumerate(data["plays"]):
        if any(a.get("type") == "FadeIn" and (a.get("mobject") or {}).get("name", "")
               .startswith("vertex:") for a in play["animations"]):
            shown.clear()
        for anim in play["animations"]:
            for label, colour, how in _given_colours(anim):
                if colour not in colours:
                    found.append(f"play {k} {label} {how} {colour}: in no legend")
                elif colour == called.upper() and label in shown:
                    found.append(f"play {k} {label} {colour}: {shown[label]}, then called")
                elif colour in kind_colours:
                    shown[label] = kind_colours[colour]
    return list(dict.fromkeys(found))


def _judging(node: dict) -> bool:
    """Whether a node coming in judges a claim: a ✗, words that start with one, or the edge
    it crosses (a run's ``edge:…``, an analysis's)."""
    name = node.get("name") or ""
    return (name == "cross" or name.startswith(("edge:", "analysis:edge:"))
            or (name == "subtitle" and str(node.get("text", "")).startswith("✗")))


def red_bursts_before_verdicts(data: dict) -> list[str]:
    """The red flashes in a play that judges nothing (:func:`_judging`), as ``"play 51"``:
    red is the
    verdict's ("fails"), and a red burst at the pick stood before any claim was made
    (Rotation's D, chapter 2)."""
    found = []
    for k, play in enumerate(data["plays"]):
        # a flash is recorded as its rays, each a passing line in its colour
        red = any(a.get("type") == "Flash" and any(
            str((ray.get("mobject") or {}).get("stroke", "")).upper() == _REJECTED
            for ray in a.get("animations", ())) for a in play["animations"])
        judged = any(a.get("type") in INCOMING and _judging(a.get("mobject") or {})
                     for a in play["animations"])
        if red and not judged:
            found.append(f"play {k}")
    return found


def picks_amber_twice(data: dict) -> list[str]:
    """The vertices turned amber (the claim to be), back to a candidate's pink, then amber
    again, as ``"play 52 E: amber, pink, amber"``: a pick goes amber once, as its tool
    reaches it (Correct Scaling's E went amber as the water came in, back to pink as it
    rose, then amber as it went under). A polygon coming in (its markers faded in), or a
    run's T drawn, starts afresh: the next run's candidates are pink again."""
    from metaphors.theme import THEME

    amber, pink = THEME.argument.upper(), THEME.candidate.upper()
    found: list[str] = []
    seen: dict[str, list[str]] = {}  # vertex label -> the colours it was given, in order
    for k, play in enumerate(data["plays"]):
        if any(a.get("type") in INCOMING and (
                (a.get("mobject") or {}).get("name", "").startswith("vertex:")
                or (a.get("mobject") or {}).get("name") == "T") for a in play["animations"]):
            seen.clear()
        for anim in play["animations"]:
            for label, colour, how in _given_colours(anim):
                if how != "target" or colour not in (amber, pink):
                    continue
                given = seen.setdefault(label, [])
                if given and given[-1] == colour:
                    continue
                given.append(colour)
                if given[-3:] == [amber, pink, amber]:
                    found.append(f"play {k} {label}: amber, pink, amber")
    return found


# --- each claim told under a caption of its own -------------------------------------------------


def untold_claims(data: dict) -> list[str]:
    """The claims that come in under a caption not naming them, as ``"play 71: GB under
    'Diagonals 3–7: the same steps, faster'"``, and the captions standing over more than one
    claim, as ``"'Diagonals 3–7: the same steps, faster' over 5 claims (plays 71–165)"``: the
    caption says what the picture does. Divide and conquer's fast part stood one summary over
    five runs (51–81 s), each a part lit, gravity's ball, a claim, its ✓ and a split. A
    claim's name: the two vertices its play turns amber (its ends), either way round; a
    claim no caption stands over is not judged."""
    from metaphors.theme import THEME

    amber = THEME.argument.upper()
    found: list[str] = []
    caption, shown = "", 0  # the subtitle on screen, and how many have come in
    over: dict[int, list[int]] = {}  # subtitle shown → the plays of the claims under it
    said: dict[int, str] = {}
    for k, play in enumerate(data["plays"]):
        claims, ends = 0, set()
        for anim in play["animations"]:
            for kind, node in _recorded(anim):
                name = node.get("name") or ""
                if name == "subtitle" and kind in INCOMING:
                    caption, shown = _text_of(node) or caption, shown + 1
                elif name == "claim" and kind in INCOMING:
                    claims += 1
            ends |= {label for label, colour, _ in _given_colours(anim) if colour == amber}
        if not claims or not caption:
            continue
        over.setdefault(shown, []).extend([k] * claims)
        said[shown] = caption
        if len(ends) == 2:
            u, v = sorted(ends)
            if not re.search(rf"\b(?:{u}{v}|{v}{u})\b", caption):
                found.append(f"play {k}: {u}{v} under {caption!r}")
    for shown, plays in over.items():
        if len(plays) > 1:
            found.append(f"{said[shown]!r} over {len(plays)} claims (plays {plays[0]}–{plays[-1]})")
    return found


# --- a keyhole cut said while it is drawn --------------------------------------------------------

#: what the words up while a run's first keyhole cut is drawn say (the knife cutting, then
#: the cut made): the rule (the right-most hole's right-most vertex, to a vertex it sees) and
#: what the cut is for (one ring, to slice)
KEYHOLE_SAID = ("right-most", "sees", "one ring")


def unexplained_keyholes(data: dict) -> list[str]:
    """The runs whose first keyhole cut (``keyhole:N`` coming in, the ``knife`` drawn just
    before it) is drawn under captions that do not say what it is and why, as ``"play 9
    keyhole:2 drawn under words without: right-most, sees, one ring"``: the viewer saw
    "Hole 2: a keyhole cut from c₂ to F" and a dark slit, and was never told that each
    hole, the right-most first, is cut open from its right-most vertex to a vertex it sees,
    making one ring that ear clipping slices (:data:`KEYHOLE_SAID`, case aside)."""
    found: list[str] = []
    caption, knife, explained = "", "", False
    for k, play in enumerate(data["plays"]):
        caption = play.get("subcaption") or caption
        for anim in play["animations"]:
            name = (anim.get("mobject") or {}).get("name") or ""
            if name == "polygon" and anim["type"] == "Create":  # a run starts
                explained = False
            if anim["type"] not in INCOMING:
                continue
            if name == "knife":
                knife = caption
            elif name.startswith(_KEYHOLE) and not explained:
                words = f"{knife} {caption}".lower()
                missing = [w for w in KEYHOLE_SAID if w not in words]
                if missing:
                    found.append(f"play {k} {name} drawn under words without: {', '.join(missing)}")
                explained = True  # the run's first cut says it; the next say less
    return found


# --- a diagonal made settles ---------------------------------------------------------------------

#: the names of a diagonal made, on the picture and in the panel (the monotone sweep's
#: ``diagonal:b₂A``, divide and conquer's ``diagonal:0``)
_DIAGONAL = re.compile(r"^(?:panel/)?diagonal:")


def amber_diagonals_left(data: dict) -> list[str]:
    """The diagonals (``diagonal:…``, and the panel's ``panel/diagonal:…``) still amber once
    the caption after the one they came under is up, as ``"play 19 diagonal:b₂A amber under
    'b₂ becomes A–B's helper in place of A'"``: amber means "being decided now" (the theme's
    legend), so a diagonal added is amber while its own words say why, then takes the ink of
    a diagonal made. The holes' sweep kept b₂A amber from 20 s to the pieces at 60 s."""
    from metaphors.theme import THEME

    amber = THEME.argument.upper()
    found: list[str] = []
    shown: dict[str, str] = {}  # an amber diagonal's name -> the caption it came under
    caption = ""
    for k, play in enumerate(data["plays"]):
        caption = play.get("subcaption") or caption
        for anim in play["animations"]:
            node = anim.get("mobject") or {}
            name = node.get("name") or ""
            if not _DIAGONAL.match(name):
                continue
            now = (anim.get("target") or node).get("stroke")
            if anim["type"] in OUTGOING or (now or "").upper() != amber:
                shown.pop(name, None)
            elif anim["type"] in INCOMING:
                shown[name] = caption
        for name, said in list(shown.items()):
            if play.get("subcaption") and caption != said:
                found.append(f"play {k} {name} amber under {caption!r}")
                del shown[name]  # each once
    return found


# --- a pseudocode's names read apart from the picture's labels ----------------------------------

#: the pseudocode names of a polygon (not a vertex): a part a row names ("Q = P (good)", "Q =
#: the good part beyond V–W", "T = triangle ABC", "divide P along it into P1 and P2")
_POLYGON_NAME = re.compile(
    r"(?<![\w′])([A-Z][0-9]*) = (?:P\b|the good part|triangle)|\binto ([A-Z][0-9]*) and ([A-Z][0-9]*)")


def polygon_names(rows: list[str]) -> set[str]:
    """The names ``rows`` of pseudocode give to polygons: P, the run's, and its parts'.

    >>> sorted(polygon_names(["G = P (good); while P is more than a triangle:", "V = the vertex"]))
    ['G', 'P']
    """
    found = {"P"}
    for row in rows:
        for match in _POLYGON_NAME.finditer(row):
            found.update(name for name in match.groups() if name)
    return found


def placeholders_as_labels(data: dict) -> list[str]:
    """The pseudocode names of polygons (:func:`polygon_names`) a run's panel shows that are
    also the label of a vertex on its picture, as ``"play 87: G"``: prune and search's "G = P
    (good)", "V = the middle vertex of G" read as vertex G, the one tested first ("Is G an ear?
    no"). A name of a polygon is never a vertex the run substitutes for it. Each name once
    per run (its polygon drawn begins one), at the first play showing both."""
    found: list[str] = []
    for k, rows, labels, said in _rows_beside_labels(data):
        for name in sorted((polygon_names(sorted(rows)) & labels) - said):
            found.append(f"play {k}: {name}")
            said.add(name)
    return found


def _rows_beside_labels(data: dict) -> Iterator[tuple[int, set[str], set[str], set[str]]]:
    """For each play: its index, the pseudocode rows (``code:``) and the vertex labels its
    run has shown so far, and the names said of it (to fill: each name once per run). A run
    begins where its polygon is drawn."""
    labels: set[str] = set()
    rows: set[str] = set()
    said: set[str] = set()
    for k, play in enumerate(data["plays"]):
        for anim in play["animations"]:
            if anim.get("type") == "Create" and (anim.get("mobject") or {}).get("name") in _POLYGONS:
                labels, rows, said = set(), set(), set()
            for _, node in _recorded(anim):
                for part in mobject_nodes(node):
                    name = part.get("name") or ""
                    if name.startswith("vertex:"):
                        labels.add(name.removeprefix("vertex:"))
                    elif name.startswith("code:") and (part.get("text") or "").strip():
                        rows.add(part["text"].strip())
        yield k, rows, labels, said
#: a one-letter name in lower case (``d``), not the article "a": read beside a vertex
#: labelled with its capital (``D``), the two are one letter in two sizes
_LOWER_NAME = re.compile(r"(?<![\w′'’])([b-z])(?![\w′'’])")


def case_twin_names(data: dict) -> list[str]:
    """The one-letter names in lower case a run's pseudocode rows say while a vertex on its
    picture is labelled with the same letter in capitals, as ``"play 12: d (D)"``: divide and
    conquer's "find an inner diagonal d of P", "divide P along d", lit beside the vertex D
    (the diagonal split along at 26 s was DG itself) — one letter, two things, told apart by
    its size only. Each name once per run (its polygon drawn begins one), at the first play
    showing both."""
    found: list[str] = []
    for k, rows, labels, said in _rows_beside_labels(data):
        names = {m for row in rows for m in _LOWER_NAME.findall(row)}
        for name in sorted(n for n in names if n.upper() in labels and n not in said):
            found.append(f"play {k}: {name} ({name.upper()})")
            said.add(name)
    return found


# --- a fill never tints a vertex label: labels and dots are drawn over fills -----------------


def _label_layers(marker: dict) -> list[tuple[tuple[float, float, float, float], float]]:
    """(box, z-index) of each label text a vertex's marker shows (its own children)."""
    return [(tuple(part["box"]), float(part.get("z", marker.get("z", 0))))
            for part in marker.get("submobjects", ())
            if part.get("box") and (part.get("text") or "").strip()]


def _fill_shapes(node: dict) -> Iterator[tuple[object, float]]:
    """(region, z-index) of each filled part of a node (not its texts)."""
    from shapely.geometry import Polygon

    for part in mobject_nodes(node):
        if (part.get("fill_opacity") or 0) <= 0 or not part.get("points") or "text" in part:
            continue
        for ring in _paths(part):
            shape = Polygon(ring)
            if shape.is_valid and shape.area > 0:
                yield shape, float(part.get("z", 0))


def fills_over_labels(data: dict) -> list[str]:
    """The fills drawn over a vertex label they cover, as ``"play 93 triangulation over M"``:
    manim draws by z-index, then in the order mobjects came, so a fill that comes after a
    label (a whole triangulation's triangles) at its z-index or above tints it (chapter 1's
    M and G at 81.5 s; a card's figure whose triangles come with a line after its labels,
    likewise). The labels as the plays leave them; a polygon coming in begins a new picture.
    Each label and fill once, where it first covers."""
    from shapely.geometry import box as area

    labels: dict[str, tuple[list, int]] = {}  # vertex: (its label layers, when it came)
    found: dict[tuple[str, str], str] = {}
    came = 0
    for k, play in enumerate(data["plays"]):
        for anim in play["animations"]:
            top = anim.get("mobject") or {}
            if anim["type"] in INCOMING and top.get("name") in (*_POLYGONS, "figure:polygon"):
                labels = {}
            for kind, node in _recorded(anim):
                name = node.get("name") or ""
                came += 1
                if kind in OUTGOING:
                    labels.pop(name, None)
                    if name == "figure:vertices":
                        labels = {k: v for k, v in labels.items() if not k.startswith(name)}
                elif name.startswith("vertex:"):
                    labels[name] = (_label_layers(node), labels.get(name, (None, came))[1])
                elif name == "figure:vertices":  # a card's figure: its markers in one group
                    for marker in node.get("submobjects", ()):
                        held = {**marker, "z": marker.get("z", node.get("z", 0))}
                        said = " ".join(_text_of(part) for part in marker.get("submobjects", ()))
                        labels[f"{name}:{said.strip()}"] = (_label_layers(held), came)
                elif kind in INCOMING:
                    for shape, z in _fill_shapes(node):
                        for vertex, (layers, when) in labels.items():
                            if any((z, came) > (lz, when)
                                   and shape.intersection(area(*box)).area > 1e-4
                                   for box, lz in layers):
                                found.setdefault((vertex, name), f"play {k} {name} over "
                                                 f"{vertex.split(':')[-1]}")
    return sorted(found.values(), key=lambda s: int(s.split()[1]))


# --- one legend: a candidate is neutral until it is picked, green only once judged ------------

#: the caption that names a run's candidates, and the verdicts' first marks
_CANDIDATES, _VERDICTS = "Candidates inside T:", ("✓", "✗")


def _vertex_of(name: str, candidates: set[str]) -> str | None:
    """The candidate a marker shows (the picture's ``vertex:E``, the panel's ``panel:E``)."""
    vertex = name.partition(":")[2] if name.startswith(("vertex:", "panel:")) else ""
    return vertex if vertex in candidates else None


def shifting_colours(data: dict) -> list[str]:
    """The candidates drawn in a claim's or a verdict's colour before their time, as ``"play
    40 E green before a verdict"`` or ``"play 41 F amber, not picked"``: after a caption naming
    T's candidates (:data:`_CANDIDATES`) and until the verdict, a candidate is green
    (``result``) only once a ✓ judges it, and, under a caption naming the one picked (its
    last word a candidate: a metaphor's step), amber (``argument``) only as that one or as
    claimed (``Claim: BE …``); a step of one's own code ("Distance to C for D: 2.2") may
    light its call's argument amber, as the legend says. Chapter 2 lit the
    candidates green, then the first one wetted green and the one not hit amber, then the
    claim amber: one colour, three meanings. Each vertex and fault once."""
    found: dict[tuple[str, str], str] = {}
    candidates: set[str] = set()
    caption, judged = "", False
    for k, play in enumerate(data["plays"]):
        caption = play.get("subcaption") or caption
        if (play.get("subcaption") or "").startswith(_CANDIDATES):
            candidates = set(_named(caption.removeprefix(_CANDIDATES).strip().rstrip(".")))
            judged = False
        judged = judged or caption.startswith(_VERDICTS)
        said = caption.removeprefix("Claim: ").replace(",", " ").replace(".", " ").split()
        # the caption naming the candidates picks none of them, though its last word is one
        picked = said[-1] if caption and not caption.startswith(("Claim:", _CANDIDATES)) else ""
        claimed = said[0] if caption.startswith("Claim:") else ""
        for role, node in (r for a in play["animations"] for r in _shown_roles(a)):
            vertex = _vertex_of(node.get("name") or "", candidates)
            if vertex is None or judged:
                continue
            if role == "result":
                found.setdefault((vertex, "green"), f"play {k} {vertex} green before a verdict")
            elif (role == "argument" and (picked in candidates or not picked)
                  and vertex not in (picked, *claimed)):
                found.setdefault((vertex, "amber"), f"play {k} {vertex} amber, not picked")
    return sorted(found.values(), key=lambda s: int(s.split()[1]))


# --- one thing, one colour: a card's figure and the run it tells of ------------------------------

#: the names under which one thing is drawn, on a card's figure and in its run: prune and
#: search's good sub-polygon (:func:`metaphors.fruit.good_style`)
SAME_THINGS = {"the good sub-polygon": ("good", "figure:good", "figure:smaller")}
#: how far apart two colours on screen may be (the largest of their channels' differences,
#: of 255) and still read as one
SAME_COLOUR = 12


def _on_screen(fill: str, opacity: float, under: str | None) -> str:
    from metaphors.theme import THEME

    return _over(fill, opacity, under or THEME.background)


def shifting_tints(data: dict) -> list[str]:
    """The things of :data:`SAME_THINGS` drawn in more than one colour as the screen shows
    them (the fill over the polygon's fill it lies on, over the background), as ``"the good
    sub-polygon: #6250a7 (play 79 figure:good), #9b837e (play 126 good)"``: the same thing
    keeps its colour. Chapter 4's card drew prune and search's good sub-polygons in violet
    and teal over P's navy, and its run in blue over the fruit's orange, a greyish pink."""
    from metaphors.theme import THEME

    found = []
    for thing, names in SAME_THINGS.items():
        colours: dict[str, str] = {}
        under: dict[str, str] = {}  # the fill as shown of the polygon a figure or run draws
        for k, play in enumerate(data["plays"]):
            for anim in play["animations"]:
                for kind, node, name in _ends(anim):
                    fill = _one_colour(node.get("fill"))
                    opacity = float(node.get("fill_opacity") or 0)
                    if name in ("polygon", "figure:polygon") and fill and opacity > 0:
                        under[name] = _over(fill, opacity, THEME.background)
                    if name not in names or kind in OUTGOING or not fill or opacity <= 0:
                        continue
                    polygon = "figure:polygon" if name.startswith("figure:") else "polygon"
                    colour = _on_screen(fill, opacity, under.get(polygon))
                    if not any(_apart(colour, c) <= SAME_COLOUR for c in colours):
                        colours[colour] = f"play {k} {name}"
        if len(colours) > 1:
            found.append(f"{thing}: " + ", ".join(f"{c} ({where})" for c, where in colours.items()))
    return found


# --- the part worked on stands out: one colour, one meaning ----------------------------------

#: how far apart (CIE76 ΔE, as the screen shows them) another part's tint must stand from the
#: part worked on: the palette's blue and violet were 21 and 18 from it, its teal is 37
LEAST_PART_APART = 25.0


def _lab(colour: str) -> tuple[float, float, float]:
    """CIE L*a*b* (D65) of a ``#rrggbb`` colour."""
    def linear(u: float) -> float:
        return ((u + 0.055) / 1.055) ** 2.4 if u > 0.04045 else u / 12.92

    r, g, b = (linear(int(colour.lstrip("#")[k:k + 2], 16) / 255) for k in (0, 2, 4))
    x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047
    y = 0.2126 * r + 0.7152 * g + 0.0722 * b
    z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883

    def f(t: float) -> float:
        return t ** (1 / 3) if t > 0.008856 else 7.787 * t + 16 / 116

    return 116 * f(y) - 16, 500 * (f(x) - f(y)), 200 * (f(y) - f(z))


def delta_e(a: str, b: str) -> float:
    """CIE76 ΔE of two ``#rrggbb`` colours: about 2 is just seen, over 25 two colours.

    >>> round(delta_e("#000000", "#ffffff"))
    100
    """
    return math.dist(_lab(a), _lab(b))


def unmarked_parts(data: dict) -> list[str]:
    """The plays where divide and conquer's part worked on (a ``piece:`` tinted in the
    ``called`` blue, the legend's "the piece divide and conquer works on") does not stand out,
    as ``"play 54 piece:GHIJKLMABCD: lit, not outlined"`` or ``"play 123 piece:HIJK reads as
    piece:KLMAH, the part worked on"``: lit, it is outlined in that blue too, and no other
    part's tint reads as its colour (:data:`LEAST_PART_APART`, each over the background: a
    split clears P's fill). The palette tinted a part in a blue (#5b8fd5) beside the lit one
    (HIJK beside KLMAH at 66 s of the scene's graph), and only gravity's turn outlined the
    lit part: a convex part (HKLM) was never outlined. Each part and fault once."""
    from metaphors.theme import THEME

    called = THEME.called.upper()
    found: dict[tuple[str, str], str] = {}
    for k, shown in _shown_after_plays(data, ("piece:",)):
        lit = {name: node for name, node in shown.items()
               if _one_colour(node.get("fill")) == called and (node.get("fill_opacity") or 0) > 0}
        for name, node in lit.items():
            if _one_colour(node.get("stroke")) != called or not node.get("stroke_width"):
                found.setdefault((name, "outline"), f"play {k} {name}: lit, not outlined")
        for name, node in lit.items():
            seen = _over(called, float(node["fill_opacity"]), THEME.background)
            for other, part in shown.items():
                fill = _one_colour(part.get("fill"))
                if other in lit or not fill or not (part.get("fill_opacity") or 0) > 0:
                    continue
                tint = _over(fill, float(part["fill_opacity"]), THEME.background)
                if delta_e(seen, tint) < LEAST_PART_APART:
                    found.setdefault((other, "alike"),
                                     f"play {k} {other} reads as {name}, the part worked on")
    return sorted(found.values(), key=lambda s: int(s.split()[1]))


#: gravity's close-up: one drawing standing in for the picture's outline while zoomed
#: (:class:`metaphors.gravity.CloseUp`)
_CLOSE_UP = "close-up"


def recoloured_close_ups(data: dict) -> list[str]:
    """The close-ups that draw the picture in other colours than its outline had, as ``"play
    101: fill #2A3A55 0.35, edges #E8ECF2 3.0 (the picture: fill #F4A259 0.75, edges #7A9E3D
    6.6)"``: a close-up is the same picture, nearer. Chapter 4's fruit turned into P's navy
    with white edges for the close-up of prune and search's gravity step (73-77 s), and
    orange again after it."""
    found = []
    outline: tuple | None = None
    for k, play in enumerate(data["plays"]):
        for anim in play["animations"]:
            node = anim.get("mobject") or {}
            if node.get("name") == "polygon":
                state = anim.get("target") or node
                outline = (state.get("fill"), state.get("fill_opacity"), state.get("stroke"),
                           state.get("stroke_width"))
            if node.get("name") != _CLOSE_UP or outline is None:
                continue
            parts = node.get("submobjects") or []
            # what is seen: a fill with some opacity, a line with some width (a zoom's
            # ``become`` leaves a line of none behind)
            fills = {(c.get("fill"), c.get("fill_opacity")) for c in parts
                     if (c.get("fill_opacity") or 0) > 0}
            edges = {(c.get("stroke"), c.get("stroke_width")) for c in parts
                     if c.get("type") == "Line" and (c.get("stroke_width") or 0) > 0}
            if fills | edges and (fills - {outline[:2]} or edges - {outline[2:]}):
                said = ", ".join([*(f"fill {f} {o}" for f, o in sorted(fills)),
                                  *(f"edges {e} {w}" for e, w in sorted(edges))])
                found.append(f"play {k}: {said} (the picture: fill {outline[0]} {outline[1]}, "
                             f"edges {outline[2]} {outline[3]})")
    return found


def _apart(a: str, b: str) -> int:
    """The largest difference of two ``#rrggbb`` colours' channels."""
    return max(abs(int(a[k:k + 2], 16) - int(b[k:k + 2], 16)) for k in (1, 3, 5))


# --- the exercises' countdown: one number a second ----------------------------------------------

#: one frame at the lecture's lowest quality (15 fps): how far a number's time may be off 1 s
ONE_FRAME = 1 / 15


def _countdown_number(play: dict) -> str | None:
    """The number the countdown shows as this play starts (None: no countdown in it)."""
    for anim in play["animations"]:
        node = anim.get("mobject") or {}
        if node.get("name") == "countdown":
            return next((n["text"] for n in mobject_nodes(node) if n.get("text")), None)
    return None


def uneven_countdowns(data: dict) -> list[str]:
    """The countdowns whose numbers are not each up for one second (± :data:`ONE_FRAME`) in
    order down to 1, then 0 as the time is up (as it goes), as ``"play 8: 15 up 15.00 s"`` or
    ``"play 8: counts 15, …, 1"``: one eased play for the whole wait kept "15" and "1" up for
    3.7 s each and rushed the others by, and a count that stops at 1 leaves the class a second
    short. A number's time is the run time of the plays it is shown in (the graph cannot see a
    rate function, so each second is a play of its own)."""
    found = []
    numbers: list[tuple[int, str, float]] = []  # (first play, number, seconds up), this countdown

    def check() -> None:
        expected = [str(k) for k in range(len(numbers) - 1, -1, -1)]
        if numbers and [n for _, n, _ in numbers] != expected:
            shown = [n for _, n, _ in numbers]
            counted = ", ".join(shown if len(shown) < 5 else [*shown[:2], "…", *shown[-2:]])
            found.append(f"play {numbers[0][0]}: counts {counted}")
        found.extend(f"play {k}: {n} up {t:.2f} s" for k, n, t in numbers[:-1]
                     if abs(t - 1.0) > ONE_FRAME)
        numbers.clear()

    for k, play in enumerate(data["plays"]):
        number = _countdown_number(play)
        if number is None:
            check()
        elif numbers and numbers[-1][1] == number:
            first, _, up = numbers[-1]
            numbers[-1] = (first, number, up + play["run_time"])
        else:
            numbers.append((k, number, play["run_time"]))
    check()
    return found


# --- an exercise's answer: no number alone on a line -------------------------------------------

_LONE_NUMBER = re.compile(r"[\d.,°%\s]+")


def lone_numbers(data: dict) -> list[str]:
    """The answers' lines that hold a number alone, as ``"play 9: 25.5"``: read by itself,
    "25.5" under "before D at" is a figure with no words (review r567)."""
    found = []
    for k, play in enumerate(data["plays"]):
        for anim in play["animations"]:
            for node in mobject_nodes(anim.get("mobject") or {}):
                if node.get("name") != "answer":
                    continue
                found += [f"play {k}: {n['text']}" for n in mobject_nodes(node)
                          if n.get("text") and _LONE_NUMBER.fullmatch(n["text"])]
    return found


# --- a run's pseudocode does not give its claim away -------------------------------------------

_CLAIM_CAPTION = re.compile(r"Claim: ([A-Z]+) is an inner diagonal")


def _code_rows(play: dict) -> Iterator[str]:
    """The texts of the pseudocode rows a play brings in."""
    for anim in play["animations"]:
        if anim["type"] in INCOMING:
            for node in mobject_nodes(anim.get("mobject") or {}):
                if str(node.get("name", "")).startswith("code:") and node.get("text"):
                    yield node["text"]


def claims_given_away(data: dict) -> list[str]:
    """A run's claim named by a pseudocode row shown before the run makes it, as
    ``"play 75: 'claim BE' before play 91's claim"``: "E = the candidate nearest to C" and
    "claim BE" stood in the panel before the distances were computed (review r567)."""
    found, shown = [], []
    for k, play in enumerate(data["plays"]):
        claimed = _CLAIM_CAPTION.fullmatch(play.get("subcaption") or "")
        if claimed:
            found += [f"play {at}: {text!r} before play {k}'s claim" for at, text in shown
                      if claimed[1] in re.findall(r"\b[A-Z]+\b", text)]
            shown = []
        shown += [(k, text) for text in _code_rows(play)]
    return found


# --- a vertex label stands clear of its polygon's edges -----------------------------------------

#: the least gap between a vertex label and an edge of the polygon it names a vertex of
#: (1.5 % of the frame's height): nearer, the letter reads as sitting on the line (chapter 2's
#: K on edge L–K, M on edge A–M)
LEAST_LABEL_EDGE_GAP = 0.12
#: each picture's polygon and the names of its vertex labels: a run's or an analysis's board
#: (a marker a vertex), a card's figure (a group of markers, the holes' one by one)
_LABELLED = ((("polygon", "analysis:polygon"), ("vertex:",)),
             (("figure:polygon",), ("figure:vertices", "figure:hole-vertex")))


def _marker_labels(name: str, node: dict) -> Iterator[tuple[str, tuple[float, float, float, float]]]:
    """(text, box) of each vertex label a marker node (a dot and a label) or a group of them
    (a figure's) shows."""
    markers = node.get("submobjects", ()) if name == "figure:vertices" else [node]
    for marker in markers:
        for part in marker.get("submobjects", ()):
            if part.get("box") and (part.get("text") or "").strip():
                yield part["text"], tuple(part["box"])


def _opening(play: dict, polygons: tuple[str, ...]) -> list | None:
    """The points of a picture's polygon that a play brings in with no turn (a picture
    opening: a run's board, a stage, a card's figure), None if it brings none in (a close-up
    fading the turned polygon back in does not open one)."""
    if any(a.get("type") == "Turn" for a in play["animations"]):
        return None
    for anim in play["animations"]:
        node = anim.get("mobject") or {}
        if anim.get("type") in INCOMING and node.get("name") in polygons and node.get("points"):
            return node["points"]
    return None


def labels_on_edges(data: dict, margin: float = LEAST_LABEL_EDGE_GAP) -> list[str]:
    """The vertex labels nearer than ``margin`` to an edge of the polygon drawn in the same
    picture (or crossed by it), as ``"play 3 K 0.03 from figure:polygon"``: each label and
    polygon once, at the first play that shows it so, the labels as :func:`_shown_after_plays`
    follows them. A letter on a line reads as part of it, or names the wrong vertex. The
    polygon as its picture opened it (:func:`_opening`), where the labels were placed for it:
    once turned (gravity's labels stay upright) or cut (the fruit's slices) it is left to
    :func:`crossed_vertex_labels`, until it stands as it opened again."""
    from shapely.geometry import LineString
    from shapely.geometry import box as area

    found: dict[tuple[str, str], str] = {}
    for polygons, labels in _LABELLED:
        opened: list | None = None
        for k, shown in _shown_after_plays(data, (*polygons, *labels), many=labels[1:]):
            opened = _opening(data["plays"][k], polygons) or opened
            outlines = [(name, LineString(s)) for name, node in shown.items()
                        if name in polygons and node.get("points") == opened
                        for s in _segments(node)]
            for name, node in shown.items():
                if not name.startswith(labels):
                    continue
                for text, box in _marker_labels(name, node):
                    for owner, edge in outlines:
                        gap = edge.distance(area(*box))
                        if gap < margin - 1e-9:
                            found.setdefault((text, owner),
                                             f"play {k} {text} {gap:.2f} from {owner}")
    return sorted(found.values(), key=lambda s: int(s.split()[1]))


# --- a label off the lines it is not on: T's sides -------------------------------------------

#: the triangle T = ABC of the heuristics' frame, on a run's board and an analysis's stage
_TRIANGLES = ("T", "analysis:T")


def labels_by_triangle_sides(data: dict, margin: float = LEAST_LABEL_EDGE_GAP) -> list[str]:
    """The vertex labels nearer than ``margin`` to a side of T that their vertex is not on
    (T's side AC, a chord of P, for a candidate inside T), as ``"play 80 E 0.10 from T"``:
    each label and T once, at the first play that shows it so, the labels and T as
    :func:`_shown_after_plays` follows them. A letter by a line it is not on reads as part
    of it (the exercises' E stood 0.10 from AC, and its pulse as a candidate, 1.4 times its
    size, pushed it against the line at 91 s)."""
    from shapely.geometry import LineString, Point
    from shapely.geometry import box as area

    found: dict[tuple[str, str], str] = {}
    for k, shown in _shown_after_plays(data, ("vertex:", *_TRIANGLES)):
        sides = [(name, s) for name, node in shown.items() if name in _TRIANGLES
                 for s in _segments(node)]
        for name, marker in shown.items():
            dot = _dot_centre(marker) if name.startswith("vertex:") else None
            if dot is None:
                continue
            for owner, (a, b) in sides:
                if min(Point(a).distance(Point(dot)), Point(b).distance(Point(dot))) < 0.02:
                    continue  # a side of its own vertex: the label stands by it
                for box in _label_boxes(marker, direct=True):
                    gap = LineString([a, b]).distance(area(*box))
                    if gap < margin - 1e-9:
                        label = name.removeprefix("vertex:")
                        found.setdefault((label, owner), f"play {k} {label} {gap:.2f} from {owner}")
    return sorted(found.values(), key=lambda s: int(s.split()[1]))


# --- review s34 item 9: a vertex marker goes with its vertex ---------------------------------

#: what a board's vertex markers stand on: its outline (ear clipping's fruit, as it shrinks
#: slice by slice), an analysis's polygon, and the triangles of a result (several under one
#: name)
_MARKED = ("polygon", "analysis:polygon", "triangle", "triangulation")
#: how far a marker's dot may stand from the corner it marks (the graph's rounding)
MARKER_AT_CORNER = 0.02


def _dot_centre(marker: dict) -> tuple[float, float] | None:
    """The centre of a vertex marker's dot (its first part's points), None if it has none."""
    parts = marker.get("submobjects") or ()
    points = parts[0].get("points") if parts else None
    if not points:
        return None
    return (sum(p[0] for p in points) / len(points), sum(p[1] for p in points) / len(points))


def stray_vertex_markers(data: dict) -> list[str]:
    """The board's vertex markers on screen whose dot stands at no corner of a polygon drawn
    (:data:`_MARKED`), as ``"play 17 A"``: each once, at the first play that leaves it so.
    Ear clipping's sliced-off ear tips stayed up, dots and labels floating round the
    shrinking fruit (chapter 4 at 98 s: E, F, D, C, I and J above the turned fruit). The
    markers and polygons as :func:`_shown_after_plays` follows them (a turn makes both
    unknown until recorded again); none is judged while no polygon is known, or one turned
    is not known again (a divide and conquer's outline, turned back upright, is recorded
    again only when it next changes)."""
    found: dict[str, str] = {}
    turned: set[str] = set()
    for k, shown in _shown_after_plays(data, ("vertex:", *_MARKED), many=_MARKED[2:],
                                       by_corners=True):
        for anim in data["plays"][k]["animations"]:
            for kind, _, name in _ends(anim):
                if name.startswith(_MARKED):
                    (turned.add if kind == "Turn" else turned.discard)(name)
        corners = [end for name, node in shown.items() if name.startswith(_MARKED)
                   for segment in _segments(node) for end in segment]
        if not corners or turned:
            continue
        for name, marker in shown.items():
            dot = _dot_centre(marker) if name.startswith("vertex:") else None
            if dot is None or name in found:
                continue
            if all(math.dist(dot, corner) > MARKER_AT_CORNER for corner in corners):
                found[name] = f"play {k} {name.removeprefix('vertex:')}"
    return sorted(found.values(), key=lambda s: int(s.split()[1]))


def _shown_roles(anim: dict) -> Iterator[tuple[str | None, dict]]:
    """(the role it is shown in, node) of every top mobject an animation (or its members)
    has (:func:`_recorded`), and of every pulse's mobject (Indicate), in the role whose colour
    the pulse lights it in: a run of one's own pulsed the candidates amber, the claim's colour,
    while the panel showed them pink (review s567), and a pulse's colour is in no mobject."""
    for _, node in _recorded(anim):
        yield node.get("role"), node
    roles = {_colour(role): role for role in ("result", "argument")}
    pulses = [anim, *anim.get("animations", ())]
    for pulse in pulses:
        if "color" in pulse and "mobject" in pulse:
            yield roles.get(str(pulse["color"]).upper()), pulse["mobject"]


# --- a triangulation drawn large enough to see, its words clear of it ----------------------------

#: the frame's height (scene units): what a triangle's height is a share of
FRAME_HEIGHT = 8.0
#: 4 % of the frame's height: the least height of a triangle of a whole triangulation drawn
#: alone (the polygon scene's counterexample: BEC, 3 % framed 9 × 5, read as a line)
LEAST_TRIANGLE = 0.04
#: the least gap between a text on the picture's screen (a title, a count) and the picture:
#: its polygon's region and its vertex labels (2.5 % of the frame's height)
LEAST_WORDS_GAP = 0.2


def _altitude(a: tuple[float, float], b: tuple[float, float], c: tuple[float, float]) -> float:
    """A triangle's shortest height: twice its area over its longest side."""
    area2 = abs((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]))
    return area2 / max(math.dist(a, b), math.dist(b, c), math.dist(c, a))


def thinnest_triangle(data: dict) -> float | None:
    """The least height, as a share of the frame's height, of the triangles of the whole
    triangulation on screen at the end (its ``triangulation`` nodes, as drawn); None if
    there is none."""
    heights = [_altitude(*corners[:3]) for node in data.get("final", ())
               for part in mobject_nodes(node) if part.get("name") == "triangulation"
               for corners in [_corners(part)] if len(corners) == 3]
    return min(heights) / FRAME_HEIGHT if heights else None


def words_on_the_picture(data: dict, gap: float = LEAST_WORDS_GAP) -> list[str]:
    """The texts on screen at the end that are no vertex label and come nearer than ``gap``
    to the picture (a drawn polygon's region, a vertex label), as ``"n − 2 = 5 − 2 = 3
    triangles: 0.05 from polygon"``: a picture framed larger must leave its title and count
    room."""
    from shapely.geometry import Polygon as Region
    from shapely.geometry import box

    final = list(data.get("final", ()))
    picture = [(n["name"], Region(_corners(n))) for top in final for n in mobject_nodes(top)
               if n.get("name") in _POLYGONS and len(n.get("points", ())) >= 12]
    picture += [(n["name"], box(*b)) for top in final for n in mobject_nodes(top)
                if (n.get("name") or "").startswith("vertex:") for b in _label_boxes(n)]
    words = [(top["text"], box(*top["box"])) for top in final
             if top.get("box") and (top.get("text") or "").strip()]
    return [f"{said}: {shape.distance(region):.2f} from {name}" for said, shape in words
            for name, region in picture if shape.distance(region) < gap]


# --- one legend in every pass: the candidates kept pink, the pick amber with its words ---------

#: a caption naming T's candidates: a run's ("Candidates inside T: E, F"), an analysis's
#: ("… defeats all three heuristics. Candidates: D, E.", "… Candidates in T: D, E.")
_NAMED_CANDIDATES = re.compile(r"Candidates(?: inside T| in T)?: ([A-Z][^.]*)\.?$")


def named_candidates(caption: str | None) -> list[str]:
    """The candidates ``caption`` names (none if it names none)."""
    found = _NAMED_CANDIDATES.search(caption or "")
    return _named(found[1]) if found else []


def _kept_candidates(anim: dict, candidate: str) -> Iterator[str]:
    """The picture's vertices (``vertex:K``) an animation (or its members) keeps in the
    candidate colour: recoloured to it (a target's stroke), or pulsed in it while its role
    is the candidate's (a run's board sets the colour it pulses in after the pulse)."""
    for child in anim.get("animations", ()):
        yield from _kept_candidates(child, candidate)
    node = anim.get("mobject") or {}
    name = node.get("name") or ""
    if not name.startswith("vertex:"):
        return
    stroke = (anim.get("target") or {}).get("stroke")
    pulsed = str(anim.get("color") or "").upper() == candidate and node.get("role") == "candidate"
    if pulsed or (isinstance(stroke, str) and stroke.upper() == candidate):
        yield name.removeprefix("vertex:")


def unmarked_candidates(data: dict) -> list[str]:
    """The candidates a caption names that the plays under it do not keep in the candidate
    colour, as ``"play 41 D: not kept pink"``: chapter 2's analyses pulsed D and E pink for
    0.8 s, then left them grey the 8.5 s the tool moved towards them, where a run keeps
    them pink until one is picked."""
    candidate = _colour("candidate")
    found: list[str] = []
    named: list[str] = []
    at, kept = 0, set()
    for k, play in enumerate([*data["plays"], {"subcaption": "end", "animations": []}]):
        if play.get("subcaption"):
            found += [f"play {at} {v}: not kept pink" for v in named if v not in kept]
            named, at, kept = named_candidates(play["subcaption"]), k, set()
        kept.update(v for anim in play["animations"] for v in _kept_candidates(anim, candidate))
    return found


#: the marks a card's figure sets on a vertex T holds: a candidate (pink) and the pick its
#: tool reaches (amber, the claim to be)
_FIGURE_MARKS = ("figure:candidate", "figure:pick")


def amber_figure_marks(data: dict) -> list[str]:
    """A card's figure marking a vertex amber before the words say it, as ``"play 9:
    figure:candidate amber with the title 'Scaling: spilled water'"``, or a candidate's mark
    in the pick's amber or a verdict's green, as ``"play 9: figure:candidate amber"``: the
    water card showed D amber (its pick) with its title, 3 s before the line "The first
    candidate it wets is D"; gravity's, prune and search's and the keyhole's cards named the
    vertex a step works on a candidate, amber."""
    found: list[str] = []
    for k, play in enumerate(data["plays"]):
        titles = [a for a in play["animations"]
                  if a["type"] in INCOMING and (a.get("mobject") or {}).get("name") == "card:title"]
        for anim in play["animations"]:
            if anim["type"] not in INCOMING | {"UpdateFromAlphaFunc"}:
                continue
            node = anim.get("mobject") or {}
            name, role = node.get("name") or "", node.get("role")
            if name == "figure:candidate" and role in ("argument", "result"):
                found.append(f"play {k}: {name} {'amber' if role == 'argument' else 'green'}")
            if name in _FIGURE_MARKS and role == "argument" and titles:
                said = play.get("subcaption") or "?"  # the card's title, said as it comes
                found.append(f"play {k}: {name} amber with the title {said!r}")
    return found


# --- review s35: chapter 5's kind words and labels off P's fill, its sweep clear of labels ------

#: the pictures' polygons whose interior a word or a label must keep off: a run's board, an
#: analysis's stage, a card's figure
_INTERIORS = ("polygon", "analysis:polygon", "figure:polygon")


def _picture_texts(node: dict) -> Iterator[tuple[str, tuple[float, float, float, float]]]:
    """(what it says, box) of each kind word (:data:`_KIND_WORDS`) and vertex label (a board's
    ``vertex:`` markers, a figure's ``figure:vertices``) in a node and its parts."""
    for part in mobject_nodes(node):
        name = part.get("name") or ""
        if name in _KIND_WORDS and part.get("box"):
            yield repr(part["text"]), tuple(part["box"])
        elif name.startswith("vertex:") or name == "figure:vertices":
            yield from _marker_labels(name, part)


def texts_over_the_picture(data: dict) -> list[str]:
    """The kind words and vertex labels (:func:`_picture_texts`) whose box lies over the
    interior of the polygon of their picture (:data:`_INTERIORS`, the one drawn last) by more
    than :data:`MOST_TEXT_OVER_FILL`, as ``"play 19 'merge' 0.26 over P"`` or ``"play 9 G
    0.05 over P"``: each text at each place once, as it comes in or moves there (review s35:
    "merge", "split", G and M stood on chapter 5's fill). A polygon with holes is read as one
    outline (:func:`_outline`): a hole's labels, in the hole, may be found over P."""
    from shapely.geometry import box as rectangle

    picture = None
    found: dict[tuple[str, tuple[float, ...]], str] = {}
    for k, play in enumerate(data["plays"]):
        for anim in play["animations"]:
            for kind, node in _recorded(anim):
                if kind in INCOMING and node.get("name") in _INTERIORS and node.get("points"):
                    picture = _outline(node)
                if kind in OUTGOING or picture is None:
                    continue
                for said, box in _picture_texts(node):
                    over = rectangle(*box).intersection(picture).area
                    if over > MOST_TEXT_OVER_FILL:
                        found.setdefault((said, box), f"play {k} {said} {over:.2f} over P")
    return sorted(set(found.values()), key=lambda s: (int(s.split()[1]), s))


def words_over_the_picture(data: dict) -> list[str]:
    """:func:`texts_over_the_picture` of the kind words only (each quoted)."""
    return [found for found in texts_over_the_picture(data) if found.split()[2][0] == "'"]


#: the least gap the monotone sweep line (:data:`_TOOL_LINES`) leaves round a vertex label: at
#: 0.04 its dashes ran up to M's and K's letters at their height, read as struck through; at
#: 0.12 it still ran along the top of A's letter (chapter 5 at 16–19 s)
LEAST_SWEEP_GAP = 0.15


def _sweep_dashes(data: dict) -> Iterator[tuple[list, dict]]:
    """(the points of a drawn dash of the monotone sweep line, the labels then shown) for
    every place the line is recorded: as it comes, and each place a Transform moves it to."""
    for anim, labels in _with_labels(data):
        for key in ("mobject", "target"):
            for line in mobject_nodes(anim.get(key) or {}):
                if line.get("name") not in _TOOL_LINES:
                    continue
                for dash in mobject_nodes(line):
                    if len(dash.get("points", ())) >= 2 and (dash.get("stroke_opacity") or 0):
                        yield dash["points"], labels


def labels_struck_by_the_sweep(data: dict) -> list[str]:
    """The vertex labels the monotone sweep line's dashes come nearer than
    :data:`LEAST_SWEEP_GAP` to, where the line is recorded (as it comes, and each place a
    Transform moves it to), as ``"the sweep 0.04 from M"``: each label once, at its least
    gap; the labels are those of the polygon drawn last."""
    from shapely.geometry import LineString
    from shapely.geometry import box as rectangle

    least: dict[str, float] = {}
    for points, labels in _sweep_dashes(data):
        drawn = LineString([p[:2] for p in points])
        for v, box in labels.items():
            gap = drawn.distance(rectangle(*box))
            if gap < LEAST_SWEEP_GAP - 1e-3:
                least[v] = min(gap, least.get(v, gap))
    return [f"the sweep {gap:.2f} from {v}" for v, gap in sorted(least.items())]


# --- over3 item 1: a label with no room outside P stands inside one piece of the fill ------------

#: the fills that cut P into pieces of their own colour: a card's triangles and halves, a run's
#: pieces and triangles, the whole triangulation (several under one name)
_CUT_FILLS = ("figure:triangle", "figure:half", "piece:", "triangle:", "triangulation")
#: the lines drawn over P's fill that divide it: a card's diagonals
_CUT_LINES = ("figure:inner-diagonal", "figure:diagonal")


def _label_texts(name: str, node: dict) -> Iterator[tuple[str, tuple[float, float, float, float]]]:
    """(text, box) of each label a board's marker or a card's group of markers shows."""
    if name.startswith("vertex:"):
        yield from ((name.removeprefix("vertex:"), box) for box in _label_boxes(node, direct=True))
    else:
        yield from _marker_labels("figure:vertices", node)


def labels_across_fills(data: dict, margin: float = LEAST_LABEL_EDGE_GAP) -> list[str]:
    """The vertex labels over a fill that reach within ``margin`` of one of its sides or of a
    line that divides it (:data:`_CUT_FILLS`, :data:`_CUT_LINES`), as ``"play 3 G on
    figure:triangle"``: a label inside P, where it has no room outside (M in its notch), reads
    only inside one piece of one colour, off its sides (chapter 1's triangulation card: G on
    its triangles' side B–E). Each label and fill once, at the first play that shows it so,
    as :func:`_shown_after_plays` follows them; a label outside every fill is
    :func:`labels_on_edges`' to judge."""
    from shapely.geometry import LineString, Polygon
    from shapely.geometry import box as area

    found: dict[tuple[str, str], str] = {}
    owners = ("vertex:", "figure:vertices", *_CUT_FILLS, *_CUT_LINES)
    for k, shown in _shown_after_plays(data, owners, many=_CUT_FILLS, by_corners=True):
        fills = [(name.partition("@")[0], Polygon(ring).buffer(0))
                 for name, node in shown.items() if name.startswith(_CUT_FILLS)
                 for part in mobject_nodes(node) if (part.get("fill_opacity") or 0) > 0
                 for ring in _paths(part)]
        lines = [(name, LineString(s)) for name, node in shown.items()
                 if name.startswith(_CUT_LINES) for s in _segments(node)]
        for name, node in shown.items():
            if not name.startswith(("vertex:", "figure:vertices")):
                continue
            for text, box in _label_texts(name, node):
                label = area(*box)
                over = [(owner, shape) for owner, shape in fills
                        if shape.intersection(label).area > 1e-4]
                near = [owner for owner, shape in over if shape.exterior.distance(label) < margin]
                if over:
                    near += [owner for owner, line in lines if line.distance(label) < margin]
                for owner in near:
                    found.setdefault((text, owner), f"play {k} {text} on {owner}")
    return sorted(found.values(), key=lambda s: int(s.split()[1]))


# --- over3 item 2: a vertex turned grey is said to be what grey means, where first seen ----------


def unexplained_grey(data: dict) -> list[str]:
    """The first vertex labels a play turns grey (``idle``: "not in the current call") when
    no caption up to it has said what grey means (a caption with "grey" in it), as ``"play
    33 A grey, unsaid"``: chapter 1's divide and conquer left the ends of each diagonal grey
    after the split, then greyed the vertices not in the smaller polygon, and never said
    why. The board's and the panel's markers; one finding, the first."""
    grey, said = _colour("idle"), False
    for k, play in enumerate(data["plays"]):
        said = said or "grey" in (play.get("subcaption") or "").lower()
        for kind, node in _recorded_all(play):
            name = node.get("name") or ""
            if (kind != "_MethodAnimation" or not name.startswith(("vertex:", "panel:"))
                    or (node.get("fill") or "").upper() != grey):
                continue
            return [] if said else [f"play {k} {name.partition(':')[2]} grey, unsaid"]
    return []


def _recorded_all(play: dict) -> Iterator[tuple[str, dict]]:
    """(the animation's type, target) of every animation of a play that has a target, its
    members' too."""
    def walk(anim: dict) -> Iterator[tuple[str, dict]]:
        if "target" in anim:
            yield anim["type"], anim["target"]
        for child in anim.get("animations", ()):
            yield from walk(child)

    for anim in play["animations"]:
        yield from walk(anim)


# --- over3 items 3 and 4: the band bends under its words; no label touches the ball --------------


def early_snags(data: dict) -> list[str]:
    """The plays that draw gravity's band with a corner at a vertex (three corners or more)
    while the caption up does not say it snags, as ``"play 26 band bent under 'It slides
    down the edge to G'"``: chapter 3's band bent at H 1.2 s before "The rubber band snags
    H" was said. A band going (faded out) is not drawn anew."""
    found, caption = [], ""
    for k, play in enumerate(data["plays"]):
        caption = play.get("subcaption") or caption
        if "snag" in caption:
            continue
        for kind, node in _recorded_all_nodes(play):
            if kind not in OUTGOING and node.get("name") == "band" and len(_segments(node)) >= 2:
                found.append(f"play {k} band bent under {caption!r}")
                break
    return found


def _recorded_all_nodes(play: dict) -> Iterator[tuple[str, dict]]:
    """(the animation's type, node) of every mobject and target of a play's animations."""
    for anim in play["animations"]:
        yield from _recorded(anim)


#: the least gap between a vertex label and gravity's ball (its stroke's width, about)
LEAST_BALL_GAP = 0.03


def labels_on_the_ball(data: dict, margin: float = LEAST_BALL_GAP) -> list[str]:
    """The vertex labels nearer than ``margin`` to gravity's ball where a play leaves it, as
    ``"play 70 C 0.00 from the ball"`` (each label once): the counterexample's C touched
    the ball at rest on C. The ball's box is its points'; the labels and the ball as
    :func:`_shown_after_plays` follows them."""
    from shapely.geometry import box as area

    found: dict[str, str] = {}
    for k, shown in _shown_after_plays(data, ("vertex:", "ball")):
        ball = shown.get("ball")
        if not ball or not ball.get("points"):
            continue
        xs, ys = [p[0] for p in ball["points"]], [p[1] for p in ball["points"]]
        disk = area(min(xs), min(ys), max(xs), max(ys))
        for name, marker in shown.items():
            for box in _label_boxes(marker, direct=True) if name.startswith("vertex:") else ():
                gap = disk.distance(area(*box))
                if gap < margin and name not in found:
                    found[name] = f"play {k} {name.removeprefix('vertex:')} {gap:.2f} from the ball"
    return sorted(found.values(), key=lambda s: int(s.split()[1]))
# --- a keyhole's cut moves no label ---------------------------------------------------------------


def labels_moved_by_cuts(data: dict) -> list[str]:
    """The vertex labels that move in a play a keyhole's cut comes in (``keyhole:N``), their
    dot where it stood, as ``"play 217 keyhole:1 moves c₁"``: a label stays put unless its
    vertex moves, and the cuts a run will make are known before its first picture (the
    labels are placed clear of them). Moved aside by each cut as it came, chapter 4's c₁, c₂
    and d₂ jumped between the two keyhole steps. The markers are as
    :func:`_shown_after_plays` follows them."""
    found = []
    before: dict[str, dict] = {}
    for k, shown in _shown_after_plays(data, ("vertex:",)):
        cuts = [name for anim in data["plays"][k]["animations"] for kind, _, name in _ends(anim)
                if kind in INCOMING and name.startswith("keyhole:")]
        for name, marker in shown.items() if cuts else ():
            old = before.get(name)
            if old is None or _dot_centre(old) != _dot_centre(marker):
                continue
            if _rounded_boxes(old) != _rounded_boxes(marker):
                found.append(f"play {k} {cuts[0]} moves {name.removeprefix('vertex:')}")
        before = dict(shown)
    return found


def _rounded_boxes(marker: dict) -> list[tuple[float, ...]]:
    """A marker's label boxes (:func:`_label_boxes`) to the thousandth."""
    return [tuple(round(v, 3) for v in box) for box in _label_boxes(marker, direct=True)]


# --- a keyhole's cut reads on the fruit ------------------------------------------------------------


def faint_cuts(data: dict) -> list[str]:
    """The keyhole cuts (``keyhole:N``) drawn in a colour under :data:`LEAST_CONTRAST` against
    the fill they cross (ear clipping's fruit, as the screen shows it), as ``"play 213
    keyhole:2 on polygon 1.1 : 1"``: chapter 4's cuts, in the rind's olive on the orange
    fruit (1.1 : 1), all but vanished, and the slicing that goes round them had nothing to go
    round. Each cut once, where it first fails."""
    from shapely.geometry import LineString

    found: dict[str, str] = {}
    for k, shown in _shown_after_plays(data, (_KEYHOLE, *_FILLED)):
        fills = _fills(shown)
        for name, node in shown.items():
            colour = _one_colour(node.get("stroke"))
            if not name.startswith(_KEYHOLE) or colour is None or name in found:
                continue
            cut = [LineString(s) for s in _segments(node)]
            for owner, shape, _, under in fills:
                ratio = contrast(colour, under)
                if any(shape.intersects(line) for line in cut) and ratio < LEAST_CONTRAST:
                    found[name] = f"play {k} {name} on {owner} {ratio:.1f} : 1"
    return sorted(found.values(), key=lambda s: int(s.split()[1]))


# --- a plot's numbers are said ---------------------------------------------------------------------

#: a card's plot: its axes, and the names that say what their numbers are
_AXES, _AXIS_NAMES = "figure:axis", ("figure:x-name", "figure:y-name")


def unnamed_axes(data: dict) -> list[str]:
    """The plays that leave a card's plot (:data:`_AXES`) on screen without both its axes
    named (:data:`_AXIS_NAMES`), as ``"play 190 figure:y-name missing"``: chapter 4's "How
    fast" showed 10, 60 and 235 and never said that they were vertices and ear tests. Each
    name once, where it is first missed."""
    found: dict[str, str] = {}
    for k, shown in _shown_after_plays(data, (_AXES, *_AXIS_NAMES)):
        if _AXES not in shown:
            continue
        for name in _AXIS_NAMES:
            if name not in shown:
                found.setdefault(name, f"play {k} {name} missing")
    return sorted(found.values(), key=lambda s: int(s.split()[1]))


# --- a label off the fruit where it has room ----------------------------------------------------

#: how far (scene units) a label's box may stand from its dot, looked for a place off the fruit
ROOM_REACH = 0.6
#: the gap such a place keeps from every edge, cut, dot and other label (labels.py's least)
ROOM_GAP = 0.12


def labels_on_the_fruit_with_room(data: dict) -> list[str]:
    """The vertex labels over ear clipping's fruit (the polygon filled in the fruit's
    orange) that have room beside their vertex off it, as ``"play 260 a₂ on the fruit,
    room off it"``: a place for the label's box within :data:`ROOM_REACH` of its dot, wholly
    off the fruit and any test triangle shown (or drawn in the next two plays),
    :data:`ROOM_GAP` clear of the fruit's edges, the keyhole cuts, the dots
    and the other labels, nearer its own dot than any other, seen from its dot across no
    edge. A hole's label stands on the orange (on its dark halo) while the hole has no room
    for it; left there once the slices round its vertex had cut the fruit away (chapter 4's
    a₂), it covered the fruit for nothing. The markers and the fruit as
    :func:`_shown_after_plays` follows them; each vertex once, where first found."""
    import shapely

    from metaphors.theme import THEME

    found: dict[str, str] = {}
    states = [(k, dict(shown)) for k, shown in
              _shown_after_plays(data, ("vertex:", "polygon", _KEYHOLE, *_TEST_TRIANGLES))]
    for at, (k, shown) in enumerate(states):
        # the labels move off a test triangle before it comes in (its words' play between)
        then = [n for _, later in states[at + 1:at + 3] for n in later.items()]
        fruit = [shape for owner, shape, (colour, _), _ in _fills(shown)
                 if owner == "polygon" and colour.lower() == THEME.fruit.lower()]
        if not fruit:
            continue
        # a place on a test triangle is none (labels_under_test_triangles)
        taken = shapely.union_all([fruit[0], *(shapely.Polygon(_corners(n))
                                               for name, n in (*shown.items(), *then)
                                               if name.startswith(_TEST_TRIANGLES)
                                               and len(n.get("points") or []) >= 12)])
        lines = [s for name, n in shown.items() if name.startswith((_KEYHOLE, "polygon"))
                 for s in _segments(n)]
        walls = shapely.union_all([shapely.LineString(s) for s in lines]) if lines else None
        markers = {name.removeprefix("vertex:"): (_dot_centre(m), list(_label_boxes(m, direct=True)))
                   for name, m in shown.items() if name.startswith("vertex:")}
        for vertex, (dot, boxes) in markers.items():
            if dot is None or not boxes or vertex in found:
                continue
            if not fruit[0].intersects(shapely.box(*boxes[0])):
                continue
            others = [b for v, (_, bs) in markers.items() if v != vertex for b in bs]
            dots = [d for v, (d, _) in markers.items() if v != vertex and d is not None]
            if _room_off(dot, boxes[0], taken, walls, others, dots):
                found[vertex] = f"play {k} {vertex} on the fruit, room off it"
    return sorted(found.values(), key=lambda s: int(s.split()[1]))


def _room_off(dot, box, fruit, walls, others, dots) -> bool:
    """Whether a box the size of ``box`` has a place round ``dot`` as
    :func:`labels_on_the_fruit_with_room` asks."""
    import numpy as np
    import shapely

    w, h = box[2] - box[0], box[3] - box[1]
    reach = ROOM_REACH + max(w, h) / 2
    xs = np.arange(dot[0] - reach, dot[0] + reach + 1e-9, 0.05)
    ys = np.arange(dot[1] - reach, dot[1] + reach + 1e-9, 0.05)
    cx, cy = (a.ravel() for a in np.meshgrid(xs, ys))
    boxes = shapely.box(cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2)
    here = shapely.Point(dot)
    ok = (shapely.distance(boxes, here) <= ROOM_REACH) & (shapely.distance(boxes, here) >= ROOM_GAP)
    ok &= ~shapely.intersects(boxes, fruit)
    if walls is not None:
        ok &= shapely.distance(boxes, walls) >= ROOM_GAP
        rays = shapely.linestrings(np.stack([np.broadcast_to(dot, (len(cx), 2)),
                                             np.column_stack([cx, cy])], axis=1))
        # seen from its dot: the way to it meets no edge away from the dot itself
        ok &= ~shapely.intersects(rays, walls.difference(here.buffer(1e-3)))
    for other in others:
        ok &= shapely.distance(boxes, shapely.box(*other)) >= ROOM_GAP
    for d in dots:
        near = shapely.distance(boxes, shapely.Point(d))
        ok &= (near >= ROOM_GAP) & (near > shapely.distance(boxes, here))
    return bool(ok.any())


# --- colour4: chapters 2 and 3, colours and timings as a viewer sees them -------------------------


def _vertex_roles(anim: dict) -> Iterator[tuple[str, str]]:
    """(label, role) of every vertex marker (a picture's ``vertex:K``, the panel's ``panel:K``)
    an animation (or its members) records, in the role it is tagged with: the role its
    colour shows (a board recolours a marker and tags it together)."""
    for _, node in _recorded(anim):
        label = _vertex_label(node)
        if label is not None and node.get("role"):
            yield label, node["role"]


def _reaches(anim: dict) -> Iterator[str]:
    """The vertices a tool is seen to reach in an animation (or its members): its ring lit
    there (``lit:K``, the clock's and the sweep line's), or the pulse it gives the marker in
    the pick's or a candidate's colour (the water's)."""
    for child in anim.get("animations", ()):
        yield from _reaches(child)
    name = (anim.get("mobject") or {}).get("name") or ""
    if anim.get("type") == "FadeIn" and name.startswith("lit:"):
        yield name.removeprefix("lit:")
    colour = str(anim.get("color") or "").upper()
    if (anim.get("type") == "Indicate" and name.startswith("vertex:")
            and colour in (_colour("argument"), _colour("candidate"))):
        yield name.removeprefix("vertex:")


def _new_picture(play: dict) -> bool:
    """Whether a play brings a polygon in: a new picture, its markers afresh."""
    return any(a.get("type") in INCOMING and (a.get("mobject") or {}).get("name") in _POLYGONS
               for a in play["animations"])


def _new_run(play: dict) -> bool:
    """Whether a play brings a run's title in: a run going on on the board the last one
    played on (the counterexample's corrections, :func:`metaphors.play.go_on`), its pick
    its own (the wrong rule's D, amber in its run, is a candidate of the correction's)."""
    return any(a.get("type") in INCOMING and (a.get("mobject") or {}).get("name") == "title"
               for a in play["animations"])


def early_picks(data: dict) -> list[str]:
    """The picks lit amber (the claim to be) before the tool reaches them, as ``"play 132 E
    amber, reached at play 134"``: chapter 2's working runs lit the pick amber as the tool
    set out, about a second before it got there (the sweep's E at 165.0 s, reached at
    166.2 s). A tool's reach is its ring or its pulse there (:func:`_reaches`)."""
    found: list[str] = []
    roles: dict[str, str] = {}
    amber: dict[str, int] = {}  # vertex: the play it turned amber in
    for k, play in enumerate(data["plays"]):
        # a new run on the same board starts its picks afresh; its markers keep the colours
        # they have on screen (an amber vertex said amber again has not turned amber)
        if _new_picture(play):
            roles, amber = {}, {}
        elif _new_run(play):
            amber = {}
        for anim in play["animations"]:
            for label, role in _vertex_roles(anim):
                if role == "argument" and roles.get(label) != "argument":
                    amber.setdefault(label, k)
                roles[label] = role
        for label in sorted({v for anim in play["animations"] for v in _reaches(anim)}):
            if amber.get(label, k) < k:
                found.append(f"play {amber[label]} {label} amber, reached at play {k}")
    return list(dict.fromkeys(found))


#: the roles a vertex is lit in that say something of it (not the ink of one out of the call,
#: nor a candidate's neutral pink): a viewer seeing a vertex turn one asks why
_SAYING_ROLES = ("called", "argument", "result", "rejected")
#: a word of a caption made only of vertex labels ("CH", "E", "a₂b₂")
_LABEL_WORD = re.compile(r"(?:[A-Z][₀-₉′″]*)+|(?:[a-z][₀-₉′″]+)+")
_ONE_LABEL = re.compile(r"[A-Z][₀-₉′″]*|[a-z][₀-₉′″]+")


def labels_said(caption: str) -> set[str]:
    """The vertex labels a caption names: its words of labels only, each label of them.

    >>> sorted(labels_said("Claim: CH is an inner diagonal; BD crosses edge E–A"))
    ['A', 'B', 'C', 'D', 'E', 'H']
    >>> sorted(labels_said("Turn the polygon so that gravity points down"))
    []
    """
    return {label for word in re.findall(r"[\w′″]+", caption) if _LABEL_WORD.fullmatch(word)
            for label in _ONE_LABEL.findall(word)}


#: the words of a caption that say its steps show what they showed before (a summary's fast
#: beats, a frame built again): its colours were said then
_AS_BEFORE = re.compile(r"the same steps|as before")


def unsaid_colour_changes(data: dict) -> list[str]:
    """The vertices lit in a new role under a caption that does not name them, as ``"play 16
    C result → called under 'Turn the polygon so that gravity points down'"``: chapter 3's
    C went green as it was picked, then blue a second later as the polygon turned, and G
    green (where the ball slid), then amber under "The rubber band snags H". A vertex's
    colour changes when the words say why; going back to its ink or to a candidate's pink
    (neutral again) needs none, nor a step the caption says is as before (:data:`_AS_BEFORE`).
    Each vertex, roles and caption once."""
    found: list[str] = []
    roles: dict[str, str] = {}
    caption = ""
    for k, play in enumerate(data["plays"]):
        caption = play.get("subcaption") or caption
        if _new_picture(play):
            roles = {}
        said = labels_said(caption) if not _AS_BEFORE.search(caption) else None
        for anim in play["animations"]:
            for label, role in _vertex_roles(anim):
                was = roles.get(label, role)
                roles[label] = role
                if role != was and role in _SAYING_ROLES and said is not None \
                        and label not in said:
                    found.append(f"play {k} {label} {was} → {role} under {caption!r}")
    # one line per change, the picture's marker and the panel's told once
    return list(dict.fromkeys(found))


#: the red regions of a failure: the part of a tool's sweep outside P (an analysis's)
_RED_REGIONS = ("analysis:outside",)


def picks_in_the_red(data: dict) -> list[str]:
    """The vertex markers whose label or dot stands on a red region (:data:`_RED_REGIONS`)
    with no dark halo (:func:`_haloed`) to set it apart, as ``"play 51 D label on
    analysis:outside"``: chapter 2's analyses drew the amber D, the pick, inside the red
    "outside P" wedge, its dot on the wedge's edge — amber on red, neither read. Each vertex
    and part once."""
    import shapely

    found: list[str] = []
    for k, shown in _shown_after_plays(data, ("vertex:", *_RED_REGIONS)):
        red = [shapely.Polygon(ring) for name, node in shown.items()
               if name.startswith(_RED_REGIONS) for part in mobject_nodes(node)
               if (part.get("fill_opacity") or 0) > 0 for ring in _paths(part)]
        red = [r for r in red if r.is_valid and r.area > 0]
        if not red:
            continue
        wedge = shapely.union_all(red)
        for name, marker in shown.items():
            if not name.startswith("vertex:"):
                continue
            for part in marker.get("submobjects", ()):
                if (part.get("text") or "").strip() and part.get("box"):
                    kind, shape = "label", shapely.box(*part["box"])
                elif part.get("type") == "Dot" and part.get("points"):
                    kind, shape = "dot", shapely.MultiPoint(_corners(part)).convex_hull
                else:
                    continue
                if shape.intersects(wedge) and not _haloed(part):
                    found.append(f"play {k} {name.removeprefix('vertex:')} {kind} on "
                                 f"{_RED_REGIONS[0]}")
    return _once_each(found)


def _once_each(found: list[str]) -> list[str]:
    """The first of the findings about each thing (``"play 51 D label on …"``: by what
    follows the play's number)."""
    seen: dict[str, str] = {}
    for line in found:
        seen.setdefault(line.split(" ", 2)[2], line)
    return list(seen.values())


#: the seconds a caption may come before what it speaks of: the words' lead of a board's play
#: (:data:`metaphors.board.WORDS_TIME`) and a frame's rounding
WORDS_LEAD = 0.35
#: gravity's ball on screen: a run's, an analysis's, a card's figure's
_BALLS = ("ball", "analysis:ball", "figure:ball")
#: a caption telling what the ball does now (not what it will do: "the ball will hang there")
_BALL_NOW = re.compile(r"\bthe ball (?:falls|slides|hangs|hits|rests)\b", re.I)


def balls_not_there(data: dict) -> list[str]:
    """The captions that tell what the ball does (:data:`_BALL_NOW`) while none is on screen,
    for longer than the words' lead (:data:`WORDS_LEAD`), as ``"55.9 s: 'A close-up: the
    ball falls only a short way' not with the ball"``: chapter 3's close-up said the ball
    falls a short way, zoomed, and showed the ball only under the next caption, 2.8 s later.
    Times as the graph has them (the plays' run times, summed)."""
    found: list[str] = []
    shown: set[str] = set()
    t, waiting = 0.0, None  # the caption waiting for the ball, and when it came
    for play in data["plays"]:
        caption = play.get("subcaption")
        if caption:
            if waiting is not None:
                found.append(f"{waiting[1]:.1f} s: {waiting[0]!r} not with the ball")
            waiting = (caption, t) if _BALL_NOW.search(caption) and not shown else None
        for anim in play["animations"]:
            for kind, _, name in _ends(anim):
                if name in _BALLS:
                    (shown.discard if kind in OUTGOING else shown.add)(name)
        if waiting is not None and shown:
            late = t - waiting[1]
            if late > WORDS_LEAD:
                found.append(f"{waiting[1]:.1f} s: {waiting[0]!r} {late:.1f} s before the ball")
            waiting = None
        t += play["run_time"]
    return found


def _fills_shown(shown: dict[str, dict]) -> Iterator[tuple[str, str, float, Any]]:
    """(owner's name, colour, z-index, region) of each filled part of the things shown
    (not a text, not a legend's swatch)."""
    import shapely

    for name, node in shown.items():
        if name.startswith(_LEGEND):
            continue
        for part in mobject_nodes(node):
            if (part.get("fill_opacity") or 0) <= 0 or "text" in part or not part.get("points"):
                continue
            rings = [shapely.Polygon(r) for r in _paths(part)]
            rings = [r for r in rings if r.is_valid and r.area > 0]
            if rings:
                yield (name, str(part.get("fill")).upper(), float(part.get("z", 0)),
                       shapely.union_all(rings))


def keys_with_nothing_shown(data: dict) -> list[str]:
    """The legend entries left up once every region in their colour is gone or covered by
    another colour drawn over it, as ``"play 48 legend:band"``: chapter 3's analysis kept
    "band swept" (rose) beside a picture whose rose region the green "swept: in P" covered
    (chapter 2's blue "swept" went before its green came). Only entries whose colour was
    shown as a region while they were up (a run's red "outside P" names a line)."""
    import shapely

    found: list[str] = []
    shown: dict[str, dict] = {}
    filled: set[str] = set()  # the entries whose colour was shown as a region
    for k, play in enumerate(data["plays"]):
        if _new_picture(play):
            shown, filled = {}, set()
        for anim in play["animations"]:
            for kind, node, name in _ends(anim):
                if kind in OUTGOING:
                    shown.pop(name, None)
                elif name:
                    shown[name] = node
        fills = list(_fills_shown(shown))
        for name, node in shown.items():
            swatch = next((p for p in mobject_nodes(node) if p.get("type") == "Square"
                           and (p.get("fill_opacity") or 0) > 0), None)
            if not name.startswith(_LEGEND) or swatch is None:
                continue
            colour = str(swatch.get("fill")).upper()
            own = [(z, r) for _, c, z, r in fills if c == colour]
            seen = shapely.union_all([r for _, r in own]) if own else shapely.Polygon()
            if own:
                cover = [r for _, c, z, r in fills if c != colour and z > min(z for z, _ in own)]
                if cover:
                    seen = seen.difference(shapely.union_all(cover))
            if seen.area > 1e-3:
                filled.add(name)
            elif name in filled:
                found.append(f"play {k} {name}")
                filled.discard(name)
    return found


# --- grav7: chapter 3 and the gravity scene as a teacher shows them ----------------------------

#: a card's figure words naming the claim its rule makes ("… claim CH"), and a run's claim
_CARD_CLAIM = re.compile(r"\bclaim ([A-Z][₀-₉′″]*[A-Z][₀-₉′″]*)\b")


def _sections(data: dict) -> Iterator[tuple[int, str, dict]]:
    """(play, the section it is in, the play): a card's title opens a section; in a graph
    with no card (a scene), each run's title (a scene of several runs on one polygon plays
    each heuristic anew), as :func:`shown_steps` has them."""
    def named(play: dict, name: str) -> list[dict]:
        return [node for a in play["animations"] if a["type"] in INCOMING
                and (node := a.get("mobject") or {}).get("name") == name]

    carded = any(named(play, "card:title") for play in data["plays"])
    section = ""
    for k, play in enumerate(data["plays"]):
        if named(play, "card:title"):
            section = play.get("subcaption") or section
        elif not carded and (titles := named(play, "title")):
            section = f"{titles[0].get('text') or ''} (play {k})"
        yield k, section, play


def answers_on_cards(data: dict) -> list[str]:
    """The claims a card's figure gives away before the run of its section makes them, as
    ``"'V = C, X = G, Y = H: claim CH' before 'Claim: CH is an inner diagonal' (Gravity …)"``:
    chapter 3's card drew the finished picture — fall, slide, band, CH — and said "claim CH"
    16 s before the run played the same example to the same answer. A card states the rule;
    its run gives the answer, once."""
    found: list[str] = []
    told: dict[tuple[str, str], str] = {}  # (section, claim): the figure's words saying it
    for _, section, play in _sections(data):
        for anim in play["animations"]:
            for kind, node in _recorded(anim):
                if kind in INCOMING and node.get("name") == "figure:label":
                    words = " ".join(n["text"] for n in mobject_nodes(node) if n.get("text"))
                    for claim in _CARD_CLAIM.findall(words):
                        told.setdefault((section, claim), words)
        said = _CLAIM_CAPTION.match(play.get("subcaption") or "")
        if said and (section, said[1]) in told:
            found.append(f"{told.pop((section, said[1]))!r} before {said[0]!r} ({section})")
    return found


def redrawn_pictures(data: dict) -> list[str]:
    """The run pictures drawn again in one card's section, as ``"play 41: the picture of
    play 14 drawn again (Gravity …)"``: a polygon of the same shape (:func:`_shape`: wherever,
    however large and turned) drawn anew where it was drawn already — chapter 3's analysis
    redrew the run's end state, ball, band and claim, on a picture of its own before shading
    it. What follows a run goes on from its picture."""
    found: list[str] = []
    drawn: dict[tuple[str, tuple], int] = {}
    for k, section, play in _sections(data):
        for anim in play["animations"]:
            node = anim.get("mobject") or {}
            if anim["type"] in INCOMING and node.get("name") in _RUN_POLYGONS and node.get("points"):
                key = (section, _shape(node))
                if key in drawn:
                    found.append(f"play {k}: the picture of play {drawn[key]} drawn again "
                                 f"({section})")
                drawn.setdefault(key, k)
    return found


#: a verdict's words: a run's claim judged
_VERDICT_WORDS = re.compile(r"^[✓✗] ")


def close_ups_left_early(data: dict) -> list[str]:
    """The close-ups (their window, ``close-up:window``) that zoom back out before the claim
    of their run is judged, as ``"play 60: zoomed out under 'The ball falls until it hits
    the boundary'"``: chapter 3's close-up showed only the short fall and zoomed out before
    the slide, so that the band staying straight and the claim EC beside edge B–C were a
    faint line 60 × 70 px wide. A close-up stays until the words say ✓ or ✗."""
    found: list[str] = []
    caption, judged = "", False
    for k, play in enumerate(data["plays"]):
        if play.get("subcaption"):
            caption = play["subcaption"]
            judged = judged or bool(_VERDICT_WORDS.match(caption))
        for anim in play["animations"]:
            for kind, node in _recorded(anim):
                if node.get("name") != _CLOSE_UP + ":window":
                    continue
                if kind in INCOMING:
                    judged = False
                elif kind in OUTGOING and not judged:
                    found.append(f"play {k}: zoomed out under {caption!r}")
    return found


#: gravity's marks and the words that name them: the arrow ("g"), what the band swept, a ring
#: where the ball hit; a word of the caption up as the mark comes in, or of the one after it
#: in the same play
_MARK_WORDS = {"gravity": re.compile(r"\(g\)|\bg\b"),
               "swept": re.compile(r"\bshaded\b|\bswept\b|\bsweeps\b"),
               "hit": re.compile(r"\bring\b")}


def unnamed_marks(data: dict) -> list[str]:
    """Gravity's marks that come in under words that do not name them, as ``"play 27 hit
    under 'The ball falls until it hits the boundary'"``: chapter 3's open amber ring where
    the ball lands, the "g" arrow and the band's shaded swept region (shown at 30.5 s,
    explained at 41 s) were named by nothing. Each mark once."""
    found: dict[str, str] = {}
    caption = ""
    for k, play in enumerate(data["plays"]):
        caption = play.get("subcaption") or caption
        for anim in play["animations"]:
            for kind, _, name in _ends(anim):
                words = _MARK_WORDS.get(name)
                if kind in INCOMING and words is not None and name not in found:
                    found[name] = "" if words.search(caption) else \
                        f"play {k} {name} under {caption!r}"
    return [line for line in found.values() if line]


#: a pseudocode row giving a placeholder (a capital) its vertex: ``V = the first …``
_GIVES = re.compile(r"^([A-Z][₀-₉′″]*) = (.*)$")


def _panel_rows(data: dict) -> Iterator[tuple[int, list[str], list[str]]]:
    """(play, the rows the panel shows, the rows lit in the play) of each play: the rows as
    the panel's ``code:K`` rows say them (renamed rows as renamed), a new picture anew."""
    rows: dict[str, str] = {}
    for k, play in enumerate(data["plays"]):
        if _new_picture(play):
            rows = {}
        for anim in play["animations"]:
            # the rows come with the panel's block (a group), and one by one as renamed
            for part in mobject_nodes(anim.get("mobject") or {}):
                name = part.get("name") or ""
                if name.startswith("code:") and part.get("role") == "idle" and part.get("text"):
                    rows[name] = part["text"].strip()
        yield k, list(rows.values()), [r for a in play["animations"] for r in _lit_rows(a)]


def unlit_givens(data: dict) -> list[str]:
    """The pseudocode rows that give a placeholder its vertex (``B = the left-most vertex``)
    never lit in a run whose lit rows use it, as ``"'B = the left-most vertex' (used by 'V =
    the first reflex vertex after B')"``: gravity's V is "the first reflex vertex after B",
    and B was never lit nor shown (chapter 3). A run is a picture's plays; a row lit at any
    time in it counts (a loop's row may use what its next round gives). Each row once."""
    found: dict[str, str] = {}
    runs: list[tuple[dict[str, str], set[str], list[str]]] = []  # (givens, lit, used)
    for k, rows, lighting in _panel_rows(data):
        if not runs or _new_picture(data["plays"][k]):
            runs.append(({}, set(), []))
        givens, lit, used = runs[-1]
        givens.update({m[1]: row for row in rows if (m := _GIVES.match(row))})
        lit.update(lighting)
        used.extend(lighting)
    for givens, lit, used in runs:
        for row in used:
            for placeholder, giving in givens.items():
                if giving != row and re.search(rf"\b{placeholder}\b", row.split(" = ", 1)[-1]) \
                        and not any(r.startswith(f"{placeholder} =") for r in lit):
                    found.setdefault(giving, f"{giving!r} (used by {row!r})")
    return list(found.values())


def untied_placeholders(data: dict) -> list[str]:
    """The lit rows that give a placeholder no label of the picture has (gravity's V, X, Y)
    under words that name the vertex the run gave it, without saying which, as ``"'V = the
    first reflex vertex after B' under 'C is the first reflex vertex after B: …'"``: the card
    and the rows said V, X, Y and the picture C, G, H, never tied (chapter 3). A row tied
    says ``V = C, …`` (:func:`story.pseudocode.bound`)."""
    found: list[str] = []
    caption = ""
    labels: set[str] = set()
    for play in data["plays"]:
        caption = play.get("subcaption") or caption
        if _new_picture(play):
            labels = set()
        for anim in play["animations"]:
            for _, node in _recorded(anim):
                label = _vertex_label(node)
                if label is not None and (node.get("name") or "").startswith("vertex:"):
                    labels.add(label)
        for anim in play["animations"]:
            for row in _lit_rows(anim):
                defines, ends = _GIVES.match(row), re.search(r"\ba vertex ([A-Z])$", row)
                # the words give the vertex: "C is …", "… snags H" for a row "V = …", "… to G"
                # for a row "… to a vertex X" (not a step that measures the candidates)
                gives = (re.search(r"^([A-Z][₀-₉′″]*) is\b|\bsnags ([A-Z][₀-₉′″]*)\b", caption)
                         if defines else re.search(r"\bto ([A-Z][₀-₉′″]*)\b", caption)
                         if ends else None)
                placeholder = (defines or ends)[1] if (defines or ends) else None
                if placeholder is None or placeholder in labels or gives is None:
                    continue
                if not re.search(rf"\b{placeholder} = [A-Z]", row):
                    found.append(f"{row!r} under {caption!r}")
    return list(dict.fromkeys(found))


def mixed_words(data: dict) -> list[str]:
    """A thing said with two words on one screen: a pseudocode row that says "side" where
    the captions and cards say "edge", as ``"'it slides down the side to a vertex X' beside
    'It slides down the edge to G'"`` (chapter 3's gravity rows). Each row once."""
    rows = {r for _, _, lighting in _panel_rows(data) for r in lighting}
    said = [p["subcaption"] for p in data["plays"] if p.get("subcaption")]
    edge = next((c for c in said if re.search(r"\bedges?\b", c)), None)
    return [f"{row!r} beside {edge!r}" for row in sorted(rows)
            if edge is not None and re.search(r"\bsides?\b", row)]


def rows_behind_words(data: dict) -> list[str]:
    """The plays whose caption says the band snags a vertex while the row lit says the ball
    slides, as ``"play 22 'it slides down the side to a vertex X' under 'The rubber band
    snags H'"``: the gravity scene's lit row ran 0.9 s behind its caption at 11.5 s."""
    found: list[str] = []
    caption, row = "", ""
    for k, play in enumerate(data["plays"]):
        caption = play.get("subcaption") or caption
        for anim in play["animations"]:
            for lit in _lit_rows(anim):
                row = lit
        if "snags" in caption and "slides" in row:
            found.append(f"play {k} {row!r} under {caption!r}")
    return list(dict.fromkeys(found))


def claims_missing_from_panel(data: dict) -> list[str]:
    """The claims drawn on a turned picture that the panel, which shows P as it stands, does
    not draw (``panel/claim``), as ``"play 33: CH"``: chapter 3's panel coloured C and H and
    never drew CH while the picture was turned."""
    found: list[str] = []
    turned = False
    caption = ""
    for k, play in enumerate(data["plays"]):
        caption = play.get("subcaption") or caption
        if _new_picture(play):
            turned = False
        names = [(a["type"], (a.get("mobject") or {}).get("name")) for a in play["animations"]]
        # a run turns P and turns it back upright after its verdict (a scene of several
        # runs, divide and conquer's, turns each piece's run anew): each turn flips it
        if any(kind == "Turn" and name == "polygon" for kind, name in names):
            turned = not turned
        if any(kind in INCOMING and name == "claim" for kind, name in names) and turned \
                and not any(kind in INCOMING and name == "panel/claim" for kind, name in names):
            said = _CLAIM_CAPTION.match(caption)
            found.append(f"play {k}: {said[1] if said else caption}")
    return found


def stale_panel_claims(data: dict) -> list[str]:
    """The panel claims judged (recoloured) when the claim on the picture was drawn without
    one, as ``"play 45: FD judged on the panel's DG"``: divide and conquer's panel kept the
    last turned run's claim DG and recoloured it with every later verdict (FD, drawn upright,
    had none on the panel), so that a ✗ would have turned DG red there."""
    found: list[str] = []
    fresh, caption = False, ""
    for k, play in enumerate(data["plays"]):
        caption = play.get("subcaption") or caption
        names = [(a["type"], (a.get("mobject") or {}).get("name")) for a in play["animations"]]
        if any(kind in INCOMING and name == "claim" for kind, name in names):
            fresh = any(kind in INCOMING and name == "panel/claim" for kind, name in names)
        if any(kind not in INCOMING and kind not in OUTGOING and name == "panel/claim"
               for kind, name in names) and not fresh:
            found.append(f"play {k}: the panel's old claim judged under {caption!r}")
    return found


def green_claims_white_ends(data: dict) -> list[str]:
    """The claims turned green (judged inner) whose ends both stay in another colour, as
    ``"play 47 analysis:claim: C, H not green"``: gravity's analysis drew CH green and left
    C and H white, where chapter 2's analyses turn the pick green with its claim. The ends
    are the vertex markers at the claim's ends, as :func:`_shown_after_plays` follows them."""
    import numpy as np

    green = _colour("result")
    found: list[str] = []
    for k, shown in _shown_after_plays(data, ("vertex:", "claim", "analysis:claim")):
        for name in ("claim", "analysis:claim"):
            claim = shown.get(name)
            if claim is None or str(claim.get("stroke") or "").upper() != green \
                    or len(claim.get("points") or []) < 2:
                continue
            ends = [tuple(claim["points"][0][:2]), tuple(claim["points"][-1][:2])]
            at: dict[str, str] = {}
            for marker, node in shown.items():
                dot = _dot_centre(node) if marker.startswith("vertex:") else None
                if dot is not None and any(np.hypot(dot[0] - x, dot[1] - y) < 0.05
                                           for x, y in ends):
                    colours = {str(p.get("fill") or p.get("stroke") or "").upper()
                               for p in mobject_nodes(node) if p.get("text")}
                    at[marker.removeprefix("vertex:")] = "green" if green in colours else "not"
            if len(at) == 2 and "green" not in at.values():
                found.append(f"play {k} {name}: {', '.join(sorted(at))} not green")
    return list(dict.fromkeys(found))


# --- the panel's polygon follows the run ---------------------------------------------------------

#: the picture's lines the panel draws too, by the name the picture gives them, and the names
#: the panel's may have (a claim split along is a diagonal in the panel)
_PANEL_TWINS = {"claim": ("panel/claim", "panel/diagonal:"), "edge:": ("panel/crossed",),
                "keyhole:": ("panel/keyhole:",), "diagonal:": ("panel/diagonal:",)}


def _twin(name: str) -> tuple[str, ...] | None:
    """The names the panel's twin of a picture's line may have; None: it has none."""
    return next((twins for start, twins in _PANEL_TWINS.items()
                 if name == start or (start.endswith(":") and name.startswith(start))), None)


def _last_ends(play: dict) -> dict[int, tuple[str, str, dict]]:
    """Each top mobject a play records, in the state the play leaves it: (animation type,
    name, node) of the last node each animation records (a transform's target)."""
    ends: dict[int, tuple[str, str, dict]] = {}
    for k, anim in enumerate(play["animations"]):
        for kind, node, name in _ends(anim):
            ends[k] = (kind, name, node)
    return ends


def _stroke(node: dict) -> str | None:
    return (_one_colour(node.get("stroke")) or "").upper() or None


def panels_behind_the_picture(data: dict) -> list[str]:
    """Where the panel's polygon (DESIGN: "the same polygon drawn plainly with objects
    coloured by their role in the current call") does not follow the picture, as
    ``"play 12 A sliced off the picture, still in the panel"``, ``"play 30 claim #F2B134 not
    in the panel"``, ``"play 31 edge:E–A not in the panel"``, ``"play 4 keyhole:2 not in the
    panel"``, ``"play 80 triangulation not in the panel"`` or ``"play 40 claim FD's piece
    not tinted in the panel"``: a vertex taken off the picture goes from the panel with it;
    a claim (amber, then green or red, then a diagonal's ink), the edge a claim crosses and a
    diagonal come into the panel in the picture's colour in the same play, a keyhole cut in
    the ink (the picture's is a dark slit through the fruit); the whole
    triangulation shows in it as in the picture; and a claim made on a piece of P (divide
    and conquer's, the picture tinted in pieces) comes with the panel tinting its piece
    (``panel/part``, the claim's ends among its corners). The panel kept the bare polygon
    while the picture sliced it (ear clipping at 9 s still drew A, sliced at 7 s), split it
    (divide and conquer's 11 triangles beside the bare 13-gon) and claimed diagonals in it.
    A run whose panel draws no polygon (the source instead) is left out."""
    found: list[str] = []
    panel: dict[str, dict] = {}  # the panel's parts shown, by name
    gone: set[str] = set()  # the picture's vertices taken off it
    pieces = False  # the picture is tinted in pieces (divide and conquer)
    for k, play in enumerate(data["plays"]):
        if _new_picture(play):
            panel, gone, pieces = {}, set(), False
        ends = _last_ends(play)
        for kind, name, node in ends.values():
            if name.startswith(("panel:", "panel/")):
                if kind in OUTGOING:
                    panel.pop(name, None)
                else:
                    panel[name] = node
            elif name.startswith("vertex:"):
                label = name.removeprefix("vertex:")
                (gone.add if kind in OUTGOING else gone.discard)(label)
            elif name.startswith(("piece:", "triangle:")) and kind in INCOMING:
                pieces = True
        if "panel:polygon" not in panel:
            continue
        # a slice: the picture's outline shrinks as vertices leave it (a close-up fades the
        # vertices outside its box for a while, the outline whole)
        sliced = any(name == "polygon" and kind not in INCOMING | OUTGOING
                     for kind, name, _ in ends.values())
        for kind, name, node in ends.values():
            if sliced and name.startswith("vertex:") and kind in OUTGOING and \
                    f"panel:{name.removeprefix('vertex:')}" in panel:
                found.append(f"play {k} {name.removeprefix('vertex:')} sliced off the picture, "
                             "still in the panel")
            twins = _twin(name)
            if twins is not None and kind not in OUTGOING and kind != "Turn":
                # the picture's keyhole cut is a dark slit (the background through the
                # fruit), the panel's an edge in the ink: only its being there is compared
                colour = None if name.startswith("keyhole:") else _stroke(node)
                shown = [n for p, n in panel.items() if p.startswith(twins)]
                if not any(colour is None or _stroke(n) == colour for n in shown):
                    found.append(f"play {k} {name} {colour} not in the panel" if name == "claim"
                                 else f"play {k} {name} not in the panel")
                if name == "claim" and kind in INCOMING and pieces:
                    found += _untinted_piece(k, panel)
            if name == "triangulation" and kind in INCOMING and not any(
                    p.startswith(("panel/triangulation", "panel/diagonal:")) for p in panel):
                found.append(f"play {k} triangulation not in the panel")
    return list(dict.fromkeys(found))


def _untinted_piece(k: int, panel: dict[str, dict]) -> list[str]:
    """``["play k claim's piece not tinted in the panel"]`` unless the panel's tint of the
    part of P worked on (``panel/part``) has both ends of the panel's claim among its corners."""
    claim, part = panel.get("panel/claim"), panel.get("panel/part")
    if claim is None:
        return []
    ends = _segments(claim)
    corners = _corners(part) if part is not None else []
    if ends and all(_near(p, corners) for p in ends[0]):
        return []
    return [f"play {k} claim's piece not tinted in the panel"]



# --- ear clipping's words -------------------------------------------------------------------------

#: a caption saying a vertex is an ear
_EAR_YES = re.compile(r"\bIs (\S+) an ear\? yes\b")
#: a label with a prime: a bridge end's second copy (``c₁′``, ``F″``)
_PRIMED = re.compile(r"(?<![\w′″‴])[A-Za-z][₀-₉]*[′″‴]+")


def ears_without_convexity(data: dict) -> list[str]:
    """The captions saying a vertex is an ear without saying both of what makes one, as
    ``"Is A an ear? yes: its triangle holds no other vertex"``: an ear is a convex vertex
    whose triangle holds no other vertex (issue 22 item 11, Meisters): the lecture's own
    counterexample has a reflex E whose triangle DEA is empty."""
    return sorted({play["subcaption"] for play in data["plays"]
                   if _EAR_YES.search(play.get("subcaption") or "")
                   and not ("convex" in play["subcaption"] and "triangle" in play["subcaption"])})


def unexplained_primes(data: dict) -> list[str]:
    """The primed labels (a keyhole cut's ends the second time round its ring: ``c₁′``,
    ``F″``) a call line or caption names before any caption has said them, as ``"play 80
    c₁′"``: KeyholeEars' call lines said ``clip_ear(c₁′, F′, c₂)`` and nothing said what the
    primes were. Each label once."""
    said: set[str] = set()
    found: dict[str, str] = {}
    for k, play in enumerate(data["plays"]):
        said |= set(_PRIMED.findall(play.get("subcaption") or ""))
        for anim in play["animations"]:
            for node in animation_nodes(anim):
                if node.get("name") in ("panel:call", "subtitle"):
                    for label in _PRIMED.findall(node.get("text") or ""):
                        if label not in said:
                            found.setdefault(label, f"play {k} {label}")
    return sorted(found.values(), key=lambda s: int(s.split()[1]))


def unexplained_plates(data: dict) -> list[str]:
    """Ear clipping's plate (``plate``) coming in, in a run whose captions never say what it
    is for (none names the plate), as ``["play 5 plate"]``: the slices went onto a plate no
    word explained."""
    found = []
    for k, play in enumerate(data["plays"]):
        for anim in play["animations"]:
            if anim.get("type") in INCOMING and (anim.get("mobject") or {}).get("name") == "plate":
                later = [p.get("subcaption") or "" for p in data["plays"][k:]]
                ends = next((j for j, p in enumerate(data["plays"][k + 1:])
                             if _new_picture(p)), len(later))
                if not any("plate" in caption for caption in later[:ends + 1]):
                    found.append(f"play {k} plate")
    return found


# --- the exercises chapter, reviewed as a class would use it (review of chapter 6) ------------

#: the least an exercise's answer stays up (seconds), and what each thing it names on the
#: picture adds to its reading time: a class checks the answer against the picture (an answer
#: naming three diagonals was up 4.5 s)
LEAST_CHECKING, CHECK_EACH = 8.0, 2.0
#: what an answer draws that the class checks: a named diagonal, a pick
_CHECKED = ("answer:diagonal", "pick")


def hurried_answers(data: dict) -> list[str]:
    """The exercises' answers taken down before a class can check them, as ``"4.5 s < 10.5
    s: BF, BM: …"``: each answer's cue (the caption of the play that brings its text in)
    lasts at least :data:`LEAST_CHECKING`, and its reading time with :data:`CHECK_EACH` for
    each diagonal or pick it draws."""
    from story.reading import reading_time

    cues = {c["text"]: c for c in data["cues"]}
    found = []
    for play in data["plays"]:
        nodes = [node for _, node in _recorded_all_nodes(play)]
        if not any(n.get("name") == "answer" for n in nodes) or not play.get("subcaption"):
            continue
        said = play["subcaption"]
        checked = sum(1 for n in nodes if n.get("name") in _CHECKED)
        least = max(LEAST_CHECKING, reading_time(said) + CHECK_EACH * max(1, checked))
        cue = cues.get(said)
        up = cue["end"] - cue["start"] if cue else 0.0
        if up < least - 1e-6:
            found.append(f"{up:.1f} s < {least:.1f} s: {said}")
    return found


#: the words a card's figure writes on its picture (:func:`metaphors.figures._vertex_word`)
_FIGURE_WORDS = ("convex", "reflex")


def unsaid_figure_words(data: dict) -> list[str]:
    """The words a figure writes on its picture ("Convex", "Reflex") that come in while the
    caption up does not say them, as ``"play 1: Reflex under 'Exercises'"``: the exercises'
    card showed both with its title and never said what they meant."""
    found = []
    caption = ""
    for k, play in enumerate(data["plays"]):
        caption = play.get("subcaption") or caption
        for kind, node in _recorded_all_nodes(play):
            word = (node.get("name") or "").removeprefix("figure:")
            if kind in INCOMING and word in _FIGURE_WORDS and word not in caption.lower():
                found.append(f"play {k}: {word.capitalize()} under {caption!r}")
    return found


#: a measure said as a bare number at a caption's end: "Distance to C for D: 2.2" (from
#: coordinates the class never saw: in what unit, compared with what?)
_BARE_MEASURE = re.compile(r":\s*-?\d+(?:\.\d+)?$")


def bare_measures(data: dict) -> list[str]:
    """The captions that end on a number with nothing to say what it measures, as
    ``"Distance to C for D: 2.2"``."""
    return [c["text"] for c in data["cues"] if _BARE_MEASURE.search(c["text"])]


#: what the screen should not say: how the answers are made ("checked by the geometry code")
_IMPLEMENTATION = re.compile(r"\b(?:geometry|the|our|its) code\b", re.IGNORECASE)


def implementation_talk(data: dict) -> list[str]:
    """The captions that speak of the program rather than the polygon, as ``"… the answer is
    checked by the geometry code."``."""
    return [c["text"] for c in data["cues"] if _IMPLEMENTATION.search(c["text"])]


def verdicts_before_red(data: dict) -> list[str]:
    """The ✗ captions that come up before anything turns red, as ``"play 230: ✗ BE is not
    …"``: the caption said BE was not inner while BE stood amber for half a second. The play
    that brings a ✗ caption brings, or turns, something red (what it says fails)."""
    found = []
    for k, play in enumerate(data["plays"]):
        said = play.get("subcaption") or ""
        if not said.startswith("✗"):
            continue
        red = any(_REJECTED in json.dumps(node).upper() for kind, node in _recorded_all_nodes(play)
                  if kind not in OUTGOING)
        if not red:
            found.append(f"play {k}: {said}")
    return found


def _exercise_t(node: dict) -> list[tuple[float, float]] | None:
    """T's corners, if ``node`` is an exercise's tinted triangle (a filled polygon of three)."""
    if node.get("type") != "Polygon" or not (node.get("fill_opacity") or 0):
        return None
    corners = list(dict.fromkeys(_corners(node)))
    return corners if len(corners) == 3 else None


def labels_on_t_without_halo(data: dict) -> list[str]:
    """The exercises' vertex labels that stand over T's tint with no dark halo, as ``"E on
    T"``: a candidate's label must (its vertex lies in T), and pink or green on the tint
    read as on the picture, not beside it (E, F, G and M stood on it)."""
    from shapely.geometry import Polygon as Region
    from shapely.geometry import box as area

    found: list[str] = []
    for play in data["plays"]:
        nodes = [node for anim in play["animations"] if anim.get("type") in INCOMING
                 for node in mobject_nodes(anim.get("mobject") or {})
                 if node.get("name") == "exercise" or anim["mobject"].get("name") == "exercise"]
        tinted = [Region(t) for node in nodes if (t := _exercise_t(node))]
        if not tinted:
            continue
        for node in nodes:
            parts = [p["type"] for p in node.get("submobjects", ())]
            if parts != ["Dot", "FlatText"]:
                continue
            label = node["submobjects"][1]
            if label.get("box") and tinted[0].intersects(area(*label["box"])) \
                    and not _haloed(label):
                found.append(f"{label['text']} on T")
    return found


def labels_across_t(data: dict) -> list[str]:
    """The vertex labels of a card's figure that stand across T's side from their vertex, as
    ``"D across T's side"``: a vertex inside T whose label stands outside it reads as the
    label of a point beyond the side (the counterexample's D, 28 px off across AC, on the
    exercises' card)."""
    from shapely.geometry import Point as ShapelyPoint
    from shapely.geometry import Polygon as Region

    found: list[str] = []
    t = markers = None
    for play in data["plays"]:
        for kind, node in _recorded_all_nodes(play):
            name = node.get("name")
            if kind not in INCOMING:
                continue
            if name == "card:title":
                t = markers = None
            elif name == "figure:T":
                t = Region(list(dict.fromkeys(_corners(node))))
            elif name == "figure:vertices":
                markers = node
        if t is None or markers is None:
            continue
        inside = t.buffer(-1e-3)
        for marker in markers.get("submobjects", ()):
            dot = _dot_centre(marker)
            label = next((p for p in marker.get("submobjects", ()) if p.get("text")), None)
            if dot is None or label is None or not label.get("box"):
                continue
            x0, y0, x1, y1 = label["box"]
            beyond = not t.contains(ShapelyPoint((x0 + x1) / 2, (y0 + y1) / 2))
            said = f"{label['text']} across T's side"
            if inside.contains(ShapelyPoint(dot)) and beyond and said not in found:
                found.append(said)
    return found


# --- ov5: a verdict's words come with its colour ---------------------------------------------------

#: the captions whose words say a colour on the picture, and that colour as the graph writes
#: it (metaphors.theme.THEME): a verdict's tick the result's green, its cross the rejected's
#: red, divide and conquer's question and its recursion the piece lit in the called blue
COLOURED_WORDS = (("✓", "#4CC46B"), ("✗", "#EF4B4B"),
                  ("Find an inner diagonal of this polygon", "#4F8FF7"),
                  ("Triangulate this part the same way", "#4F8FF7"))


def _shown_colours(anim: dict) -> set[str]:
    """The colours an animation (and its members) puts on the picture: what a fade or a
    drawing brings in, or what a recolouring turns a mobject to (its target), every part; the
    subtitle and the panel (its lit row's light, its rows, its small polygon) are not the
    picture."""
    found: set[str] = set()
    node = anim.get("target") if anim["type"] == "_MethodAnimation" else anim.get("mobject")
    name = (node or {}).get("name") or ""
    if anim["type"] not in OUTGOING and node and name != "subtitle" \
            and not name.startswith(("panel:", "code:")):
        for part in mobject_nodes(node):
            found |= {(part.get(key) or "").upper() for key in ("stroke", "fill")}
    for child in anim.get("animations", ()):
        found |= _shown_colours(child)
    return found


def words_ahead_of_colours(data: dict) -> list[str]:
    """The plays that put up a caption saying a colour (:data:`COLOURED_WORDS`: "✓ DG is an
    inner diagonal", "Find an inner diagonal of this polygon") without bringing that colour on
    the picture, which came only in a later play, as ``"play 26: '✓ DG is an inner
    diagonal' before #4CC46B"``: chapter 1's ✓ stood 0.6 s over an amber DG, its question
    0.5 s before the piece turned blue, chapters 3 and 6's ✗ over an amber BE."""
    found = []
    for k, play in enumerate(data["plays"]):
        said = play.get("subcaption") or ""
        colour = next((c for words, c in COLOURED_WORDS if said.startswith(words)), None)
        if colour is None:
            continue
        shown = set().union(*(_shown_colours(a) for a in play["animations"]))
        if colour not in shown:
            found.append(f"play {k}: {said!r} before {colour}")
    return found


# --- ov5: each row of a run's pseudocode is lit when it runs ----------------------------------------


def _listed_rows(anim: dict) -> list[str]:
    """The rows of a pseudocode listing an animation puts on the screen (its ``code:`` rows,
    not lit: the panel's whole listing), in order."""
    if anim["type"] not in INCOMING:
        return []
    return [(node.get("text") or "").strip() for node in mobject_nodes(anim.get("mobject") or {})
            if (node.get("name") or "").startswith("code:") and node.get("role") != "called"
            and node is not anim.get("mobject") and (node.get("text") or "").strip()]


def unlit_rows(data: dict) -> list[str]:
    """The rows of a run's pseudocode never lit while its listing is shown, as ``"'if P is a
    triangle, we are done' (run 1)"``: chapter 1's divide and conquer ran its base case and
    its recursion eleven and nine times, and lit neither row (nothing it ran said so). For a
    run whose every row runs (divide and conquer on a polygon of four vertices or more)."""
    found, runs = [], 0
    listed: list[str] = []
    lit: set[str] = set()

    def close() -> None:
        found.extend(f"{row!r} (run {runs})" for row in listed if row not in lit)

    for play in data["plays"]:
        for anim in play["animations"]:
            rows = _listed_rows(anim)
            if rows:
                close()
                runs, listed, lit = runs + 1, rows, set()
            lit.update(_lit_rows(anim))
    close()
    return found


# --- recap5: the recap's rules each with the picture of why; claims told from edges --------

#: the cards that give the rules' verdicts ("Recap: the rules that fail", "… that hold")
_VERDICT_CARD = re.compile(r"\brules that (fail|hold)\b")
#: the rules a verdict card may name, as the screen names them: the wrong ones (their name
#: alone, not after "Correct") and the holding ones
_WRONG_NAMES = re.compile(r"(?<!Correct )\b(Scaling|Rotation|Translation)\b")
_RIGHT_NAMES = re.compile(r"\b(Correct (?:Scaling|Rotation|Translation)|Gravity)\b")


def _card_title(play: dict) -> str | None:
    """The title of the card a play brings in, if it does."""
    for anim in play["animations"]:
        node = anim.get("mobject") or {}
        if node.get("name") == "card:title" and anim["type"] in INCOMING:
            return _text_of(node) or play.get("subcaption") or ""
    return None


def rules_without_their_picture(data: dict) -> list[str]:
    """Issue 22 item 8: on a card giving the rules' verdicts (:data:`_VERDICT_CARD`), each rule
    its words name without the picture of why coming as they name it, as ``"Recap: the rules
    that fail: Scaling"``: a wrong rule with a region filled red (its motion outside P), a
    holding one with a region filled green (what its motion swept, inside P) or in the
    band's colour (gravity's band). The recap's one picture of BD crossing E–A stood for all
    three wrong rules, their motion never drawn, and the holding rules' none."""
    red, kept = {_colour("rejected")}, {_colour("result"), _colour("band")}
    found: list[str] = []
    card: str | None = None
    named: dict[str, bool] = {}

    def close() -> None:
        if card is not None:
            found.extend(f"{card}: {rule}" for rule, seen in named.items() if not seen)

    for play in data["plays"]:
        title = _card_title(play)
        if title is not None:
            close()
            card, named = (title if _VERDICT_CARD.search(title) else None), {}
        said = play.get("subcaption") or ""
        if card is None or not said or title is not None:
            continue
        fills = [n for anim in play["animations"] if anim["type"] not in OUTGOING
                 for n in _shaded(anim, red | kept)]
        has_red = any(_filled_in(n, red) for n in fills)
        has_kept = any(_filled_in(n, kept) for n in fills)
        for rule in _WRONG_NAMES.findall(said):
            named[rule] = named.get(rule, False) or has_red
        for rule in _RIGHT_NAMES.findall(said):
            named[rule] = named.get(rule, False) or has_kept
    close()
    return found


# --- ov5: a finished triangulation's triangles counted one by one -----------------------------------

#: the names of a finished triangulation's triangles: a run's end, a card's figure, the
#: comparison's
_TRIANGLES = ("triangulation", "figure:triangle", "compare:triangle")


def alike_neighbours(data: dict) -> list[str]:
    """The triangles of a finished triangulation drawn alike (one fill, one opacity) beside a
    triangle that shares a side with them, and those filled in a colour the parts of a split
    had (a ``piece:`` tint), as ``"play 104: 2 sides between alike triangles"`` and ``"play
    104: a triangle in a part's tint #8E6CF0"``: chapter 1's GCD and GDF, side by side in one
    purple, read as one triangle, and purple had been "the other half" at 41 s. Triangles
    drawn as outlines only (the Delaunay card's) have no fill to tell apart."""
    tints = {(n.get("fill") or "").upper() for n in graph_nodes(data)
             if (n.get("name") or "").startswith("piece:")}
    found = []
    for k, play in enumerate(data["plays"]):
        drawn = [a["mobject"] for a in play["animations"] if a["type"] in INCOMING
                 and (a.get("mobject") or {}).get("name") in _TRIANGLES
                 and a["mobject"].get("points") and (a["mobject"].get("fill_opacity") or 0) > 0]
        looks = [((n.get("fill") or "").upper(), round(n.get("fill_opacity") or 0, 3))
                 for n in drawn]
        corners = [_corners(n) for n in drawn]
        alike = sum(1 for i, j in itertools.combinations(range(len(drawn)), 2)
                    if looks[i] == looks[j]
                    and sum(_near(p, corners[j]) for p in corners[i]) == 2)
        if alike:
            found.append(f"play {k}: {alike} sides between alike triangles")
        found += [f"play {k}: a triangle in a part's tint {colour}"
                  for colour in sorted({c for c, _ in looks} & tints)]
    return found


# --- ov5: one picture per idea; the rule before its numbers ----------------------------------------


def _normalised(points: list, frame: tuple[float, float, float, float]) -> frozenset:
    """Corners in the unit box of their polygon's ``frame`` (its box on screen), rounded:
    the same vertex drawn in a card's figure and on a run's board is the same point."""
    x0, y0, x1, y1 = frame
    scale = max(x1 - x0, y1 - y0) or 1.0
    return frozenset((round((x - x0) / scale, 2), round((y - y0) / scale, 2))
                     for x, y in points)


def _pictures(data: dict, kinds: dict[str, str]) -> Iterator[tuple[int, str, frozenset]]:
    """(play, kind, corners) of every shape named as ``kinds`` says (a name, or a prefix ending
    in ``:``) that a play brings in, its corners in the unit box of the polygon drawn last
    before it (a run's ``polygon``, a card's ``figure:polygon``)."""
    frame = None
    for k, play in enumerate(data["plays"]):
        for anim in play["animations"]:
            node = anim.get("mobject") or {}
            name = node.get("name") or ""
            if anim["type"] not in INCOMING or not node.get("points"):
                continue
            corners = _corners(node)
            if name in ("polygon", "figure:polygon"):
                xs, ys = [p[0] for p in corners], [p[1] for p in corners]
                frame = (min(xs), min(ys), max(xs), max(ys))
            for prefix, kind in kinds.items():
                if frame and (name == prefix or (prefix.endswith(":") and name.startswith(prefix))):
                    yield k, kind, _normalised(corners, frame)


def replayed_splits(data: dict) -> list[str]:
    """The parts a card's figure cuts P into (``figure:half``) that a run then cuts it into
    again (a ``piece:``), as ``"play 11: a card's part is the run's, play 30"``: chapter 1's
    Lennes card split along DG into 4 and 11 vertices, then the run found DG and split along
    it again (one picture per idea)."""
    cut = [(k, c) for k, kind, c in _pictures(data, {"figure:half": "card"}) if kind == "card"]
    split = [(k, c) for k, _, c in _pictures(data, {"piece:": "run"})]
    return [f"play {k}: a card's part is the run's, play {m}" for k, c in cut
            for m, d in split if m > k and c == d][:len(cut)]


def restyled_triangulations(data: dict) -> list[str]:
    """A triangulation drawn twice in a chapter (a card's figure, a run's end) in other
    fills, unsaid, as ``"play 104: 11 triangles, 2 as on play 0"``:
    chapter 1's card at 0–18 s and its run's end at 83 s were one triangulation in other
    colours, which read as another."""
    drawn: dict[int, dict[frozenset, tuple]] = {}
    for k, play in enumerate(data["plays"]):
        for anim in play["animations"]:
            node = anim.get("mobject") or {}
            if anim["type"] in INCOMING and node.get("name") in ("figure:triangle",
                                                                 "triangulation"):
                drawn.setdefault(k, {})[frozenset(_corners(node))] = (
                    (node.get("fill") or "").upper(), round(node.get("fill_opacity") or 0, 3))
    # each picture's triangles in the unit box of its own corners
    shown = []
    for k, triangles in sorted(drawn.items()):
        points = [p for t in triangles for p in t]
        xs, ys = [p[0] for p in points], [p[1] for p in points]
        frame = (min(xs), min(ys), max(xs), max(ys))
        shown.append((k, {_normalised(list(t), frame): look for t, look in triangles.items()}))
    found = []
    for (k, first), (m, later) in itertools.combinations(shown, 2):
        if set(first) != set(later):  # another triangulation: its own run says so
            continue
        alike = sum(1 for t, look in later.items() if first.get(t) == look)
        if alike < len(later):
            found.append(f"play {m}: {len(later)} triangles, {alike} as on play {k}")
    return found


#: a count of triangles (a number), and the rule it follows from
_COUNT, _RULE = re.compile(r"\b\d+ triangles\b"), "n − 2"


def numbers_before_rules(data: dict) -> list[str]:
    """The counts of triangles ("11 triangles") shown or said in a chapter before the rule
    they follow ("n − 2") is, as ``"play 6: 'n = 13: 11 triangles, 10 inner diagonals'
    before the rule"``: chapter 1 counted 11 triangles 4 s before it said n − 2."""
    for k, play in enumerate(data["plays"]):
        texts = [play.get("subcaption") or ""] + [
            _text_of(a["mobject"]) for a in play["animations"]
            if a["type"] in INCOMING and a.get("mobject")]
        if any(_RULE in t for t in texts):
            return []
        counted = [t for t in texts if _COUNT.search(t)]
        if counted:
            return [f"play {k}: {counted[0]!r} before the rule"]
    return []


# --- mono5: chapter 5 taught on its picture (fresh teacher's review of 05-faster) ----------------

#: each word of the monotone lesson, and what the first caption that says it must say with it
#: (a word said before it is taught): y-monotone with its horizontal line, the helper with
#: the lowest vertex that sees its edge, each kind of vertex with its neighbours (as the sweep
#: meets it). The card opened with "y-monotone pieces" and "split and merge vertices" 14 s
#: before the run said what they are, and "D joins its helper F" said helper unexplained.
TAUGHT = {
    "y-monotone": re.compile(r"horizontal line"),
    "helper": re.compile(r"the lowest vertex"),
    "split": re.compile(r"neighbours below, interior above: a split vertex"),
    "merge": re.compile(r"neighbours above, interior below: a merge vertex"),
}


def _captions(data: dict) -> list[str]:
    """The captions in the order they are said, each once where it first comes."""
    said: list[str] = []
    for play in data["plays"]:
        caption = play.get("subcaption")
        if caption and (not said or said[-1] != caption):
            said.append(caption)
    return said


def untaught_words(data: dict) -> list[str]:
    """The words of :data:`TAUGHT` whose first caption does not teach them, as ``"'helper'
    before taught: 'Diagonal DF: …'"``."""
    found = []
    for word, teaching in TAUGHT.items():
        first = next((c for c in _captions(data) if re.search(rf"\b{re.escape(word)}\b", c)),
                     None)
        if first is not None and not teaching.search(first):
            found.append(f"{word!r} before taught: {first!r}")
    return found


#: the kinds of vertex of the monotone sweep
VERTEX_KINDS = ("start", "end", "split", "merge", "regular")


def kinds_said(data: dict) -> set[str]:
    """The kinds of vertex a caption names a vertex as (``"E: … an end vertex"``): chapter
    5's sweep met two end vertices, E and C, and named neither (both went by under "Vertices
    E and C: the same steps, faster")."""
    return {kind for caption in _captions(data) for kind in VERTEX_KINDS
            if re.match(rf"^\S+: .*\ban? {kind} vertex\b", caption)}


_DIAGONAL_CAPTION = re.compile(r"^Diagonal ((?!\d)\S+(?: \S+)*?): ")
_HELPER_SET = re.compile(r"^(\S+) becomes \S+'s helper\b")


def unseen_helpers(data: dict) -> list[str]:
    """The diagonals of the monotone sweep whose helper (the diagonal's second end) was
    never seen becoming one: no earlier caption says ``"F becomes B–C's helper"`` with the
    helper drawn (an object named ``helper``) in its play, as ``"DF: F never seen to become
    a helper"``. F became D's helper under "Vertices H, B, G and F: the same steps, faster",
    and "Diagonal DF: the split vertex D joins its helper F" came from nowhere."""
    seen: set[str] = set()
    found, caption = [], ""
    for play in data["plays"]:
        new = play.get("subcaption")
        caption = new or caption  # the picture plays after its words, under them
        if (m := _HELPER_SET.match(caption)) and any(
                node.get("name") == "helper" for anim in play["animations"]
                for key in ("mobject", "target") for node in mobject_nodes(anim.get(key) or {})):
            seen.add(m.group(1))
        if new and (m := _DIAGONAL_CAPTION.match(new)):
            ends = m.group(1)
            helper = ends.split()[-1] if " " in ends else ends[-1]
            if helper not in seen:
                found.append(f"{ends}: {helper} never seen to become a helper")
    return sorted(set(found))


def stack_returns_unsaid(data: dict) -> list[str]:
    """The monotone stack's labels that come back onto its column after leaving it under
    words that do not say so, as ``"'A is done: H and B wait on the stack': H left, comes
    back unsaid"``: "H leaves" then "H and B wait" read as a contradiction (72–81 s), while
    the column drew H popped and pushed back."""
    found, caption = [], ""
    shown: list[str] = []
    left: set[str] = set()
    for play in data["plays"]:
        caption = play.get("subcaption") or caption
        for anim in play["animations"]:
            node = anim.get("mobject", {})
            if node.get("name") != "stack:column":
                continue
            if anim.get("type") in OUTGOING:
                shown, left = [], set()
                continue
            new = _stack_labels(anim.get("target", node))
            for v in new:
                if v in left and v not in shown and not re.search(
                        rf"\b{re.escape(v)}\b[^:]*\b(?:goes|go|comes|come) back\b", caption):
                    found.append(f"{caption!r}: {v} left, comes back unsaid")
            left |= {v for v in shown if v not in new}
            shown = new
    return found


#: the least gap beside a label (scene units) that the sweep line leaves where it passes at
#: the label's height: 0.12 each side of K's and M's letters read as a line through them
LEAST_SWEEP_SIDE_GAP = 0.35


def labels_beside_the_sweep(data: dict) -> list[str]:
    """The vertex labels the monotone sweep line passes at their own height (a dash meeting
    the label's band, its bottom to its top) nearer than :data:`LEAST_SWEEP_SIDE_GAP` beside
    them, as ``"the sweep 0.12 beside K"``; each label once, at its least gap."""
    least: dict[str, float] = {}
    for points, labels in _sweep_dashes(data):
        xs, ys = [p[0] for p in points], [p[1] for p in points]
        for v, (x0, y0, x1, y1) in labels.items():
            if max(ys) < y0 or min(ys) > y1:
                continue  # not at the label's height
            gap = max(x0 - max(xs), min(xs) - x1, 0.0)
            if gap < LEAST_SWEEP_SIDE_GAP - 1e-3:
                least[v] = min(gap, least.get(v, gap))
    return [f"the sweep {gap:.2f} beside {v}" for v, gap in sorted(least.items())]


def counts_on_two_lines(data: dict) -> list[str]:
    """The counts (a ``counter`` text) broken over lines, as ``"'n − 2 = 13 − 2 / = 11
    triangles'"``: its halves read as two things (chapter 5's count in the top-left corner)."""
    found = []
    for play in data["plays"]:
        for anim in play["animations"]:
            for node in mobject_nodes(anim.get("mobject") or {}):
                text = node.get("text") or ""
                if node.get("name") == "counter" and "\n" in text.strip():
                    found.append(repr(text.replace("\n", " / ")))
    return sorted(set(found))


#: another name for an algorithm, said on screen only beside its one name (:data:`SPOKEN`):
#: chapter 4 said "With ear status kept up to date" and its plot "ear status kept", chapter 5
#: then "Faster ear clipping", never taught
OTHER_NAMES = {"ear status kept": "faster ear clipping"}


def names_said_otherwise(data: dict) -> list[str]:
    """The texts on screen (and the cues) that name an algorithm by another name of
    :data:`OTHER_NAMES` without its own, as ``"'ear status kept: 235' for faster ear
    clipping"``."""
    captions = [" ".join(c.split()) for c in _captions(data)]
    found = {}
    for text in _all_shown_texts(data, frozenset()):
        said = " ".join(text.split())
        if any(said in caption and said != caption for caption in captions):
            continue  # a row of a card's line: the line is read whole, as its caption
        for other, name in OTHER_NAMES.items():
            if other in said.lower() and name not in said.lower():
                found[f"{said!r} for {name}"] = None
    return sorted(found)


#: the claims a reading rule measures against the edges: a run's, an analysis's, an
#: exercise's answer's and a card's figure's
_ALL_CLAIMS = (*_CLAIMS, "figure:claim")
#: a claim that runs within this many degrees of an edge of P at the vertex they share, its
#: far end nearer than :data:`LEAST_OUTSIDE` (4 % of the frame's height) to the edge's line,
#: reads as a part of the edge (gravity's EC ran 7° off B–C, its E 2.9 % of the frame's
#: height from it; the corrections' BE 4° off it)
LEAST_CLAIM_ANGLE = 15.0


def _segment_of(node: dict) -> tuple[tuple[float, float], tuple[float, float]] | None:
    """A drawn line's ends: its own points', or its last part's with points (a claim on a
    casing is the casing, then the line)."""
    if node.get("points"):
        return tuple(node["points"][0][:2]), tuple(node["points"][-1][:2])
    for child in reversed(node.get("submobjects", ())):
        found = _segment_of(child)
        if found is not None:
            return found
    return None


def claims_along_edges(data: dict, least: float = LEAST_CLAIM_ANGLE) -> list[str]:
    """Issue 22 item 3: the claims drawn within ``least`` degrees of an edge of their polygon
    at a vertex they share, their other end nearer than :data:`LEAST_OUTSIDE` to the edge's
    line, as ``"figure:claim (x, y)–(x, y): 7.3° off an edge, 0.23 from it"``: such a claim
    reads as a part of the edge. A claim is matched to the drawn polygon that has both its
    ends as corners."""
    nodes = list(graph_nodes(data))
    polygons = [_corners(n) for n in nodes if n.get("points") and n.get("name") in _PICTURES]
    found = {}
    for node in nodes:
        if node.get("name") not in _ALL_CLAIMS:
            continue
        ends = _segment_of(node)
        if ends is None:
            continue
        home = [c for c in polygons if _near(ends[0], c) and _near(ends[1], c)]
        if not home:
            continue
        corners = home[0]
        for here, there in (ends, ends[::-1]):
            k = next(i for i, q in enumerate(corners) if _near(here, [q]))
            for q in (corners[k - 1], corners[(k + 1) % len(corners)]):
                if _near(q, [there]):
                    continue  # the claim is this edge: no diagonal
                a = math.atan2(there[1] - here[1], there[0] - here[0])
                b = math.atan2(q[1] - here[1], q[0] - here[0])
                off = abs(math.degrees((a - b + math.pi) % (2 * math.pi) - math.pi))
                gap = math.dist(here, there) * math.sin(math.radians(off))
                if off < least and gap < LEAST_OUTSIDE:
                    where = f"{node['name']} ({ends[0][0]:g}, {ends[0][1]:g})–" \
                            f"({ends[1][0]:g}, {ends[1][1]:g})"
                    found[where] = f"{off:.1f}° off an edge, {gap:.2f} from it"
    return [f"{where}: {what}" for where, what in sorted(found.items())]


def _solid_strokes(node: dict) -> set[str]:
    """The stroke colours a node draws in solid lines (a dashed line is drawn in pieces: a
    ``DashedLine``, or a group of dashes; a dark casing under a line is none)."""
    if node.get("type") == "DashedLine":
        return set()
    own = (node.get("stroke") or "").upper()
    found = {own} if node.get("points") and own and (node.get("stroke_opacity") or 1) > 0 \
        and own != _colour("background") else set()
    for child in node.get("submobjects", ()):
        found |= _solid_strokes(child)
    return found


def claims_like_their_edges(data: dict) -> list[str]:
    """Issue 22 item 4: a card's figure drawing a crossed edge (``figure:edge:…``) in the same
    solid colour as a claim it shows, as ``"play 4: figure:edge:E–A like its claim"``: BD and
    E–A, both solid red, read as one red cross, the claim not told from the edge it crosses."""
    found = []
    claims: list[set[str]] = []
    for k, play in enumerate(data["plays"]):
        if _card_title(play) is not None:
            claims = []
        for anim in play["animations"]:
            node = anim.get("mobject") or {}
            if anim["type"] in OUTGOING or anim["type"] not in INCOMING | {"UpdateFromAlphaFunc"}:
                continue
            if node.get("name") == "figure:claim":
                claims.append(_solid_strokes(node))
        for anim in play["animations"]:
            node = anim.get("mobject") or {}
            name = node.get("name") or ""
            if name.startswith("figure:edge:") and anim["type"] not in OUTGOING \
                    and any(_solid_strokes(node) & c for c in claims):
                found.append(f"play {k}: {name} like its claim")
    return found


# --- panel7: chapter 4 reviewed (the band on the fruit, the ending's count, V's triangle) -----

#: a vertex named by arithmetic on a placeholder (``V−1``, ``V+1``): read as a sum, not as
#: "the vertex before V"
_VERTEX_ARITHMETIC = re.compile(r"\b[A-Z]\s?[−+-]\s?1\b")


def arithmetic_vertex_names(data: dict) -> list[str]:
    """The texts on screen (and the cues) that name a vertex by arithmetic, as ``"'is V an
    ear? (convex, V−1 V V+1 empty)'"``: chapter 4's card and ear clipping's rows said "V−1 V
    V+1", read as a sum (review); the triangle of V and its two neighbours is said in words.
    The panel's call line (a programmer's, in ``trex render``) is not read."""
    return sorted({repr(text) for text in _all_shown_texts(data, frozenset({"panel:call"}))
                   if _VERTEX_ARITHMETIC.search(text)})


#: how a run's ending caption begins (:func:`metaphors.drawing.ending_caption`)
_WHOLE_WORDS = "The whole triangulation"


def counts_before_triangulations(data: dict) -> list[str]:
    """The plays that put up "The whole triangulation: 11 triangles" without the whole
    triangulation coming in (``triangulation``), as ``"play 82: 'The whole triangulation: 11
    triangles'"``: led by its words, the count stood half a second over the last slice (ear
    clipping, prune and search), the last pieces (monotone) and the finished triangles
    (divide and conquer) before what it counts was drawn (review, chapter 4 at 109.9 s)."""
    found = []
    for k, play in enumerate(data["plays"]):
        said = play.get("subcaption") or ""
        if not said.startswith(_WHOLE_WORDS):
            continue
        if not any(a.get("type") in INCOMING and (a.get("mobject") or {}).get("name")
                   == "triangulation" for a in play["animations"]):
            found.append(f"play {k}: {said!r}")
    return found


#: the lines a run draws over its polygon that must read on the fruit's orange: gravity's band
_ON_THE_FRUIT = ("band",)
#: the least width of a dark casing under a line (of the line's own width) that lets it read
#: on any fill
LEAST_CASING = 2.0


def _cased(node: dict) -> bool:
    """Whether a line has a dark, opaque casing (a background stroke) :data:`LEAST_CASING`
    times its own width."""
    halo = node.get("halo") or {}
    colour = _one_colour(halo.get("stroke"))
    return (colour is not None and _luminance(colour) < 0.15
            and (halo.get("stroke_opacity") or 0) >= 0.99
            and (halo.get("stroke_width") or 0) >= LEAST_CASING * (node.get("stroke_width") or 0))


def lines_lost_on_the_fruit(data: dict) -> list[str]:
    """The lines drawn over the fruit (:data:`_ON_THE_FRUIT`) that do not read on it, as
    ``"play 90 band 1.4 : 1"``: the contrast of the line's colour with the fruit's as the
    screen shows it is under :data:`LEAST_CONTRAST`, and the line has no dark casing
    (:func:`_cased`). Gravity's rose band on prune and search's orange fruit was all but
    invisible (review, chapter 4 at 79–88 s). Each name once."""
    from metaphors.theme import THEME

    found: dict[str, str] = {}
    fruit: str | None = None  # the fruit's colour on screen, once it is drawn
    for k, play in enumerate(data["plays"]):
        if _new_picture(play):
            fruit = None
        for anim in play["animations"]:
            for node in animation_nodes(anim):
                name = node.get("name")
                if name == "fruit" and node.get("fill"):
                    fruit = _over(_one_colour(node["fill"]) or "#000000",
                                  node.get("fill_opacity") or 0.0, THEME.background)
                elif name in _ON_THE_FRUIT and fruit is not None and node.get("points"):
                    colour = _one_colour(node.get("stroke"))
                    ratio = contrast(colour, fruit) if colour else 0.0
                    if ratio < LEAST_CONTRAST and not _cased(node):
                        found.setdefault(name, f"play {k} {name} {ratio:.1f} : 1")
    return sorted(found.values())


def unanswered_card_questions(data: dict) -> list[str]:
    """The card lines that ask a question and leave it open (a ``card:line`` ending in "?"),
    as their text: chapter 2's frame card asked "say G: is BG inner?" over a dashed amber
    BG, and nothing on that card, nor after it, said whether it is (review of chapter 2). A
    card says what a thing is; a question for the class goes in the exercises, with its
    answer after time to think (:func:`rushed_questions`)."""
    found: list[str] = []
    for play in data["plays"]:
        for anim in play["animations"]:
            node = anim.get("mobject") or {}
            if anim["type"] in INCOMING and node.get("name") == "card:line":
                text = _text_of(node).strip()
                if text.endswith("?") and text not in found:
                    found.append(text)
    return found


def fading_while_zooming(data: dict) -> list[str]:
    """What fades in or out while a close-up zooms, as ``"play 76: vertex:A"``: the
    vertices outside the close-up's box faded at their places in the whole picture while P
    was drawn zoomed, so their dots and labels stood off P — ghosts of L, K and M over the
    zoomed fruit as the close-up came (chapter 4 at 79 s), A's dot above the box and B's
    left of it as it went (chapter 3 at 75 s). They go before the zoom in and come back
    once the picture is whole."""
    found = []
    for k, play in enumerate(data["plays"]):
        zooming = any((anim.get("mobject") or {}).get("name") == _CLOSE_UP
                      and anim["type"] == "UpdateFromAlphaFunc" for anim in play["animations"])
        if zooming:
            found += [f"play {k}: {(anim.get('mobject') or {}).get('name')}"
                      for anim in play["animations"] if anim["type"] in INCOMING | OUTGOING
                      and not ((anim.get("mobject") or {}).get("name") or "").startswith(
                          _CLOSE_UP)]
    return found


def pieces_in_the_called_blue(data: dict) -> list[str]:
    """The pieces (``piece:…``, a split's or a partition's parts) tinted so that they read as
    the blue of what a call runs on, as ``"play 60 piece:2"``: within
    :data:`LEAST_PART_APART` of that blue at the piece's own opacity, each over the
    background. Chapter 5's monotone pieces took the palette in turn, and the piece KLM was
    blue beside the violet rest of P: no call runs on it. The piece a call runs on, in that
    blue itself (divide and conquer's part worked on), is not judged. Each piece once."""
    from metaphors.theme import THEME

    found: dict[str, str] = {}
    for k, play in enumerate(data["plays"]):
        for anim in play["animations"]:
            for node in animation_nodes(anim):
                name, fill = node.get("name") or "", _one_colour(node.get("fill"))
                opacity = float(node.get("fill_opacity") or 0)
                if (not name.startswith("piece:") or not fill or not opacity or name in found
                        or fill == THEME.called.upper()):
                    continue
                blue = _over(THEME.called.upper(), opacity, THEME.background)
                if delta_e(_over(fill, opacity, THEME.background), blue) < LEAST_PART_APART:
                    found[name] = f"play {k} {name}"
    return list(found.values())


# --- open9: chapters 1 and 2 as a teacher reviewed them (labels, marks, captions off the picture) --

#: the least gap between a subtitle's lines and a vertex label of the picture on screen (1 %
#: of the frame's height): nearer, the caption reads over the picture, or covers a letter. A
#: run's board leaves its lowest label 0.10 above a one-line subtitle (chapters 1, 3 and 5)
LEAST_CAPTION_LABEL_GAP = 0.08


def _text_boxes_of(node: dict) -> list[tuple[float, float, float, float]]:
    """The boxes of a node's texts (a subtitle's lines)."""
    return [tuple(part["box"]) for part in mobject_nodes(node)
            if part.get("box") and (part.get("text") or "").strip()]


def captions_over_labels(data: dict, gap: float = LEAST_CAPTION_LABEL_GAP) -> list[str]:
    """The vertex labels (a board's, a stage's, a card's figure's) that a subtitle shown
    with them comes nearer than ``gap`` to, as ``"play 96 C 0.00 from the subtitle"``: chapter
    2's two-line caption "Parallel to AC, … / E is the farthest from AC …" ran over C's label
    at 176-182 s. The picture sits clear of the subtitles' band. (:func:`words_on_the_picture`
    judged only the end's texts, in the scenes.) Each label once, at the first play."""
    from shapely.geometry import box as area

    found: dict[str, str] = {}
    for k, shown in _shown_after_plays(data, ("vertex:", "figure:vertices", "subtitle")):
        subtitle = shown.get("subtitle")
        if subtitle is None:
            continue
        lines = [area(*b) for b in _text_boxes_of(subtitle)]
        for name, node in shown.items():
            if not name.startswith(("vertex:", "figure:vertices")):
                continue
            for text, box in _marker_labels(name, node):
                near = min((line.distance(area(*box)) for line in lines), default=gap)
                if near < gap - 1e-9:
                    found.setdefault(text, f"play {k} {text} {near:.2f} from the subtitle")
    return sorted(found.values(), key=lambda s: (int(s.split()[1]), s))


#: how much of a label's box may lie on the red "outside P" region (scene units²): a speck
#: where a box's corner grazes it
MOST_ON_THE_RED = 1e-3
#: the least gap between the crossed edge's name and the red region or P's fill (3 % of the
#: frame's height): "edge E–A" 0.14 from the red wedge, in T's thin corridor beside it, read
#: as written on it (chapter 2 at 56-60 s)
LEAST_NAME_GAP = 0.24


def labels_on_the_red(data: dict) -> list[str]:
    """The vertex labels over the red "outside P" region (:data:`_RED_REGIONS`), halo or not,
    and the crossed edge's name (``analysis:edge-name``) within :data:`LEAST_NAME_GAP` of it
    or of P's fill, as ``"play
    51 D on the red"`` or ``"play 53 'edge E–A' on P"``: chapter 2's amber D and "edge E–A"
    stood on the red wedge (56-60 s, and again in each heuristic's pass), where a dark halo
    (:func:`picks_in_the_red`) let them read but hid the red the pass is about. A name of the
    edge stands beside it, off the picture's fills. Each text and region once a picture."""
    import shapely

    found: dict[tuple[str, str], str] = {}
    names = ("vertex:", "analysis:edge-name", "analysis:polygon", *_RED_REGIONS)
    picture, last = 0, None
    for k, shown in _shown_after_plays(data, names):
        if shown is not last:  # a picture opened: each pass judged on its own
            picture, last = picture + 1, shown
        red = [shapely.Polygon(ring) for name, node in shown.items()
               if name.startswith(_RED_REGIONS) for part in mobject_nodes(node)
               if (part.get("fill_opacity") or 0) > 0 for ring in _paths(part)]
        regions = [("the red", shapely.union_all([r for r in red if r.is_valid]))] if red else []
        edge_regions = list(regions)
        if "analysis:polygon" in shown:
            edge_regions.append(("P", _outline(shown["analysis:polygon"])))
        for name, node in shown.items():
            if name.startswith("vertex:"):
                texts, against = list(_marker_labels(name, node)), regions
            elif name == "analysis:edge-name":
                texts, against = [(repr(t), b) for t, b in _marker_labels(name, {
                    "submobjects": [node]})] or [(repr(node.get("text")), node.get("box"))], \
                    edge_regions
            else:
                continue
            for text, box in texts:
                if not box:
                    continue
                for where, region in against:
                    if region is None:
                        continue
                    on = (region.intersection(shapely.box(*box)).area > MOST_ON_THE_RED
                          if name.startswith("vertex:")
                          else region.distance(shapely.box(*box)) < LEAST_NAME_GAP - 1e-9)
                    if on:
                        found.setdefault((picture, text, where),
                                         f"play {k} {text} on {where}")
    return sorted(found.values(), key=lambda s: (int(s.split()[1]), s))


#: the plays within which a polygon faded out is not drawn again: one picture per idea
REDRAWN_WITHIN = 4
#: the pictures' polygons: a run's board, an analysis's stage, a card's figure
_ALL_POLYGONS = ("polygon", "analysis:polygon", "figure:polygon")


def refaded_polygons(data: dict, within: int = REDRAWN_WITHIN,
                     involving: tuple[str, ...] = _ALL_POLYGONS) -> list[str]:
    """The polygons (:data:`_ALL_POLYGONS`) faded out and drawn anew, the same shape
    (:func:`_shape`: wherever, however large), within ``within`` plays, as ``"play 14:
    figure:polygon faded at play 12, analysis:polygon drawn"``: chapter 2's card drew the
    counterexample small beside its words, faded it, and its pass drew it again full size
    (20-30 s, in each heuristic): two pictures of one idea. The picture goes on: moved and
    grown into place, or drawn once. Only the hand-overs where the one faded or the one
    drawn is named in ``involving``."""
    found: list[str] = []
    faded: list[tuple[int, str, tuple]] = []
    for k, play in enumerate(data["plays"]):
        for anim in play["animations"]:
            for kind, node in _recorded(anim):
                for part in mobject_nodes(node):
                    if part.get("name") not in _ALL_POLYGONS or len(part.get("points") or ()) < 12:
                        continue
                    if kind in OUTGOING:
                        faded.append((k, part["name"], _shape(part)))
                    elif kind in INCOMING:
                        shape = _shape(part)
                        went = [(j, name) for j, name, was in faded
                                if was == shape and 0 < k - j <= within
                                and involving and (name in involving
                                                   or part["name"] in involving)]
                        if went:
                            found.append(f"play {k}: {went[-1][1]} faded at play {went[-1][0]}, "
                                         f"{part['name']} drawn")
    return found


#: the least gap a label of the panel's polygon keeps from a line the run draws on it (a
#: claim, a diagonal, a crossed edge): :data:`LABEL_ROOM`, as from its edges
_PANEL_LINES = "panel/"


#: the whole triangulation drawn in the panel at a run's end: every label stands among its
#: lines, on a halo (metaphors.panel.panel_markers), as the run ends
_PANEL_WHOLE = ("panel/triangulation",)


def panel_labels_on_lines(data: dict, room: float = LABEL_ROOM) -> list[str]:
    """The labels of the panel's polygon that a line the run draws on it (``panel/…``: its
    claims, diagonals, crossed edges) comes within ``room`` of, as ``"play 40 M × panel/
    diagonal:3"``: chapter 1's mini-map drew its diagonals through M, H and G (68-102 s).
    :func:`crowded_panel_labels` measured the labels against the outline only, as they first
    came. The whole triangulation at the end (:data:`_PANEL_WHOLE`) is not judged. Each label
    and line once, at the first play that shows them so."""
    from shapely.geometry import LineString
    from shapely.geometry import box as area

    found: dict[tuple[str, str], str] = {}
    for k, shown in _shown_after_plays(data, ("panel:", _PANEL_LINES)):
        lines = [(name, LineString(s)) for name, node in shown.items()
                 if name.startswith(_PANEL_LINES) and name not in _PANEL_WHOLE
                 for part in mobject_nodes(node)
                 if (part.get("stroke_opacity") or 0) > 0 for s in _segments(part)]
        for name, node in shown.items():
            if not name.startswith("panel:") or name in _PANEL_PARTS:
                continue
            for part in mobject_nodes(node):
                if not (part.get("box") and (part.get("text") or "").strip()):
                    continue
                for owner, line in lines:
                    if line.distance(area(*part["box"])) < room:
                        found.setdefault((part["text"], owner.partition("@")[0]),
                                         f"play {k} {part['text']} × {owner}")
    return sorted(found.values(), key=lambda s: (int(s.split()[1]), s))


#: the names of crossed edges: an analysis's, a card's figure's
_EDGE_NAMES = ("analysis:edge-name", "figure:edge-name")


def edge_names_on_the_picture(data: dict, gap: float = LEAST_NAME_GAP) -> list[str]:
    """The crossed edges' names (:data:`_EDGE_NAMES`) nearer than ``gap`` to the convex hull
    of the polygon drawn with them, as ``"play 5 'F–G' 0.00 from figure:polygon"``: a name in
    a slot of P, its fill on both sides (chapter 1's "F–G" between F–G and H–I, 16 s), or in
    T's corridor by the red wedge (chapter 2's "edge E–A", 56 s), reads as written on the
    picture. Beside the picture, by its edge's end, it names the edge. Each name once a
    picture."""
    import shapely

    found: dict[tuple[int, str], str] = {}
    picture, last = 0, None
    for k, shown in _shown_after_plays(data, (*_EDGE_NAMES, *_ALL_POLYGONS)):
        if shown is not last:
            picture, last = picture + 1, shown
        hulls = [(name, _outline(node).convex_hull) for name, node in shown.items()
                 if name in _ALL_POLYGONS and node.get("points") and _outline(node) is not None]
        for name, node in shown.items():
            if name not in _EDGE_NAMES:
                continue
            for text, box in [(repr(p.get("text")), p["box"]) for p in mobject_nodes(node)
                              if p.get("box") and (p.get("text") or "").strip()][:1]:
                for owner, hull in hulls:
                    near = hull.distance(shapely.box(*box))
                    if near < gap - 1e-9:
                        found.setdefault((picture, text),
                                         f"play {k} {text} {near:.2f} from {owner}")
    return sorted(found.values(), key=lambda s: (int(s.split()[1]), s))


#: how near the black box (``finder``) a run's ✓ stands to be its answer, checked
NEAR_THE_BOX = 0.4


def ticks_by_the_box(data: dict) -> set[tuple[float, ...]]:
    """The boxes of the run's ✓ marks that come in beside the black box (``finder``, on
    screen), within :data:`NEAR_THE_BOX` of it: the box asked "an inner diagonal?" and its
    answer holds — the ✓ stands off the picture (chapter 1). :func:`ticks_outside` and
    :func:`far_verdicts` leave them be."""
    from shapely.geometry import box as area

    finder, found = None, set()
    for play in data["plays"]:
        for anim in play["animations"]:
            for kind, node in _recorded(anim):
                name = node.get("name")
                if name == "finder":
                    finder = None if kind in OUTGOING else (_box_of(node) or finder)
                elif name == "tick" and kind in INCOMING and finder is not None:
                    box = _box_of(node)
                    if box is not None and area(*box).distance(area(*finder)) <= NEAR_THE_BOX:
                        found.add(tuple(box))
    return found


def ticks_on_the_picture(data: dict) -> list[str]:
    """A run's ✓ marks (``tick``) over its polygon's fill while the black box (``finder``)
    is on screen, as ``"play 36 tick 0.19 over P"``: chapter 1's ✓ stood on P's fill beside
    each diagonal the box gave (68-102 s), where the box's own answer stands beside it, off
    the picture (:func:`ticks_by_the_box`)."""
    from shapely.geometry import box as area

    found, finder, polygon = [], False, None
    for k, play in enumerate(data["plays"]):
        for anim in play["animations"]:
            for kind, node in _recorded(anim):
                name = node.get("name")
                if name == "finder":
                    finder = kind not in OUTGOING
                elif name == "polygon" and kind in INCOMING and node.get("points"):
                    polygon = _outline(node)
                elif name == "tick" and kind in INCOMING and finder and polygon is not None:
                    box = _box_of(node)
                    over = polygon.intersection(area(*box)).area if box else 0.0
                    if over > MOST_TEXT_OVER_FILL:
                        found.append(f"play {k} tick {over:.2f} over P")
    return found


# --- faster9: chapter 5's kind words off P's hull, its stack drawn as a stack, its plot's colours --

#: the notes that say a vertex's kind: the word beside it, and the legend entry or note beside
#: the picture where no place beside it is free
_KIND_NOTES = (*_KIND_WORDS, "legend:kind")


def kind_words_in_the_picture(data: dict) -> list[str]:
    """The monotone sweep's kind words and kind notes (:data:`_KIND_NOTES`) whose box lies
    within the convex hull of the polygon drawn last (:data:`_INTERIORS`) by more than
    :data:`MOST_TEXT_OVER_FILL`, as ``"play 34 'regular' 0.44 in P's hull"``: in a notch or
    slot of P the background hardly differs from P's faint fill, and a word there reads as
    written on the picture (teacher review: "regular" in the slot by I, chapter 5 at 52 s,
    "merge" in K's notch at 42 s, passed :func:`words_over_the_picture`, being just off P).
    Each text at each place once."""
    from shapely.geometry import box as rectangle

    hull = None
    found: dict[tuple[str, tuple[float, ...]], str] = {}
    for k, play in enumerate(data["plays"]):
        for anim in play["animations"]:
            for kind, node in _recorded(anim):
                if kind in INCOMING and node.get("name") in _INTERIORS and node.get("points"):
                    outline = _outline(node)
                    hull = outline.convex_hull if outline is not None else None
                if kind not in INCOMING or hull is None:
                    continue
                for part in mobject_nodes(node):
                    if part.get("name") not in _KIND_NOTES:
                        continue
                    box = box_of_parts(part)
                    if box is None:
                        continue
                    said = " ".join(t for p in mobject_nodes(part) if (t := p.get("text")))
                    over = rectangle(*box).intersection(hull).area
                    if over > MOST_TEXT_OVER_FILL:
                        found.setdefault((said, box), f"play {k} {said!r} {over:.2f} in P's hull")
    return list(found.values())


#: the least gap between a kind's note beside the picture (``legend:kind``) and a vertex
#: label: "F: regular vertex" stood 0.1 right of L's label, read as L's (chapter 5 at 64 s)
KIND_NOTE_OFF_LABELS = 0.45


def kind_notes_by_labels(data: dict) -> list[str]:
    """The kind notes beside the picture (``legend:kind``) nearer than
    :data:`KIND_NOTE_OFF_LABELS` to a vertex label on screen, as ``"'F: regular vertex' by
    L"``: beside a label, the note is read as that vertex's."""
    from shapely.geometry import box as rectangle

    found = []
    for anim, labels in _with_labels(data):
        if anim.get("type") not in INCOMING:
            continue
        for part in mobject_nodes(anim.get("mobject", {})):
            if part.get("name") != "legend:kind" or (box := box_of_parts(part)) is None:
                continue
            said = " ".join(t for p in mobject_nodes(part) if (t := p.get("text")))
            found += [f"{said!r} by {v}" for v, b in sorted(labels.items())
                      if rectangle(*box).distance(rectangle(*b)) < KIND_NOTE_OFF_LABELS]
    return sorted(set(found))


def box_of_parts(node: dict, points_of: tuple[str, ...] | None = ("Dot",)
                 ) -> tuple[float, float, float, float] | None:
    """A node's box with all its parts: its texts' boxes and the points of its parts of the
    types ``points_of`` (all types if None): a note's swatches (``Dot``) by default, a text's
    own glyph points not being where it stands on screen."""
    xs, ys = [], []
    for part in mobject_nodes(node):
        if part.get("box") is not None:
            x0, y0, x1, y1 = part["box"]
            xs += [x0, x1]
            ys += [y0, y1]
        elif points_of is None or part.get("type") in points_of:
            for x, y, *_ in part.get("points") or ():
                xs.append(x)
                ys.append(y)
    return (min(xs), min(ys), max(xs), max(ys)) if xs else None


#: the lines of a card's plots, by their names' beginnings (chapter 5's measured steps and
#: the bounds it drew, chapter 4's ear tests)
_PLOT_SERIES = ("figure:measured:", "figure:bound:", "figure:growth:")
#: nearer than this (CIE76 ΔE) to a colour of the legend, a line reads as that meaning
LEAST_SERIES_APART = 20.0


def _legend_colours() -> dict[str, str]:
    """The colours of :mod:`metaphors.theme`'s legend, by their meaning: the roles, the kinds
    of vertex, the stack, P's fill, the metaphors' tools and what they sweep, the fruit, the
    pieces' tints and the triangles' green."""
    from metaphors.theme import THEME

    fields = ("called", "argument", "result", "rejected", "idle", "candidate", "split", "merge",
              "stack", "polygon_fill", "water", "ball", "band", "hand", "sweep", "swept",
              "dial", "fruit", "rind")
    colours = {field: getattr(THEME, field) for field in fields}
    colours.update({f"piece tint {k + 1}": c for k, c in enumerate(THEME.part_tints)})
    return colours


def plot_series_in_role_colours(data: dict) -> list[str]:
    """The lines of a card's plot (:data:`_PLOT_SERIES`) drawn in a colour of the legend, or
    within :data:`LEAST_SERIES_APART` of one, as ``"figure:measured:ear-clipping:half-disc
    reads as piece tint 1"``: a line in the called blue or a piece's teal reads as that
    meaning (teacher review of chapter 5's plot: its six lines took the palette's teal and tan,
    the pieces' tints, its blue, the called blue's neighbour, and its olive). Each line once."""
    legend = _legend_colours()
    found: dict[str, str] = {}
    for play in data["plays"]:
        for anim in play["animations"]:
            for node in animation_nodes(anim):
                name = node.get("name") or ""
                colour = node.get("stroke")
                if not name.startswith(_PLOT_SERIES) or name in found or not colour:
                    continue
                near = min(legend, key=lambda k: delta_e(colour, legend[k]))
                if delta_e(colour, legend[near]) < LEAST_SERIES_APART:
                    found[name] = f"{name} reads as {near}"
    return list(found.values())


def _bounds_centre(node: dict) -> tuple[float, float] | None:
    """The centre of a node's points' bounds."""
    points = node.get("points") or ()
    if not points:
        return None
    xs, ys = [p[0] for p in points], [p[1] for p in points]
    return (min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2


#: how near (scene units) a chain's mark or segment end stands to the vertex it marks
CHAIN_AT = 0.02


def _chain_faults(chain: dict, stacked: list[str], dots: dict[str, tuple[float, float]]
                  ) -> list[str]:
    """What a drawn chain (``stack:chain``) misses of the stack ``stacked`` (bottom first): a
    vertex with no mark (a ``Dot`` of the chain) at its dot, a mark on no stacked vertex, two
    vertices one above the other on the stack with no segment between them."""
    marks = [c for p in mobject_nodes(chain) if p.get("type") == "Dot" and (c := _bounds_centre(p))]
    ends = [(p["points"][0][:2], p["points"][-1][:2]) for p in mobject_nodes(chain)
            if p.get("type") == "Line" and len(p.get("points") or ()) >= 2]

    def at(point, v: str) -> bool:
        return v in dots and math.dist(point, dots[v]) <= CHAIN_AT

    found = [f"no mark on {v}" for v in stacked if not any(at(m, v) for m in marks)]
    found += [f"a mark on no stacked vertex at ({m[0]:.1f}, {m[1]:.1f})" for m in marks
              if not any(at(m, v) for v in stacked)]
    found += [f"no segment {u}–{v}" for u, v in itertools.pairwise(stacked)
              if not any((at(a, u) and at(b, v)) or (at(a, v) and at(b, u)) for a, b in ends)]
    return found


def chains_off_the_stack(data: dict) -> list[str]:
    """The monotone stack's changes whose waiting chain, drawn on P, is not the stack's: at
    each play that changes the column (``stack:column``, as it comes or what it turns into),
    the chain (``stack:chain``, likewise) marks each stacked vertex at its dot, marks no
    other, and joins each two vertices one above the other on the stack with a segment
    (:func:`_chain_faults`), as ``"'M waits on the stack': no mark on A"``; and the column
    marks its top (``stack:top``) beside its top name, as ``"'A waits …': top unmarked"``.
    The issue asked for "the chain waiting to be triangulated, as it grows and pops": it was
    one yellow line, its vertices unmarked, beside a column of words (chapter 5, 90–120 s)."""
    dots: dict[str, tuple[float, float]] = {}
    found, caption = [], ""
    for play in data["plays"]:
        caption = play.get("subcaption") or caption
        column = chain = None
        for anim in play["animations"]:
            node = anim.get("mobject", {})
            if anim.get("type") in INCOMING and node.get("name") in _POLYGONS:
                dots = {}
            for key in ("mobject", "target"):
                dots.update(dict(_dot_centres(anim.get(key, {}))))
            if anim.get("type") in OUTGOING:
                continue
            shown = anim.get("target", node)
            if shown.get("name") == "stack:column":
                column = shown
            elif shown.get("name") == "stack:chain":
                chain = shown
        if column is None:
            continue
        stacked = list(reversed(_stack_labels(column)))  # the bottom first
        if chain is None:
            found.append(f"{caption!r}: no chain drawn")
        else:
            found += [f"{caption!r}: {fault}" for fault in _chain_faults(chain, stacked, dots)]
        tops = [p for p in mobject_nodes(column) if p.get("name") == "stack:top"]
        if stacked and not tops:
            found.append(f"{caption!r}: top unmarked")
    return found
# --- exer9: the exercises' answers say fails in its red; the recap's pictures named -------------

#: a text that says a claim fails: an answer "no …", a ✗, "wrong", "fails" (not "crosses no
#: edge", which says why a claim holds)
_SAYS_FAILS = re.compile(r"^(?:Answer:\s*)?(?:no\b|✗)|\?\s*no\b|\bwrong\b|\bfails?\b")


def _incoming_texts(play: dict) -> Iterator[tuple[dict, str]]:
    """(node, its whole text) of each top-level mobject a play brings in that holds text (a
    wrapped answer's lines joined)."""
    for anim in play["animations"]:
        node = anim.get("mobject") or {}
        if anim.get("type") not in INCOMING:
            continue
        said = " ".join(n["text"] for n in mobject_nodes(node) if n.get("text"))
        if said:
            yield node, said


def fails_in_the_correct_colour(data: dict) -> list[str]:
    """The texts saying no, wrong or fails that come in, any line of them, in the green of
    "correct" (the legend's ``result``), as ``"play 87: 'Answer: no (it claims BE) …'"``:
    chapter 6 wrote every answer green, "no (it claims BE)" too."""
    green = _colour("result")
    found = []
    for k, play in enumerate(data["plays"]):
        for node, said in _incoming_texts(play):
            if _SAYS_FAILS.search(said) and any(
                    (n.get("fill") or "").upper() == green for n in mobject_nodes(node)
                    if n.get("text")):
                found.append(f"play {k}: {said[:40]!r}")
    return found


def unmarked_failures_in_answers(data: dict) -> list[str]:
    """The exercises' answers that draw a claim in red (a rejected ``answer:diagonal``)
    without T's part outside P in red (``answer:outside``) or without naming the edge it
    crosses (``answer:edge-name``), as ``"play 87: T's part outside P not red"``: chapter 6's
    answers kept T all blue, where chapter 2's analyses turn the part outside P red and
    name the crossed edge."""
    found = []
    for k, play in enumerate(data["plays"]):
        brought = [node for kind, node in _recorded_all_nodes(play) if kind in INCOMING]
        names = {(n.get("name"), n.get("role")) for node in brought for n in mobject_nodes(node)
                 if n.get("name") != "FlatText" or n.get("role")}
        if ("answer:diagonal", "rejected") not in names:
            continue
        red = any(float(part.get("fill_opacity") or 0) > 0
                  and (part.get("fill") or "").upper() == _REJECTED
                  for node in brought for n in mobject_nodes(node)
                  if n.get("name") == "answer:outside" for part in mobject_nodes(n))
        if not red:
            found.append(f"play {k}: T's part outside P not red")
        if ("answer:edge-name", "rejected") not in names:
            found.append(f"play {k}: the crossed edge unnamed")
    return found


def unexplained_amber_lines(data: dict) -> list[str]:
    """The amber lines (``argument``, no text) an exercise's answer draws (``answer:…``)
    while its caption does not say what amber is there, as ``"play 87 answer:measured"``:
    the hunted rule's answer drew E–C amber and said nothing of it."""
    amber = _colour("argument")
    found = []
    for k, play in enumerate(data["plays"]):
        said = "amber" in (play.get("subcaption") or "").lower()
        for kind, node in _recorded_all_nodes(play):
            name = node.get("name") or ""
            if (kind in INCOMING and name.startswith("answer:") and not node.get("text")
                    and (node.get("stroke") or "").upper() == amber and not said):
                found.append(f"play {k} {name}")
    return sorted(set(found), key=lambda s: int(s.split()[1]))


def unnamed_triangulations(data: dict) -> list[str]:
    """The triangulations a figure draws side by side (``figure:triangle:<algorithm>``) with
    no heading over them naming their algorithm (``figure:name`` texts, as
    :func:`story.registry.spoken` says it), as ``"play 30 ear-clipping"``: the recap's three
    pictures stood with "11 triangles" over each, alike, their names said one by one later."""
    from story.registry import spoken

    found = []
    for k, play in enumerate(data["plays"]):
        brought = [node for kind, node in _recorded_all_nodes(play) if kind in INCOMING]
        drawn = dict.fromkeys(
            n["name"].removeprefix("figure:triangle:") for node in brought
            for n in mobject_nodes(node) if (n.get("name") or "").startswith("figure:triangle:"))
        headings = " ".join(n.get("text") or "" for node in brought for n in mobject_nodes(node)
                            if node.get("name") == "figure:name")
        found += [f"play {k} {name}" for name in drawn
                  if spoken(name, start=True) not in headings]
    return found


#: the least CIE76 ΔE between a tinted region not failing and the red of "fails", both at the
#: opacity the analyses draw that red (:data:`SEEN_AT`) over P's fill, as a tint reads when it
#: is plainly there: the rubber band's rose swept area (#ff5fa2) was 25 from it and read as
#: failing in chapter 3 and the recap; the parts' tan is 40, the fruit's orange 32
LEAST_APART_FROM_FAILS, SEEN_AT = 30.0, 0.6
#: a tint: a region drawn at most this opaque (a dot, the ball dimmed too, is no region)
MOST_TINT = 0.5


def regions_read_as_failing(data: dict) -> list[str]:
    """The tinted regions (no text; fill opacity up to :data:`MOST_TINT`) not in the red of
    "fails" whose colour is within :data:`LEAST_APART_FROM_FAILS` of that red, as ``"play 28
    swept #FF5FA2"``: a correct rule's region read as failing. Each name and colour once."""
    from metaphors.theme import THEME

    found: dict[tuple[str, str], str] = {}
    red = _over(_REJECTED, SEEN_AT, THEME.polygon_fill)
    for k, play in enumerate(data["plays"]):
        for kind, node in _recorded_all_nodes(play):
            if kind in OUTGOING:  # coming in, or redrawn as it sweeps (chapter 3's band)
                continue
            for n in mobject_nodes(node):
                fill, opacity = _one_colour(n.get("fill")), float(n.get("fill_opacity") or 0)
                if (not fill or not 0 < opacity <= MOST_TINT or n.get("text")
                        or n.get("type") == "Dot" or fill.upper() == _REJECTED):
                    continue
                key = (n.get("name") or node.get("name") or "", fill.upper())
                near = delta_e(_over(fill, SEEN_AT, THEME.polygon_fill), red)
                if near < LEAST_APART_FROM_FAILS and key not in found:
                    found[key] = f"play {k} {key[0]} {key[1]}"
    return list(found.values())


# --- ears9 (chapter 4 review): the ball seen, labels by their dots, the plot as the words ------

#: the least CIE76 ΔE between gravity's ball and the fill it falls over, as the screen shows
#: them: the orange ball on ear clipping's orange fruit was 30 off it, and lost (chapter 4 at
#: 80 s, prune and search)
LEAST_BALL_APART = 40.0
#: what a ball falls over: P's fill (the fruit's, a figure's, the close-up's unnamed copy) and
#: what lies on it
_BALLS_ON = ("polygon", "fruit", "figure:polygon", "analysis:polygon", "Polygon")
_UNDER_BALLS = (*_BALLS_ON, "good", "figure:good", "swept")


def balls_on_like_fills(data: dict) -> list[str]:
    """Gravity's ball (:data:`_BALLS`, drawn solid: not resting see-through on X) over a fill
    it does not stand out from, as ``"play 120 ball on fruit ΔE 30"``: P's fill under the
    ball's centre over the background, each fill over that (a good sub-polygon, the band's
    sweep) over what is under it, each nearer than :data:`LEAST_BALL_APART`. Each fill
    once, where first found."""
    from shapely.geometry import Point

    from metaphors.theme import THEME

    found: dict[str, str] = {}
    for k, shown in _shown_after_plays(data, (*_BALLS, *_UNDER_BALLS)):
        fills = _fills_under_balls(shown)
        for name, node in shown.items():
            colour = _one_colour(node.get("fill"))
            if (name not in _BALLS or not colour or not node.get("points")
                    or float(node.get("fill_opacity") or 0) < 0.99):
                continue
            at, screen = Point(_centre(node)), THEME.background
            for owner, shape, (fill, opacity) in fills:  # back to front: P's first
                if not shape.contains(at):
                    continue
                screen = _over(fill, opacity, screen)
                if (apart := delta_e(colour, screen)) < LEAST_BALL_APART:
                    found.setdefault(owner, f"play {k} {name} on {owner} ΔE {apart:.0f}")
    return sorted(found.values(), key=lambda s: int(s.split()[1]))


def _fills_under_balls(shown: dict[str, dict]) -> list[tuple[str, Any, tuple[str, float]]]:
    """The fills of :data:`_UNDER_BALLS` shown (name, shape, colour and opacity), P's before
    those on it."""
    from shapely.geometry import Polygon

    fills = []
    for name, node in shown.items():
        colour = _one_colour(node.get("fill"))
        if name not in _UNDER_BALLS or colour is None or not node.get("fill_opacity"):
            continue
        rings = sorted((Polygon(p) for p in _paths(node) if len(p) >= 3 and Polygon(p).is_valid),
                       key=lambda r: -r.area)
        if rings:
            shape = Polygon(rings[0].exterior, [r.exterior for r in rings[1:]])
            fills.append((name, shape, (colour, float(node["fill_opacity"]))))
    return sorted(fills, key=lambda f: f[0] not in _BALLS_ON)


def primes_not_on_screen(data: dict) -> list[str]:
    """The primed vertex names (:data:`_PRIMED`: ``c₂′``, ``F″``) a caption says while no
    text on screen (a label, the call line; not the subtitle) shows them, as ``"play 214
    c₂′"``: chapter 4's keyhole said "past the cut, c₂ and F are named c₂′ and F′", and
    neither name was anywhere on screen (the lecture shows no call line). Each name once."""
    found: dict[str, str] = {}
    for k, shown in _shown_after_plays(data, ("",)):
        caption = data["plays"][k].get("subcaption") or ""
        said = set(_PRIMED.findall(caption)) - set(found)
        if not said:
            continue
        # the subtitle's lines, under any name, are not on the picture (a label is one word)
        texts = " ".join(text for name, node in shown.items() if name != "subtitle"
                         for part in mobject_nodes(node)
                         if not (" " in (text := (part.get("text") or "").strip())
                                 and text in caption))
        for label in sorted(said):
            if not re.search(rf"(?<![\w′″‴]){re.escape(label)}(?![′″‴₀-₉])", texts):
                found[label] = f"play {k} {label}"
    return sorted(found.values(), key=lambda s: int(s.split()[1]))


#: the farthest a vertex label moved aside may stand from its own dot on the picture (its
#: box; scene units, 36 px at 480p: the farthest place labels.py tries, :data:`GAPS`): chapter
#: 4's d₂, moved off a slice's cut, stood 0.6 off its dot and 0.19 from b₁'s (184 s). A label
#: with no room nearer stands up to this far off for a moment (b₁ off a test triangle, 0.57)
FARTHEST_LABEL = 0.6


def labels_moved_off_their_dots(data: dict) -> list[str]:
    """The vertex labels on the picture moved aside (off a cut, a test triangle, the ball's
    fall) to a place farther than :data:`FARTHEST_LABEL` from their own dot, or nearer
    another vertex's dot than their own (box to dot), as ``"play 239 d₂ 0.60 off its dot,
    by b₁"``: such a label names the dot it stands by (chapter 4's d₂ stood stacked on b₁'s
    label, by b₁'s dot). A label where it was first placed is not judged here (the placing's
    own rules judge it). Each vertex once, where first found; markers as
    :func:`_shown_after_plays` follows them.

    Not asserted yet (ears9): it fires on chapter 4 (d₂ by b₁'s dot, 184 s; G, b₁, a₂). A
    fix in :func:`metaphors.labels.crossed_labels` that keeps a moved label by its own dot
    passed it, but left chapter 4's M and chapter 5's G across a triangulation's side
    (labels_across_fills): their only clear place off the sides is nearer another dot."""
    from shapely.geometry import Point
    from shapely.geometry import box as area

    found: dict[str, str] = {}
    first: dict[str, tuple[float, ...]] = {}  # each label's box as it came in
    for k, shown in _shown_after_plays(data, ("vertex:",)):
        markers = {name.removeprefix("vertex:"): (dot, boxes[0]) for name, m in shown.items()
                   if (dot := _dot_centre(m)) is not None
                   and (boxes := list(_label_boxes(m, direct=True)))}
        first = {v: box for v, box in first.items() if v in markers}
        for vertex, (dot, box) in markers.items():
            if first.setdefault(vertex, box) == box or vertex in found:
                continue
            label = area(*box)
            own = label.distance(Point(dot))
            by = min(((label.distance(Point(d)), v) for v, (d, _) in markers.items()
                      if v != vertex and d != dot), default=(math.inf, ""))
            if own > FARTHEST_LABEL or by[0] < own:
                found[vertex] = f"play {k} {vertex} {own:.2f} off its dot, by {by[1]}"
    return sorted(found.values(), key=lambda s: int(s.split()[1]))


#: a method card's parts that are its run's result: prune and search's kept half, the
#: keyhole's bridges
_CARD_RESULTS = ("figure:good", "figure:bridge:")


def results_on_method_cards(data: dict) -> list[str]:
    """A card's figure that draws what the run after it computes (:data:`_CARD_RESULTS`), as
    ``"play 79 figure:good"``: one picture per idea, the card poses the method and the run
    shows its result once (chapter 4's prune and search card drew GB and the kept half, the
    keyhole card both bridges, and the runs drew them again seconds later). Each name once."""
    found: dict[str, str] = {}
    for k, play in enumerate(data["plays"]):
        for anim in play["animations"]:
            if anim.get("type") not in INCOMING:
                continue
            for node in animation_nodes(anim):
                name = node.get("name") or ""
                if name.startswith(_CARD_RESULTS):
                    found.setdefault(name, f"play {k} {name}")
    return list(found.values())
