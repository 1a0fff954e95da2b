"""The step player: one picture per beat of a run, and an offline HTML page to step through them.

:func:`render_steps` plays the scene's beats once on a real (Cairo) renderer that skips
animations — every ``play`` jumps to its end state and draws no frames in between — and,
after each beat, draws the board as it then stands into a PNG. One pass, so the cost is one
skipped run of the scene plus one frame per beat, not a render per prefix of beats.

:func:`write_player` writes ``index.html`` beside the pictures: inline CSS and JavaScript, no
font, script or image from anywhere else (pictures are referenced relatively, ``steps/…``);
←/→ step, Home/End jump to the first/last step, and the address's ``#n`` remembers the step.
"""

from __future__ import annotations

import tempfile
from dataclasses import dataclass
from pathlib import Path

from story.beats import Beat
from trex.offline_page import write_page

#: manim's low quality (``-ql``): 854×480.
PIXELS = (854, 480)
STEPS_DIR = "steps"


@dataclass(frozen=True)
class Still:
    """The player's picture of one step (a beat): its path (relative), caption, call line and
    action."""

    image: str
    caption: str
    call: str | None
    action: str

    def to_dict(self) -> dict:
        return {"image": self.image, "caption": self.caption, "call": self.call,
                "action": self.action}


def render_steps(scene_class: type, log, folder: Path, pixels: tuple[int, int] = PIXELS,
                 progress=None) -> list[Still]:
    """Play ``log`` on a board of ``scene_class`` (a TraceScene subclass: its beats, theme,
    title and metaphor box) and write ``folder/steps/NNN.png`` after each beat.

    The call line of a step is the one the panel shows then (the last one set so far).
    ``progress(k, n)``, if given, is called after each picture.
    """
    from manim import tempconfig

    from metaphors.play import board_for, play_beats

    out = folder / STEPS_DIR
    out.mkdir(parents=True, exist_ok=True)
    width, height = pixels
    with tempfile.TemporaryDirectory(prefix="trex-player-media-") as media:
        settings = {
            "pixel_width": width, "pixel_height": height, "frame_rate": 15,
            "media_dir": media, "disable_caching": True, "write_to_movie": False,
            "save_last_frame": False, "preview": False, "verbosity": "WARNING",
            "progress_bar": "none",
        }
        with tempconfig(settings):
            scene = scene_class(skip_animations=True)
            scene.camera.background_color = scene.theme.background
            beats: list[Beat] = scene.beats(log)
            board = board_for(scene, log, beats, scene.title, scene.theme)
            digits = max(3, len(str(len(beats))))
            steps: list[Still] = []

            def picture(k: int, beat: Beat) -> None:
                name = f"{k:0{digits}d}.png"
                _snapshot(scene).save(out / name)
                call = beat.call if beat.call is not None else (steps[-1].call if steps else None)
                steps.append(Still(f"{STEPS_DIR}/{name}", beat.caption, call, beat.action))
                if progress is not None:
                    progress(k, len(beats))

            play_beats(board, beats, after=picture)
    return steps


def _snapshot(scene):
    """The scene as it stands, drawn afresh (not over the last animation's static background)."""
    renderer = scene.renderer
    renderer.static_image = None
    renderer.update_frame(scene, ignore_skipping=True)
    return renderer.camera.get_image().convert("RGB")


def write_player(folder: Path, steps: list[Still], title: str, subtitle: str = "") -> Path:
    """Write ``folder/index.html`` for the steps; returns its path."""
    return write_page(folder, _PAGE, title, [s.to_dict() for s in steps], SUBTITLE=subtitle,
                      FIRST=steps[0].image if steps else "", WIDTH=PIXELS[0], HEIGHT=PIXELS[1])


_PAGE = """{{HEAD}}
<style>
{{BASE_CSS}}  figure { margin: 0; }
  img { display: block; width: 100%; height: auto; aspect-ratio: {{WIDTH}} / {{HEIGHT}};
        background: #10141c; border: 1px solid #2a3a55; border-radius: 4px; }
  #call { font-family: "DejaVu Sans Mono", ui-monospace, monospace; color: var(--called);
          min-height: 1.3em; margin: 6px 0; }
</style>
</head>
<body>
<main>
  <h1>{{TITLE}}</h1>
  <p class="sub">{{SUBTITLE}}</p>
  <figure><img id="picture" src="{{FIRST}}" alt="" width="{{WIDTH}}" height="{{HEIGHT}}"></figure>
  <div class="bar">
    <button id="first" title="Home">⇤</button>
    <button id="prev" title="←">←</button>
    <span id="counter">step 1 / 1</span>
    <button id="next" title="→">→</button>
    <button id="last" title="End">⇥</button>
  </div>
  <p id="caption"></p>
  <p id="call"></p>
  <p class="keys"><kbd>←</kbd> <kbd>→</kbd> step · <kbd>Home</kbd> <kbd>End</kbd> first, last</p>
</main>
<script id="player-data" type="application/json">{{DATA}}</script>
<script>
(function () {
  "use strict";
  var data = JSON.parse(document.getElementById("player-data").textContent);
  var steps = data.steps, n = steps.length, at = 0;
  var $ = function (id) { return document.getElementById(id); };
  function show(k) {
    if (!n) { $("counter").textContent = "no steps"; return; }
    at = Math.max(0, Math.min(n - 1, k));
    var step = steps[at];
    $("picture").src = step.image;
    $("picture").alt = step.caption;
    $("counter").textContent = "step " + (at + 1) + " / " + n;
    $("caption").textContent = step.caption;
    $("call").textContent = step.call || "";
    $("first").disabled = $("prev").disabled = at === 0;
    $("last").disabled = $("next").disabled = at === n - 1;
    try { history.replaceState(null, "", "#" + (at + 1)); } catch (err) { /* not kept */ }
  }
  document.addEventListener("keydown", function (e) {
    if (e.altKey || e.ctrlKey || e.metaKey) { return; }
    var to = {ArrowRight: at + 1, ArrowLeft: at - 1, Home: 0, End: n - 1}[e.key];
    if (to === undefined) { return; }
    e.preventDefault();
    show(to);
  });
  $("first").onclick = function () { show(0); };
  $("prev").onclick = function () { show(at - 1); };
  $("next").onclick = function () { show(at + 1); };
  $("last").onclick = function () { show(n - 1); };
  var start = parseInt(location.hash.slice(1), 10);
  show(isNaN(start) ? 0 : start - 1);
})();
</script>
</body>
</html>
"""
