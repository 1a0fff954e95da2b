"""The slides' page: one clip per step, played one key press at a time, offline.

:func:`write_slides` writes ``index.html`` beside the clips: inline CSS and JavaScript, no
font, script or video from anywhere else (clips are named relatively, ``clips/…``).

- → Space PageDown (what presentation clickers send): play the next step; it stops on its
  last frame and never moves on by itself. ← PageUp: the step before, shown at its end.
  Home: the first step, played; End: the last, at its end. A number, then Enter: that step,
  at its end. R: play the step again. F: full screen. S: a speaker window.
- The caption and "step 7 / 31" are under the video (and the chapter, for a lecture). The
  speaker view (``index.html?notes``, or the window S opens, which follows this one and
  steers it) shows the next step's caption too, its video smaller so that the caption stays
  above the fold on a laptop (1366×768).
- ``#7`` in the address opens step 7 at its end; without it step 1 plays (the clips have no
  sound, so a muted video may play unasked).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from trex.offline_page import write_page

CLIPS_DIR = "clips"


@dataclass(frozen=True)
class Slide:
    """One step of the slides: its clip (relative path), caption, call line, kind, the
    chapter it is in (None: not a lecture) and ``last``, the time (seconds) of the clip's
    last frame (None: not known; the page then seeks to the clip's end)."""

    clip: str
    caption: str
    call: str | None = None
    kind: str = "beat"
    chapter: str | None = None
    last: float | None = None
    notes: tuple[str, ...] = ()  # the chapter's notes for its teacher (the speaker window's)

    def to_dict(self) -> dict:
        return {"clip": self.clip, "caption": self.caption, "call": self.call,
                "kind": self.kind, "chapter": self.chapter, "last": self.last,
                "notes": list(self.notes)}


def write_slides(folder: Path, slides: Sequence[Slide], title: str, subtitle: str,
                 pixels: tuple[int, int]) -> Path:
    """Write ``folder/index.html`` for the slides; returns its path."""
    return write_page(folder, _PAGE, title, [s.to_dict() for s in slides], SUBTITLE=subtitle,
                      WIDTH=pixels[0], HEIGHT=pixels[1])


_PAGE = """{{HEAD}}
<style>{{BASE_CSS}}
  main { max-width: 1100px; }
  figure { margin: 0; background: #000; }
  video { display: block; width: 100%; height: auto; aspect-ratio: {{WIDTH}} / {{HEIGHT}};
          background: #10141c; border: 1px solid #2a3a55; border-radius: 4px; }
  :fullscreen figure, figure:fullscreen { display: flex; align-items: center; height: 100vh; }
  figure:fullscreen video { border: 0; border-radius: 0; max-height: 100vh; }
  #chapter { color: var(--idle); margin: 6px 0 0; min-height: 1.2em; }
  #jump { color: var(--called); font-variant-numeric: tabular-nums; min-width: 4em; }
  #notes { display: none; border-top: 1px solid #2a3a55; margin-top: 12px; padding-top: 8px; }
  .speaker #notes { display: block; }
  /* the speaker view on a laptop (1366×768): a smaller video, so that the next step's
     caption stays above the fold */
  .speaker figure { display: flex; justify-content: center; }
  .speaker video { width: auto; max-width: 100%; height: 46vh; }
  #next { color: var(--idle); font-size: 1.1rem; }
  #teacher { color: var(--ink); margin: 8px 0 0; padding-left: 1.2em; }
</style>
</head>
<body>
<main>
  <h1>{{TITLE}}</h1>
  <p class="sub">{{SUBTITLE}}</p>
  <figure id="stage"><video id="clip" muted playsinline preload="auto"
    width="{{WIDTH}}" height="{{HEIGHT}}"></video></figure>
  <div class="bar">
    <button id="first" title="Home">⇤</button>
    <button id="prev" title="← PageUp">←</button>
    <span id="counter">step 1 / 1</span>
    <button id="next-button" title="→ Space PageDown">→</button>
    <button id="last" title="End">⇥</button>
    <span id="jump"></span>
  </div>
  <p id="chapter"></p>
  <p id="caption"></p>
  <section id="notes"><p>Next: <span id="next"></span></p><ul id="teacher"></ul></section>
  <p class="keys"><kbd>→</kbd> <kbd>Space</kbd> <kbd>PageDown</kbd> play the next step ·
    <kbd>←</kbd> <kbd>PageUp</kbd> back · <kbd>Home</kbd> <kbd>End</kbd> first, last ·
    a number, <kbd>Enter</kbd>: go there · <kbd>R</kbd> again · <kbd>F</kbd> full screen ·
    <kbd>S</kbd> speaker window</p>
</main>
<script id="slides-data" type="application/json">{{DATA}}</script>
<script>
(function () {
  "use strict";
  var data = JSON.parse(document.getElementById("slides-data").textContent);
  var steps = data.steps, n = steps.length, at = 0, typed = "", other = null;
  var $ = function (id) { return document.getElementById(id); };
  var video = $("clip");
  var speaker = /(^|[?&])notes\\b/.test(location.search);
  if (speaker) { document.body.className = "speaker"; }

  // A step's end is its last frame, sought in the middle of the time it shows. Chromium
  // now and then paints no new frame after a seek (2 in 60 under load, the seek done and the
  // first frame still shown), so the page looks at the frame presented and seeks again.
  function showEnd(step, tries) {
    if (step.last === null) { video.currentTime = video.duration; return; }
    var last = step.last;
    video.currentTime = (last + video.duration) / 2 - (tries % 2) * 1e-3;
    if (!video.requestVideoFrameCallback || tries >= 5) { return; }
    var presented = null;
    video.requestVideoFrameCallback(function (now, frame) { presented = frame.mediaTime; });
    video.addEventListener("seeked", function () {
      setTimeout(function () {
        var stale = presented === null || Math.abs(presented - last) > 2e-3;
        if (stale && steps[at] === step && video.paused && !video.seeking) {
          showEnd(step, tries + 1);
        }
      }, 250);
    }, {once: true});
  }
  // Show step k: "play" plays it from its start, "end" shows its last frame.
  function show(k, how, quiet) {
    if (!n) { $("counter").textContent = "no steps"; return; }
    at = Math.max(0, Math.min(n - 1, k));
    var step = steps[at];
    if (video.getAttribute("src") !== step.clip) { video.setAttribute("src", step.clip); }
    video.pause();
    if (how === "play") {
      video.currentTime = 0;
      var playing = video.play();
      if (playing && playing.catch) { playing.catch(function () { /* not allowed: paused */ }); }
    } else if (video.readyState >= 1) {
      showEnd(step, 0);
    } else {
      video.addEventListener("loadedmetadata", function () {
        if (steps[at] === step) { showEnd(step, 0); }
      }, {once: true});
    }
    $("counter").textContent = "step " + (at + 1) + " / " + n;
    $("caption").textContent = step.caption;
    $("chapter").textContent = step.chapter || "";
    $("next").textContent = at + 1 < n ? steps[at + 1].caption : "(the end)";
    $("teacher").replaceChildren(...(step.notes || []).map(function (line) {
      const item = document.createElement("li"); item.textContent = line; return item;
    }));
    $("first").disabled = $("prev").disabled = at === 0;
    $("last").disabled = $("next-button").disabled = at === n - 1;
    try { history.replaceState(null, "", location.search + "#" + (at + 1)); } catch (e) { }
    if (!quiet) { tell({at: at, how: how}); }
  }
  function next() { if (at < n - 1) { show(at + 1, "play"); } }
  function back() { show(at - 1, "end"); }

  // The speaker window and this one follow each other (postMessage works between file:
  // pages, whose origins are opaque).
  function tell(message) {
    message.trex = "slides";
    var peer = other || window.opener;
    if (peer && !peer.closed) { peer.postMessage(message, "*"); }
  }
  window.addEventListener("message", function (e) {
    var m = e.data;
    if (!m || m.trex !== "slides" || typeof m.at !== "number") { return; }
    if (e.source && e.source !== window.opener) { other = e.source; }
    show(m.at, m.how === "play" ? "play" : "end", true);
  });
  function speakerWindow() {
    other = window.open(location.pathname + "?notes#" + (at + 1), "trex-slides-notes");
  }

  function fullscreen() {
    if (document.fullscreenElement) { document.exitFullscreen(); }
    else if ($("stage").requestFullscreen) { $("stage").requestFullscreen(); }
  }

  document.addEventListener("keydown", function (e) {
    if (e.altKey || e.ctrlKey || e.metaKey) { return; }
    var key = e.key;
    if (/^[0-9]$/.test(key)) { typed += key; $("jump").textContent = "→ " + typed; }
    else if (key === "Enter" && typed) { show(parseInt(typed, 10) - 1, "end"); typed = ""; }
    else if (key === "Escape" || key === "Backspace") { typed = ""; }
    else if (key === "ArrowRight" || key === " " || key === "PageDown") { next(); }
    else if (key === "ArrowLeft" || key === "PageUp") { back(); }
    else if (key === "Home") { show(0, "play"); }
    else if (key === "End") { show(n - 1, "end"); }
    else if (key === "r" || key === "R") { show(at, "play"); }
    else if (key === "f" || key === "F") { fullscreen(); }
    else if (key === "s" || key === "S") { speakerWindow(); }
    else { return; }
    if (!/^[0-9]$/.test(key)) { $("jump").textContent = typed ? "→ " + typed : ""; }
    e.preventDefault();
  });
  $("first").onclick = function () { show(0, "play"); };
  $("prev").onclick = back;
  $("next-button").onclick = next;
  $("last").onclick = function () { show(n - 1, "end"); };
  var start = parseInt(location.hash.slice(1), 10);
  if (isNaN(start)) { show(0, "play"); } else { show(start - 1, "end"); }
})();
</script>
</body>
</html>
"""
