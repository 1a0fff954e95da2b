// trex studio's page: draw a polygon (SVG), ask the studio's API about it after every edit,
// and start its jobs (hunt, video, slides). Plain JavaScript, no build step, nothing fetched
// from elsewhere: every request goes to the studio that served this page.
"use strict";

const SIZE = 640, PAD = 40, HIT = 9, DEBOUNCE_MS = 120, POLL_MS = 300;
const NS = "http://www.w3.org/2000/svg";
const $ = (id) => document.getElementById(id);

const state = {
  rings: [[]],          // ring 0 the outer one, then the holes; points in world coordinates
  active: 0,            // the ring a click adds to
  holeNext: false,      // "new hole": the next click starts one
  selected: null,       // {ring, index} of the vertex Backspace deletes
  undo: [], redo: [],
  view: {x0: 0, y0: 0, scale: (SIZE - 2 * PAD) / 10},
  check: null,          // the last /api/check answer for the drawn rings
  claims: [],           // the last /api/claims rows
  rules: [],            // /api/rules
  chosen: "scaling",    // the rule whose row and claim are highlighted
  triangles: null,      // the last triangulation, until the next edit
  seq: 0,               // answers to older edits are dropped
};

// --- coordinates -------------------------------------------------------------------------

const toScreen = ([x, y]) => [PAD + (x - state.view.x0) * state.view.scale,
                              SIZE - PAD - (y - state.view.y0) * state.view.scale];
const toWorld = (sx, sy) => [state.view.x0 + (sx - PAD) / state.view.scale,
                             state.view.y0 + (SIZE - PAD - sy) / state.view.scale];

function gridStep() {
  const span = (SIZE - 2 * PAD) / state.view.scale;
  const raw = span / 10, power = 10 ** Math.floor(Math.log10(raw));
  return [1, 2, 5, 10].map((m) => m * power).find((s) => s >= raw) || power;
}

function snapped([x, y]) {
  if (!$("snap").checked) return [round(x), round(y)];
  const s = gridStep();
  return [round(Math.round(x / s) * s), round(Math.round(y / s) * s)];
}

const round = (v) => Math.round(v * 1000) / 1000;  // three decimals: readable files

function eventPoint(event) {
  const box = $("canvas").getBoundingClientRect();
  return [(event.clientX - box.left) * SIZE / box.width, (event.clientY - box.top) * SIZE / box.height];
}

function fit() {
  const points = state.rings.flat();
  if (points.length < 2) return;
  const xs = points.map((p) => p[0]), ys = points.map((p) => p[1]);
  const [x0, x1, y0, y1] = [Math.min(...xs), Math.max(...xs), Math.min(...ys), Math.max(...ys)];
  const scale = (SIZE - 2 * PAD) / Math.max(x1 - x0, y1 - y0, 1e-9);
  state.view = {scale, x0: x0 - ((SIZE - 2 * PAD) / scale - (x1 - x0)) / 2,
                y0: y0 - ((SIZE - 2 * PAD) / scale - (y1 - y0)) / 2};
}

// --- editing, with undo ------------------------------------------------------------------

const snapshot = () => JSON.stringify({rings: state.rings, active: state.active});

function remember() {
  state.undo.push(snapshot());
  state.redo = [];
}

function restore(text) {
  const saved = JSON.parse(text);
  state.rings = saved.rings;
  state.active = Math.min(saved.active, state.rings.length - 1);
  state.selected = null;
  edited();
}

function undo() {
  if (!state.undo.length) return;
  state.redo.push(snapshot());
  restore(state.undo.pop());
}

function redo() {
  if (!state.redo.length) return;
  state.undo.push(snapshot());
  restore(state.redo.pop());
}

function addVertex(point, newRing) {
  remember();
  if (newRing && state.rings[0].length >= 3) {
    state.rings.push([]);
    state.active = state.rings.length - 1;
  }
  // after the selected vertex of this ring (to add one in the middle of an edge), else last
  const ring = state.rings[state.active], chosen = state.selected;
  const at = chosen && chosen.ring === state.active ? chosen.index + 1 : ring.length;
  ring.splice(at, 0, snapped(point));
  state.selected = {ring: state.active, index: at};
  edited();
}

