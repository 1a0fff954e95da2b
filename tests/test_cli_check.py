"""``trex check`` and ``trex sample``: one line per polygon, one line per error, exit 2."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest
from click.testing import CliRunner

from geometry.io import MAX_FILE_BYTES, MAX_VERTICES
from geometry.samples import make_sample
from trex.cli import main

ROOT = Path(__file__).resolve().parent.parent
BAD = ROOT / "tests" / "data" / "bad"
BAD_INPUTS = [*sorted(p.name for p in BAD.iterdir()), "missing.json"]
COUNTER_LINE = "valid, 5 vertices, counter-clockwise, area 12.52, 1 reflex vertex (E)"


def invoke(*args: str):
    return CliRunner().invoke(main, list(args))


def trex(*args: str, cwd: Path = ROOT) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "trex", *args], capture_output=True, text=True, cwd=cwd
    )


def assert_one_error_line(stderr: str, prefix: str) -> None:
    assert "Traceback" not in stderr
    lines = stderr.splitlines()
    assert len(lines) == 1, stderr
    assert lines[0].startswith(prefix), stderr


# --- valid polygons -------------------------------------------------------------


def test_counterexample_summary():
    result = invoke("check", "counterexample")
    assert result.exit_code == 0
    assert result.stdout == f"counterexample: {COUNTER_LINE}\n"
    assert result.stderr == ""


def test_orientation_is_as_given():
    assert ", clockwise," in invoke("check", "counterexample-twin").stdout


def test_convex_and_plural_wording():
    assert invoke("check", "square").stdout.endswith("area 1, 0 reflex vertices (convex)\n")
    assert "5 reflex vertices (D, G, H, K, M)" in invoke("check", "lecture").stdout


def test_many_reflex_labels_are_truncated():
    out = invoke("check", "comb:100").stdout
    assert out.endswith("48 reflex vertices (F, G, J, K, N, O, R, S, … 40 more)\n")


def test_files_and_warnings(tmp_path):
    path = tmp_path / "c.json"
    path.write_text("[[0.4, 2.5], [7, 1], [7, 1], [4, 3.5], [4.4, 2.2], [0.8, 7], [0.4, 2.5]]")
    result = invoke("check", str(path))
    assert result.exit_code == 0
    assert result.stdout == f"{path}: {COUNTER_LINE}\n"
    assert result.stderr == f"warning: {path}: dropped 1 repeated consecutive point\n"


def test_valid_and_invalid_together():
    result = invoke("check", "square", str(BAD / "bow-tie.json"), "lecture")
    assert result.exit_code == 2
    assert [line.split(":")[0] for line in result.stdout.splitlines()] == ["square", "lecture"]
    assert_one_error_line(result.stderr, f"error: {BAD / 'bow-tie.json'}: edges B–C and D–A")


# --- every bad input: exit 2, one line, no traceback ----------------------------


@pytest.mark.parametrize("name", BAD_INPUTS)
def test_bad_input_in_process(name):
    result = invoke("check", str(BAD / name))
    assert result.exit_code == 2
    assert result.stdout == ""
    assert_one_error_line(result.stderr, f"error: {BAD / name}: ")


@pytest.mark.parametrize("name", BAD_INPUTS)
def test_bad_input_in_a_subprocess(name):
    result = trex("check", f"tests/data/bad/{name}")
    assert result.returncode == 2
    assert result.stdout == ""
    assert_one_error_line(result.stderr, f"error: tests/data/bad/{name}: ")


def test_all_bad_inputs_at_once_with_the_console_script():
    script = Path(sys.executable).with_name("trex")
    if not script.exists():
        pytest.skip("trex console script not installed (pip install -e .)")
    args = [f"tests/data/bad/{name}" for name in BAD_INPUTS]
    result = subprocess.run([script, "check", *args], capture_output=True, text=True, cwd=ROOT)
    assert result.returncode == 2
    assert "Traceback" not in result.stderr
    lines = result.stderr.splitlines()
    assert [line.split(": ")[1] for line in lines] == args
    assert all(line.startswith("error: ") for line in lines)


def test_unexpected_read_errors_become_one_line(monkeypatch):
    def explode(arg):
        raise ValueError("shapely said no\nand more")

    monkeypatch.setattr("trex.inputs.read_any_polygon", explode)
    result = invoke("check", "square")
    assert result.exit_code == 2
    assert result.stderr == "error: square: shapely said no\n"


# --- usage errors ----------------------------------------------------------------


@pytest.mark.parametrize(
    ("args", "fragment"),
    [
        (("check",), "error: Missing"),
        (("frobnicate",), "error: No such command 'frobnicate'"),
        (("sample", "star", "--n", "many"), "error: Invalid value for '-n' / '--n': 'many'"),
        (("check", "--bogus", "square"), "error: No such option"),
    ],
)
def test_usage_errors_are_one_line(args, fragment):
    result = trex(*args)
    assert result.returncode == 2
    assert_one_error_line(result.stderr, fragment)


def test_bare_trex_prints_help_and_exits_2():
    result = trex()
    assert result.returncode == 2
    assert result.stdout.startswith("Usage: trex")
    assert result.stderr == ""


def test_help_still_works():
    result = trex("check", "--help")
    assert result.returncode == 0
    assert "POLYGON" in result.stdout


# --- trex sample -------------------------------------------------------------------


def test_sample_to_stdout():
    result = invoke("sample", "random-star", "--n", "9", "--seed", "4")
    assert result.exit_code == 0
    assert json.loads(result.stdout) == [list(p) for p in make_sample("random-star", 9, 4)]


@pytest.mark.parametrize("suffix", [".json", ".wkt", ".geojson", ".dat"])
def test_sample_to_file_then_check(tmp_path, suffix):
    path = tmp_path / f"lecture{suffix}"
    assert invoke("sample", "lecture", "-o", str(path)).exit_code == 0
    result = invoke("check", str(path))
    assert result.exit_code == 0
    assert "valid, 13 vertices" in result.stdout


@pytest.mark.parametrize(
    ("args", "fragment"),
    [
        (("sample", "nope"), "error: unknown sample 'nope'; known: comb"),
        (("sample", "comb", "-n", "3"), "error: sample comb needs n ≥ 12, got 3"),
        (("sample", "square", "-o", "out.xyz"), "error: out.xyz: unknown format '.xyz'"),
        (("sample", "square", "-o", "/no/such/dir/x.json"), "error: /no/such/dir/x.json: no such directory: /no/such/dir"),
    ],
)
def test_sample_errors(args, fragment):
    result = invoke(*args)
    assert result.exit_code == 2
    assert_one_error_line(result.stderr, fragment)


# --- light imports -------------------------------------------------------------------


def test_check_does_not_import_manim():
    code = (
        "import sys\n"
        "from click.testing import CliRunner\n"
        "from trex.cli import main\n"
        "result = CliRunner().invoke(main, ['check', 'lecture'])\n"
        "assert result.exit_code == 0, result.output\n"
        "print(sorted(m for m in sys.modules if m.split('.')[0] in ('manim', 'manimpango')))\n"
    )
    result = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, check=True
    )
    assert result.stdout.strip() == "[]"


def test_python_dash_m_trex_cli():
    result = subprocess.run(
        [sys.executable, "-m", "trex.cli", "check", "square"],
        capture_output=True,
        text=True,
        cwd=ROOT,
    )
    assert result.returncode == 0
    assert result.stdout.startswith("square: valid, 4 vertices")


# --- areas beyond a float's range (issue 24 items 2 and 14) ------------------------


@pytest.mark.parametrize(("points", "area"), [
    ([[0, 0], [4e300, 0], [4e300, 4e300], [2e300, 1e300], [0, 4e300]], "1e+601"),
    ([[-1.7e308, -1.7e308], [1.7e308, -1.7e308], [1.7e308, 1.7e308], [-1.7e308, 1.7e308]],
     "1.156e+617"),
    ([[0, 0], [1e300, 0], [1e300, 1e300], [0, 1e300]], "1e+600"),
])
def test_check_gives_huge_areas_exactly_without_warnings(tmp_path, points, area):
    path = tmp_path / "huge.json"
    path.write_text(json.dumps(points))
    result = trex("check", str(path))
    assert result.returncode == 0, result.stderr
    assert result.stderr == ""
    assert f", area {area}, " in result.stdout


def test_check_of_an_empty_argument_says_so():
    result = trex("check", "")
    assert result.returncode == 2
    assert_one_error_line(result.stderr, "error: ")
    assert "directory" not in result.stderr
    assert "empty" in result.stderr


# --- the readers' robustness (issue 24 items 12 and 14) -----------------------------


@pytest.mark.parametrize(("name", "text", "message"), [
    ("curve.wkt", "CURVEPOLYGON (CIRCULARSTRING (0 0, 1 1, 2 0, 1 -1, 0 0))",
     "WKT CURVEPOLYGON is not supported"),
    ("nan.wkt", "POLYGON ((0 0, nan 0, 0 1, 0 0))", "NaN"),
    ("inf.wkt", "POLYGON ((0 0, 1e999 0, 0 1, 0 0))", "+inf"),
    ("digits.wkt", f"POLYGON ((0 0, 1{'0' * 5000} 0, 0 1, 0 0))", "+inf"),
])
def test_check_reports_unreadable_wkt_in_one_line(tmp_path, name, text, message):
    (tmp_path / name).write_text(text)
    result = trex("check", str(tmp_path / name))
    assert result.returncode == 2
    assert_one_error_line(result.stderr, f"error: {tmp_path / name}: ")
    assert message in result.stderr


def test_check_refuses_files_that_never_end(tmp_path):
    (tmp_path / "zero.json").symlink_to("/dev/zero")
    os.mkfifo(tmp_path / "fifo.json")
    for name in ("zero.json", "fifo.json"):
        result = subprocess.run([sys.executable, "-m", "trex", "check", str(tmp_path / name)],
                                capture_output=True, text=True, cwd=ROOT, timeout=60)
        assert result.returncode == 2
        assert_one_error_line(result.stderr, f"error: {tmp_path / name}: not a regular file")


def test_check_refuses_a_file_beyond_the_size_limit_at_once(tmp_path):
    path = tmp_path / "big.json"
    with open(path, "w") as handle:  # sparse beyond the limit: nothing is parsed
        handle.truncate(MAX_FILE_BYTES + 1)
    result = trex("check", str(path))
    assert result.returncode == 2
    assert_one_error_line(result.stderr, f"error: {path}: file has {MAX_FILE_BYTES + 1:,} bytes")


def test_check_refuses_too_many_vertices_before_validating(tmp_path):
    path = tmp_path / "many.dat"
    path.write_text("".join(f"{i} {i % 7}\n" for i in range(MAX_VERTICES + 1)))
    result = trex("check", str(path))
    assert result.returncode == 2
    assert_one_error_line(result.stderr, f"error: {path}: {MAX_VERTICES + 1:,} points")


def test_check_reads_a_multipolygon_of_one_polygon(tmp_path):
    ring = [[0, 0], [4, 0], [0, 4], [0, 0]]
    (tmp_path / "one.geojson").write_text(
        json.dumps({"type": "MultiPolygon", "coordinates": [[ring]]}))
    (tmp_path / "two.geojson").write_text(
        json.dumps({"type": "MultiPolygon", "coordinates": [[ring], [ring]]}))
    one = trex("check", str(tmp_path / "one.geojson"))
    assert one.returncode == 0, one.stderr
    assert "valid, 3 vertices" in one.stdout
    two = trex("check", str(tmp_path / "two.geojson"))
    assert two.returncode == 2
    assert_one_error_line(two.stderr, f"error: {tmp_path / 'two.geojson'}: GeoJSON MultiPolygon "
                                      "has 2 polygons; expected exactly one")
