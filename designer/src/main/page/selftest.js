// The page's self-test (index.html#selftest, run by designer/src/test/browser/check-designer.sh in
// headless Chromium): plays the library scenes of ../check/check-data.js (written on the JVM by
// ParityCheck) and compares every tick's body state with the JVM's bit for bit, times the first
// scene, then builds a small world through the page's own controls, saves it as .phy with the Save
// button, opens the file again and checks that it reads back to the same document and plays the same.
// The result goes to <pre id="selftest-result"> as JSON.
"use strict";

window.runSelfTest = function () {
  const s = document.createElement("script");
  s.src = "../check/check-data.js";
  s.onload = () => selfTest().catch(e => report({ ok: false, error: "self-test failed: " + e + "\n" + e.stack }));
  s.onerror = () => report({ ok: false, error: "no ../check/check-data.js (run ParityCheck first)" });
  document.head.appendChild(s);
};

function report(result) {
  const pre = $("selftest-result");
  pre.textContent = JSON.stringify(result);
  pre.hidden = false;
}

const f32 = new Float32Array(1);
const u32 = new Uint32Array(f32.buffer);

function bitsOf(v) {
  f32[0] = v;
  return u32[0] | 0;
}

// FNV-1a over the floats' bits, as ParityCheck.hash computes it on the JVM.
function hashFrame(arrays) {
  let h = 0x811C9DC5 | 0;
  for (const a of arrays) {
    for (let i = 0; i < a.length; i++) h = Math.imul(h ^ bitsOf(a[i]), 0x01000193);
  }
  return h;
}

function base64Bytes(b64) {
  const bin = atob(b64);
  const out = new Int8Array(bin.length);
  for (let i = 0; i < bin.length; i++) out[i] = bin.charCodeAt(i);
  return out;
}

function bytesBase64(bytes) {
  let s = "";
  for (let i = 0; i < bytes.length; i++) s += String.fromCharCode(bytes[i] & 255);
  return btoa(s);
}

function fail(list, what) {
  list.push(what);
}

async function selfTest() {
  const result = { ok: true, scenes: [], problems: [] };
  const check = window.EMINI_CHECK;
  // 1. The library scenes, tick by tick against the JVM.
  for (const sc of check.scenes) {
    const msg = openPhy(base64Bytes(sc.phy));
    $("tps").value = sc.ticksPerSecond;
    $("iterations").value = sc.iterations;
    rebuild();
    const r = { file: sc.file, bodies: E.frame().length / 7, ticks: check.ticks, identicalTicks: 0, firstDifferentTick: -1 };
    if (msg) fail(result.problems, sc.file + ": " + msg);
    for (let t = 0; t < check.ticks; t++) {
      E.tick(1);
      if (hashFrame([E.frame(), E.particles()]) === sc.hashes[t]) r.identicalTicks++;
      else if (r.firstDifferentTick < 0) r.firstDifferentTick = t + 1;
    }
    const last = E.frame();
    let maxDiff = 0, bitsDiffer = 0;
    for (let i = 0; i < last.length; i++) {
      if (bitsOf(last[i]) !== sc.lastBits[i]) {
        bitsDiffer++;
        f32[0] = 0;
        u32[0] = sc.lastBits[i];
        maxDiff = Math.max(maxDiff, Math.abs(last[i] - f32[0]));
      }
    }
    r.lastTickFloatsDiffering = bitsDiffer;
    r.lastTickMaxDifference = maxDiff;
    if (last.length !== sc.lastBits.length || r.identicalTicks !== check.ticks || bitsDiffer) {
      fail(result.problems, `${sc.file}: not bit-identical (first differing tick ${r.firstDifferentTick}, `
        + `${bitsDiffer} floats differ at the last tick, by up to ${maxDiff})`);
    }
    result.scenes.push(r);
  }
  // 2. The first scene timed as the JVM timed it: a warm-up world, then a fresh one.
  const timed = check.scenes[0];
  openPhy(base64Bytes(timed.phy));
  $("tps").value = timed.ticksPerSecond;
  $("iterations").value = timed.iterations;
  rebuild();
  E.tick(timed.timedTicks);
  rebuild();
  const t0 = performance.now();
  E.tick(timed.timedTicks);
  const ms = (performance.now() - t0) / timed.timedTicks;
  result.timing = { file: timed.file, bodies: timed.bodies, ticks: timed.timedTicks, browserMsPerTick: +ms.toFixed(3),
                    jvmMsPerTick: +timed.jvmMsPerTick.toFixed(3) };
  await uiTest(result);
  result.ok = result.problems.length === 0;
  report(result);
}

