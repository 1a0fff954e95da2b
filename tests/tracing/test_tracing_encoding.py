"""encode(): the argument/result/state encoding rules."""

import enum
from dataclasses import dataclass

import pytest

import tracing
from tracing import encode


class Vertex:
    def __init__(self, label: str) -> None:
        self.trace_key = label

    def trace_state(self) -> dict:
        return {"kind": "point", "at": [0, 0]}


class FakeScalar:
    """Behaves like numpy.float64: zero-dimensional with .item()."""

    ndim = 0

    def __init__(self, value):
        self.value = value

    def item(self):
        return self.value


class FakeArray:
    """Behaves like a 1-d numpy array: has .item() but more than zero dimensions."""

    ndim = 1

    def item(self):
        raise AssertionError("must not be called")


class Colour(enum.IntEnum):
    RED = 1


class Label(str):
    pass


@dataclass
class Hit:
    vertex: Vertex
    at: tuple
    t: float


@pytest.mark.parametrize("value", [None, True, False, 0, -5, 2**80, "", "É"])
def test_plain_values_pass_through(value):
    assert encode(value) is value


@pytest.mark.parametrize(
    ("value", "expected"),
    [
        (1.5, 1.5),
        (-0.0, -0.0),
        (float("nan"), "nan"),
        (float("inf"), "inf"),
        (float("-inf"), "-inf"),
    ],
)
def test_floats(value, expected):
    assert encode(value) == expected
    assert type(encode(value)) is type(expected)


def test_containers_are_encoded_recursively():
    assert encode((1, [2, (3.0, None)], {"k": (Vertex("B"),)})) == [
        1, [2, [3.0, None]], {"k": [{"ref": "B"}]},
    ]  # fmt: skip


def test_traceable_becomes_a_ref():
    assert encode(Vertex("W(B)")) == {"ref": "W(B)"}


def test_trace_key_that_is_not_a_string_is_ignored():
    class Odd:
        trace_key = 5

    assert encode(Odd()) == {"type": "Odd"}


def test_dict_with_non_string_keys_is_a_type():
    assert encode({1: "a"}) == {"type": "dict"}


def test_dataclass_becomes_dict_of_fields():
    assert encode(Hit(Vertex("D"), (1, 2), float("inf"))) == {
        "vertex": {"ref": "D"}, "at": [1, 2], "t": "inf",
    }  # fmt: skip


def test_dataclass_class_itself_is_a_type():
    assert encode(Hit) == {"type": "type"}


def test_numpy_like_scalar_uses_item():
    assert encode(FakeScalar(2.5)) == 2.5
    assert encode(FakeScalar(float("nan"))) == "nan"
    assert encode(FakeScalar(7)) == 7


def test_numpy_like_array_is_a_type():
    assert encode(FakeArray()) == {"type": "FakeArray"}


def test_subclasses_of_plain_types_become_plain():
    assert encode(Colour.RED) == 1
    assert type(encode(Colour.RED)) is int
    assert type(encode(Label("A"))) is str


def test_anything_else_is_its_type_name_never_its_repr():
    class Secret:
        def __repr__(self):
            return "<Secret at 0xdeadbeef>"

    assert encode(Secret()) == {"type": "Secret"}
    assert encode({1, 2}) == {"type": "set"}
    assert encode(len) == {"type": "builtin_function_or_method"}
    assert encode(b"x") == {"type": "bytes"}


def test_cycles_are_cut():
    loop: list = []
    loop.append(loop)
    encoded = encode(loop)
    depth = 0
    while isinstance(encoded, list):
        encoded, depth = encoded[0], depth + 1
    assert encoded == {"type": "list"}
    assert depth == tracing.encoding.MAX_DEPTH


def test_encode_copies_containers():
    point = [1.0, 2.0]
    encoded = encode({"at": point})
    point[0] = 9.0
    assert encoded == {"at": [1.0, 2.0]}


def test_traceable_protocol():
    assert isinstance(Vertex("A"), tracing.Traceable)
    assert isinstance(tracing.Shape("S", "point"), tracing.Traceable)
    assert not isinstance(object(), tracing.Traceable)
