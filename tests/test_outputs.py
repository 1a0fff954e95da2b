"""Output paths and formats are checked before any work (issue 24 items 3 and 4).

A bad ``-o`` (an unknown extension, a directory, a missing directory, an extension that
contradicts ``--format``) is one line naming the path and exit 2, before the search, the
run or the render starts, and nothing is written.
"""

from __future__ import annotations

import pytest
from click.testing import CliRunner

from trex import hunt_command, render_command
from trex.cli import main


def run(*args):
    result = CliRunner().invoke(main, [str(a) for a in args])
    return result.exit_code, result.stdout, result.stderr


def files(folder) -> list[str]:
    return sorted(p.name for p in folder.iterdir())


def bad_outputs(tmp_path, extension: str) -> list[tuple[str, str]]:
    """(-o, what the one line says after it) for each kind of bad path."""
    return [(str(tmp_path / "ce.xyz"), "unknown format '.xyz'; expected "),
            (str(tmp_path), "is a directory; give a file path"),
            (str(tmp_path / "missing" / f"ce{extension}"),
             f"no such directory: {tmp_path / 'missing'}")]


@pytest.fixture
def no_search(monkeypatch):
    monkeypatch.setattr(hunt_command, "hunt", lambda *a, **k: pytest.fail("searched"))


@pytest.mark.parametrize("kind", [0, 1, 2])
def test_hunt_checks_its_output_before_the_search(kind, tmp_path, no_search):
    output, says = bad_outputs(tmp_path, ".json")[kind]
    code, stdout, stderr = run("hunt", "scaling", "-o", output)
    assert code == 2 and stdout == ""
    assert stderr.startswith(f"error: {output}: {says}") and stderr.count("\n") == 1
    assert files(tmp_path) == []


@pytest.mark.parametrize("kind", [0, 1, 2])
def test_sample_checks_its_output_first(kind, tmp_path):
    output, says = bad_outputs(tmp_path, ".wkt")[kind]
    code, _, stderr = run("sample", "star", "-o", output)
    assert code == 2
    assert stderr.startswith(f"error: {output}: {says}") and stderr.count("\n") == 1
    assert files(tmp_path) == []


@pytest.mark.parametrize("kind", [1, 2])
def test_log_checks_its_output_before_the_run(kind, tmp_path, monkeypatch):
    from story import spec

    monkeypatch.setattr(spec.RunSpec, "log", lambda self: pytest.fail("ran"))
    output, says = bad_outputs(tmp_path, ".json")[kind]
    code, _, stderr = run("log", "gravity", "counterexample", "-o", output)
    assert code == 2
    assert stderr == f"error: {output}: {says}\n"
    assert files(tmp_path) == []


@pytest.fixture
def no_render(monkeypatch):
    monkeypatch.setattr(render_command, "render_into", lambda *a, **k: pytest.fail("rendered"))


@pytest.mark.parametrize(("fmt", "output", "says"), [
    ("png", "p.mp4", "the extension .mp4 contradicts --format png; give -o p.png, or drop "
                     "--format"),
    ("gif", "x.mp4", "the extension .mp4 contradicts --format gif; give -o x.gif, or drop "
                     "--format"),
    ("mp4", "clip.GIF", "the extension .gif contradicts --format mp4; give -o clip.mp4, or "
                        "drop --format"),
    (None, "out.webm", "unknown format '.webm'; expected .mp4, .gif or .png (or --format)"),
    (None, "out", "no extension to name the format; expected .mp4, .gif or .png (or --format)"),
])
def test_render_refuses_a_format_the_name_contradicts(fmt, output, says, tmp_path, no_render):
    target = tmp_path / output
    args = ["render", "gravity", "-o", target] + (["--format", fmt] if fmt else [])
    code, stdout, stderr = run(*args)
    assert (code, stdout) == (2, "")
    assert stderr == f"error: {target}: {says}\n"
    assert files(tmp_path) == []


@pytest.mark.parametrize(("fmt", "output", "chosen"), [
    (None, "clock.gif", "gif"), (None, "still.PNG", "png"), ("png", "still.png", "png"),
    ("gif", "noextension", "gif"),
])
def test_render_takes_a_format_the_name_agrees_with(fmt, output, chosen, tmp_path, monkeypatch):
    seen = []

    def fake_render(make_scene, target, fmt, quality, **kw):
        seen.append(fmt)
        target.write_bytes(b"x")
        return target

    monkeypatch.setattr(render_command, "render_into", fake_render)
    args = ["render", "gravity", "-o", tmp_path / output] + (["--format", fmt] if fmt else [])
    code, _, stderr = run(*args)
    assert (code, stderr) == (0, "")
    assert seen == [chosen]


@pytest.mark.parametrize("command", [["render", "gravity"], ["hunt", "scaling"],
                                     ["sample", "star"]])
def test_an_empty_output_path_is_one_line(command, no_render, no_search):
    code, _, stderr = run(*command, "-o", "")
    assert code == 2
    assert stderr == "error: '': empty path; give a file path\n"
