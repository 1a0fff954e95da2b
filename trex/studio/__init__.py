"""``trex studio``: a local web app to draw a polygon and see every heuristic decide on it."""
