"""The board a scene plays on: the metaphor's polygon (left), the panel (right), the subtitle.

Performers (one module per metaphor family) receive the board and a beat, build mobjects at
the log's coordinates with :meth:`Board.at`, and hand their animations to :meth:`Board.play`,
which adds the panel's updates and the subtitle, applies the beat's pacing, and writes the
caption as a Manim subcaption (so every render also writes an ``.srt``), held until it has
been read (:mod:`metaphors.captions`).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import replace
from typing import Any, Protocol, TypeAlias

import numpy as np
import shapely
from manim import Animation, FadeIn, FadeOut, Mobject, Scene, Transform, VGroup
from manim.mobject.mobject import _AnimationBuilder

from geometry.polygon import Polygon
from metaphors.captions import CaptionTrack, whole_frames
from metaphors.drawing import Frame, polygon_mobject
from metaphors.labels import (
    MARGIN,
    crossed_labels,
    drawn_edges,
    filled_region,
    measured_markers,
    move_label,
    new_colour,
)
from metaphors.layout import (
    METAPHOR,
    SUBTITLE_WIDTH,
    TITLE_Y,
    Box,
    ring_edges,
    subtitle_centre,
)
from metaphors.panel import Panel
from metaphors.tags import tag
from metaphors.theme import THEME, Theme
from rendering.layers import BACKDROP_Z, STILL_Z
from rendering.typeset import balanced, glyphs, text
from story.beats import Beat, Hole, Point
from story.reading import reading_time

#: seconds the words of a beat take to change (at most half the beat)
WORDS_TIME = 0.3
#: a shorter play is not split (a frame at 15 fps lasts 1/15 s)
MIN_PLAY = 0.1
#: z-index of the words while they change: above everything
WORDS_Z = 10

#: z-index of the vertex markers (dots and labels): over every fill and tool a performer
#: draws after them (tints −1, the clock hand and the sweep line 1), which at
#: their own z-index would tint a label (chapter 1's M and G under the triangulation) or
#: run through it (chapter 2's clock hand through F)
LABEL_Z = 5

#: how near (scene units) a point of a metaphor object comes to a vertex to be drawn from it
HELD = 1e-3
#: how far apart (scene units) two rings of the outline may lie and be one ring drawn twice
SAME_RING = 1e-6

#: what a play takes: an animation, a mobject's ``.animate`` (its builder, or the mobject)
Playable: TypeAlias = Animation | Mobject | _AnimationBuilder


def animate(mobject: Mobject, **anim_args: Any) -> _AnimationBuilder:
    """``mobject.animate(**anim_args)`` (a builder given the play's arguments, ``rate_func``
    …), typed: manim types ``animate`` as the builder or the mobject itself, but it is always
    the builder."""
    builder = mobject.animate
    assert isinstance(builder, _AnimationBuilder)
    return builder(**anim_args)


class CloseUp(Protocol):
    """A close-up on the board (:class:`metaphors.gravity.CloseUp`): what ends it, and
    what was drawn up close (to go before it ends)."""

    def made_here(self, key: str) -> bool: ...

    def zoom_out(self) -> list[Playable]: ...

    def done(self) -> None: ...

    def come_back(self) -> list[Playable]: ...


#: the least a step of a summary takes (seconds): long enough to see what changed
SEEN_STEP = 0.5
#: the objects that hold the vertex they are drawn from in its blue (:meth:`Board.held`):
#: T round B, gravity's ball and band, a claim and the edge it crosses
HOLDING = frozenset({"T", "ball", "band", "claim", "crossed"})


class Board:
    """Everything on screen, and the play loop's helpers."""

    def __init__(self, scene: Scene, points, labels, shown: str | None, title: str,
                 theme: Theme = THEME, box: Box = METAPHOR, holes=(), *,
                 captions: CaptionTrack, claims: Sequence[tuple[str, str]] = (),
                 cuts: Sequence[Sequence[Sequence[float]]] = (),
                 drawn: Sequence[tuple[Point, Point]] = (), leaders: bool = False):
        self.scene, self.theme = scene, theme
        self.polygon = Polygon(tuple(map(tuple, points)), tuple(labels),
                               tuple(range(len(labels))))
        self.holes: list[Hole] = list(holes)  # drawn unfilled, their vertices marked
        self.box = box  # the picture's part of the screen (nothing drawn leaves it)
        self.frame = Frame(self.polygon.points, box.center, box.width, box.height)
        self.outline = tag(polygon_mobject(self.polygon, self.frame, theme, self.holes), "idle",
                           "polygon")
        # the labels clear of the claims the run will draw (``claims``: pairs of labels), as
        # of the edges: a label moved off a claim drawn on a turned picture would turn back
        # upright beside it, not where it was placed
        pairs = [(self.polygon.labels.index(u), self.polygon.labels.index(v))
                 for u, v in claims if u in self.polygon.labels and v in self.polygon.labels]
        self.claim_pairs = pairs  # placed again clear of them when the picture turns
        # and of the lines the run will cut (``cuts``, two points each: a keyhole's, a
        # slice's), so that no cut moves a label: moved by each keyhole as it was cut, c₂
        # stood in three places in two steps, and c₁ and d₂ jumped with it
        lines = [(self.frame.to_scene(a), self.frame.to_scene(b)) for a, b in cuts]
        self.markers: dict[str, Mobject] = {
            label: tag(m, "idle", f"vertex:{label}").set_z_index(LABEL_Z)
            for label, m in measured_markers(self.polygon, self.holes, self.frame, theme, pairs,
                                             lines, leaders)
        }
        self.where: dict[str, tuple[float, ...]] = {
            label: p for label, p in zip(labels, self.polygon.points, strict=True)}
        self.where.update({label: tuple(p) for hole in self.holes
                           for label, p in zip(hole.labels, hole.points, strict=True)})
        # ``drawn``: the segments the run will draw in the panel (claims, cuts, slices' cuts),
        # which its labels keep clear of
        self.panel = Panel(points, labels, shown, theme, self.holes, drawn)
        self.title = tag(glyphs(title, font=theme.font, size=30, colour=theme.ink), None, "title")
        self.title.move_to((0, TITLE_Y, 0))
        self.subtitle = tag(text(" ", font=theme.font, size=theme.caption_size), None,
                            "subtitle")
        self.objects: dict[str, Mobject] = {}  # persistent metaphor objects by key
        self.caption = ""  # the caption of this board's subtitle
        # the subtitle a beat replaces, cut once the beat's caption shows
        self.outgoing: Mobject | None = None
        # notes of a beat that stay up while its caption is read and go with the next beat's
        # words (the monotone sweep's kind word)
        self.leaving: list[Mobject] = []
        # text that comes with the next beat's words (a run going on on this board: its
        # title and its pseudocode come with its first caption, never before it)
        self.arriving: list[Mobject] = []
        # the keys of metaphor objects that only the beat which drew them speaks of (ear
        # clipping's red test triangle): the next beat's words take them away, whatever
        # metaphor plays it (left up, the triangle lay under the gravity step after it)
        self.passing: dict[str, Mobject] = {}
        # the keys of lines drawn amber ("being decided now") that are settled once their
        # beat is over: the next beat's words turn them to the ink of a diagonal made, on the
        # picture and in the panel (the holes' sweep kept its diagonals amber for 40 s)
        self.settling: list[str] = []
        self.captions = captions  # the scene's one track (metaphors.recorded.captions_of)
        self.roles: dict[str, str] = {}
        # the labels of the part of P the current call runs on (divide and conquer's piece,
        # :func:`metaphors.labels.new_colour`): None, all of P
        self.focus: frozenset[str] | None = None
        # how many beats the caption of the beat being played stands over, in its unbroken
        # stretch of beats (:meth:`shared_time`; set by :func:`metaphors.play.play_beats`)
        self.share = 1
        # labels moved aside for a while (:meth:`clear_labels` ``for_now``): where they stood,
        # in the polygon's coordinates
        self.moved_for_now: dict[str, tuple[float, float]] = {}
        # labels moved aside off a thing that goes with the next beat's words (ear clipping's
        # test triangle, :meth:`clear_labels` ``aside``): where they stood, in the polygon's
        # coordinates; they go back with it (:meth:`play`): left where they were moved, H
        # stood on the fruit for a second after G's triangle went, with room off it
        self.aside: dict[str, tuple[float, float]] = {}
        # the markers of vertices a metaphor took off the picture for a while (ear clipping's
        # sliced-off ear tips), by label: out of :attr:`markers`, so that no recolouring,
        # label move or turn brings them back on screen before the metaphor does
        self.off: dict[str, Mobject] = {}
        # where each label stood beside its dot, upright, before the picture turned: it comes
        # back there when the picture turns upright (:func:`metaphors.picture.turn_to`)
        self.home: dict[str, np.ndarray] = {}
        # a close-up in progress (gravity's, from the fall to the verdict), which the verdict
        # ends (:func:`metaphors.picture.upright`)
        self.close_up: CloseUp | None = None
        # the run's last picture is kept as it is, turned, with its ball and band: an analysis
        # goes on from it (:class:`metaphors.lecture.LectureScene`)
        self.kept_end = False

    # --- coordinates -----------------------------------------------------------------------------

    def at(self, p: Sequence[float]) -> np.ndarray:
        """Scene point of a polygon-coordinate point (follows the metaphor's rotation)."""
        return self.frame.to_scene(p)

    def vertex(self, label: str) -> np.ndarray:
        return self.at(self.where[label])

    def length(self, d: float) -> float:
        """Scene length of a polygon-coordinate length."""
        return d * self.frame.scale

    def left_group(self) -> VGroup:
        """What turns when the metaphor turns the polygon: outline, vertices, metaphor objects."""
        parts = {id(m): m for m in (self.outline, *self.markers.values(), *self.objects.values())}
        return VGroup(*parts.values())  # once each: the fruit is the outline itself

    # --- playing ----------------------------------------------------------------------------------

    def shared_time(self, beat: Beat) -> float:
        """The seconds each beat under ``beat``'s caption takes at least, so that together
        they last as long as the caption takes to read: a summary's fast steps ("Vertices H,
        B, G and F: the same steps, faster") share its reading time, each long enough to see
        (at 0.2 s each they flashed by, then the screen stood still on the last for 2 s).
        Only the beats of its own stretch share it: the same words said again later are
        read again (counted over the whole run, each step of a summary whose caption came
        back was cut short by the beats of the other). Never under :data:`SEEN_STEP`: a
        summary of many steps (the monotone sweep's, each vertex's kind and the edge it
        helps) takes longer than its words, each step still seen."""
        return max(SEEN_STEP, reading_time(beat.caption) / max(1, self.share))

    def play(self, beat: Beat, *anims: Playable, run_time: float = 1.0,
             together: bool = False, at_rest: bool = False, least: float = 0.0) -> None:
        """Play a beat: first its words (subtitle, lit line, call line) change, briefly; then its
        own animations play with the roles on both sides, for the rest of the beat's time.

        Two plays, not one: manim redraws, in every frame of a play, what it animates and all
        that lies above that. The words change on top of everything (:data:`WORDS_Z`), so their
        short play redraws only them; then they go to the bottom (:meth:`settle`), so the
        picture's play does not redraw them. Nothing overlaps the words, so their place in the
        drawing order does not show. ``together``: one play, the words with the picture (a
        run's first beat in the lecture: the words do not come before what they speak of).
        ``at_rest``: the run's ending, no call runs: every vertex label goes back to the ink
        it was drawn in, on the board and in the panel (grey, "not in the current call", no
        longer means anything, and labels of two colours would seem to mean two things).
        ``least``: the seconds the beat's picture takes at least, whatever its pace
        (:meth:`shared_time`), after its words."""
        # A marker the beat already animates (a pulse) is recoloured after the play: two
        # animations of one mobject in one play would cancel the first.
        passed: list[Playable] = [*self.drop(*[key for key, m in self.passing.items()
                                               if self.objects.get(key) is m])]
        self.passing = {}
        passed += self._settle()
        # the labels moved aside off what goes go back with it
        busy = {id(getattr(a, "mobject", None)) for a in anims}
        passed += self.labels_aside_back(busy) if passed else []
        busy |= {id(getattr(a, "mobject", None)) for a in passed}
        beat = replace(beat, roles=self.held_roles(beat.roles))
        recolour, after = self._recolour(beat.roles, busy, at_rest)
        action = [*anims, *recolour]
        words = [*self.panel.follow_text(beat), *self._subtitle(beat.caption),
                 *(FadeOut(m) for m in self.leaving), *(FadeIn(m) for m in self.arriving)]
        # the panel's colours change with its call line and lit row, not after them: under
        # "is_ear(B) → False" its E and F were still green from the slice before (review)
        roles = self.panel.follow_roles(beat, at_rest, self.focus)
        self.leaving, self.arriving = [], []
        paced = max(0.1, run_time * beat.pace)
        lead = min(WORDS_TIME, paced / 2)
        split = bool(words) and lead >= MIN_PLAY and not together
        # ``least`` is the picture's own time: the words' lead, if any, comes before it
        rest = max(paced - lead, least)
        total = lead + rest if split else max(paced, least)
        # a new caption waits until the one before it has been read
        caption = self.captions.show(beat.caption, total) if beat.caption != self.caption else {}
        self._cut_outgoing()  # read: it goes before the next comes in (never crossfaded)
        if split:
            for animation in words:
                animation.mobject.set_z_index(WORDS_Z)
            self.scene.play(*words, *roles, *passed, run_time=lead, **caption)
            self.settle()
            if action:
                self.scene.play(*action, run_time=rest)
            else:
                self.scene.wait(whole_frames(rest))
        elif words or action or passed or roles:
            self.scene.play(*words, *roles, *passed, *action, run_time=total, **caption)
        for marker, colour in after:
            marker.set_color(colour)
        self.caption = beat.caption
        self.settle()

    def close(self) -> None:
        """The run is over: its last caption is held until read, its cue lasting to now (it
        stays on screen, and its cue goes on, until the screen is cleared)."""
        self.captions.hold()
        self.captions.stretch()

    def settle(self) -> None:
        """Put the text at the bottom of the scene's drawing order: title and code lowest
        (:data:`~rendering.layers.STILL_Z`), then the text that changes from beat to beat
        (:data:`~rendering.layers.BACKDROP_Z`). manim redraws, in every frame of a play, each
        mobject from the first animated one upwards (ordered by z-index, then by when it was
        added); text below everything else stays in the play's static image, and the title and
        code stay in :class:`~rendering.renderer.BackdropRenderer`'s kept layer. Nothing else
        on screen overlaps the text, so the picture does not change."""
        layers = ((STILL_Z, [self.title, self.panel.code]),
                  (BACKDROP_Z, [*self.panel.changing(), self.subtitle]))
        bottom = []
        for z, mobjects in layers:
            for mobject in mobjects:
                if mobject in self.scene.mobjects:
                    if mobject.z_index != z:
                        mobject.set_z_index(z)
                    bottom.append(mobject)
        self.scene.bring_to_back(*bottom)

    def held_roles(self, roles: Mapping[str, str]) -> Mapping[str, str]:
        """``roles``, and the object the call ran on (blue) kept so while a tool or a claim
        drawn from its vertex stays on the picture (:meth:`held`): the call's work on it is
        still seen (gravity's band hanging from C while the ball slides, T drawn round B,
        the vertex it was built on). Before, the vertex lapsed as the step after it named it
        no more, and went grey, blue again, in a second."""
        lapsed = {label for label, was in self.roles.items()
                  if was == "called" and roles.get(label, "idle") == "idle"}
        kept = lapsed & self.held()
        return {**roles, **dict.fromkeys(kept, "called")} if kept else roles

    def held(self) -> set[str]:
        """The labels of the vertices a tool or claim on the picture (:data:`HOLDING`; not
        one going with the next words, :attr:`passing`) has a point on: a band's anchor, T's
        corner. Not the pieces, diagonals or triangles of a run's result: their corners
        stayed blue for 20 to 30 plays in chapter 5 (review s35)."""
        going = {id(m) for m in self.passing.values()}
        points = [m.get_all_points() for key, m in self.objects.items()
                  if key in HOLDING and id(m) not in going]
        points = [p[:, :2] for p in points if len(p)]
        if not points:
            return set()
        drawn = np.concatenate(points)
        return {label for label in self.markers
                if np.min(np.linalg.norm(drawn - self.vertex(label)[:2], axis=1)) < HELD}

    def _recolour(self, roles: Mapping[str, str], busy: set[int],
                  at_rest: bool = False) -> tuple[list, list]:
        """Animations for markers whose role changed, and (marker, colour) to set after;
        ``at_rest``: every marker not in its ink goes back to it (:meth:`play`)."""
        anims, after = [], []
        for label, marker in self.markers.items():
            role = roles.get(label, "idle")
            colour = new_colour(marker, label, role, self.roles.get(label, "idle"), self.theme,
                                self.focus, at_rest)
            if colour is None:
                continue
            tag(marker, "idle" if at_rest else role)
            if id(marker) in busy:
                after.append((marker, colour))
            else:
                anims.append(marker.animate.set_color(colour))
        self.roles = {} if at_rest else {k: v for k, v in roles.items() if k in self.markers}
        if at_rest:
            self.focus = None
        return anims, after

    def _subtitle(self, caption: str) -> list:
        if caption == self.caption:
            return []
        new = tag(balanced(caption, font=self.theme.font, size=self.theme.caption_size,
                           colour=self.theme.ink, width=SUBTITLE_WIDTH), None, "subtitle")
        new.move_to(subtitle_centre(new.height))
        self.outgoing, self.subtitle = self.subtitle, new
        return [FadeIn(new)]

    def _cut_outgoing(self) -> None:
        """Take the subtitle and the call line being replaced off the screen at once (a cut):
        two of them are never up together, as a crossfade would show them."""
        old, self.outgoing = self.outgoing, None
        for gone in (old, *self.panel.cut_outgoing()):  # the call line likewise
            if gone is not None:
                self.scene.remove(gone)

    def keep(self, key: str, mobject: Mobject) -> None:
        """Remember a metaphor object (it turns with the polygon and is cleared by ``drop``)."""
        self.objects[key] = mobject

    def outline_rings(self) -> list[list[np.ndarray]]:
        """The outline's rings as drawn (not P: ear clipping's fruit shrinks as its slices
        go), the largest first (the outer one, then the holes'), each its corners."""
        paths = [path for part in self.outline.family_members_with_points()
                 for path in part.get_subpaths() if len(path) >= 12]  # a triangle's, at least
        rings = [list(path[:-1:4]) for path in paths]
        # each once: a close-up's drawing, redrawn by ``become`` from one with fewer parts,
        # holds its outline twice (its fill, and an edge stretched round it), and a ring
        # that is its own hole leaves no inside for a ✓ (it stood off P, under edge B–C).
        # The same ring (within :data:`SAME_RING`), not the same points: ``become`` splits a curve in two, so the copy
        # has a corner more at each side's middle (chapter 4's ✓ for GB, placed with no
        # inside, stood 0.41 off its claim)
        unique: list[tuple[shapely.Polygon, list[np.ndarray]]] = []
        for ring in rings:
            shape = shapely.Polygon([p[:2] for p in ring])
            # nearly: the middle corner lies off the side by a rounding error, which
            # ``equals`` counts as another ring
            if not any(shapely.hausdorff_distance(shape.exterior, seen.exterior) < SAME_RING
                       for seen, _ in unique):
                unique.append((shape, ring))
        return [ring for _, ring in sorted(unique, key=lambda pair: -pair[0].area)]

    def clear_labels(self, *lines: Mobject, for_now: bool = False,
                     apart: float = MARGIN, aside: bool = False,
                     returning: bool = False, near: float = MARGIN) -> list[Playable]:
        """The moves, to play with ``lines`` (about to be drawn: a diagonal, a cut, the
        triangles of a triangulation), of the vertex labels they would cross: each to a clear
        place beside its vertex, measured against the outline's edges, the lines and
        triangles drawn and the other labels (:func:`metaphors.labels.crossed_labels`); a
        label the lines keep clear of stays. A move transforms the whole marker, so
        :meth:`play` recolours it after the play. ``for_now``: the lines go again soon (the
        ball's fall), and :meth:`labels_back` puts the labels back where they stood.
        ``apart``: the gap a moved label keeps from the other labels. ``aside``: the lines
        go with the next beat's words (:meth:`passes`: a test triangle), and the labels go
        back with them (:meth:`labels_aside_back`). ``returning``: what the labels were
        moved aside off goes now (the test triangle before): they go back where they stood,
        unless these lines cross them there too."""
        # the vertices on the picture (not those taken off it, :attr:`off`), in ring order
        rings = [[label for label in ring if label in self.markers]
                 for ring in (self.polygon.labels, *(h.labels for h in self.holes))]
        drawn = [edge for ring in self.outline_rings() for edge in ring_edges(ring)]
        drawn += [edge for m in self.objects.values() if m not in lines
                  for edge in drawn_edges(m)]
        markers = {label: m for label, m in self.markers.items() if isinstance(m, VGroup)}
        moves: list[Playable] = []
        fill = filled_region([[p[:2] for p in ring] for ring in self.outline_rings()])
        homes = {label: place for label, place in self.aside.items() if label in markers}
        back = {label: self.at(place) for label, place in homes.items()} if returning else {}
        self.aside = {} if returning else self.aside
        crossed = crossed_labels(rings, markers, drawn,
                                 [edge for line in lines for edge in drawn_edges(line)],
                                 self.theme.dot_radius, apart, fill, back, near)
        for label, centre in {**back, **crossed}.items():
            moved = self.markers[label].copy()
            # in the polygon's coordinates: the picture may turn before it goes back
            where = homes.get(label, self.frame.from_scene(self.markers[label][1].get_center()))
            if for_now:
                self.moved_for_now.setdefault(label, where)
            if aside and label in crossed:
                self.aside.setdefault(label, where)
            move_label(moved, centre)
            # a move for now is an ``animate`` (it is undone), a lasting one a Transform
            moves.append(animate(self.markers[label]).become(moved) if for_now
                         else Transform(self.markers[label], moved))
        return moves

    def labels_aside_back(self, busy: set[int]) -> list[Playable]:
        """The moves putting the labels moved aside (:meth:`clear_labels` ``aside``) back
        where they stood, but those whose markers ``busy`` holds (ids: animated in the same
        play already, they stay where that puts them)."""
        moves: list[Playable] = []
        for label, place in sorted(self.aside.items()):
            marker = self.markers.get(label)
            if marker is not None and id(marker) not in busy:
                back = marker.copy()
                move_label(back, self.at(place))
                moves.append(Transform(marker, back))
        self.aside = {}
        return moves

    def labels_back(self) -> list[Playable]:
        """The moves putting the labels moved aside ``for_now`` (:meth:`clear_labels`) back
        where they stood, or where they would stand had they not moved (the picture turned
        since: they turn with it)."""
        moves: list[Playable] = []
        for label, place in sorted(self.moved_for_now.items()):
            back = self.markers[label].copy()
            move_label(back, self.at(place))
            moves.append(animate(self.markers[label]).become(back))
        self.moved_for_now = {}
        return moves

    def passes(self, *keys: str) -> None:
        """The objects kept under ``keys`` go with the next beat's words (:attr:`passing`),
        unless taken away or replaced before."""
        self.passing.update({key: self.objects[key] for key in keys if key in self.objects})

    def settles(self, *keys: str) -> None:
        """The lines kept under ``keys`` turn to the ink with the next beat's words: drawn
        amber while their beat decides them, settled after it (:attr:`settling`)."""
        self.settling += [key for key in keys if key in self.objects]

    def _settle(self) -> list[Playable]:
        """The lines waiting to settle (:meth:`settles`), turning to the ink, in the panel
        too; each kept under its key, now in the idle role."""
        anims: list[Playable] = []
        for key in self.settling:
            line = self.objects.get(key)
            if line is None:
                continue
            tag(line, "idle", line.name)
            anims += [line.animate.set_color(self.theme.ink), *self.panel.recolour(key, None)]
        self.settling = []
        return anims

    def drop(self, *keys: str) -> list[Animation]:
        """Fade-outs for remembered objects, and for what the panel draws of them under the
        same keys (a claim, the edge it crosses: :meth:`metaphors.panel.Panel.draw`)."""
        return [*(FadeOut(self.objects.pop(k)) for k in keys if k in self.objects),
                *self.panel.drop(*keys)]