// ---------- the page's controls ----------

function click(id) {
  $(id).dispatchEvent(new MouseEvent("click", { bubbles: true }));
}

function tool(name) {
  document.querySelector(`#tools button[data-tool="${name}"]`).click();
}

function mouse(type, x, y) {
  const [sx, sy] = toScreen(x, y);
  const r = canvas.getBoundingClientRect();
  const target = type === "mouseup" ? window : canvas;
  target.dispatchEvent(new MouseEvent(type, { clientX: r.left + sx, clientY: r.top + sy, bubbles: true }));
}

function clickAt(x, y) {
  mouse("mousedown", x, y);
  mouse("mouseup", x, y);
}

function setField(label, value) {
  const input = document.querySelector(`#props input[data-field="${label}"]`);
  if (!input) throw new Error("no field " + label);
  if (input.type === "checkbox") input.checked = value; else input.value = value;
  input.dispatchEvent(new Event("input"));
  input.dispatchEvent(new Event("change"));
}

function setInput(id, value) {
  $(id).value = value;
  $(id).dispatchEvent(new Event("change"));
}

async function uiTest(result) {
  const p = result.problems;
  const u = result.ui = {};
  click("new");
  setInput("tps", 60);
  setInput("iterations", 8);
  ui.camX = 0; ui.camY = 0; $("zoom").value = 0; setZoom();
  const start = doc.bodies.length;
  // Bodies: a static rectangle, a rectangle, a circle, a hexagon and a multi-shape.
  $("new-static").checked = true;
  $("new-size").value = 60;
  tool("rectangle"); clickAt(-200, 40);
  $("new-static").checked = false;
  $("new-size").value = 30;
  clickAt(-200, -20);
  tool("circle"); clickAt(150, -100);
  tool("polygon"); $("new-corners").value = 6; clickAt(250, -100);
  tool("multi"); clickAt(0, -150);
  u.bodiesAdded = doc.bodies.length - start;
  if (u.bodiesAdded !== 5) fail(p, "the tools added " + u.bodiesAdded + " bodies, not 5");
  // The multi-shape built as one engine body of three parts.
  const multi = ui.geometry.bodies[ui.docToWorld[doc.bodies.length - 1]];
  u.multiParts = multi ? multi.parts.length : 0;
  if (u.multiParts !== 3) fail(p, "the multi-shape body has " + u.multiParts + " parts, not 3");
  // Properties through the panel: the circle's material and a collision layer.
  tool("select");
  clickAt(150, -100);
  if (!ui.selection || ui.selection.index !== start + 2) fail(p, "clicking the circle did not select it");
  setField("layers (bits)", "10");
  [...document.querySelectorAll("#props button")].find(b => b.textContent === "Edit its shape").click();
  setField("elasticity", 0.5);
  setField("friction", 0.75);
  // The engine's validation message for a polygon that is not convex.
  tool("select");
  clickAt(250, -100);
  [...document.querySelectorAll("#props button")].find(b => b.textContent === "Edit its shape").click();
  const verts = document.querySelector('#props input[data-field="vertices (x y, px)"]');
  verts.value = "0 0, 20 0, 5 5, 0 20";
  verts.dispatchEvent(new Event("input"));
  u.polygonMessage = document.querySelector("#props .problem").textContent;
  if (!u.polygonMessage) fail(p, "no validation message for a non-convex polygon");
  // Constraints: a joint between the two boxes' neighbours, a spring, a motor, then the landscape and the rest.
  tool("joint"); clickAt(150, -100); clickAt(250, -100);
  tool("spring"); clickAt(-200, -20); clickAt(150, -100);
  tool("motor"); clickAt(250, -100);
  tool("segment"); mouse("mousedown", -300, 150); mouse("mousemove", 300, 120); mouse("mouseup", 300, 120);
  tool("emitter"); clickAt(-100, -250);
  tool("event"); clickAt(-200, -20);
  u.constraints = doc.constraints.map(c => c.kind).join(",");
  if (u.constraints !== "joint,spring,motor") fail(p, "constraints built: " + u.constraints);
  u.segments = doc.landscape ? doc.landscape.segments.length : 0;
  u.emitters = doc.emitters.length;
  u.events = doc.events.length;
  if (u.segments !== 1 || u.emitters !== 1 || u.events !== 1) fail(p, "segment, emitter, event: " + [u.segments, u.emitters, u.events]);
  // Undo and redo restore the document exactly.
  const full = JSON.stringify(doc);
  click("undo"); click("undo");
  u.undoneEvents = doc.events.length + doc.emitters.length;
  click("redo"); click("redo");
  if (u.undoneEvents !== 0 || JSON.stringify(doc) !== full) fail(p, "undo/redo did not restore the document");
  // Moving a body with the mouse (snapped to the grid) is one undoable edit.
  setInput("snap-step", 10);
  tool("select");
  const moved = doc.bodies[start + 1].position.slice();
  mouse("mousedown", -200, -20); mouse("mousemove", -163, -27); mouse("mouseup", -163, -27);
  u.movedTo = doc.bodies[start + 1].position.map(v => v / FX);
  if (u.movedTo[0] !== -160 || u.movedTo[1] !== -30) fail(p, "the dragged box is at " + u.movedTo + ", not the snapped -160,-30");
  click("undo");
  if (doc.bodies[start + 1].position[0] !== moved[0]) fail(p, "undo did not put the dragged box back");
  click("redo");
  // Save with the page's buttons: the scene (the harness's converter, compiled with the engine) and
  // the world file (the engine's PhyWriter); open the file again (its PhyReader).
  ui.fileName = "page-saved.phy";
  click("save-yaml");
  result.sceneYaml = ui.lastDownload && ui.lastDownload.name === "page-saved.yaml" ? ui.lastDownload.data : "";
  if (!result.sceneYaml) fail(p, "Save scene .yaml wrote nothing: " + $("status").textContent);
  const written = E.load(JSON.stringify(doc), 60, 8) || E.document();
  click("save-phy");
  const saved = ui.lastDownload && ui.lastDownload.data;
  if (!saved || !saved.length) { fail(p, "Save .phy wrote nothing: " + $("status").textContent); return; }
  u.savedBytes = saved.length;
  result.savedPhy = bytesBase64(saved);
  const played = playHash(60);
  const msg = openPhy(Int8Array.from(saved));
  if (msg) fail(p, "the saved file does not open: " + msg);
  u.reopenedSame = E.document() === written;
  if (!u.reopenedSame) {
    const again = E.document();
    let i = 0;
    while (i < written.length && written[i] === again[i]) i++;
    fail(p, "the reopened file's document differs from the saved one at character " + i + ": saved "
      + written.slice(Math.max(0, i - 80), i + 80) + " / reopened " + again.slice(Math.max(0, i - 80), i + 80));
  }
  u.reopenedPlaysSame = playHash(60) === played;
  if (!u.reopenedPlaysSame) fail(p, "the reopened world plays differently");
  // Dragging while it plays: the engine's mouse joint pulls the circle toward the pointer.
  rebuild();
  tool("select");
  E.tick(1);
  const k = ui.docToWorld[start + 2];
  const before = E.frame().slice(7 * k, 7 * k + 2);
  mouse("mousedown", before[0], before[1]);
  mouse("mousemove", before[0] + 100, before[1] - 100);
  E.tick(30);
  mouse("mouseup", before[0] + 100, before[1] - 100);
  const after = E.frame().slice(7 * k, 7 * k + 2);
  u.dragMoved = [+(after[0] - before[0]).toFixed(1), +(after[1] - before[1]).toFixed(1)];
  if (!(u.dragMoved[0] > 50 && u.dragMoved[1] < -50)) fail(p, "the dragged circle moved by " + u.dragMoved);
  E.tick(60);
  draw();
  // The collision event on the box fires when it lands (on the static block or the ground).
  const m = E.metrics();
  u.metrics = { kinetic: m[0], total: m[2], tick: m[7], eventsFired: m[8], lastEvent: m[9] };
  if (!(m[8] > 0 && m[9] === 0)) fail(p, "the box's collision event did not fire: " + m[8] + " events");
}

// Plays the built world n ticks and hashes the end state.
function playHash(n) {
  rebuild();
  E.tick(n);
  return hashFrame([E.frame(), E.particles()]);
}
