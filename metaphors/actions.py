"""Which performer plays which beat action. A beat with no performer plays as a caption only."""

from __future__ import annotations

from metaphors import basics, clock, fruit, generic, gravity, monotone, sweep, water

PERFORMERS = {
    "polygon": basics.polygon,
    "pick": basics.pick,
    "triangle": basics.triangle,
    "candidates": basics.candidates,
    "claim": basics.claim,
    "verdict": gravity.verdict,  # the shared verdict, then a turned picture turns back
    "note": basics.note,
    "water": water.water,
    "walled-water": water.walled_water,
    "flood": water.flood,
    "gravity-turn": gravity.gravity_turn,
    "drop": gravity.drop,
    "slide": gravity.slide,
    "snag": gravity.snag,
    "split": gravity.split,
    "clock": clock.clock,
    "sweep": sweep.sweep,
    "call": generic.call,  # a heuristic of one's own: its traced calls and shapes
    "shape": generic.shape,
    "ear-test": fruit.ear_test,
    "clip": fruit.clip,
    "last-slice": fruit.last_slice,
    "good": fruit.good,
    "classify": monotone.classify,
    "monotone-diagonal": monotone.monotone_diagonal,
    "pieces": monotone.pieces,
    "stack": monotone.stack,
}


def perform(board, beat) -> None:
    """Play one beat on the board."""
    PERFORMERS.get(beat.action, basics.note)(board, beat)
