"""The roles an object plays in a call, after the seed's viewer (colours: :mod:`metaphors.theme`).

The object a call runs on is *called*, its other inputs are *arguments* while it runs, what it
returns is the *result*, a refused object is *rejected*, everything else *idle*. A vertex in T
a heuristic may pick is a *candidate* (neutral: neither claimed nor judged; the one it picks is
an *argument*, the claim to be, until the verdict makes it a *result* or *rejected*). Two roles
are kinds of vertex, not verdicts: a *split* or a *merge* vertex of the monotone sweep (so
a vertex kind never borrows the red of "fails").
"""

ROLES = ("called", "argument", "result", "rejected", "idle", "split", "merge", "candidate")
