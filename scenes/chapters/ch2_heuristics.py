"""Lecture chapter 2: Inner diagonals: water, clock, sweep.

Each wrong heuristic is shown once (issue 22 item 4): its card with its metaphor drawn, then
one continuous pass on the counterexample — the metaphor runs and freezes at the decisive
moment, the part outside P turns red, the crossed edge flashes and is named, and its
correction runs on the same polygon, inside P (:mod:`metaphors.analysis`). No run on another
polygon comes between: the card already shows the motion, so a second run of it would tell the
same idea twice. Nothing is replayed.

Run: ``manim -pql scenes/chapters/ch2_heuristics.py``; the whole lecture: ``trex lecture``.
"""

from metaphors.figures import Figure, ringed_reflex
from metaphors.lecture import Analysis, Card, LectureScene
from story.registry import SPOKEN, entry

#: the polygon that defeats all three wrong heuristics
COUNTEREXAMPLE = "counterexample"
#: the pass opens on the frame: the first time with what this polygon is (said once, not per
#: heuristic) and why five is the fewest (tests/test_diagonals.py checks that no quadrilateral
#: defeats any rule), then as the same polygon: every card and pass of the chapter draws it
INTRO_FIRST = ("This polygon of {n} vertices defeats all three heuristics; no smaller one can: "
               "with four, T holds one candidate at most. Candidates: {candidates}.")
INTRO_AGAIN = "The same polygon of {n} vertices. Candidates in T: {candidates}."
#: seconds each tool takes to its pick, and the picture holds at the decisive moments: the
#: pass is shown once, so it is shown slowly
SLOW, FREEZE = 8.5, 3.5

#: The wrong heuristic of each metaphor: the card of its metaphor, and what its analysis says
#: on the counterexample — as the part outside P turns red, and why its correction (the
#: registry's) holds. The family is named after the metaphor.
FAMILIES = (
    ("scaling",
     ("Spill water at B: it spreads as a growing circle.",
      "The first candidate it wets is picked: the nearest one."),
     "Red: the water outside P but inside T. It wets {pick} from outside P.",
     "Still dry as {pick} goes under: no vertex, so no wall. {claim} is inside P."),
    ("rotation",
     ("Put a clock at B, set the hand to A and let it turn towards C.",
      "The first candidate the hand passes is picked."),
     "Red: the hand outside P. That part passes {pick} first.",
     "From C, the hand meets {pick} before any part of it in T leaves P."),
    ("translation",
     ("Sweep a vertical line from B to the right.",
      "The first candidate it touches is picked: the left-most."),
     "Red: the line outside P but inside T. That part touches {pick} first.",
     # Correct Scaling's pick too (tests/test_diagonals.py): the same rule, two pictures
     "Parallel to AC, the line meets {pick} before any part of it in T leaves P. "
     "{pick} is the farthest from AC: Correct Scaling's pick too."),
)


def family_segments(family: tuple, intro: str = INTRO_AGAIN) -> tuple:
    """A wrong heuristic's segments: its card (its metaphor drawn at B) and the one pass on
    the counterexample that ends on its correction."""
    wrong, metaphor, fails, holds = family
    known = entry(wrong)
    if known.correct or known.correction is None:
        raise ValueError(f"{wrong} is no wrong heuristic with a correction")
    said = SPOKEN[wrong]  # each name said with its picture the first time: its card
    return (
        Card(f"{said.name}: {said.picture}", metaphor,
             Figure("metaphor", COUNTEREXAMPLE, heuristic=wrong)),
        Analysis(wrong, COUNTEREXAMPLE, fails=fails, holds=holds, intro=intro, slow=SLOW,
                 freeze=FREEZE),
    )


class Heuristics(LectureScene):
    chapter_title = "2. Inner diagonals: water, clock, sweep"
    slug = "heuristics"
    teacher_notes = (
        Card("The wrong heuristics first", (
            "Let students propose a way to find D before showing any.",
            "Almost everyone proposes the nearest or the left-most vertex.",
            "The counterexample needs only five vertices: draw it on the board.")),
        Card("Metaphors", (
            "Water, a clock, a sweeping line: each wrong heuristic is a familiar motion.",
            "Ask where the motion leaves the polygon — that is the bug.",
            "The corrections move only inside T, up to the first candidate: inside P.")),
        Card("From metaphor to proof", (
            "Kinesthetic heuristics are fast to invent and easy to get wrong.",
            "Ask for the invariant: what does the water, hand or line never cross?",
            "Then write the proof with that invariant.")),
    )

    def chapter_segments(self) -> tuple:
        # the figure rings a reflex vertex: a line says what the ring marks, as it comes in
        # (it stood unspoken of beside "Convex", chapter 2 at 2 s)
        reflex = ringed_reflex(self.lecture_polygon())
        frame = Card("The frame every heuristic shares", (
            "B: the left-most vertex, always convex: P lies to its right.",
            *([f"{reflex} is reflex: its angle inside P is over 180°."]
              if reflex else []),
            "A and C: its neighbours; T = triangle ABC.",
            # the figure's own names: its D is a reflex vertex outside T, its candidates G, H
            "No other vertex in T: AC is an inner diagonal.",
            # the dashed amber BG is a claim, and the card says what decides it ("say G: is
            # BG inner?" asked it and nothing answered, review of chapter 2)
            "Else claim BG: inner only if the candidate G is picked well. "
            "Each heuristic picks G its own way."),
            Figure("frame"))
        families = [family_segments(f, INTRO_FIRST if k == 0 else INTRO_AGAIN)
                    for k, f in enumerate(FAMILIES)]
        return (frame, *[s for segments in families for s in segments])
