"""Typed shape states (story/states.py) and the one lookup of a log's references
(story/refs.py): the metaphors' beats carry records, the analysis matches on their type, and
a log that lacks an argument a reading needs fails with one line naming the function and the
parameter."""

from __future__ import annotations

from dataclasses import replace

import pytest

import tracing
from geometry.diagonals import find_diagonal
from geometry.errors import GeometryError, LogFormatError
from geometry.polygon import Polygon
from geometry.samples import make_sample
from metaphors import clock, gravity, sweep, water
from metaphors.catalog import beats
from story.analysis import Motion, motion
from story.refs import arg, ref, ref_list, result_ref, result_refs
from story.states import BallSlide, Disk, Hand, Line, Moving, RubberBand, Tide
from story.storyboard import storyboard
from tracing import Event, Log

COUNTEREXAMPLE = Polygon.from_points(make_sample("counterexample"))
AT = dict(zip(COUNTEREXAMPLE.labels, COUNTEREXAMPLE.points, strict=True))
T = [(1.6, 8.0), (1.0, 4.5), (9.0, 2.0)]


def _log(heuristic: str, polygon: Polygon = COUNTEREXAMPLE) -> Log:
    with tracing.record(algorithm=heuristic) as log:
        find_diagonal(polygon, heuristic)
    return log


def _moving(heuristic: str) -> Moving:
    return next(b for b in beats(_log(heuristic)) if isinstance(b, Moving))


# --- the records the beats carry ---------------------------------------------------------------


@pytest.mark.parametrize(("heuristic", "record"), [
    ("scaling", Disk), ("scaling-walled", Disk), ("rotation", Hand), ("rotation-ccw", Hand),
    ("rotation-correct", Hand), ("translation", Line), ("translation-correct", Line),
    ("scaling-correct", Tide)])
def test_a_metaphors_step_carries_records_of_its_tool(heuristic, record):
    beat = _moving(heuristic)
    assert isinstance(beat.states, tuple) and beat.states
    assert all(type(s) is record for s in beat.states), heuristic
    first, *reached = beat.states
    assert first.reached is None and all(s.reached for s in reached)
    assert beat.at_pick() is not None and beat.at_pick().reached == beat.result


def test_the_water_starts_dry_and_grows_through_each_candidate():
    beat = _moving("scaling")
    assert isinstance(beat, water.Water)
    radii = [s.radius for s in beat.states]
    assert radii[0] == 0.0 and radii[1:] == sorted(radii[1:]) and radii[1] > 0
    assert {s.center for s in beat.states} == {AT["B"]}  # all spilled at B


def test_the_tide_keeps_its_shore_and_rises():
    beat = _moving("scaling-correct")
    assert isinstance(beat, water.Flood)
    assert {s.shore for s in beat.states} == {(AT["A"], AT["C"])}  # A and C
    assert beat.states[0].level == 0.0 and beat.states[-1].reached == beat.result


def test_the_clock_and_the_line_are_their_own_records():
    assert isinstance(_moving("rotation"), clock.Clock)
    assert isinstance(_moving("translation"), sweep.Sweep)
    hand = _moving("rotation").states[1]
    assert hand.angle > 0 and not hasattr(hand, "radius")


def test_gravity_carries_the_ball_and_the_rubber_band():
    polygon = Polygon.from_points(make_sample("gravity-snag"))
    shown = {b.action: b for b in beats(_log("gravity", polygon))}
    assert shown["drop"].drop.vertex == "C"
    assert isinstance(shown["slide"].slide, BallSlide)
    band = shown["snag"].band
    assert isinstance(band, RubberBand) and band.snagged and len(band.corners) == 3
    assert shown["snag"].snagged == "H"


def test_a_straight_band_is_told_by_none_not_by_its_display_form():
    # band_snag returned None: the band stays straight, with no corner at a vertex "—"
    polygon = Polygon.from_points(make_sample("gravity-snag"))
    log = _log("gravity", polygon)
    (ret,) = log.find(kind="return", name="band_snag")
    call = log.events[ret.call]
    straight = Log(meta=dict(log.meta), events=[
        replace(e, result=None) if e is ret else e for e in log.events])
    (snag,) = [b for b in storyboard(straight, readings=gravity.READS)
               if isinstance(b, gravity.Snag)]
    assert snag.snagged is None and snag.caption == "The rubber band stays straight"
    assert snag.band == RubberBand(corners=tuple(
        tuple(p) for p in (polygon.points[polygon.labels.index(ref(call, "v"))],
                           polygon.points[polygon.labels.index(ref(call, "x"))])))
    assert not snag.band.snagged


