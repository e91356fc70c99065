// The World Designer's page: the document (a world file's records as JSON with their raw integer
// fields, see designer/README.md) is edited here; the engine, compiled to WebAssembly by TeaVM,
// builds and plays it (Bridge.java). Opens from the file system: the module is embedded as base64.
"use strict";

const FX = 4096;          // positions, velocities, materials: raw / 4096
const FX2 = 16777216;     // angles (rad) and angular velocities: raw / 2^24
const FLAG_DYNAMIC = 1, FLAG_ROTATES = 2, FLAG_NOT_INTERACTING = 4, FLAG_NO_GRAVITY = 8;
const NONE = 255;

const $ = id => document.getElementById(id);
const ui = {
  tool: "select", playing: false, selection: null, zoom: 1, camX: 0, camY: 0,
  undo: [], redo: [], geometry: null, docToWorld: [], pending: null, drag: null,
  replay: null, tickMs: []
};
let E = null;             // the engine's exports
let doc = null;           // the document

// ---------- the engine ----------

async function loadEngine() {
  const bin = atob(EMINI_ENGINE_WASM);
  const bytes = new Uint8Array(bin.length);
  for (let i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);
  const teavm = await TeaVM.wasmGC.load(bytes);
  E = teavm.exports;
}

function settings() {
  return { tps: Math.max(1, Math.round(+$("tps").value || 60)), iterations: Math.max(1, Math.round(+$("iterations").value || 10)) };
}

// Builds the document's world (tick 0); returns the engine's message or "".
function rebuild() {
  const s = settings();
  const msg = E.load(JSON.stringify(doc), s.tps, s.iterations);
  if (msg) {
    status("The engine refused the document: " + msg);
    return msg;
  }
  ui.geometry = JSON.parse(E.geometry());
  ui.docToWorld = [];
  ui.geometry.bodies.forEach((b, k) => { if (b.doc >= 0) ui.docToWorld[b.doc] = k; });
  const report = $("report");
  report.innerHTML = "";
  for (const u of ui.geometry.unsupported) li(report, "not built: " + u);
  for (const a of ui.geometry.approximations) li(report, "approximated: " + a);
  if (!report.children.length) li(report, "every record built");
  status("");
  ui.tickMs = [];
  draw();
  return "";
}

function li(list, text) {
  const e = document.createElement("li");
  e.textContent = text;
  list.appendChild(e);
}

function status(text) {
  $("status").textContent = text;
}

// ---------- the document ----------

function newDocument() {
  return {
    version: 2560,
    settings: { gravity: [0, 200 * FX], dampingLinear: 0, dampingRotational: 0 },
    shapes: [rectShape(800, 20, true), rectShape(40, 40), circleShape(20)],
    bodies: [
      body(0, 0, 100, FLAG_ROTATES),
      body(1, -60, 0, FLAG_DYNAMIC | FLAG_ROTATES),
      body(2, 60, -40, FLAG_DYNAMIC | FLAG_ROTATES)
    ],
    constraints: [], events: [], emitters: []
  };
}

function material(extra) {
  return Object.assign({ elasticity: 0, friction: Math.round(0.5 * FX), mass: FX, legacyId: 0, userData: "" }, extra);
}

function rectShape(w, h) {
  const x = Math.round(w / 2 * FX), y = Math.round(h / 2 * FX);
  return material({ kind: "polygon", vertices: [-x, -y, x, -y, x, y, -x, y] });
}

function circleShape(r) {
  return material({ kind: "circle", vertices: [Math.round(r) * FX, 0] });
}

function regularShape(r, n) {
  const v = [];
  for (let i = 0; i < n; i++) {
    const a = 2 * Math.PI * i / n - Math.PI / 2;
    v.push(Math.round(r * Math.cos(a) * FX), Math.round(r * Math.sin(a) * FX));
  }
  return material({ kind: "polygon", vertices: v });
}

function body(shape, x, y, flags) {
  return { shape, position: [Math.round(x * FX), Math.round(y * FX)], velocity: [0, 0], angle: 0, angularVelocity: 0,
           flags, layers: 0, legacyMass: 0, userData: "" };
}

// Every edit goes through here: the old document goes on the undo stack and the world is rebuilt.
function edit(change) {
  const before = JSON.stringify(doc);
  change(doc);
  const msg = rebuild();
  if (msg) {
    doc = JSON.parse(before);
    rebuild();
    status("Not applied: " + msg);
    return false;
  }
  ui.undo.push(before);
  if (ui.undo.length > 200) ui.undo.shift();
  ui.redo = [];
  stop();
  showProps();
  return true;
}

// Undo takes from the undo stack and puts the current document on the redo stack; redo the reverse.
function travel(from, to) {
  if (!from.length) return;
  to.push(JSON.stringify(doc));
  doc = JSON.parse(from.pop());
  stop();
  readWorldFields();
  rebuild();
  clampSelection();
  showProps();
}

function undo() {
  travel(ui.undo, ui.redo);
}

function redo() {
  travel(ui.redo, ui.undo);
}

function clampSelection() {
  const s = ui.selection;
  if (!s) return;
  const list = s.kind === "body" ? doc.bodies : s.kind === "constraint" ? doc.constraints : s.kind === "segment"
    ? (doc.landscape ? doc.landscape.segments : []) : s.kind === "event" ? doc.events : s.kind === "emitter" ? doc.emitters : null;
  if (list && s.index >= list.length) ui.selection = null;
}

// ---------- the view ----------

const canvas = $("view");
const ctx = canvas.getContext("2d");

function toScreen(x, y) {
  return [(x - ui.camX) * ui.zoom + canvas.width / 2, (y - ui.camY) * ui.zoom + canvas.height / 2];
}

function toWorld(sx, sy) {
  return [(sx - canvas.width / 2) / ui.zoom + ui.camX, (sy - canvas.height / 2) / ui.zoom + ui.camY];
}

function snap(v) {
  if (!$("snap").checked) return v;
  const step = Math.max(1, +$("snap-step").value || 10);
  return Math.round(v / step) * step;
}

// A body's pose: the engine's while a world is built, else the document's.
function pose(frame, k) {
  return { x: frame[7 * k], y: frame[7 * k + 1], a: frame[7 * k + 2], vx: frame[7 * k + 3], vy: frame[7 * k + 4],
           w: frame[7 * k + 5], sleeping: frame[7 * k + 6] > 0 };
}

function localToWorld(p, lx, ly) {
  const c = Math.cos(p.a), s = Math.sin(p.a);
  return [p.x + c * lx - s * ly, p.y + s * lx + c * ly];
}