function deleteVertex(ring, index) {
  remember();
  state.rings[ring].splice(index, 1);
  if (ring > 0 && state.rings[ring].length === 0) {
    state.rings.splice(ring, 1);
    state.active = Math.min(state.active, state.rings.length - 1);
  }
  state.selected = null;
  edited();
}

function setRings(body) {
  remember();
  state.rings = [body.polygon.map((p) => [...p]), ...(body.holes || []).map((h) => h.map((p) => [...p]))];
  state.active = 0;
  state.selected = null;
  fit();
  edited();
}

function vertexAt(sx, sy) {
  let best = null, bestDistance = HIT;
  state.rings.forEach((ring, r) => ring.forEach((p, i) => {
    const [x, y] = toScreen(p), d = Math.hypot(x - sx, y - sy);
    if (d <= bestDistance) { best = {ring: r, index: i}; bestDistance = d; }
  }));
  return best;
}

// --- drawing -----------------------------------------------------------------------------

function svg(name, attributes, parent) {
  const node = document.createElementNS(NS, name);
  for (const [k, v] of Object.entries(attributes)) node.setAttribute(k, v);
  if (parent) parent.appendChild(node);
  return node;
}

function clear(id) {
  const g = $(id);
  while (g.firstChild) g.removeChild(g.firstChild);
  return g;
}

const pointsAttr = (ring) => ring.map((p) => toScreen(p).join(",")).join(" ");

// The request's index (rings concatenated) of each drawn vertex, and back.
function flatIndex(ring, index) {
  let k = index;
  for (let r = 0; r < ring; r += 1) k += state.rings[r].length;
  return k;
}

function pointAt(k) {
  for (const ring of state.rings) {
    if (k < ring.length) return ring[k];
    k -= ring.length;
  }
  return null;
}

function drawGrid() {
  const g = clear("grid"), s = gridStep();
  const [wx0, wy0] = toWorld(0, SIZE), [wx1, wy1] = toWorld(SIZE, 0);
  for (let x = Math.ceil(wx0 / s) * s; x <= wx1; x += s) {
    const [sx] = toScreen([x, 0]);
    svg("line", {x1: sx, y1: 0, x2: sx, y2: SIZE, class: Math.abs(x) < s / 2 ? "axis" : ""}, g);
  }
  for (let y = Math.ceil(wy0 / s) * s; y <= wy1; y += s) {
    const [, sy] = toScreen([0, y]);
    svg("line", {x1: 0, y1: sy, x2: SIZE, y2: sy, class: Math.abs(y) < s / 2 ? "axis" : ""}, g);
  }
}

function drawRings() {
  const g = clear("rings"), vertices = clear("vertices");
  const reflex = new Set(state.check && state.check.valid ? state.check.reflex : []);
  state.rings.forEach((ring, r) => {
    if (ring.length >= 2) {
      const closed = ring.length >= 3 ? "" : " open";
      svg(ring.length >= 3 ? "polygon" : "polyline",
          {points: pointsAttr(ring), class: `ring${r ? " hole" : ""}${closed}`, "data-ring": r}, g);
    }
    ring.forEach((p, i) => {
      const [x, y] = toScreen(p);
      const chosen = state.selected && state.selected.ring === r && state.selected.index === i;
      const classes = ["vertex", r === state.active ? "active-ring" : "",
                       reflex.has(flatIndex(r, i)) ? "reflex" : "", chosen ? "selected" : ""];
      svg("circle", {cx: x, cy: y, r: 6, class: classes.join(" ").trim(), "data-ring": r,
                     "data-index": i}, vertices);
    });
  });
}

function drawCheck() {
  const labels = clear("labels"), bad = clear("bad-edges"), frame = clear("frame");
  const answer = state.check;
  if (!answer) return;
  if (!answer.valid) {
    for (const [i, j] of answer.edges) {
      const [a, b] = [toScreen(pointAt(i)), toScreen(pointAt(j))];
      svg("line", {x1: a[0], y1: a[1], x2: b[0], y2: b[1], class: "bad-edge",
                   "data-edge": `${i}-${j}`}, bad);
    }
    return;
  }
  answer.labels.forEach((label, k) => {
    if (label === null) return;
    const [x, y] = toScreen(pointAt(k));
    svg("text", {x: x + 8, y: y - 8, class: "label", "data-vertex": k}, labels).textContent = label;
  });
  if (answer.triangle) {
    svg("polygon", {points: pointsAttr(answer.triangle.map(pointAt)), class: "triangle-t"}, frame);
    for (const k of answer.candidates) {
      const [x, y] = toScreen(pointAt(k));
      svg("circle", {cx: x, cy: y, r: 11, class: "candidate", "data-vertex": k}, frame);
    }
  }
}

