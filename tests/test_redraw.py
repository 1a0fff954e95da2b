"""What manim redraws in every frame of a play: the scenes keep their text out of it.

manim draws the mobjects a play does not animate once, into the play's static image, and in
every frame redraws the rest: each mobject from the first animated one upwards (in z-index,
then insertion order). The board keeps its title, code, call line and subtitle at the bottom
(``Board.settle``), and lights a code row by laying a copy over it instead of recolouring the
row, so the code stays static in every play. These tests read the moving mobjects of each
play of real scenes built in dry run (:func:`metaphors.snapshot.build`).
"""

from __future__ import annotations

import functools
import importlib.util
from pathlib import Path

import numpy as np
import pytest
from manim.renderer.cairo_renderer import CairoRenderer

from metaphors.board import Board
from metaphors.layout import BACKDROP_Z
from metaphors.snapshot import build

SCENES = Path(__file__).resolve().parents[1] / "scenes"


def scene_class(file: str, name: str):
    spec = importlib.util.spec_from_file_location(f"trex_redraw_{file}", SCENES / f"{file}.py")
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return getattr(module, name)


@functools.cache
def played(file: str, name: str):
    """Build the scene in dry run: (its boards, [set of ids of moving mobjects per play])."""
    moving: list[set[int]] = []
    boards: list[Board] = []
    play, init = CairoRenderer.play, Board.__init__

    def record_play(self, scene, *args, **kwargs):
        play(self, scene, *args, **kwargs)
        moving.append({id(m) for m in scene.moving_mobjects})

    def record_board(self, *args, **kwargs):
        init(self, *args, **kwargs)
        boards.append(self)

    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(CairoRenderer, "play", record_play)  # snapshot's GraphRenderer inherits it
        patch.setattr(Board, "__init__", record_board)
        build(scene_class(file, name), {"TREX_LOG": None, "TREX_POLYGON": None})
    return boards, moving


@pytest.mark.parametrize(("file", "name"), [("gravity", "Gravity"), ("scaling", "Scaling"),
                                            ("ears", "Ears")])
def test_code_and_title_are_never_redrawn_per_frame(file, name):
    boards, moving = played(file, name)
    board = boards[0]
    rows = {id(m) for m in board.panel.code.get_family()}
    assert len(rows) > 5 and len(moving) > 5
    for k, ids in enumerate(moving):
        assert not rows & ids, f"play {k}: code rows redrawn in every frame"
        if k > 0:
            assert id(board.title) not in ids, f"play {k}: the title redrawn in every frame"
    assert any(moving), "nothing moved: the hook saw no plays"


def test_lit_row_is_a_copy_over_the_row():
    boards, _ = played("gravity", "Gravity")
    panel = boards[0].panel
    index, copy = panel.lit
    row = panel.code[index]
    assert np.array_equal(copy.points, row.points)
    assert copy.get_fill_color().to_hex().lower() == panel.theme.ink.lower()
    # the rows themselves stay grey: the light is the copy and the rectangle behind it
    assert {r.get_fill_color().to_hex().lower() for r in panel.code} == {panel.theme.idle.lower()}


def test_settle_puts_the_text_at_the_bottom():
    boards, _ = played("gravity", "Gravity")
    board = boards[0]
    scene_mobjects = board.scene.mobjects
    backdrop = [m for m in (board.title, *board.panel.backdrop(), board.subtitle)
                if m in scene_mobjects]
    assert scene_mobjects[:len(backdrop)] == backdrop
    assert {m.z_index for m in backdrop} == {BACKDROP_Z}
