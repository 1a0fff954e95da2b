"""Issue 12's rules for what a viewer reads, checked on a scene graph (dry run, no timing):
every cue of the ``.srt`` at least 0.83 s and at most 17 characters per second
(:func:`story.reading.readable`), every visible text at least 2.5 % of the frame's height
(:data:`LEAST_LINE`) per line. The test modules of the scenes and of the lecture apply them."""

from __future__ import annotations

import itertools
import json
import re
from collections.abc import Iterator
from itertools import pairwise

from story.reading import readable

#: 2.5 % of the frame's height (8 units): the least a line of text may be (27 px at 1080p)
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


def unreadable_cues(data: dict) -> list[str]:
    """The cues too short or too fast to read, as ``"1.20 s, 41 cps: …"``."""
    bad = []
    for cue in data["cues"]:
        seconds = cue["end"] - cue["start"]
        if not readable(cue["text"], seconds):
            cps = len(cue["text"]) / seconds if seconds > 0 else float("inf")
            bad.append(f"{seconds:.2f} s, {cps:.0f} cps: {cue['text']}")
    return bad


def line_height(node: dict) -> float:
    """The height of one line of a text node (its box over its lines)."""
    _, bottom, _, top = node["box"]
    return (top - bottom) / (node["text"].count("\n") + 1)


def small_texts(data: dict) -> list[str]:
    """The visible texts whose lines are under :data:`LEAST_LINE`, as ``"name 'text' 0.15"``."""
    found = {}
    for node in graph_nodes(data):
        if node.get("box") is None or not node.get("text", "").strip():
            continue
        if (node.get("fill_opacity") or 0) <= 0:
            continue  # not drawn
        height = line_height(node)
        if height < LEAST_LINE:
            found[(node["name"], node["text"])] = height
    return [f"{name} {text!r} {h:.3f}" for (name, text), h in sorted(found.items())]


#: the animations that take a mobject off the screen, and those that put one on
OUTGOING = {"FadeOut", "Uncreate", "Unwrite", "ShrinkToCenter"}
INCOMING = {"FadeIn", "Write", "Create", "AddTextLetterByLetter", "GrowFromCenter"}


def _played_subtitles(anim: dict) -> Iterator[tuple[str, str]]:
    """(animation type, text) of every subtitle an animation (or its members) plays."""
    mobject = anim.get("mobject") or {}
    if mobject.get("name") == "subtitle" and (mobject.get("text") or "").strip():
        yield anim["type"], mobject["text"]
    for child in anim.get("animations", ()):
        yield from _played_subtitles(child)


def crossfaded_subtitles(data: dict) -> list[str]:
    """Issue 22 item 9: the plays that take one subtitle off while putting the next on (two
    subtitles on screen at once), as ``"play 12: 'old' → 'new'"``. A caption goes before the
    next comes: a cut, or a play that takes it off and then one that puts the next on."""
    found = []
    for k, play in enumerate(data["plays"]):
        played = [pair for anim in play["animations"] for pair in _played_subtitles(anim)]
        gone = [text for kind, text in played if kind in OUTGOING]
        come = [text for kind, text in played if kind in INCOMING]
        if gone and come:
            found.append(f"play {k}: {gone[0]!r} → {come[0]!r}")
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
    if (node.get("text") or "").strip() and (node.get("fill_opacity") or 0) > 0:
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


def _near(p: tuple[float, float], corners: list[tuple[float, float]]) -> bool:
    return any(abs(p[0] - x) < 1e-3 and abs(p[1] - y) < 1e-3 for x, y in corners)


def hidden_failures(data: dict) -> list[str]:
    """Issue 22 items 3 and 6: the red (rejected) claims, and exercises' rejected diagonals,
    whose part outside their polygon is under
    :data:`LEAST_OUTSIDE` on screen, as ``"claim (x, y)–(x, y): 0.14 outside"``, or which
    pass nearer than :data:`LEAST_CLEARANCE` to a vertex not their own. A claim is
    matched to the drawn polygon that has both its ends as corners; one with no such polygon
    is reported too, so that a claim drawn elsewhere cannot pass unmeasured."""
    from shapely.geometry import LineString
    from shapely.geometry import Point as ShapelyPoint
    from shapely.geometry import Polygon as Region

    nodes = list(graph_nodes(data))
    polygons = [_corners(n) for n in nodes if n.get("points") and (
        n.get("name") in _POLYGONS or (n.get("name"), n["type"]) == ("exercise", "Polygon"))]
    found = {}
    for node in nodes:
        if node.get("name") not in _CLAIMS \
                or (node.get("stroke") or "").upper() != _REJECTED:
            continue
        a, b = (tuple(node["points"][k][:2]) for k in (0, -1))
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