function draw() {
  if (!E || !ui.geometry) return;
  const frame = E.frame();
  ctx.setTransform(1, 0, 0, 1, 0, 0);
  ctx.clearRect(0, 0, canvas.width, canvas.height);
  drawGrid();
  const land = doc.landscape;
  if (land) {
    land.segments.forEach((g, i) => {
      const a = toScreen(g[0] / FX, g[1] / FX), b = toScreen(g[2] / FX, g[3] / FX);
      ctx.strokeStyle = isSel("segment", i) ? "#e07000" : "#3a5";
      ctx.lineWidth = 3;
      line(a, b);
      if (g[4]) {   // the face: a tick on the colliding side (1 left, 2 right of start → end)
        const dx = b[0] - a[0], dy = b[1] - a[1], len = Math.hypot(dx, dy) || 1, s = g[4] === 1 ? -1 : 1;
        const m = [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2];
        ctx.lineWidth = 1;
        line(m, [m[0] - s * dy / len * 8, m[1] + s * dx / len * 8]);
      }
    });
  }
  if (ui.replay) {   // the trace's paths, faint, under the bodies
    ctx.strokeStyle = "#c9a26a";
    ctx.lineWidth = 1;
    for (const b of Object.values(ui.replay.trace.bodies)) {
      ctx.beginPath();
      b.x.forEach((x, i) => {
        if (x === null || b.y[i] === null) return;
        const s = toScreen(x, b.y[i]);
        if (i === 0) ctx.moveTo(s[0], s[1]); else ctx.lineTo(s[0], s[1]);
      });
      ctx.stroke();
    }
  }
  const replayPose = ui.replay ? replayPoses() : null;
  ui.geometry.bodies.forEach((b, k) => {
    let p = pose(frame, k);
    if (replayPose && b.doc >= 0 && replayPose[b.doc]) p = replayPose[b.doc];
    const sel = b.doc >= 0 && isSel("body", b.doc);
    ctx.fillStyle = b.sensor ? "rgba(120,120,255,0.15)" : !b.dynamic ? "#9aa" : p.sleeping ? "#b8c4d8" : "#6c9bd2";
    ctx.strokeStyle = sel ? "#e07000" : "#234";
    ctx.lineWidth = sel ? 2.5 : 1;
    for (const part of b.parts) {
      ctx.beginPath();
      if (part.circle) {
        const c = toScreen(...localToWorld(p, part.circle[0], part.circle[1]));
        ctx.arc(c[0], c[1], part.circle[2] * ui.zoom, 0, 2 * Math.PI);
        ctx.fill();
        ctx.stroke();
        const e = toScreen(...localToWorld(p, part.circle[0] + part.circle[2], part.circle[1]));
        line(c, e);
      } else {
        const v = part.polygon;
        for (let i = 0; i < v.length; i += 2) {
          const s = toScreen(...localToWorld(p, v[i], v[i + 1]));
          if (i === 0) ctx.moveTo(s[0], s[1]); else ctx.lineTo(s[0], s[1]);
        }
        ctx.closePath();
        ctx.fill();
        ctx.stroke();
      }
    }
    if ($("show-velocities").checked && b.dynamic) {
      const c = toScreen(p.x, p.y);
      ctx.strokeStyle = "#c0c";
      ctx.lineWidth = 1.5;
      line(c, [c[0] + p.vx * 0.1 * ui.zoom, c[1] + p.vy * 0.1 * ui.zoom]);
    }
  });
  if ($("show-joints").checked) drawConstraints(frame);
  // Emitters: their emit segment (in the world, or in their body's frame when they ride one).
  doc.emitters.forEach((em, i) => {
    const k = em.body === NONE ? undefined : ui.docToWorld[em.body];
    const at = v => k === undefined ? [v[0] / FX, v[1] / FX] : localToWorld(pose(frame, k), v[0] / FX, v[1] / FX);
    const a = toScreen(...at(em.position1)), b = toScreen(...at(em.position2));
    ctx.strokeStyle = isSel("emitter", i) ? "#e07000" : "#d40";
    ctx.lineWidth = 2;
    line(a, b);
    ctx.beginPath();
    ctx.arc(a[0], a[1], 5, 0, 2 * Math.PI);
    ctx.stroke();
  });
  const parts = E.particles();
  ctx.fillStyle = "#d40";
  for (let i = 0; i < parts.length; i += 2) {
    const s = toScreen(parts[i], parts[i + 1]);
    ctx.fillRect(s[0] - 1.5, s[1] - 1.5, 3, 3);
  }
  if ($("show-contacts").checked || $("show-normals").checked) {
    const c = E.contacts();
    for (let i = 0; i < c.length; i += 5) {
      const s = toScreen(c[i], c[i + 1]);
      if ($("show-contacts").checked) {
        ctx.fillStyle = "#e00";
        ctx.fillRect(s[0] - 2, s[1] - 2, 4, 4);
      }
      if ($("show-normals").checked) {
        ctx.strokeStyle = "#e00";
        ctx.lineWidth = 1;
        line(s, [s[0] + c[i + 2] * 15, s[1] + c[i + 3] * 15]);
      }
    }
  }
  if (ui.pending && ui.pending.from) {
    ctx.strokeStyle = "#e07000";
    ctx.setLineDash([4, 3]);
    line(toScreen(...ui.pending.from), toScreen(...ui.pending.to || ui.pending.from));
    ctx.setLineDash([]);
  }
  drawScale();
  showMetrics();
}

function line(a, b) {
  ctx.beginPath();
  ctx.moveTo(a[0], a[1]);
  ctx.lineTo(b[0], b[1]);
  ctx.stroke();
}

function drawGrid() {
  const step = Math.max(1, +$("snap-step").value || 10) * ui.zoom;
  if (step < 6) return;
  ctx.strokeStyle = "#eef0f3";
  ctx.lineWidth = 1;
  const o = toScreen(0, 0);
  for (let x = o[0] % step; x < canvas.width; x += step) line([x, 0], [x, canvas.height]);
  for (let y = o[1] % step; y < canvas.height; y += step) line([0, y], [canvas.width, y]);
  ctx.strokeStyle = "#d6dae0";
  line([o[0], 0], [o[0], canvas.height]);
  line([0, o[1]], [canvas.width, o[1]]);
}

// A scale bar: a round length in px (world units) at the current zoom.
function drawScale() {
  let len = 1;
  while (len * ui.zoom < 60) len *= len.toString()[0] === "2" ? 2.5 : 2;
  while (len * ui.zoom > 200) len /= 2;
  const x = 14, y = canvas.height - 14;
  ctx.strokeStyle = "#222";
  ctx.lineWidth = 2;
  line([x, y], [x + len * ui.zoom, y]);
  line([x, y - 4], [x, y + 4]);
  line([x + len * ui.zoom, y - 4], [x + len * ui.zoom, y + 4]);
  ctx.fillStyle = "#222";
  ctx.font = "12px sans-serif";
  ctx.fillText(+len.toPrecision(3) + " px", x + 4, y - 6);
}

