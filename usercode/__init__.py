"""The user's code in a room of its own: heuristics of one's own, ``path/to/file.py:function``.

A user's heuristic is a function that takes a :class:`~geometry.polygon.Polygon` and returns
the diagonal it claims. Everything that touches the user's code lives here, one module per
job, so that geometry holds only geometry:

- :mod:`usercode.errors`: the one-line errors (:class:`~usercode.errors.UserHeuristicError`,
  :class:`~usercode.errors.UserHeuristicExit`) and how an exception of the user's is told;
- :mod:`usercode.loading`: the file run as a fresh module (its folder on ``sys.path``);
- :mod:`usercode.rewriting`: its function's ``return`` statements rewritten to note their
  line, so the claim is stated on the line that ran;
- :mod:`usercode.limits`: the time limit (SIGALRM), its prints moved to stderr, and how an
  exit or interrupt of its own is told from a real one;
- :mod:`usercode.checking`: its answer read as two vertices of the polygon, or refused;
- :mod:`usercode.heuristic`: all of them together, the loaded heuristic that runs like ours.

The source the panel shows (:func:`story.source.shown_source`) is the story's, not this
room's. It imports geometry and tracing only; the story, the metaphors and trex import it.
No manim here.
"""
