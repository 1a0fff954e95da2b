"""The role and name a mobject carries, which scene graphs report (:mod:`trex.scene_graph`)."""

from __future__ import annotations


def tag(mobject, role: str | None = None, name: str | None = None):
    """Attach the role (and a name) a snapshot reports for a mobject; returns it.

    >>> class Thing: ...
    >>> t = tag(Thing(), "result", "claim")
    >>> t.trex_role, t.name
    ('result', 'claim')
    """
    mobject.trex_role = role
    if name:
        mobject.name = name
    return mobject


def role_of(mobject: object) -> str | None:
    """The role :func:`tag` gave a mobject (None: none, or never tagged).

    >>> role_of(tag(type("Thing", (), {})(), "result")), role_of(object())
    ('result', None)
    """
    role: str | None = getattr(mobject, "trex_role", None)
    return role
