"""The manim side: theme, layout, the board and its panel, the play loop, one module per
metaphor (its beat kinds, what it reads from the log, how it plays) and the scenes' base
classes."""