# --- issue 22 item 4: one picture per idea ----------------------------------------------------

#: the polygons a run or an analysis draws its steps on (a card's figure is no run)
_RUN_POLYGONS = ("polygon", "analysis:polygon")


def _shape(node: dict) -> tuple[tuple[float, float], ...]:
    """A drawn polygon's shape wherever and however large it is drawn: its corners over the
    size of its box, rounded (a run and an analysis draw one polygon in different boxes)."""
    corners = _corners(node)
    x0, y0 = min(x for x, _ in corners), min(y for _, y in corners)
    size = max(max(x for x, _ in corners) - x0, max(y for _, y in corners) - y0, 1e-9)
    return tuple((round((x - x0) / size, 2), round((y - y0) / size, 2)) for x, y in corners)


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


def replayed_beats(data: dict) -> list[str]:
    """Issue 22 item 4: the runs' beats shown twice, as ``"'caption' (section)"``. A run is a
    polygon drawn in a card's section; its beats are the captions said over it
    (:func:`shown_steps`). A beat is replayed when the same caption is said again over a
    polygon of the same shape in one section *and* the same picture is on screen at its
    end (the run, or an analysis that plays it again). One step's caption said over each
    piece of divide and conquer, each batch of a fast summary, or one claim of several
    heuristics on one polygon, is no replay: each time something else is on screen (another
    piece, another diagonal, another metaphor)."""
    seen: set[Step] = set()
    found = []
    for step in shown_steps(data):
        if step[1] is not None and step in seen:
            found.append(f"{step[2]!r} ({step[0]})")
        seen.add(step)
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


# --- issue 22 item 5 for the exercises: polygons a class can read --------------------------------

#: the least angle at a vertex, inside or out, as drawn (degrees)
LEAST_ANGLE = 15.0
#: the least gap between a vertex label and an edge or another label (touching is crowding)
LEAST_LABEL_GAP = 0.02


def _exercise_pictures(data: dict) -> Iterator[tuple[list[tuple[float, float]], list[tuple]]]:
    """Each exercise picture coming on screen: its polygon's corners and its labels, as
    ``(text, box)`` in the order of the corners."""
    corners: list[tuple[float, float]] | None = None
    for play in data["plays"]:
        for anim in play["animations"]:
            node = anim.get("mobject") or {}
            if anim.get("type") not in INCOMING or node.get("name") != "exercise":
                continue
            if node["type"] == "Polygon" and node.get("points"):
                shape = _corners(node)
                if corners is None or len(shape) > len(corners):  # P, not its triangle T
                    corners = shape
            markers = [m for m in node.get("submobjects", ()) if [c["type"] for c in
                       m.get("submobjects", ())] == ["Dot", "FlatText"]]
            if markers and corners is not None:
                yield corners, [(m["submobjects"][1]["text"], m["submobjects"][1]["box"])
                                for m in markers]
                corners = None


def _inner_angle(p, q, r) -> float:
    import math

    u, v = (p[0] - q[0], p[1] - q[1]), (r[0] - q[0], r[1] - q[1])
    return math.degrees(math.atan2(v[0] * u[1] - v[1] * u[0], v[0] * u[0] + v[1] * u[1])) % 360


def crowded_exercises(data: dict) -> list[str]:
    """Issue 22 items 5 and 6: the exercise pictures a class cannot read, as drawn on screen:
    an angle under :data:`LEAST_ANGLE` (a needle) or over 360° minus it (a notch), a vertex
    nearer than :data:`LEAST_CLEARANCE` to an edge it is not on, and two vertex labels, or a
    label and an edge, nearer than :data:`LEAST_LABEL_GAP`; as ``"angle at E: 2°"``."""
    from shapely.geometry import LineString, box
    from shapely.geometry import Point as ShapelyPoint

    found = []
    for corners, labels in _exercise_pictures(data):
        n = len(corners)
        names = [text for text, _ in labels] if len(labels) == n else [str(k) for k in range(n)]
        if corners[0] == corners[-1]:
            corners = corners[:-1]
            n -= 1
        edges = [LineString([corners[k], corners[(k + 1) % n]]) for k in range(n)]
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