function drawConstraints(frame) {
  doc.constraints.forEach((c, i) => {
    ctx.strokeStyle = isSel("constraint", i) ? "#e07000" : c.kind === "spring" ? "#a60" : "#333";
    ctx.lineWidth = isSel("constraint", i) ? 2.5 : 1.5;
    if (c.kind === "motor") {
      const k = ui.docToWorld[c.body];
      if (k === undefined) return;
      const s = toScreen(frame[7 * k], frame[7 * k + 1]);
      ctx.beginPath();
      ctx.arc(s[0], s[1], 9, 0.3, 5.5);
      ctx.stroke();
      return;
    }
    const a = anchor(frame, c.body1, c.anchor1), b = anchor(frame, c.body2, c.anchor2);
    if (!a || !b) return;
    const sa = toScreen(...a), sb = toScreen(...b);
    if (c.kind === "spring") ctx.setLineDash([5, 3]);
    line(sa, sb);
    ctx.setLineDash([]);
    for (const s of [sa, sb]) {
      ctx.beginPath();
      ctx.arc(s[0], s[1], 3, 0, 2 * Math.PI);
      ctx.stroke();
    }
  });
}

// An anchor (body-local, raw) in the world; index 255 is the world itself.
function anchor(frame, bodyIndex, a) {
  if (bodyIndex === NONE) return [a[0] / FX, a[1] / FX];
  const k = ui.docToWorld[bodyIndex];
  if (k === undefined) return null;
  return localToWorld(pose(frame, k), a[0] / FX, a[1] / FX);
}

function isSel(kind, index) {
  return ui.selection && ui.selection.kind === kind && ui.selection.index === index;
}

function showMetrics() {
  const m = E.metrics();
  const rows = [["tick", m[7].toFixed(0)], ["energy: kinetic", m[0].toPrecision(6)], ["potential", m[1].toPrecision(6)],
    ["total", m[2].toPrecision(6)], ["momentum x", m[3].toPrecision(6)], ["momentum y", m[4].toPrecision(6)],
    ["angular momentum", m[5].toPrecision(6)], ["penetration max (px)", m[6].toPrecision(4)],
    ["contact points", (E.contacts().length / 5).toFixed(0)],
    ["events fired", m[8].toFixed(0) + (m[9] >= 0 ? ` (last: event ${m[9]})` : "")]];
  if (ui.tickMs.length) {
    const sorted = ui.tickMs.slice().sort((a, b) => a - b);
    rows.push(["ms per tick (median)", sorted[sorted.length >> 1].toFixed(3)]);
  }
  $("metrics").innerHTML = rows.map(r => `<tr><td>${r[0]}</td><td>${r[1]}</td></tr>`).join("");
  $("tick").textContent = "tick " + m[7].toFixed(0);
}

// ---------- playing ----------

function tickOnce() {
  const t0 = performance.now();
  const msg = E.tick(1);
  ui.tickMs.push(performance.now() - t0);
  if (ui.tickMs.length > 120) ui.tickMs.shift();
  if (msg) {
    stop();
    status("The engine stopped: " + msg);
  }
}

function loop() {
  if (!ui.playing) return;
  tickOnce();
  if (ui.replay) ui.replay.frame = Math.min(ui.replay.frame + 1, ui.replay.trace.tick.length - 1);
  draw();
  requestAnimationFrame(loop);
}

function play() {
  if (ui.playing) { stop(); return; }
  ui.playing = true;
  $("play").textContent = "Pause";
  $("play").classList.add("on");
  requestAnimationFrame(loop);
}

function stop() {
  ui.playing = false;
  $("play").textContent = "Play";
  $("play").classList.remove("on");
}

// ---------- the mouse ----------

function eventPoint(e) {
  const r = canvas.getBoundingClientRect();
  return toWorld(e.clientX - r.left, e.clientY - r.top);
}

function worldBodyAt(x, y) {
  return E.bodyAt(x, y);
}

canvas.addEventListener("mousedown", e => {
  const [x, y] = eventPoint(e);
  const k = worldBodyAt(x, y);
  const docIndex = k >= 0 ? ui.geometry.bodies[k].doc : -1;
  const tickNow = E.metrics()[7];
  switch (ui.tool) {
    case "select":
      if (tickNow > 0 || ui.playing) {   // a world in motion: drag with the engine's mouse joint
        if (k >= 0 && E.dragStart(k, x, y)) ui.drag = { live: true };
        if (docIndex >= 0) { ui.selection = { kind: "body", index: docIndex }; showProps(); }
        draw();
        return;
      }
      if (docIndex >= 0) {
        ui.selection = { kind: "body", index: docIndex };
        const p = doc.bodies[docIndex].position;
        ui.drag = { index: docIndex, dx: p[0] / FX - x, dy: p[1] / FX - y, before: JSON.stringify(doc), moved: false };
      } else {
        ui.selection = pickOther(x, y);
      }
      showProps();
      draw();
      return;
    case "rectangle": case "circle": case "polygon": case "multi":
      addBody(ui.tool, snap(x), snap(y));
      return;
    case "joint": case "spring":
      if (!ui.pending) {
        ui.pending = { body: docIndex >= 0 ? docIndex : NONE, from: [snap(x), snap(y)] };
        status(`${ui.tool}: now click the second body (or empty space for the world)`);
      } else {
        addPair(ui.tool, ui.pending, docIndex >= 0 ? docIndex : NONE, snap(x), snap(y));
        ui.pending = null;
      }
      draw();
      return;
    case "motor":
      if (docIndex >= 0) addMotor(docIndex);
      return;
    case "segment":
      ui.pending = { from: [snap(x), snap(y)], to: [snap(x), snap(y)] };
      return;
    case "emitter":
      addEmitter(snap(x), snap(y));
      return;
    case "event":
      if (docIndex >= 0) addEvent(docIndex);
      return;
  }
});

canvas.addEventListener("mousemove", e => {
  const [x, y] = eventPoint(e);
  if (ui.drag && ui.drag.live) {
    E.dragMove(x, y);
    if (!ui.playing) draw();
  } else if (ui.drag) {
    const b = doc.bodies[ui.drag.index];
    b.position = [Math.round(snap(x + ui.drag.dx) * FX), Math.round(snap(y + ui.drag.dy) * FX)];
    ui.drag.moved = true;
    rebuild();
  } else if (ui.pending && ui.pending.from) {
    ui.pending.to = [snap(x), snap(y)];
    draw();
  }
});

window.addEventListener("mouseup", () => {
  if (ui.drag && ui.drag.live) {
    E.dragEnd();
  } else if (ui.drag && ui.drag.moved) {
    ui.undo.push(ui.drag.before);
    ui.redo = [];
    showProps();
  }
  ui.drag = null;
  if (ui.tool === "segment" && ui.pending && ui.pending.to) {
    const p = ui.pending;
    ui.pending = null;
    if (p.from[0] !== p.to[0] || p.from[1] !== p.to[1]) addSegment(p.from, p.to);
    draw();
  }
});

