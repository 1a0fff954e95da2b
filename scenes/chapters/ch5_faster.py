"""Lecture chapter 5: Faster algorithms.

Run: ``manim -pql scenes/chapters/ch5_faster.py``; the whole lecture: ``trex lecture``.
"""

from metaphors.figures import Figure
from metaphors.lecture import Card, Compare, LectureScene, Run


class Faster(LectureScene):
    chapter_title = "5. Faster algorithms"
    slug = "faster"

    def chapter_segments(self) -> tuple:
        return (
            # y-monotone said and drawn (the line meeting P twice) before it is used; split
            # and merge are the run's to teach, on the picture, when the sweep meets them
            Card("Garey, Johnson, Preparata, Tarjan (1978)", (
                "y-monotone: every horizontal line meets the polygon in one segment, or none.",
                "Cut P into y-monotone pieces with a line swept down, in O(n log n);",
                "a stack triangulates each piece in linear time: O(n log n) in all.",
                "The sweep shown next is the textbooks' later telling of their cut."),
                 Figure("monotone-pieces")),
            Run("monotone", None, "Monotone partition, then the stack", speed=0.7),
            # the plot's words: which polygons were counted, and what each line shows (it
            # showed random polygons only, where faster ear clipping keeps pace with
            # monotone partition, while the chapter set O(n²) against O(n log n)); two lines
            # now, the half discs' (six lines and a legend table read as crowded): the random
            # polygons' result and the bounds are said, not drawn
            Card("Tarjan and van Wyk (1988), Chazelle (1990)", (
                "Counted on dented half discs: faster ear clipping grows as n², monotone "
                "partition as n log n;",
                "on random polygons, not drawn, the two keep pace.",
                "O(n log log n): Tarjan and van Wyk; Kirkpatrick et al. matched it simply "
                "(1990).",
                "Chazelle: O(n), not practical. Neither runs here."),
                 Figure("measured")),
            # one sentence a bullet; libraries by their own names (Shapely, Mapbox's earcut)
            Card("Constrained Delaunay", (
                "It keeps the polygon's edges, and each triangle's circumcircle holds no "
                "vertex seen from inside the triangle.",
                "Our reference here: GEOS, through Shapely.",
                "Mapbox's earcut, another library, clips ears instead."),
                 Figure("delaunay-circle")),
            Compare(None),
        )
