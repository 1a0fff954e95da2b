"""Colours by role, fonts, stroke widths and sizes: the only place they are written.

Roles follow the seed's viewer: the object a call runs on is blue, its
arguments amber while the call runs, the result green, a rejected object red,
everything idle grey.

The legend: each colour has one meaning for the whole lecture and every scene.

============  ==========  ===========================================================
field         colour      meaning
============  ==========  ===========================================================
called        blue        the object a call runs on (a vertex being looked at; the
                          piece divide and conquer works on, filled and outlined in it,
                          and in the panel tinted)
argument      amber       a call's other inputs while it runs; a diagonal being drawn;
                          a claim not yet judged (then green or red)
result        green       what a call gives; a correct claim; a triangulation's count
rejected      red         fails: a wrong claim, its part outside P, the crossed edge
                          (dashed in the recap, beside its solid claim), a vertex inside
                          a triangle that is not an ear — never a kind
idle          grey        everything not in the current call: the code's rows; a vertex
                          outside the piece divide and conquer works on (said in
                          chapter 1); elsewhere a vertex out of the call is in its ink
candidate     pink        a vertex in T a heuristic may pick: neutral, neither claimed
                          nor judged (the one it picks turns amber, the claim to be)
split         cyan        a split vertex of the monotone sweep (a kind, not a verdict)
merge         magenta     a merge vertex of the monotone sweep (a kind, not a verdict)
stack         yellow      the monotone stack: the chain waiting to be triangulated
polygon_fill  navy        inside P
water         light blue  spilled or rising water (Scaling)
ball, band    violet,     gravity's ball, its rubber band and what the band swept
              pale lemon  (Gravity): the ball not orange, as it falls on ear clipping's
                          orange fruit too (prune and search, chapter 4 at 80 s); the
                          band far from the red of "fails" (a correct rule)
hand, sweep   purple      the clock hand (Rotation) and the sweeping line
                          (Translation, the monotone sweep)
swept         pale blue   what water, clock hand or sweep line swept on its way to its
                          pick (one colour for all three; red where it is outside P)
dial          grey        the frame of a close-up (gravity's window)
fruit, rind   orange,     the fruit sliced (ear clipping), on its plate; its rind a
              brown       peel's brown, no role's (its olive was near the "yes" green)
pieces        tints       the sub-polygons of divide and conquer and the monotone
                          pieces (the parts a split or a partition makes): teal, tan
                          and olive, far from the blue of what a call runs on
triangles     green       the triangles of a finished triangulation: the result's green,
              shades      neighbours in other shades (never the pieces' tints)
============  ==========  ===========================================================

>>> THEME.role_colour("result") == THEME.result
True
>>> THEME.role_colour("merge") in (THEME.rejected, THEME.result)
False
"""

from __future__ import annotations

from dataclasses import dataclass

from rendering.typeset import DEFAULT_FONT, DEFAULT_INK
from story.roles import ROLES


@dataclass(frozen=True)
class Theme:
    """Everything visual a scene needs besides geometry (colours as hex strings manim reads)."""

    background: str = "#10141c"
    called: str = "#4f8ff7"
    argument: str = "#f2b134"
    result: str = "#4cc46b"
    rejected: str = "#ef4b4b"
    idle: str = "#8a93a3"
    #: the candidates in T: one neutral colour, never a verdict's (amber, green and red are
    #: the claim's, chapter 2 lit them in all three)
    candidate: str = "#f59fd6"
    split: str = "#3ad6e0"  # a split vertex: a kind of vertex, never a verdict's red or green
    #: a merge vertex: likewise; a vivid magenta, far from the candidates' pale pink (chapter
    #: 2; CIE76 ΔE 61, hue 22° apart — the old #f06fe0 was 33 and 14°) and from the sweep
    #: line's lilac it is drawn beside in chapter 5 (ΔE 52, was 28)
    merge: str = "#ff4dff"
    stack: str = "#ffe45c"  # the monotone stack's waiting chain
    ink: str = DEFAULT_INK
    polygon_fill: str = "#2a3a55"
    water: str = "#3aa0ff"
    #: a deep violet: it reads on P's navy (CIE76 ΔE 55 as the screen shows it), on the
    #: fruit (87) and on prune and search's good sub-polygon over it (62); the orange
    #: #ff8c42 was the fruit's own colour (ΔE 30 on it), and stood on it unseen
    ball: str = "#6a3d9a"
    #: the rubber band and what it sweeps: a pale lemon, no role's (CIE76 ΔE 55 from the red of
    #: "fails" as both tint P at 0.6; the rose #ff5fa2 was 25, and its swept area read as
    #: failing, chapter 3 and the recap at 38 s); 30 from the stack's yellow
    band: str = "#f0f0a0"
    gravity: str = "#c7cfdb"
    #: tints of the figures' series and parts (the overview's, chapter 5's plot)
    pieces: tuple[str, ...] = ("#8e6cf0", "#2bb5a8", "#c9a25a", "#5b8fd5", "#9cbf4a")
    piece_opacity: float = 0.3
    #: the tints divide and conquer's parts and the monotone pieces take (neighbours unlike):
    #: the palette's but its blue and violet, which beside the part worked on (``called`` at
    #: :attr:`active_opacity`) read as its colour (CIE76 ΔE 21 and 18 as the screen shows
    #: them; teal 37, tan 47, olive 54): the part worked on was told from its neighbours only
    #: by a shade of blue (the scene at 72 s)
    part_tints: tuple[str, ...] = ("#2bb5a8", "#c9a25a", "#9cbf4a")
    #: the fills of a finished triangulation's triangles, in the result's green: two that
    #: share a side differ (:func:`metaphors.drawing.neighbour_shades`; a polygon's need two)
    triangle_shades: tuple[float, ...] = (0.5, 0.2, 0.75, 0.35)
    done_opacity: float = 0.62
    active_opacity: float = 0.5  # the piece divide and conquer works on
    #: the width of its outline in ``called``: drawn as it lights up (only gravity's turn
    #: drew it, a convex piece, which gravity does not turn, had none)
    active_stroke: float = 7.5
    hand: str = "#c792ea"  # the clock hand (drawn solid inside the polygon, dashed outside)
    sweep: str = "#c792ea"  # the sweep line (likewise)
    #: what a heuristic's tool (water, clock hand, sweep line) has swept on its way to its
    #: pick: one colour for all three, so that the same region means the same colour
    swept: str = "#8fc1ff"
    dial: str = "#8a93a3"  # the frame of a close-up (the clock draws no face: its hand only)
    fruit: str = "#f4a259"  # the fruit's flesh (ear clipping)
    #: its rind: a peel's brown, far from every role's colour (CIE76 ΔE 48 and more; the
    #: olive #7a9e3d was 29 from the result's green, and read as "yes" round the fruit)
    rind: str = "#8b5a2b"
    plate: str = "#d9dee7"  # where the slices go
    knife: str = "#f5f7fa"
    dash_length: float = 0.09
    font: str = DEFAULT_FONT
    mono_font: str = "DejaVu Sans Mono"
    stroke: float = 3.0
    thin_stroke: float = 1.5
    dot_radius: float = 0.06
    label_size: int = 22
    caption_size: int = 26
    pseudocode_size: int = 20  # the panel's pseudocode rows (a line about 3.4 % of the frame)
    title_size: int = 40
    fill_opacity: float = 0.35

    def role_colour(self, role: str) -> str:
        """Colour of a role name (one of :data:`ROLES`)."""
        if role not in ROLES:
            raise ValueError(f"unknown role {role!r}; expected one of {', '.join(ROLES)}")
        return getattr(self, role)


THEME = Theme()