canvas.addEventListener("wheel", e => {
  e.preventDefault();
  const z = Math.max(-3, Math.min(3, +$("zoom").value - Math.sign(e.deltaY) * 0.1));
  $("zoom").value = z;
  setZoom();
});

// A joint, spring or segment near a point (within 6 screen px).
function pickOther(x, y) {
  const frame = E.frame();
  const near = (a, b) => distToSegment([x, y], a, b) * ui.zoom < 6;
  for (let i = 0; i < doc.constraints.length; i++) {
    const c = doc.constraints[i];
    if (c.kind === "motor") continue;
    const a = anchor(frame, c.body1, c.anchor1), b = anchor(frame, c.body2, c.anchor2);
    if (a && b && near(a, b)) return { kind: "constraint", index: i };
  }
  const segs = doc.landscape ? doc.landscape.segments : [];
  for (let i = 0; i < segs.length; i++) {
    if (near([segs[i][0] / FX, segs[i][1] / FX], [segs[i][2] / FX, segs[i][3] / FX])) return { kind: "segment", index: i };
  }
  for (let i = 0; i < doc.emitters.length; i++) {
    const p = doc.emitters[i].position1;
    if (Math.hypot(p[0] / FX - x, p[1] / FX - y) * ui.zoom < 8) return { kind: "emitter", index: i };
  }
  return null;
}

function distToSegment(p, a, b) {
  const dx = b[0] - a[0], dy = b[1] - a[1], l2 = dx * dx + dy * dy;
  const t = l2 ? Math.max(0, Math.min(1, ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2)) : 0;
  return Math.hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy);
}

// ---------- adding records ----------

function addBody(kind, x, y) {
  const size = Math.max(1, +$("new-size").value || 40);
  const flags = $("new-static").checked ? FLAG_ROTATES : FLAG_DYNAMIC | FLAG_ROTATES;
  edit(d => {
    let shape;
    if (kind === "rectangle") shape = pushShape(d, rectShape(size, size));
    else if (kind === "circle") shape = pushShape(d, circleShape(size / 2));
    else if (kind === "polygon") shape = pushShape(d, regularShape(size / 2, Math.max(3, Math.min(32, +$("new-corners").value || 6))));
    else {
      // A bar with a ball (a 12-gon) at each end: the parts share the body's frame.
      const bar = pushShape(d, rectShape(size * 2, size / 4));
      const left = pushShape(d, offsetShape(regularShape(size / 4, 12), -size, 0));
      const right = pushShape(d, offsetShape(regularShape(size / 4, 12), size, 0));
      shape = pushShape(d, { kind: "multi", parts: [bar, left, right] });
    }
    d.bodies.push(body(shape, x, y, flags));
    ui.selection = { kind: "body", index: d.bodies.length - 1 };
  });
}

function offsetShape(s, dx, dy) {
  s.vertices = s.vertices.map((v, i) => v + Math.round((i % 2 ? dy : dx) * FX));
  return s;
}

function pushShape(d, s) {
  d.shapes.push(s);
  return d.shapes.length - 1;
}

// Anchors are stored in the body's frame (its document pose).
function localAnchor(d, bodyIndex, x, y) {
  if (bodyIndex === NONE) return [Math.round(x * FX), Math.round(y * FX)];
  const b = d.bodies[bodyIndex], a = -b.angle / FX2;
  const dx = x - b.position[0] / FX, dy = y - b.position[1] / FX;
  return [Math.round((Math.cos(a) * dx - Math.sin(a) * dy) * FX), Math.round((Math.sin(a) * dx + Math.cos(a) * dy) * FX)];
}

function addPair(kind, first, second, x, y) {
  if (first.body === NONE && second === NONE) { status("Pick at least one body"); return; }
  edit(d => {
    if (kind === "joint") {
      d.constraints.push({ kind: "joint", body1: first.body, anchor1: localAnchor(d, first.body, x, y), body2: second,
                           anchor2: localAnchor(d, second, x, y), fixed: 0, userData: "" });
    } else {
      const len = Math.hypot(x - first.from[0], y - first.from[1]);
      d.constraints.push({ kind: "spring", body1: first.body, anchor1: localAnchor(d, first.body, ...first.from), body2: second,
                           anchor2: localAnchor(d, second, x, y), restLength: Math.round(len * FX), coefficient: 20 * FX, userData: "" });
    }
    ui.selection = { kind: "constraint", index: d.constraints.length - 1 };
  });
  status("");
}

function addMotor(bodyIndex) {
  edit(d => {
    d.constraints.push({ kind: "motor", body: bodyIndex, targetA: -2 * FX2, targetB: 0, maxForce: 1000 * FX, flags: 1, userData: "" });
    ui.selection = { kind: "constraint", index: d.constraints.length - 1 };
  });
}

function addSegment(a, b) {
  edit(d => {
    if (!d.landscape) d.landscape = { segments: [], material: material({ kind: "polygon", vertices: [] }) };
    d.landscape.segments.push([Math.round(a[0] * FX), Math.round(a[1] * FX), Math.round(b[0] * FX), Math.round(b[1] * FX), 0]);
    ui.selection = { kind: "segment", index: d.landscape.segments.length - 1 };
  });
}

function addEmitter(x, y) {
  edit(d => {
    const p = [Math.round(x * FX), Math.round(y * FX)];
    d.emitters.push({ body: NONE, axesFixed: 0, position1: p, position2: p.slice(), emitAngle: Math.round(-Math.PI / 2 * FX2),
      emitAngleSpread: Math.round(0.3 * FX2), speed: 200 * FX, speedSpread: 20 * FX, rate: 30 * FX, rateSpread: 0,
      lifetime: 3 * FX, lifetimeSpread: 0, maxParticles: 200, elasticity: Math.round(0.3 * FX), gravityFactor: FX, damping: 0, userData: "" });
    ui.selection = { kind: "emitter", index: d.emitters.length - 1 };
  });
}

function addEvent(bodyIndex) {
  edit(d => {
    d.events.push({ type: 4, legacyId: d.events.length, triggerOnce: 0, bodyFilter: bodyIndex, shapeFilter: NONE,
                    constraintFilter: NONE, targets: [1, 1, 1, 1], userData: "" });
    ui.selection = { kind: "event", index: d.events.length - 1 };
  });
}

// ---------- the properties panel ----------

// The event types of a world file (org.emini.io.PhyEvent); targets A to D are raw values.
const EVENT_TYPES = [[0, "0 body position (A..D: min x, min y, max x, max y)"], [1, "1 body velocity (A, B: speed² range)"],
  [2, "2 body rotation (A, B: angle range)"], [3, "3 angular velocity (A, B)"], [4, "4 collision (A..D > 0: above, right, below, left)"],
  [5, "5 sensor"], [6, "6 relative collision (A direction, B min cosine)"], [10, "10 constraint force (A, B: range)"]];

