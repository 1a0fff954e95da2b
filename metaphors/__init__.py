"""Manim side: theme, the algorithm panel, one module per metaphor, the storyboard."""
