"""The ``trex`` command line: check, sample, and (later) diagonal, triangulate, log, render.

Importing this package is cheap: it never imports manim, so ``trex check``
answers without loading the video stack.
"""
