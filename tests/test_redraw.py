"""What manim redraws in every frame of a play: the scenes keep their text out of it.

manim draws the mobjects a play does not animate once, into the play's static image, and in
every frame redraws the rest: each mobject from the first animated one upwards (in z-index,
then insertion order). The board keeps its title, code, call line and subtitle at the bottom
(``Board.settle``), and lights a code row by laying a copy over it instead of recolouring the
row, so the code stays static in every play. These tests read the moving mobjects of each
play of real scenes built in dry run (:func:`trex.scene_graph.build`).
"""

from __future__ import annotations

import functools
import hashlib
from pathlib import Path

import numpy as np
import pytest
from manim import BLUE, RIGHT, Circle, FadeIn, Scene, Square, tempconfig
from manim.renderer.cairo_renderer import CairoRenderer

from metaphors.board import Board
from rendering.layers import BACKDROP_Z, STILL_Z
from rendering.renderer import BackdropRenderer
from trex.render_command import load_scene_class
from trex.scene_graph import build

SCENES = Path(__file__).resolve().parents[1] / "scenes"


def scene_class(file: str, name: str, panel: str = "pseudocode"):
    """The scene, handed its default run (whatever TREX_POLYGON and TREX_LOG say), its panel
    showing ``panel``."""
    return load_scene_class(SCENES / f"{file}.py", name).with_panel(panel).handed()


@functools.cache
def played(file: str, name: str, panel: str = "pseudocode"):
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
        build(scene_class(file, name, panel))
    return boards, moving


@pytest.mark.parametrize(("file", "name", "panel"), [
    ("gravity", "Gravity", "pseudocode"), ("scaling", "Scaling", "pseudocode"),
    ("ears", "Ears", "pseudocode"), ("scaling", "Scaling", "source")])
def test_code_and_title_are_never_redrawn_per_frame(file, name, panel):
    boards, moving = played(file, name, panel)
    board = boards[0]
    rows = {id(m) for m in board.panel.code.get_family()}
    assert len(rows) > 5 and len(moving) > 5
    written = next(k for k, ids in enumerate(moving) if id(board.title) in ids)  # Write(title)
    # the panel fades in with the title and the picture (its words never before them), then
    # stands still: neither is redrawn in a later play
    for k, ids in enumerate(moving[written + 1:], start=written + 1):
        assert not rows & ids, f"play {k}: code rows redrawn in every frame"
        assert id(board.title) not in ids, f"play {k}: the title redrawn in every frame"
    assert not any(rows & ids for ids in moving[:written]), "the panel came before the title"
    assert any(moving), "nothing moved: the hook saw no plays"


@pytest.mark.parametrize("mode", ["pseudocode", "source"])
def test_lit_row_is_a_copy_over_the_row(mode):
    boards, _ = played("gravity", "Gravity", mode)
    panel = boards[0].panel
    assert panel.mode == mode
    index, light, copy = panel.lit
    # a pseudocode row is one row; a source line one or more (it wraps), lit together
    rows, copies = ([panel.code[index]], [copy]) if mode == "pseudocode" else (
        panel.shown[index], list(copy))
    assert len(rows) == len(copies) >= 1
    for row, lit in zip(rows, copies, strict=True):
        assert np.array_equal(lit.points, row.points)
        assert lit.get_fill_color().to_hex().lower() == panel.theme.ink.lower()
        assert light.get_bottom()[1] < row.get_bottom()[1] < row.get_top()[1] < light.get_top()[1]
        assert light.z_index == lit.z_index == BACKDROP_Z > row.z_index  # over the grey row
    # the light lies behind the whole row: centred on it (a pseudocode row: on its line; a
    # source line: on the middle of its rows' slots)
    ys = [panel.line_y[index]] if mode == "pseudocode" else panel.slot_y[index]
    middle = (ys[0] + ys[-1]) / 2
    assert light.get_center()[1] == pytest.approx(middle)
    # the rows themselves stay grey: the light is the copy and the rectangle behind it
    assert {r.get_fill_color().to_hex().lower() for r in panel.code} == {panel.theme.idle.lower()}


def test_settle_puts_the_text_at_the_bottom():
    boards, _ = played("gravity", "Gravity")
    board = boards[0]
    scene_mobjects = board.scene.mobjects
    still = [board.title, board.panel.code]
    changing = [m for m in (*board.panel.changing(), board.subtitle) if m in scene_mobjects]
    assert scene_mobjects[:2 + len(changing)] == still + changing
    assert [m.z_index for m in still + changing] == [STILL_Z] * 2 + [BACKDROP_Z] * len(changing)


def frames(scene, media: str) -> list[tuple[str, int]]:
    """Render ``scene`` at 5 frames per second: a digest of every frame written, and its count."""
    written: list[tuple[str, int]] = []
    add_frame = CairoRenderer.add_frame

    def record(self, frame, num_frames=1):
        written.append((hashlib.sha256(frame.tobytes()).hexdigest(), num_frames))
        add_frame(self, frame, num_frames)

    settings = {"quality": "low_quality", "frame_rate": 5, "media_dir": media,
                "disable_caching": True, "progress_bar": "none",
                "verbosity": "WARNING"}
    with pytest.MonkeyPatch.context() as patch, tempconfig(settings):
        patch.setattr(CairoRenderer, "add_frame", record)
        scene().render()
    return written


def test_kept_backdrop_gives_the_same_pixels(tmp_path):
    """Every frame of a render with the backdrop kept equals manim's own, bit for bit."""
    Scaling = scene_class("scaling", "Scaling")
    renderers: list[BackdropRenderer] = []

    def ours():
        renderers.append(BackdropRenderer())
        return Scaling(renderer=renderers[-1])

    kept = frames(ours, str(tmp_path / "kept"))
    plain = frames(lambda: Scaling(renderer=CairoRenderer()), str(tmp_path / "plain"))
    assert len(kept) > 50 and kept == plain
    assert renderers[0].reused > 5  # the backdrop was really kept, not redrawn every play


class _ChangingBackdrop(Scene):
    """A bottom-layer square, then a change the kept pixels must notice, then another play."""

    change = "none"

    def construct(self):
        square = Square(3).set_stroke(BLUE, width=np.float32(2)).set_z_index(STILL_Z)
        self.add(square)
        self.play(FadeIn(Circle(0.3)), run_time=0.2)
        if self.change == "numpy scalar":  # a width given as a NumPy float32
            square.set_stroke(width=np.float32(30))
        elif self.change == "background":  # manim's own API; the colour attributes stay
            red = np.zeros_like(self.renderer.camera.background)
            red[..., 0] = red[..., 3] = 255
            self.renderer.camera.set_background(red)
        self.play(FadeIn(Circle(0.5).shift(2 * RIGHT)), run_time=0.2)


@pytest.mark.parametrize("change", ["numpy scalar", "background"])
def test_kept_backdrop_sees_every_change(tmp_path, change):
    scene = type("Changing", (_ChangingBackdrop,), {"change": change})
    kept = frames(lambda: scene(renderer=BackdropRenderer()), str(tmp_path / "kept"))
    plain = frames(lambda: scene(renderer=CairoRenderer()), str(tmp_path / "plain"))
    assert len(kept) >= 2 and kept == plain
