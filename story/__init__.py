"""The story of a run, without manim: the registry, runs, and the storyboard that turns a log
into beats (plain data a metaphor performs)."""
