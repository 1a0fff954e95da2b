"""The legend's candidates in every pass and card (tests/reading_rules.py): each rule fails on
a hand-made graph with the defect chapter 2 had (its plays as the dry run recorded them before
the fix) and passes on the mended one."""

from metaphors.theme import THEME
from tests.reading_rules import amber_figure_marks, named_candidates, unmarked_candidates

INTRO = "This polygon of 5 vertices defeats all three heuristics. Candidates: D, E."


def _said(caption: str, *anims: dict) -> dict:
    return {"animations": list(anims), "run_time": 1.0, "subcaption": caption}


def _still(*anims: dict) -> dict:
    return {"animations": list(anims), "run_time": 0.8, "subcaption": ""}


def _pulse(vertex: str, colour: str, role: str) -> dict:
    return {"type": "Indicate", "color": colour,
            "mobject": {"name": f"vertex:{vertex}", "role": role}}


def _recolour(vertex: str, colour: str, role: str) -> dict:
    return {"type": "_MethodAnimation", "mobject": {"name": f"vertex:{vertex}", "role": role},
            "target": {"stroke": colour}}


def test_the_captions_naming_candidates_are_read():
    assert named_candidates(INTRO) == ["D", "E"]
    assert named_candidates("The same polygon of 5 vertices. Candidates in T: D, E.") == ["D", "E"]
    assert named_candidates("Candidates inside T: E, F") == ["E", "F"]
    assert named_candidates("Water spilled at B spreads; the first candidate it wets is D") == []


def test_candidates_only_pulsed_pink_are_found():
    """Chapter 2's analyses: D and E pulsed pink for 0.8 s (their markers idle), then grey
    the 8.5 s the tool moved towards them."""
    plays = [_said(INTRO), _still(_pulse("D", THEME.candidate, "idle"),
                                  _pulse("E", THEME.candidate, "idle")),
             _said("Water spilled at B spreads; the first candidate it wets is D")]
    assert unmarked_candidates({"plays": plays}) == ["play 0 D: not kept pink",
                                                     "play 0 E: not kept pink"]


def test_candidates_kept_pink_pass():
    """Turned pink and kept (an analysis), or pulsed pink as candidates (a run's board keeps
    the colour it pulses in)."""
    analysis = [_said(INTRO), _still(_recolour("D", THEME.candidate, "candidate"),
                                     _recolour("E", THEME.candidate, "candidate"))]
    run = [_said("Candidates inside T: E, F"), _still(_pulse("E", THEME.candidate, "candidate"),
                                                      _pulse("F", THEME.candidate, "candidate"))]
    assert unmarked_candidates({"plays": analysis}) == []
    assert unmarked_candidates({"plays": run}) == []


def _card(title: str, *figure: dict) -> dict:
    return _said(title, {"type": "Write", "mobject": {"name": "card:title"}}, *figure)


def _mark(name: str, role: str, kind: str = "FadeIn") -> dict:
    return {"type": kind, "mobject": {"name": name, "role": role}}


def test_a_cards_pick_amber_with_its_title_is_found():
    """The water card drew D amber (named a candidate) with its title, 3 s before the line
    that names it; gravity's card named the vertex its step works on a candidate."""
    plays = [_card("Scaling: spilled water", _mark("figure:tool", "argument"),
                   _mark("figure:candidate", "argument")),
             _said("Spill water at B: it spreads as a growing circle.",
                   _mark("card:line", None)),
             _said("The first candidate it wets is D, the nearest one.",
                   _mark("card:line", None))]
    assert amber_figure_marks({"plays": plays}) == [
        "play 0: figure:candidate amber",
        "play 0: figure:candidate amber with the title 'Scaling: spilled water'"]


def test_a_cards_candidates_pink_and_its_pick_with_its_line_pass():
    plays = [_card("Scaling: spilled water", _mark("figure:candidate", "candidate"),
                   _mark("figure:candidate", "candidate")),
             _said("Spill water at B: it spreads as a growing circle.",
                   _mark("card:line", None), _mark("figure:tool", "argument",
                                                   "UpdateFromAlphaFunc")),
             _said("The first candidate it wets is D, the nearest one.",
                   _mark("card:line", None), _mark("figure:pick", "argument"))]
    assert amber_figure_marks({"plays": plays}) == []
