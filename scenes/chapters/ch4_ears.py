"""Lecture chapter 4: Ears.

Run: ``manim -pql scenes/chapters/ch4_ears.py``; the whole lecture: ``trex lecture``.
"""

from metaphors.figures import Figure
from metaphors.lecture import FRUIT_BOX, Card, LectureScene, Run
from story.registry import spoken


class Ears(LectureScene):
    chapter_title = "4. Ears"
    slug = "ears"

    def chapter_segments(self) -> tuple:
        return (
            Card("Ears: slicing fruit", (
                # V's triangle in words: "V−1 V V+1" read as arithmetic (review)
                "An ear: a convex vertex V whose triangle with its two neighbours",
                "holds no other vertex, so the neighbours' segment is an inner diagonal.",
                "Slice an ear off, put it on the plate, repeat until one triangle is left."),
                 Figure("ear")),
            Run("ear-clipping-naive", None, "Ear clipping (Meisters): slice the first ear found",
                box=FRUIT_BOX, speed=0.6),
            Card("The two-ears theorem (Meisters, 1975)", (
                "Every simple polygon with more than three vertices has two ears",
                "that do not overlap — so there is always a slice to cut.",
                "Testing every vertex: O(n²) for one ear, O(n³) for all."),
                 Figure("ears")),
            Card("Prune and search (ElGindy, Everett, Toussaint)", (
                "Test the middle vertex of a good sub-polygon (one cut edge).",
                "Not an ear? Its diagonal cuts off a smaller good sub-polygon — keep that half.",
                "About half the vertices go each time: one ear in O(n)."),
                 Figure("prune")),
            Run("prune-and-search", None, "Prune and search: the good sub-polygons shrink",
                box=FRUIT_BOX, speed=0.5),
            Card("How fast", (
                # the plot counts ear tests on random polygons: the words say what it counts
                # and the worst case apart (they said O(n³), O(n²), O(n) beside lines that
                # grew almost straight); one name for faster ear clipping, the later chapters'
                "An ear test looks at up to n vertices. Naive ear clipping may make O(n²) "
                "tests: O(n³) at worst.",
                "Faster ear clipping keeps each vertex's ear status: a slice retests its two "
                "neighbours, so O(n) tests, O(n²) in all.",
                "Prune and search: one ear in O(n). On the random polygons plotted, every "
                "count stays far under n²."),
                 Figure("growth")),
            Card("Fruit with holes: a keyhole cut", (
                "Real polygons have holes: the columns of a floor plan, a country's lakes.",
                "Cut from each hole's right-most vertex to a vertex it sees (Eberly, 2002):",
                "one ring again, with two vertices more per hole. Then slice as before."),
                 Figure("keyhole", "keyhole")),
            Run("ear-clipping", "keyhole",
                f"{spoken('ear-clipping', start=True)} with holes: keyholes, then slices",
                box=FRUIT_BOX, speed=0.5),
        )