// Each field: [label, read from the record, write to it (in the user's units), kind].
function fieldsOf(sel) {
  const num = (get, set) => ({ get, set });
  if (sel.kind === "body") {
    const flag = f => ({ get: b => (b.flags & f) !== 0, set: (b, v) => { b.flags = v ? b.flags | f : b.flags & ~f; }, check: true });
    const notFlag = f => ({ get: b => (b.flags & f) === 0, set: (b, v) => { b.flags = v ? b.flags & ~f : b.flags | f; }, check: true });
    return [
      ["x (px)", num(b => b.position[0] / FX, (b, v) => { b.position[0] = Math.round(v * FX); })],
      ["y (px)", num(b => b.position[1] / FX, (b, v) => { b.position[1] = Math.round(v * FX); })],
      ["angle (rad)", num(b => b.angle / FX2, (b, v) => { b.angle = Math.round(v * FX2); })],
      ["velocity x", num(b => b.velocity[0] / FX, (b, v) => { b.velocity[0] = Math.round(v * FX); })],
      ["velocity y", num(b => b.velocity[1] / FX, (b, v) => { b.velocity[1] = Math.round(v * FX); })],
      ["dynamic", flag(FLAG_DYNAMIC)], ["rotates", flag(FLAG_ROTATES)],
      ["interacting", notFlag(FLAG_NOT_INTERACTING)], ["gravity", notFlag(FLAG_NO_GRAVITY)],
      ["layers (bits)", { get: b => b.layers.toString(2), set: (b, v) => { b.layers = parseInt(v, 2) | 0; }, text: true }],
      ["name", { get: b => b.userData, set: (b, v) => { b.userData = v; }, text: true }]
    ];
  }
  if (sel.kind === "shape") {
    const s = doc.shapes[sel.index];
    const common = [
      ["friction", num(s => s.friction / FX, (s, v) => { s.friction = Math.round(v * FX); })],
      ["elasticity", num(s => s.elasticity / FX, (s, v) => { s.elasticity = Math.round(v * FX); })],
      ["mass", num(s => s.mass / FX, (s, v) => { s.mass = Math.round(v * FX); })]];
    if (s.kind === "multi") {
      return [["parts (shape indices)", { get: s => s.parts.join(" "), set: (s, v) => { s.parts = v.trim().split(/[\s,]+/).map(Number); }, text: true }]];
    }
    if (s.kind === "circle") {
      return [["radius (px)", num(s => Math.hypot(s.vertices[0], s.vertices[1]) / FX, (s, v) => { s.vertices = [Math.round(v) * FX, 0]; })]].concat(common);
    }
    return [["vertices (x y, px)", { get: s => verticesText(s.vertices), set: (s, v) => { s.vertices = parseVertices(v); }, text: true, polygon: true }]].concat(common);
  }
  if (sel.kind === "constraint") {
    const c = doc.constraints[sel.index];
    if (c.kind === "motor") {
      return [["body", num(c => c.body, (c, v) => { c.body = v | 0; })],
        ["rotational", { get: c => (c.flags & 1) !== 0, set: (c, v) => { c.flags = v ? c.flags | 1 : c.flags & ~1; }, check: true }],
        ["target A (speed)", num(c => c.targetA / ((c.flags & 1) ? FX2 : FX), (c, v) => { c.targetA = Math.round(v * ((c.flags & 1) ? FX2 : FX)); })],
        ["target B (linear: vy)", num(c => c.targetB / FX, (c, v) => { c.targetB = Math.round(v * FX); })],
        ["max force (per tick)", num(c => c.maxForce / FX, (c, v) => { c.maxForce = Math.round(v * FX); })],
        ["flags", num(c => c.flags, (c, v) => { c.flags = v | 0; })]];
    }
    const anchor = k => ({ get: c => `${c[k][0] / FX} ${c[k][1] / FX}`, text: true,
      set: (c, v) => { const xy = v.trim().split(/[\s,]+/).map(Number); if (xy.length === 2 && xy.every(isFinite)) c[k] = xy.map(n => Math.round(n * FX)); } });
    const f = [["body 1 (255: world)", num(c => c.body1, (c, v) => { c.body1 = v | 0; })],
      ["anchor 1 (x y in body 1)", anchor("anchor1")],
      ["body 2 (255: world)", num(c => c.body2, (c, v) => { c.body2 = v | 0; })],
      ["anchor 2 (x y in body 2)", anchor("anchor2")]];
    if (c.kind === "spring") {
      f.push(["rest length (px)", num(c => c.restLength / FX, (c, v) => { c.restLength = Math.round(v * FX); })],
             ["coefficient (0: rigid)", num(c => c.coefficient / FX, (c, v) => { c.coefficient = Math.round(v * FX); })]);
    } else {
      f.push(["fixed (no rotation)", { get: c => c.fixed > 0, set: (c, v) => { c.fixed = v ? 1 : 0; }, check: true }]);
    }
    return f;
  }
  if (sel.kind === "segment") {
    const at = (i) => num(g => g[i] / FX, (g, v) => { g[i] = Math.round(v * FX); });
    return [["start x", at(0)], ["start y", at(1)], ["end x", at(2)], ["end y", at(3)],
      ["face (0 none, 1 left, 2 right)", num(g => g[4], (g, v) => { g[4] = v | 0; })]];
  }
  if (sel.kind === "emitter") {
    const fx = k => num(p => p[k] / FX, (p, v) => { p[k] = Math.round(v * FX); });
    const a2 = k => num(p => p[k] / FX2, (p, v) => { p[k] = Math.round(v * FX2); });
    return [["body (255: world)", num(p => p.body, (p, v) => { p.body = v | 0; })], ["emit angle (rad)", a2("emitAngle")],
      ["angle spread", a2("emitAngleSpread")], ["speed", fx("speed")], ["speed spread", fx("speedSpread")], ["rate (1/s)", fx("rate")],
      ["lifetime (s)", fx("lifetime")], ["capacity", num(p => p.maxParticles, (p, v) => { p.maxParticles = v | 0; })],
      ["elasticity", fx("elasticity")], ["gravity factor", fx("gravityFactor")], ["damping", fx("damping")]];
  }
  if (sel.kind === "event") {
    return [["type", { get: e => e.type, set: (e, v) => { e.type = v | 0; }, options: EVENT_TYPES }],
      ["body filter (255: any)", num(e => e.bodyFilter, (e, v) => { e.bodyFilter = v | 0; })],
      ["targets A B C D (raw)", { get: e => e.targets.join(" "), set: (e, v) => { e.targets = v.trim().split(/\s+/).map(x => x | 0); }, text: true }],
      ["once", { get: e => e.triggerOnce > 0, set: (e, v) => { e.triggerOnce = v ? 1 : 0; }, check: true }]];
  }
  return [];
}