# --- one motion per record, matched on its type ------------------------------------------------


@pytest.mark.parametrize("state", [
    Disk(center=(1.0, 4.5), radius=2.83, reached="D"),
    Hand(origin=(9.0, 2.0), heading=162.6, angle=8.16, reached="E"),
    Line(through=(1.0, 4.5), direction=(7.4, -6.0), offset=1.9566, reached="E"),
    Tide(shore=((1.6, 8.0), (9.0, 2.0)), towards=(1.0, 4.5), level=1.14, reached="E")])
def test_each_record_makes_its_motion(state):
    m = motion(state, T)
    assert isinstance(m, Motion) and m.state is state and m.reached == state.reached
    assert m.rising == isinstance(state, Tide)
    assert not m.tool(0.5).is_empty and m.swept(1.0).area > 0


def test_a_motion_of_something_else_is_refused():
    with pytest.raises(TypeError, match="no motion"):
        motion(RubberBand(corners=((0.0, 0.0), (1.0, 1.0))), T)


# --- one lookup of a log's references --------------------------------------------------------


CALL = Event(3, "call", "nearest_to", None,
             {"b": {"ref": "B"}, "candidates": [{"ref": "D"}, {"ref": "E"}], "k": 2}, call=3)


def test_ref_reads_arguments_and_results():
    assert ref(CALL, "b") == "B" and ref_list(CALL, "candidates") == ["D", "E"]
    assert arg(CALL, "k") == 2
    ret = Event(4, "return", "nearest_to", result={"ref": "D"}, call=3)
    assert result_ref(ret) == "D"
    assert result_refs(replace(ret, result=[{"ref": "P(AB)"}])) == ["P(AB)"]


@pytest.mark.parametrize(("lookup", "words"), [
    (lambda: ref(CALL, "v"), "the log's call of nearest_to has no argument 'v'"),
    (lambda: ref(CALL, "k"), "nearest_to: argument 'k' is not an object of the log"),
    (lambda: ref_list(CALL, "b"), "nearest_to: argument 'b' is not a list"),
    (lambda: result_ref(Event(4, "return", "claim", result=None, call=3)),
     "the log's return of claim: its result is not an object of the log")])
def test_a_missing_or_wrong_reference_is_one_line_naming_function_and_parameter(lookup, words):
    with pytest.raises(LogFormatError) as raised:
        lookup()
    assert str(raised.value) == words or words in str(raised.value)
    assert "\n" not in str(raised.value) and isinstance(raised.value, GeometryError)


def test_a_log_whose_parameter_was_renamed_fails_in_the_reading_by_name():
    # water reads nearest_to's B by its parameter name; a log with another name says so
    log = _log("scaling")
    renamed = Log(meta=dict(log.meta), events=[
        replace(e, args={("centre" if k == "b" else k): v for k, v in e.args.items()})
        if e.kind == "call" and e.name == "nearest_to" else e for e in log.events])
    with pytest.raises(LogFormatError, match="call of nearest_to has no argument 'b'"):
        storyboard(renamed, readings=water.READS)


def test_a_saved_log_with_a_renamed_parameter_is_refused_in_one_line():
    # what trex player/snapshot/slides say of such a --log, before anything is drawn
    from scenes.scaling import Scaling
    from trex.scene_inputs import check_log

    log = _log("scaling")
    renamed = Log(meta=dict(log.meta), events=[
        replace(e, args={("centre" if k == "b" else k): v for k, v in e.args.items()})
        if e.kind == "call" and e.name == "nearest_to" else e for e in log.events])
    with pytest.raises(ValueError) as refused:
        check_log(Scaling, renamed)
    assert str(refused.value) == ("cannot be played: LogFormatError: the log's call of "
                                  "nearest_to has no argument 'b'")