function drawClaims() {
  const g = clear("claims");
  for (const row of state.claims) {
    if (!row.diagonal) continue;
    const [a, b] = row.diagonal.map((k) => toScreen(pointAt(k)));
    const classes = ["claim", row.inner ? "inner" : "outer", row.name === state.chosen ? "selected" : ""];
    svg("line", {x1: a[0], y1: a[1], x2: b[0], y2: b[1], class: classes.join(" ").trim(),
                 "data-rule": row.name}, g);
    if (row.name === state.chosen && row.crossed) {  // the edge the wrong claim crosses
      const [c, d] = row.crossed.map((k) => toScreen(pointAt(k)));
      svg("line", {x1: c[0], y1: c[1], x2: d[0], y2: d[1], class: "crossed",
                   "data-edge": row.crossed.join("-")}, g);
    }
  }
}

function drawTriangles() {
  const g = clear("triangles");
  if (!state.triangles) return;
  for (const t of state.triangles) svg("polygon", {points: pointsAttr(t.map(pointAt)), class: "tri"}, g);
}

function draw() {
  drawGrid();
  drawTriangles();
  drawRings();
  drawCheck();
  drawClaims();
}

// --- the rules' table --------------------------------------------------------------------

// The names are the thesis's, from the registry's one table (story.registry.SPOKEN).
function ruleCell(rule) {
  const name = rule.spoken;
  const metaphor = rule.picture || "your own";
  return `<b>${escapeHtml(name)}</b> <span class="metaphor">(${escapeHtml(metaphor)})</span>`;
}