function verticesText(v) {
  const out = [];
  for (let i = 0; i < v.length; i += 2) out.push(`${+(v[i] / FX).toFixed(3)} ${+(v[i + 1] / FX).toFixed(3)}`);
  return out.join(", ");
}

function parseVertices(text) {
  const nums = text.split(/[\s,]+/).filter(s => s.length).map(Number);
  return nums.map(n => Math.round(n * FX));
}

function record(sel) {
  switch (sel.kind) {
    case "body": return doc.bodies[sel.index];
    case "shape": return doc.shapes[sel.index];
    case "constraint": return doc.constraints[sel.index];
    case "segment": return doc.landscape.segments[sel.index];
    case "emitter": return doc.emitters[sel.index];
    case "event": return doc.events[sel.index];
  }
  return null;
}

function showProps() {
  const box = $("props");
  const sel = ui.selection;
  if (!sel || !record(sel)) {
    box.innerHTML = "<em>Nothing selected. Click a body, joint, spring, segment or emitter.</em>";
    return;
  }
  box.innerHTML = "";
  const title = document.createElement("div");
  title.textContent = `${sel.kind} ${sel.index}` + (sel.kind === "constraint" ? ` (${doc.constraints[sel.index].kind})` : "")
    + (sel.kind === "shape" ? ` (${doc.shapes[sel.index].kind})` : "");
  box.appendChild(title);
  const problem = document.createElement("div");
  problem.className = "problem";
  for (const [label, f] of fieldsOf(sel)) {
    const row = document.createElement("label");
    row.textContent = label;
    const input = document.createElement(f.options ? "select" : "input");
    input.dataset.field = label;
    if (f.options) {
      for (const [v, text] of f.options) {
        const o = document.createElement("option");
        o.value = v;
        o.textContent = text;
        input.appendChild(o);
      }
      input.value = f.get(record(sel));
    } else if (f.check) { input.type = "checkbox"; input.checked = f.get(record(sel)); }
    else if (f.text) { input.type = "text"; input.value = f.get(record(sel)); }
    else { input.type = "number"; input.step = "any"; input.value = +f.get(record(sel)).toPrecision(7); }
    if (f.polygon) {
      // The engine's own validation, as the vertices are typed.
      input.addEventListener("input", () => {
        const px = parseVertices(input.value).map(v => v / FX);
        problem.textContent = px.length % 2 ? "an odd count of coordinates" : E.polygonProblem(px);
      });
    }
    input.addEventListener("change", () => {
      const value = f.check ? input.checked : f.text ? input.value : +input.value;
      if (!f.check && !f.text && !f.options && !isFinite(value)) { problem.textContent = label + ": not a number"; return; }
      const s = ui.selection;
      edit(() => f.set(record(s), value));
      ui.selection = s;
      showProps();
    });
    row.appendChild(input);
    box.appendChild(row);
  }
  box.appendChild(problem);
  const buttons = document.createElement("div");
  if (sel.kind === "body") {
    buttons.appendChild(button("Edit its shape", () => { ui.selection = { kind: "shape", index: doc.bodies[sel.index].shape }; showProps(); draw(); }));
  }
  buttons.appendChild(button("Delete", () => deleteSelection()));
  box.appendChild(buttons);
  // A shape's messages from the engine's build (a refused polygon is listed there).
  if (sel.kind === "shape") {
    const msgs = ui.geometry.unsupported.filter(u => u.indexOf("shape " + sel.index) >= 0);
    if (msgs.length) problem.textContent = msgs.join("; ");
  }
}

function button(text, action) {
  const b = document.createElement("button");
  b.textContent = text;
  b.addEventListener("click", action);
  return b;
}

// Deleting a body deletes what refers to it and renumbers the rest.
function deleteSelection() {
  const sel = ui.selection;
  if (!sel) return;
  edit(d => {
    if (sel.kind === "body") {
      const i = sel.index, fix = v => (v === NONE ? NONE : v > i ? v - 1 : v);
      d.bodies.splice(i, 1);
      d.constraints = d.constraints.filter(c => c.kind === "motor" ? c.body !== i : c.body1 !== i && c.body2 !== i);
      d.constraints.forEach(c => { if (c.kind === "motor") c.body = fix(c.body); else { c.body1 = fix(c.body1); c.body2 = fix(c.body2); } });
      d.events = d.events.filter(e => e.bodyFilter !== i);
      d.events.forEach(e => { e.bodyFilter = fix(e.bodyFilter); });
      d.emitters = d.emitters.filter(p => p.body !== i);
      d.emitters.forEach(p => { p.body = fix(p.body); });
    } else if (sel.kind === "constraint") d.constraints.splice(sel.index, 1);
    else if (sel.kind === "segment") d.landscape.segments.splice(sel.index, 1);
    else if (sel.kind === "emitter") d.emitters.splice(sel.index, 1);
    else if (sel.kind === "event") d.events.splice(sel.index, 1);
    ui.selection = null;
  });
}

// ---------- world settings, zoom ----------

function readWorldFields() {
  const s = doc.settings || (doc.settings = { gravity: [0, 0], dampingLinear: 0, dampingRotational: 0 });
  $("gravity-x").value = s.gravity[0] / FX;
  $("gravity-y").value = s.gravity[1] / FX;
  $("damping").value = s.dampingLinear / FX;
}

for (const id of ["gravity-x", "gravity-y", "damping"]) {
  $(id).addEventListener("change", () => edit(d => {
    d.settings = d.settings || { gravity: [0, 0], dampingLinear: 0, dampingRotational: 0 };
    d.settings.gravity = [Math.round(+$("gravity-x").value * FX), Math.round(+$("gravity-y").value * FX)];
    d.settings.dampingLinear = d.settings.dampingRotational = Math.round(+$("damping").value * FX);
  }));
}
for (const id of ["tps", "iterations"]) $(id).addEventListener("change", () => { stop(); rebuild(); });

function setZoom() {
  ui.zoom = Math.pow(2, +$("zoom").value);
  draw();
}

function fit() {
  let minX = Infinity, minY = Infinity, maxX = -Infinity, maxY = -Infinity;
  const frame = E.frame();
  for (let k = 0; k < frame.length / 7; k++) {
    minX = Math.min(minX, frame[7 * k]); maxX = Math.max(maxX, frame[7 * k]);
    minY = Math.min(minY, frame[7 * k + 1]); maxY = Math.max(maxY, frame[7 * k + 1]);
  }
  if (ui.replay) {   // the whole path of a replay
    for (const b of Object.values(ui.replay.trace.bodies)) {
      b.x.forEach((x, i) => {
        if (x === null || b.y[i] === null) return;
        minX = Math.min(minX, x); maxX = Math.max(maxX, x); minY = Math.min(minY, b.y[i]); maxY = Math.max(maxY, b.y[i]);
      });
    }
  }
  for (const g of (doc.landscape ? doc.landscape.segments : [])) {
    for (const [x, y] of [[g[0], g[1]], [g[2], g[3]]]) {
      minX = Math.min(minX, x / FX); maxX = Math.max(maxX, x / FX); minY = Math.min(minY, y / FX); maxY = Math.max(maxY, y / FX);
    }
  }
  if (!isFinite(minX)) return;
  ui.camX = (minX + maxX) / 2;
  ui.camY = (minY + maxY) / 2;
  const z = Math.min(canvas.width / (maxX - minX + 200), canvas.height / (maxY - minY + 200));
  $("zoom").value = Math.max(-3, Math.min(3, Math.log2(z)));
  setZoom();
}

