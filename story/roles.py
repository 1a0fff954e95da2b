"""The roles an object plays in a call, after the seed's viewer (colours: :mod:`metaphors.theme`).

The object a call runs on is *called*, its other inputs are *arguments* while it runs, what it
returns is the *result*, a refused object is *rejected*, everything else *idle*.
"""

ROLES = ("called", "argument", "result", "rejected", "idle")