function escapeHtml(text) {
  return String(text).replace(/[&<>"]/g, (c) => ({"&": "&amp;", "<": "&lt;", ">": "&gt;", '"': "&quot;"}[c]));
}

function verdictCell(row) {
  if (row.error) return `<span class="bad">error</span> ${escapeHtml(row.error)}`;
  if (row.inner) return '<span class="ok">✓</span> inner diagonal';
  return `<span class="bad">✗</span> ${escapeHtml(row.why)}`;
}

function drawTable(message) {
  const body = $("rules").tBodies[0];
  body.innerHTML = "";
  const rows = new Map(state.claims.map((row) => [row.name, row]));
  for (const rule of state.rules) {
    const tr = body.insertRow();
    tr.dataset.rule = rule.name;
    if (rule.name === state.chosen) tr.classList.add("selected");
    const row = rows.get(rule.name);
    tr.insertCell().innerHTML = ruleCell(rule);
    tr.insertCell().textContent = row && row.labels ? row.labels.join("") : "";
    tr.insertCell().innerHTML = row ? verdictCell(row) : escapeHtml(message || "");
    tr.addEventListener("click", () => {  // the chosen rule is the one Hunt and Video act on
      state.chosen = $("hunt-rule").value = $("scene").value = rule.name;
      drawTable(message);
      drawClaims();
    });
  }
}

// --- asking the studio -------------------------------------------------------------------

async function api(path, body, method) {
  const options = body === undefined ? {method: method || "GET"}
    : {method: "POST", headers: {"Content-Type": "application/json"}, body: JSON.stringify(body)};
  const response = await fetch(path, options);
  const answer = await response.json();
  if (!response.ok) throw new Error(answer.error || `${response.status}`);
  return answer;
}

const request = () => ({polygon: state.rings[0], holes: state.rings.slice(1).filter((h) => h.length)});

function setStatus(text, kind) {
  const status = $("status");
  status.textContent = text;
  status.className = `status ${kind || ""}`.trim();
}

let pending = null;

function edited() {
  state.triangles = null;
  $("tri-result").textContent = "";
  state.check = null;
  state.claims = [];
  draw();
  clearTimeout(pending);
  pending = setTimeout(recheck, DEBOUNCE_MS);
}

async function recheck() {
  const seq = ++state.seq;
  if (state.rings[0].length < 3) {
    setStatus("draw at least 3 vertices");
    drawTable("");
    return;
  }
  try {
    const answer = await api("/api/check", request());
    if (seq !== state.seq) return;
    state.check = answer;
    const n = answer.labels.filter((l) => l !== null).length;
    const holes = request().holes.length;
    if (answer.valid) {
      setStatus(`valid: ${n} vertices${holes ? `, ${holes} hole${holes > 1 ? "s" : ""}` : ""}`, "valid");
    } else {
      setStatus(`invalid: ${answer.why}`, "invalid");
    }
    draw();
    if (!answer.valid) { drawTable("the polygon is not valid"); return; }
    if (holes) { drawTable("the heuristics take polygons without holes"); return; }
    const claims = await api("/api/claims", request());
    if (seq !== state.seq) return;
    state.claims = claims;
    drawTable("");
    drawClaims();
  } catch (error) {
    if (seq === state.seq) { setStatus(error.message, "invalid"); drawTable(""); }
  }
}

async function triangulate() {
  const algorithm = $("algorithm").value, started = performance.now();
  try {
    // divide and conquer finds each diagonal with the chosen rule (a wrong one stops it)
    const heuristic = algorithm === "divide-and-conquer" ? state.chosen : undefined;
    const answer = await api("/api/triangulate", {...request(), algorithm, heuristic});
    state.triangles = answer.triangles;
    const n = state.check ? state.check.labels.filter((l) => l !== null).length : 0;
    const h = request().holes.length;
    const ms = (answer.seconds * 1000).toFixed(1), total = (performance.now() - started).toFixed(0);
    const count = `${answer.triangles.length} triangle${answer.triangles.length === 1 ? "" : "s"}`;
    $("tri-result").textContent = answer.valid
      ? `${count} (n + 2h − 2 = ${n} + ${2 * h} − 2 = ${n + 2 * h - 2}), valid, in ${ms} ms (${total} ms with the request)`
      : `stopped after ${count}: ${answer.why}`;
    drawTriangles();
  } catch (error) {
    $("tri-result").textContent = error.message;
  }
}

// --- jobs: hunt, video, slides -----------------------------------------------------------

let running = null;  // the render job the Cancel button ends

async function follow(job, bar, onDone, onFail) {
  bar.hidden = false;
  bar.value = 0;
  for (;;) {
    const status = await api(`/api/jobs/${job}`);
    bar.value = status.progress;
    if (status.state === "done") { bar.value = 1; onDone(status.result); return; }
    if (status.state === "failed" || status.state === "cancelled") {
      onFail(status.state === "cancelled" ? "cancelled" : status.error);
      return;
    }
    await new Promise((resolve) => setTimeout(resolve, POLL_MS));
  }
}

async function hunt() {
  const heuristic = $("hunt-rule").value, out = $("hunt-result");
  out.textContent = "hunting…";
  try {
    const {job} = await api("/api/hunt", {heuristic});
    await follow(job, $("hunt-progress"), (result) => {
      if (!result.found) { out.textContent = `nothing found among ${result.tried} polygons`; return; }
      out.textContent = `found: ${result.why}`;
      setRings({polygon: result.polygon, holes: []});
    }, (error) => { out.textContent = error; });
  } catch (error) {
    out.textContent = error.message;
  }
}

async function render(kind) {
  const out = $("render-result"), scene = $("scene").value;
  out.textContent = kind === "video" ? "rendering…" : "building the slides…";
  try {
    const {job} = await api("/api/render", {...request(), scene, kind});
    running = job;
    $("cancel").hidden = false;
    await follow(job, $("render-progress"), (result) => {
      out.textContent = "";
      if (kind === "video") {
        const player = $("player");
        player.hidden = false;
        player.src = result.url;
        player.play().catch(() => {});
      } else {
        window.open(result.url, "_blank");
        out.innerHTML = `<a href="${escapeHtml(result.url)}" target="_blank">slides</a>`;
      }
    }, (error) => { out.textContent = error; });
  } catch (error) {
    out.textContent = error.message;
  } finally {
    running = null;
    $("cancel").hidden = true;
  }
}

async function cancel() {
  if (running) await api(`/api/jobs/${running}`, undefined, "DELETE");
}

// --- files -------------------------------------------------------------------------------

function save() {
  const {polygon, holes} = request();
  const data = holes.length ? [polygon, ...holes] : polygon;  // the command line reads both
  const link = document.createElement("a");
  link.href = URL.createObjectURL(new Blob([JSON.stringify(data) + "\n"], {type: "application/json"}));
  link.download = "polygon.json";
  link.click();
  URL.revokeObjectURL(link.href);
}

async function load(body) {
  try {
    setRings(await api("/api/load", body));
  } catch (error) {
    setStatus(error.message, "invalid");
  }
}

// --- events ------------------------------------------------------------------------------

function listen() {
  const canvas = $("canvas");
  let drag = null, moved = false;
  // A press on a vertex starts a drag, and its click (after the release) only selects; every
  // press sets `drag` anew, so a click never reads the last one's (a release clearing it on a
  // timer lost the race with the next click on a loaded machine: that click added nothing).
  canvas.addEventListener("mousedown", (event) => {
    if (event.button !== 0) return;
    const hit = vertexAt(...eventPoint(event));
    drag = hit || null;
    moved = false;
    if (hit) { state.selected = hit; state.active = hit.ring; }
  });
  canvas.addEventListener("mousemove", (event) => {
    if (!drag || !(event.buttons & 1)) return;  // a drag moves only while the button is held
    if (!moved) { remember(); moved = true; }
    state.rings[drag.ring][drag.index] = snapped(toWorld(...eventPoint(event)));
    edited();
  });
  canvas.addEventListener("click", (event) => {
    if (drag) {
      drag = null;
      if (!moved) drawRings();
      return;
    }
    const [sx, sy] = eventPoint(event);
    if (vertexAt(sx, sy)) return;
    addVertex(toWorld(sx, sy), event.shiftKey || state.holeNext);
    state.holeNext = false;
  });
  canvas.addEventListener("contextmenu", (event) => {
    event.preventDefault();
    const hit = vertexAt(...eventPoint(event));
    if (hit) deleteVertex(hit.ring, hit.index);
  });
  document.addEventListener("keydown", (event) => {
    if (event.target.tagName === "INPUT" || event.target.tagName === "SELECT") return;
    const key = event.key.toLowerCase();
    if ((event.ctrlKey || event.metaKey) && key === "z") {
      event.preventDefault();
      if (event.shiftKey) redo(); else undo();
    } else if ((event.ctrlKey || event.metaKey) && key === "y") {
      event.preventDefault();
      redo();
    } else if (event.key === "Backspace" || event.key === "Delete") {
      event.preventDefault();
      const ring = state.rings[state.active];
      const target = state.selected || (ring.length ? {ring: state.active, index: ring.length - 1} : null);
      if (target) deleteVertex(target.ring, target.index);
    }
  });
  $("undo").onclick = undo;
  $("redo").onclick = redo;
  $("new-hole").onclick = () => { state.holeNext = true; };
  $("clear").onclick = () => { remember(); state.rings = [[]]; state.active = 0; edited(); };
  $("fit").onclick = () => { fit(); draw(); };
  $("snap").onchange = () => draw();
  $("save").onclick = save;
  $("load-sample").onclick = () => load({sample: $("sample").value});
  $("file").onchange = async (event) => {
    const file = event.target.files[0];
    if (file) await load({file: {name: file.name, text: await file.text()}});
    event.target.value = "";
  };
  $("triangulate").onclick = triangulate;
  $("hunt").onclick = hunt;
  $("video").onclick = () => render("video");
  $("slides").onclick = () => render("slides");
  $("cancel").onclick = cancel;
}

function fill(select, names, chosen) {
  for (const name of names) {
    const option = document.createElement("option");
    option.value = option.textContent = name;
    if (name === chosen) option.selected = true;
    select.appendChild(option);
  }
}

async function start() {
  listen();
  const [setup, rules] = await Promise.all([api("/api/setup"), api("/api/rules")]);
  state.rules = rules;
  fill($("sample"), setup.samples, "counterexample");
  fill($("algorithm"), setup.algorithms, "ear-clipping");
  fill($("hunt-rule"), rules.map((r) => r.name), "rotation");
  fill($("scene"), [...rules.map((r) => r.name), ...setup.algorithms], "scaling");
  if (setup.initial) setRings(setup.initial); else { draw(); drawTable(""); }
  document.body.dataset.ready = "yes";
}

start();