// ---------- files ----------

function download(name, data, type) {
  ui.lastDownload = { name, data };
  if (location.hash === "#selftest") return;
  const a = document.createElement("a");
  a.href = URL.createObjectURL(new Blob([data], { type }));
  a.download = name;
  a.click();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}

// The current document as a world file, by the engine's PhyWriter; null (and a message) if refused.
function phyBytes() {
  const msg = E.load(JSON.stringify(doc), settings().tps, settings().iterations);
  if (msg) { status("Cannot save: " + msg); return null; }
  const bytes = E.writePhy();
  if (!bytes.length) { status("Cannot save: " + E.lastError()); return null; }
  rebuild();
  return bytes instanceof Int8Array ? bytes : Int8Array.from(bytes);
}

// Reads a world file with the engine's PhyReader into the document; returns "" or the message.
function openPhy(bytes) {
  const r = JSON.parse(E.readPhy(bytes));
  if (r.error) { status("Not a world file the engine reads: " + r.error); return r.error; }
  const before = doc ? JSON.stringify(doc) : null;
  doc = r.doc;
  if (before) { ui.undo.push(before); ui.redo = []; }
  ui.selection = null;
  ui.replay = null;
  stop();
  readWorldFields();
  const msg = rebuild();
  showProps();
  return msg;
}

function openDocumentJson(text) {
  let d;
  try { d = JSON.parse(text); } catch (e) { status("Not JSON: " + e.message); return; }
  if (d.format === "emini-trace") { openTrace(d); return; }
  if (!d.document) {
    status("A scene (YAML or JSON) is converted to a world file first: ./emini harness convert -o scene.phy scene.yaml; open the .phy");
    return;
  }
  const before = JSON.stringify(doc);
  doc = d.document;
  if (d.ticksPerSecond) $("tps").value = d.ticksPerSecond;
  if (d.iterations) $("iterations").value = d.iterations;
  if (rebuild()) { doc = JSON.parse(before); rebuild(); return; }
  ui.undo.push(before);
  readWorldFields();
  showProps();
}

$("open").addEventListener("change", async () => {
  const f = $("open").files[0];
  if (!f) return;
  ui.fileName = f.name;
  if (/\.(phy|world)$/i.test(f.name)) {
    openPhy(new Int8Array(await f.arrayBuffer()));
  } else {
    openDocumentJson(await f.text());
  }
  $("open").value = "";
  fit();
});

// The name the document saves under: the opened file's, else world.phy.
function stem() {
  return (ui.fileName || "world.phy").replace(/\.[^.]*$/, "");
}

$("save-phy").addEventListener("click", () => { const b = phyBytes(); if (b) download(stem() + ".phy", b, "application/octet-stream"); });
$("save-yaml").addEventListener("click", () => {
  if (!phyBytes()) return;
  let yaml = E.sceneYaml(stem() + ".phy");
  if (!yaml) { status("Cannot convert to a scene: " + E.lastError()); return; }
  // A world file holds no tick rate or iterations: the scene gets the page's.
  yaml = yaml.replace(/^world:\n/m, `world:\n  ticksPerSecond: ${settings().tps}\n  iterations: ${settings().iterations}\n`);
  download(stem() + ".yaml", yaml, "text/yaml");
});
$("save-json").addEventListener("click", () => download("world.json",
  JSON.stringify({ format: "emini-designer", ticksPerSecond: settings().tps, iterations: settings().iterations, document: doc }, null, 1),
  "application/json"));

// ---------- replay of a trace (reports/traces/*.trace.json) ----------

// A trace holds the named bodies' poses at its sample ticks; the document's bodies named alike
// (user data "name=..." as harness convert writes them, or the plain name) are drawn at those poses.
function openTrace(trace) {
  const names = Object.keys(trace.bodies || {});
  const byName = {};
  doc.bodies.forEach((b, i) => { byName[b.userData.replace(/^name=/, "")] = i; });
  const matched = names.filter(n => n in byName);
  ui.replay = { trace, frame: 0, byName };
  const box = $("replay-box");
  box.innerHTML = "";
  const info = document.createElement("div");
  info.textContent = `${trace.scene} (${trace.source}): ${trace.tick.length} samples, ${names.length} bodies, `
    + `${matched.length} drawn on this document's bodies` + (matched.length < names.length ? "; the others as dots" : "");
  box.appendChild(info);
  const slider = document.createElement("input");
  slider.type = "range"; slider.min = 0; slider.max = trace.tick.length - 1; slider.value = 0; slider.id = "replay-slider";
  slider.addEventListener("input", () => { ui.replay.frame = +slider.value; draw(); });
  box.appendChild(slider);
  box.appendChild(button("Close replay", () => { ui.replay = null; $("replay-box").innerHTML = ""; draw(); }));
  draw();
}

function replayPoses() {
  const r = ui.replay, t = r.trace, out = [], i = r.frame;
  for (const name of Object.keys(t.bodies)) {
    const b = t.bodies[name];
    const p = { x: b.x[i], y: b.y[i], a: b.angle ? b.angle[i] : 0, vx: b.vx ? b.vx[i] : 0, vy: b.vy ? b.vy[i] : 0, w: 0, sleeping: false };
    if (name in r.byName) out[r.byName[name]] = p;
    else if (p.x !== null) {
      const s = toScreen(p.x, p.y);
      ctx.fillStyle = "#c60";
      ctx.beginPath();
      ctx.arc(s[0], s[1], 4, 0, 2 * Math.PI);
      ctx.fill();
    }
  }
  const slider = $("replay-slider");
  if (slider) slider.value = i;
  $("tick").textContent = `replay tick ${t.tick[i]}`;
  return out;
}

// ---------- wiring ----------

$("new").addEventListener("click", () => {
  const before = JSON.stringify(doc);
  doc = newDocument();
  ui.undo.push(before);
  ui.selection = null;
  ui.replay = null;
  stop();
  readWorldFields();
  rebuild();
  showProps();
});
$("undo").addEventListener("click", undo);
$("redo").addEventListener("click", redo);
$("play").addEventListener("click", play);
$("step").addEventListener("click", () => { stop(); tickOnce(); draw(); });
$("reset").addEventListener("click", () => { stop(); rebuild(); });
$("zoom").addEventListener("input", setZoom);
$("fit").addEventListener("click", fit);
for (const id of ["show-contacts", "show-normals", "show-velocities", "show-joints"]) $(id).addEventListener("change", draw);
document.querySelectorAll("#tools button[data-tool]").forEach(b => b.addEventListener("click", () => {
  document.querySelectorAll("#tools button[data-tool]").forEach(o => o.classList.remove("on"));
  b.classList.add("on");
  ui.tool = b.dataset.tool;
  ui.pending = null;
  status("");
}));
window.addEventListener("keydown", e => {
  if (e.target.tagName === "INPUT") return;
  if ((e.ctrlKey || e.metaKey) && e.key === "z") { e.preventDefault(); undo(); }
  if ((e.ctrlKey || e.metaKey) && (e.key === "y" || e.key === "Z")) { e.preventDefault(); redo(); }
  if (e.key === "Delete") deleteSelection();
  if (e.key === " ") { e.preventDefault(); play(); }
});

async function start() {
  try {
    await loadEngine();
  } catch (e) {
    status("The engine did not load (this page needs a browser with WebAssembly GC: Chromium 119+, Firefox 120+): " + e);
    return;
  }
  doc = newDocument();
  readWorldFields();
  rebuild();
  fit();
  // A replay the dashboard links to: #replay=<dashboard replay script>&scene=<id> (see designer/README.md).
  const hash = new URLSearchParams(location.hash.slice(1));
  if (hash.has("replay")) openDashboardReplay(hash.get("replay"), hash.get("scene"));
  if (hash.has("open")) openExported(hash.get("open"));
  if (location.hash === "#selftest" && window.runSelfTest) window.runSelfTest();
}

// A scene file read by the harness (./emini designer SCENE writes it as a script: SceneExport).
function openExported(src) {
  const s = document.createElement("script");
  s.src = src;
  s.onload = () => {
    const x = window.EMINI_OPEN;
    if (!x) { status("Nothing to open in " + src); return; }
    openDocumentJson(JSON.stringify(x));
    const report = $("report");
    for (const n of x.notConverted || []) li(report, "not in a world file: " + n);
    fit();
    if (new URLSearchParams(location.hash.slice(1)).has("report")) {
      const before = E.frame().slice();
      E.tick(30);
      const after = E.frame();
      let moved = 0;
      for (let k = 0; k < after.length; k += 7) if (after[k] !== before[k] || after[k + 1] !== before[k + 1]) moved++;
      draw();
      const pre = $("selftest-result");
      pre.textContent = JSON.stringify({ ok: doc.bodies.length > 0 && ui.geometry.bodies.length >= doc.bodies.length && moved > 0,
        scene: x.scene, documentBodies: doc.bodies.length, worldBodies: ui.geometry.bodies.length, movedIn30Ticks: moved,
        ticksPerSecond: +$("tps").value, notBuilt: ui.geometry.unsupported.length, status: $("status").textContent });
      pre.hidden = false;
    }
  };
  s.onerror = () => status("Cannot read " + src);
  document.head.appendChild(s);
}

// The dashboard's replay data (reports/dashboard/replay/rN.js, window.EMINI_REPLAY[scene] with the
// scene's shapes and the thinned trace) is a script, so it loads from the file system without a
// server. Its bodies become a document (named as in the scene) and the trace poses them.
function openDashboardReplay(src, scene) {
  const s = document.createElement("script");
  s.src = src;
  s.onload = () => {
    const r = (window.EMINI_REPLAY || {})[scene];
    if (!r) { status("No replay of " + scene + " in " + src); return; }
    const before = JSON.stringify(doc);
    doc = replayDocument(r);
    if (rebuild()) { doc = JSON.parse(before); rebuild(); return; }
    ui.undo.push(before);
    const bodies = {};
    for (const [name, b] of Object.entries(r.engine.bodies)) bodies[name] = { x: b.x, y: b.y, angle: b.a };
    openTrace({ format: "emini-trace", scene, source: r.engine.source, tick: r.engine.time.map((t, i) => i), bodies });
    fit();
    if (new URLSearchParams(location.hash.slice(1)).has("report")) reportReplay();
  };
  s.onerror = () => status("Cannot read " + src);
  document.head.appendChild(s);
}

// With &report in the address (check-designer.sh): plays the replay to its end and reports what it drew.
function reportReplay() {
  const r = ui.replay, names = Object.keys(r.trace.bodies);
  const drawn = names.filter(n => n in r.byName).length;
  const first = replayPoses(), x0 = first.map(p => p && p.x);
  r.frame = r.trace.tick.length - 1;
  draw();
  const last = replayPoses();
  const moved = last.filter((p, i) => p && x0[i] !== undefined && (p.x !== x0[i])).length;
  const inView = last.filter(p => {
    const q = p && toScreen(p.x, p.y);
    return q && q[0] >= 0 && q[0] <= canvas.width && q[1] >= 0 && q[1] <= canvas.height;
  }).length;
  const pre = $("selftest-result");
  pre.textContent = JSON.stringify({ ok: drawn === names.length && names.length > 0 && r.trace.tick.length > 1 && inView === drawn,
    scene: r.trace.scene, traceBodies: names.length, drawn, inView, frames: r.trace.tick.length, movedBodies: moved,
    documentBodies: doc.bodies.length, status: $("status").textContent });
  pre.hidden = false;
}

function replayDocument(r) {
  const d = newDocument();
  d.shapes = [];
  d.bodies = [];
  const polygon = (v, ox, oy, oa) => {
    const c = Math.cos(oa || 0), sn = Math.sin(oa || 0), out = [];
    for (const [x, y] of v) out.push(Math.round((ox + c * x - sn * y) * FX), Math.round((oy + sn * x + c * y) * FX));
    return material({ kind: "polygon", vertices: out });
  };
  const shapeOf = (sh, ox, oy, oa) => {
    if (sh.kind === "circle") {
      if (!ox && !oy) return pushShape(d, circleShape(sh.r));
      const v = [];
      for (let i = 0; i < 16; i++) v.push([sh.r * Math.cos(i * Math.PI / 8), sh.r * Math.sin(i * Math.PI / 8)]);
      return pushShape(d, polygon(v, ox, oy, 0));
    }
    if (sh.kind === "multi") {
      const parts = sh.parts.map(p => shapeOf(p, p.ox, p.oy, p.oa));
      return pushShape(d, { kind: "multi", parts });
    }
    return pushShape(d, polygon(sh.v, ox || 0, oy || 0, oa || 0));
  };
  for (const [name, b] of Object.entries(r.bodies)) {
    const shape = shapeOf(b.shape, 0, 0, 0);
    const rec = body(shape, b.x, b.y, b.static ? FLAG_ROTATES : FLAG_DYNAMIC | FLAG_ROTATES);
    rec.angle = Math.round((b.angle || 0) * FX2);
    rec.userData = name;
    d.bodies.push(rec);
  }
  return d;
}

start();
