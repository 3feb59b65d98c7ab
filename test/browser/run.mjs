// Browser tests of the page (web/): headless Chromium (the system one, software
// WebGL2) against the real `manifold serve`, plus one load from file://.
//
//   node test/browser/run.mjs            (after `manifold build`, which writes web/gen)
//
// Env: MANIFOLD_EXE (else `cabal list-bin exe:manifold`), CHROMIUM (else /usr/bin/chromium).
// Screenshots of every space go to test-output/browser/. Ends with "N passed, M failed".
//
// The parts (each space's own checks run with the space): interaction (selector,
// hash, orbit, zoom, previews, camera, curvature colours, antialiasing, stats,
// resize), performance (what the running page allocates a frame: performance.mjs),
// bodies (bodies.mjs), controls (the engine parameters' controls, made
// from the generated scene keys, and worlds of the engine's most bodies:
// controls.mjs), keys (the keys and the help overlay: keys.mjs), tools (the
// geodesic tool, throws, the new body's controls, trails: tools.mjs), joints
// (the joint presets, drawing, the joint tool: joints.mjs), capture
// (Save image and Record / Stop, their downloads: capture.mjs), errors
// (the error paths), file (file://), hidpi (HiDPI and touch), compare
// (compare.mjs), types (web/manifold.d.ts against the page and web/gen:
// types.mjs), layout (the controls' panel at 640 to 1920 px: layout.mjs), thread (the
// physics worker: thread.mjs), disc (a hyperbolic space's flat views: disc.mjs), benchmarks
// (the bench scripts end to end: benchscripts.mjs).
// The default run is all of them.
import fs from "node:fs";
import path from "node:path";
import url from "node:url";
import {
  WEB, OUT, launchBrowser, serve, canvasShot, createChecks,
} from "./lib.mjs";
import { checkVisibleBodies, shotDifference, testBodies } from "./bodies.mjs";
import { testPerformance } from "./performance.mjs";
import { testControls } from "./controls.mjs";
import { testKeys } from "./keys.mjs";
import { testTools } from "./tools.mjs";
import { testJoints } from "./joints.mjs";
import { testCapture } from "./capture.mjs";
import { testCompare } from "./compare.mjs";
import { testBenchScripts } from "./benchscripts.mjs";
import { testTypes } from "./types.mjs";
import { testLayout } from "./layout.mjs";
import { testThread } from "./thread.mjs";
import { testDisc } from "./disc.mjs";
import { commandLine } from "../../bench/options.mjs";

const VIEWPORT = { width: 640, height: 480 };
const PICKS = 20;           // surface pixels picked per space
const FIELD_TOL = 1e-3;     // |field| at a picked point
const PIXEL_TOL = 1.5;      // project(pick(x, y)) vs the pixel's centre
const BG_TOL = 4;           // per channel, background pixel vs the expected gradient

// For working on one thing: --spaces a,b runs only those spaces' tests, --parts
// p,q only those other parts; either alone skips the rest. A mistyped option
// or part is refused (exit 2) rather than run everything or nothing, and a
// space the page does not have fails a check.
const PARTS = ["interaction", "performance", "bodies", "controls", "keys", "tools", "joints", "capture", "errors", "file", "hidpi", "compare", "types", "layout", "thread", "disc", "benchmarks"];
const USAGE = "node test/browser/run.mjs [--spaces A,B] [--parts P,Q]   (parts: " + PARTS.join(", ") + ")";
const { text } = commandLine({ usage: USAGE, known: ["--spaces", "--parts"] });
function listArg(name) {
  const value = text(name, null);
  return value === null ? null : value.split(",").filter(Boolean);
}
const onlySpaces = listArg("--spaces");
const onlyParts = listArg("--parts");
const unknownParts = (onlyParts || []).filter(function (p) { return PARTS.indexOf(p) < 0; });
if (unknownParts.length) { console.error("no such part: " + unknownParts.join(", ") + "\nusage: " + USAGE); process.exit(2); }
const spaceWanted = function (n) { return onlySpaces ? onlySpaces.indexOf(n) >= 0 : !onlyParts; };
const partWanted = function (n) { return onlyParts ? onlyParts.indexOf(n) >= 0 : !onlySpaces; };

const { check, summary } = createChecks();
const started = Date.now();

// A page with its console errors and uncaught exceptions recorded.
async function openPage(context, address) {
  const page = await context.newPage();
  const errors = [];
  page.on("console", function (m) { if (m.type() === "error") errors.push("console: " + m.text()); });
  page.on("pageerror", function (e) { errors.push("pageerror: " + e.message); });
  await page.goto(address);
  await page.waitForFunction(function () { return !!window.manifold; });
  const failure = await page.evaluate(function () {
    return window.manifold.ready().then(function () { return null; }, function (e) { return String(e && e.message || e); });
  });
  return { page: page, errors: errors, failure: failure };
}

function close(a, b, tol) {
  return a.every(function (x, i) { return Math.abs(x - b[i]) <= tol; });
}

// Expected background colour (0..255) at canvas row y: the shader's vertical gradient.
function backgroundAt(opts, y, height) {
  const s = (height - y - 0.5) / height;
  return opts.background.bottom.map(function (b, i) { return 255 * (b + (opts.background.top[i] - b) * s); });
}

// Deterministic pseudo-random pixels.
function* pixels(width, height, seed) {
  let s = seed >>> 0;
  for (;;) {
    s = (Math.imul(s, 1664525) + 1013904223) >>> 0;
    const x = s % width;
    s = (Math.imul(s, 1664525) + 1013904223) >>> 0;
    const y = s % height;
    yield [x, y];
  }
}

// Picks up to n surface pixels; for each, the field at the picked point (by the
// generated JS), the boundary, and where the point projects back to.
async function pickSurface(page, name, n, seed) {
  const st = await page.evaluate(function () { return window.manifold.stats(); });
  const candidates = [];
  const gen = pixels(st.width, st.height, seed);
  for (let i = 0; i < 1500; i++) candidates.push(gen.next().value);
  return page.evaluate(function (a) {
    const m = window.manifold, s = window.Manifold.spaces[a.name];
    const out = [];
    for (const [x, y] of a.candidates) {
      if (out.length >= a.n) break;
      const p = m.pick(x, y);
      if (!p) continue;
      const q = m.project(p);
      out.push({
        pixel: [x, y], p: p, field: s.field(p[0], p[1], p[2]),
        boundary: s.boundary ? s.boundary(p[0], p[1], p[2]) : null,
        curvature: s.curvature(p[0], p[1], p[2]),
        error: q ? Math.hypot(q[0] - (x + 0.5), q[1] - (y + 0.5)) : Infinity,
      });
    }
    return out;
  }, { name: name, n: n, candidates: candidates });
}

function pickReport(name, picks, n) {
  const maxField = Math.max.apply(null, picks.map(function (p) { return Math.abs(p.field); }));
  const maxErr = Math.max.apply(null, picks.map(function (p) { return p.error; }));
  const minB = Math.min.apply(null, picks.map(function (p) { return p.boundary === null ? Infinity : p.boundary; }));
  const bad = picks.filter(function (p) {
    return !(Math.abs(p.field) < FIELD_TOL) || !(p.error <= PIXEL_TOL) || (p.boundary !== null && !(p.boundary >= -1e-4));
  });
  check(name + ": pick " + n + " surface pixels: |field| < " + FIELD_TOL + ", inside the boundary, project() within " + PIXEL_TOL + " px",
    picks.length === n && bad.length === 0,
    picks.length + " picked; max |field| " + maxField.toExponential(2) + ", max error " + maxErr.toFixed(3) + " px" +
    (isFinite(minB) ? ", min boundary " + minB.toExponential(2) : "") +
    (bad.length ? "; bad: " + JSON.stringify(bad.slice(0, 3)) : ""));
  return { maxField: maxField, maxErr: maxErr };
}

// ---- per space: loads cleanly, draws the surface over a background, picks exactly ----
async function testSpace(context, base, name) {
  const { page, errors, failure } = await openPage(context, base + "#space=" + name);
  const info = await page.evaluate(function () {
    const m = window.manifold;
    const space = window.Manifold.spaces[m.space()] || {};
    return {
      space: m.space(), error: m.error(), hash: location.hash, select: document.getElementById("space").value,
      stats: m.stats(), opts: m.options(), scene: (space.scene || []).map(function (b) { return b.p; }),
    };
  });
  check(name + ": loads from #space=" + name + ", shader compiles, no console errors",
    failure === null && info.error === null && errors.length === 0 && info.space === name &&
      info.select === name && info.hash === "#space=" + name,
    failure || info.error || errors.join("; ") || (info.space + " " + info.hash));
  if (failure !== null) { await page.close(); return null; }

  // paused, so that the spot below is looked for among the bodies the screenshot shows
  await page.evaluate(function () { window.manifold.pause(); window.manifold.render(); });
  const shot = await canvasShot(page, path.join(OUT, name + ".png"));
  const W = info.stats.width, H = info.stats.height;
  if (!check(name + ": screenshot is the canvas's backing store", shot.width === W && shot.height === H,
    "screenshot " + shot.width + "×" + shot.height + ", canvas " + W + "×" + H)) { await page.close(); return null; }
  await checkVisibleBodies(check, page, name);

  // a surface pixel with no body on it: the centre if the camera looks at the
  // surface, else a scene point's pixel, else a pixel of a coarse grid
  const spot = await page.evaluate(function (scene) {
    const m = window.manifold, st = m.stats(), bodies = m.bodies();
    const tries = [[Math.floor(st.width / 2), Math.floor(st.height / 2)]];
    scene.forEach(function (p) { const q = m.project(p); if (q) tries.push([Math.floor(q[0]), Math.floor(q[1])]); });
    for (let y = 20; y < st.height; y += 40) for (let x = 20; x < st.width; x += 40) tries.push([x, y]);
    // a body (or its image through the origin, in a quotient space) covers
    // less than twice its size around its centre
    const bare = function (q) {
      return bodies.every(function (b) {
        return [1, -1].every(function (s) {
          const d = Math.hypot(q[0] - s * b.p[0], q[1] - s * b.p[1], q[2] - s * b.p[2]);
          return d > 2 * b.size;
        });
      });
    };
    for (const [x, y] of tries) {
      if (x < 2 || y < 2 || x >= st.width - 2 || y >= st.height - 2) continue;
      // away from silhouettes and bodies: the 5×5 neighbourhood is bare surface too
      let all = true;
      for (let dy = -2; dy <= 2 && all; dy++) for (let dx = -2; dx <= 2 && all; dx++) {
        const q = m.pick(x + dx, y + dy);
        all = !!q && bare(q);
      }
      if (all) return [x, y];
    }
    return null;
  }, info.scene);
  if (check(name + ": a surface pixel found (centre or a scene point)", spot !== null)) {
    const c = shot.at(spot[0], spot[1]);
    const bg = backgroundAt(info.opts, spot[1], H);
    const diff = Math.abs(c[0] - bg[0]) + Math.abs(c[1] - bg[1]) + Math.abs(c[2] - bg[2]);
    check(name + ": screenshot shows the lit surface at " + spot.join(","), diff > 60 && c[0] + c[1] + c[2] > 120,
      "pixel " + c.join(",") + " vs background " + bg.map(Math.round).join(","));
  }

  // a background corner: pick says background and the screenshot has the gradient's colour
  const corners = [[1, 1], [W - 2, 1], [1, H - 2], [W - 2, H - 2]];
  const bgCorner = await page.evaluate(function (cs) {
    return cs.find(function (c) { return window.manifold.pick(c[0], c[1]) === null; }) || null;
  }, corners);
  if (check(name + ": a corner is background (pick → null)", bgCorner !== null)) {
    const c = shot.at(bgCorner[0], bgCorner[1]);
    const bg = backgroundAt(info.opts, bgCorner[1], H);
    check(name + ": background colour at corner " + bgCorner.join(","), close(c, bg, BG_TOL),
      "pixel " + c.join(",") + ", expected " + bg.map(Math.round).join(","));
  }

  const picks = await pickSurface(page, name, PICKS, 12345 + name.length * 7919);
  const report = pickReport(name, picks, PICKS);

  // no holes: without antialiasing, no background-coloured pixel has surface all around it
  await page.evaluate(function () { window.manifold.setOptions({ antialias: "off" }); window.manifold.render(); });
  const raw = await canvasShot(page, path.join(OUT, name + "-noaa.png"));
  const holes = [];
  const isBg = function (x, y) { return close(raw.at(x, y), backgroundAt(info.opts, y, H), BG_TOL); };
  for (let y = 1; y < H - 1; y++) {
    for (let x = 1; x < W - 1; x++) {
      if (!isBg(x, y)) continue;
      let surrounded = true;
      for (let dy = -1; dy <= 1 && surrounded; dy++) for (let dx = -1; dx <= 1 && surrounded; dx++) {
        if (dx || dy) surrounded = !isBg(x + dx, y + dy);
      }
      if (surrounded) holes.push([x, y]);
    }
  }
  check(name + ": no holes (isolated background pixels inside the surface)", holes.length === 0,
    holes.length + " found" + (holes.length ? ": " + JSON.stringify(holes.slice(0, 5)) : ""));

  // the default scene (quotients drawn at their images, the trumpet's bent
  // bodies, the flat spaces' clipped squares) drawn in the coarser forms
  // where they fit is the picture every whole mesh gives
  const forms = await page.evaluate(function () {
    const m = window.manifold, auto = m.stats().bodyForms;
    m.setOptions({ bodyDetail: "mesh" });
    m.render();
    return { auto: auto, mesh: m.stats().bodyForms };
  });
  const meshShot = await canvasShot(page, path.join(OUT, name + "-noaa-mesh.png"));
  const d = shotDifference(raw, meshShot, 32);
  check(name + ": the default scene looks the same drawn in coarser forms where they fit as with every whole mesh (" +
    forms.auto.fans + " fans, " + forms.auto.coarser + " coarser, " + forms.auto.meshes + " meshes; " + d.differ +
    " px differ, body px " + d.bodyA + "/" + d.bodyB + ")",
    forms.mesh.meshes === forms.auto.fans + forms.auto.coarser + forms.auto.meshes &&
      Math.abs(d.bodyA - d.bodyB) <= 0.05 * d.bodyB + 20 && d.differ <= 0.25 * d.bodyB + 20, "");
  await page.close();
  report.fans = forms.auto.fans;
  return report;
}

// ---- interaction: UI selector, hash links, orbit and zoom, curvature colours, AA, API ----
async function testInteraction(context, base) {
  const { page, errors, failure } = await openPage(context, base + "#space=sphere");
  check("interaction page loads", failure === null, failure || "");

  // the selector switches space and the hash follows
  await page.selectOption("#space", "torus");
  const viaSelect = await page.evaluate(function () {
    return window.manifold.ready().then(function () {
      return { space: window.manifold.space(), hash: location.hash, centre: window.manifold.pick(320, 200) };
    });
  });
  check("space selector switches to torus and the hash says #space=torus",
    viaSelect.space === "torus" && viaSelect.hash === "#space=torus", JSON.stringify(viaSelect));

  // editing the hash switches space (a link reproduces the view)
  await page.evaluate(function () { location.hash = "#space=disc"; });
  await page.waitForFunction(function () { return window.manifold.space() === "disc"; });
  const viaHash = await page.evaluate(function () {
    return window.manifold.ready().then(function () {
      return { space: window.manifold.space(), select: document.getElementById("space").value, error: window.manifold.error() };
    });
  });
  check("hash change #space=disc switches space and selector", viaHash.space === "disc" && viaHash.select === "disc" && viaHash.error === null,
    JSON.stringify(viaHash));

  // orbit with a right-drag anywhere and a left-drag off the surface, zoom with the wheel
  // (a left press on the surface throws a body, on a body grabs it)
  await page.evaluate(function () { return window.manifold.setSpace("torus").then(function () { window.manifold.clear(); }); });
  const box = await page.locator("#view").boundingBox();
  const dist = function (c) { return Math.hypot(c.eye[0] - c.target[0], c.eye[1] - c.target[1], c.eye[2] - c.target[2]); };
  const orbitDrag = async function (x, y, button) {
    const c0 = await page.evaluate(function () { return window.manifold.camera(); });
    await page.mouse.move(x, y);
    await page.mouse.down({ button: button });
    await page.mouse.move(x + 80, y + 30, { steps: 4 });
    await page.mouse.up({ button: button });
    const c1 = await page.evaluate(function () { return window.manifold.camera(); });
    const bodies = await page.evaluate(function () { return window.manifold.stats().bodies; });
    return { ok: !close(c0.eye, c1.eye, 1e-3) && close(c0.target, c1.target, 1e-9) && Math.abs(dist(c0) - dist(c1)) < 1e-6 && bodies === 0,
      c0: c0, c1: c1, bodies: bodies };
  };
  const onBackground = await page.evaluate(function () { return window.manifold.pick(4, 4) === null; });
  const right = await orbitDrag(box.x + box.width / 2, box.y + box.height / 2, "right");
  const left = await orbitDrag(box.x + 4, box.y + 4, "left");
  const afterDrag = left.c1;
  check("a right-drag on the surface and a left-drag off it orbit the camera about its target (distance kept, no body thrown)",
    onBackground && right.ok && left.ok,
    "corner off the surface " + onBackground + "; right: eye " + right.c0.eye.map(function (x) { return x.toFixed(3); }) + " → " +
      right.c1.eye.map(function (x) { return x.toFixed(3); }) + ", bodies " + right.bodies + "; left: bodies " + left.bodies);
  await page.mouse.wheel(0, -300);
  await page.waitForFunction(function (d0) {
    const c = window.manifold.camera();
    return Math.hypot(c.eye[0] - c.target[0], c.eye[1] - c.target[1], c.eye[2] - c.target[2]) < d0 - 1e-3;
  }, dist(afterDrag), { timeout: 5000 }).then(function () { return true; }, function () { return false; }).then(function (ok) {
    check("the wheel zooms in", ok);
  });
  const orbited = await pickSurface(page, "torus", 10, 777);
  pickReport("torus after orbit and zoom", orbited, 10);

  // on a slow GPU (this software one) the view draws half-resolution previews while it
  // moves, and a sharp frame when it stops
  const frameMs = await page.evaluate(function () { return window.manifold.measureFrame(); });
  const twoFrames = function () {
    return page.evaluate(function () {
      return new Promise(function (r) { requestAnimationFrame(function () { requestAnimationFrame(function () { r(window.manifold.stats()); }); }); });
    });
  };
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down({ button: "right" });
  let sawPreview = false;
  for (let i = 1; i <= 5; i++) {
    await page.mouse.move(box.x + box.width / 2 + 10 * i, box.y + box.height / 2);
    if ((await twoFrames()).preview) sawPreview = true;
  }
  await page.mouse.up({ button: "right" });
  await page.waitForTimeout(500);
  const settled = await twoFrames();
  // previews exactly when frames are slow (the page's threshold is 40 ms; a frame
  // within 10 ms of it may go either way)
  const slow = frameMs > 50, fast = frameMs < 30;
  check("moving view: previews while it moves on a slow GPU and none on a fast one, then a sharp frame (frame " + Math.round(frameMs) + " ms)",
    (slow ? sawPreview : fast ? !sawPreview : true) && settled.preview === false,
    "previews seen: " + sawPreview + ", after: preview " + settled.preview);
  pickReport("torus after previews", await pickSurface(page, "torus", 5, 31), 5);

  // setCamera / camera round trip
  const cam = { eye: [0, 3, 0.5], target: [0, 0, 0], up: [0, 1, 0], fov: 40 };
  const got = await page.evaluate(function (c) { window.manifold.setCamera(c); return window.manifold.camera(); }, cam);
  check("setCamera then camera() round-trips", JSON.stringify(got) === JSON.stringify(cam), JSON.stringify(got));
  const badCam = await page.evaluate(function () {
    try { window.manifold.setCamera({ eye: [0, 0, 0], target: [0, 0, 0] }); return null; } catch (e) { return e.message; }
  });
  check("setCamera rejects eye == target", typeof badCam === "string", badCam);

  // the view-projection matrix (for the engine's polygons) agrees with project()
  const vp = await page.evaluate(function () {
    const m = window.manifold, st = m.stats();
    const cam = new window.ManifoldWeb.camera.Camera();
    cam.set(m.camera());
    const M = cam.viewProjection(st.width / st.height, 0.01, 100);
    let worst = 0;
    [[0.3, 0.1, -0.2], [1, 0, 0], [-0.5, 0.4, 0.7], [0, 0, 0]].forEach(function (p) {
      const c = [0, 1, 2, 3].map(function (r) { return M[r] * p[0] + M[4 + r] * p[1] + M[8 + r] * p[2] + M[12 + r]; });
      const px = (c[0] / c[3] + 1) / 2 * st.width, py = (1 - c[1] / c[3]) / 2 * st.height;
      const q = m.project(p);
      worst = Math.max(worst, Math.hypot(px - q[0], py - q[1]));
    });
    return worst;
  });
  check("camera.viewProjection maps points where project() does", vp < 1e-3, "max " + vp.toExponential(2) + " px");

  // curvature colouring agrees with the generated curvature: red where K > 0, blue where K < 0 (no bodies in the way)
  await page.evaluate(function () { return window.manifold.setSpace("torus").then(function () { window.manifold.clear(); }); });
  await page.click("#curvature");
  const curv = await page.evaluate(function () {
    return { hash: location.hash, on: window.manifold.options().curvature, legend: !document.getElementById("curvature-legend").hidden };
  });
  check("curvature toggle turns colouring on, shows the legend, hash has curvature=1",
    curv.on && curv.legend && curv.hash === "#space=torus&bodies=0&curvature=1", JSON.stringify(curv));
  await page.evaluate(function () { window.manifold.setOptions({ grid: false }); window.manifold.render(); });
  const shot = await canvasShot(page, path.join(OUT, "torus-curvature.png"));
  const cpicks = await pickSurface(page, "torus", 200, 4242);
  const interior = await page.evaluate(function (ps) {
    const m = window.manifold;
    return ps.filter(function (p) {
      for (let dy = -2; dy <= 2; dy++) for (let dx = -2; dx <= 2; dx++) if (!m.pick(p.pixel[0] + dx, p.pixel[1] + dy)) return false;
      return true;
    });
  }, cpicks);
  let agree = 0, total = 0;
  const wrong = [];
  for (const p of interior) {
    if (Math.abs(p.curvature) < 0.3) continue;
    const c = shot.at(p.pixel[0], p.pixel[1]);
    total++;
    if ((p.curvature > 0) === (c[0] > c[2])) agree++;
    else wrong.push({ K: p.curvature, rgb: c });
  }
  const signs = interior.filter(function (p) { return p.curvature < -0.3; }).length > 0 &&
    interior.filter(function (p) { return p.curvature > 0.3; }).length > 0;
  check("curvature colours match the sign of the generated curvature (torus, K > 0 red, K < 0 blue)",
    total >= 20 && agree === total && signs, agree + "/" + total + " agree" + (wrong.length ? "; " + JSON.stringify(wrong.slice(0, 3)) : ""));
  await page.evaluate(function () { window.manifold.setOptions({ curvature: false, grid: true }); });

  // every antialiasing mode picks as exactly
  for (const aa of ["ssaa", "off", "fxaa"]) {
    await page.selectOption("#antialias", aa);
    const ps = await pickSurface(page, "torus", 10, 99);
    pickReport("torus with antialiasing " + aa, ps, 10);
  }

  // bad requests are refused in words
  const unknown = await page.evaluate(function () {
    return window.manifold.setSpace("no-such-space").then(function () { return null; }, function (e) { return e.message; });
  });
  check("setSpace of an unknown name rejects, listing the spaces", typeof unknown === "string" && /torus/.test(unknown), unknown);

  // stats
  await page.evaluate(function () { return window.manifold.setSpace("torus"); });
  await page.waitForTimeout(400); // a stats line after the switch
  const st = await page.evaluate(function () { return window.manifold.stats(); });
  const line = await page.textContent("#stats");
  check("stats() and the stats line report size, fps and the default scene's bodies",
    st.bodies === 6 && st.width > 0 && typeof st.fps === "number" && /bodies 6/.test(line) && /(fps|idle)/.test(line), line);

  // the canvas follows its container
  await page.setViewportSize({ width: 520, height: 420 });
  await page.waitForFunction(function () { return window.manifold.stats().width === 520; }, null, { timeout: 5000 })
    .then(function () { return true; }, function () { return false; }).then(function (ok) {
      check("the canvas backing store follows a resize", ok);
    });
  const resized = await pickSurface(page, "torus", 5, 3);
  pickReport("torus after resize", resized, 5);

  check("interaction page: no console errors", errors.length === 0, errors.join("; "));
  await page.close();
}

// ---- HiDPI and touch (a phone-like context): the backing store is CSS size ×
// devicePixelRatio, picking in its pixels; one finger throws on the surface and orbits off it, two fingers pinch-zoom ----
async function testHiDPI(browser, base) {
  const context = await browser.newContext({ viewport: { width: 360, height: 300 }, deviceScaleFactor: 2, hasTouch: true });
  const { page, errors, failure } = await openPage(context, base + "#space=sphere");
  const r = await page.evaluate(function () {
    const c = document.getElementById("view"), b = c.getBoundingClientRect();
    return { w: c.width, h: c.height, cw: b.width, ch: b.height, dpr: devicePixelRatio };
  });
  check("HiDPI: backing store is CSS size × devicePixelRatio",
    failure === null && r.dpr === 2 && r.w === Math.round(r.cw * 2) && r.h === Math.round(r.ch * 2), JSON.stringify(r));
  pickReport("HiDPI sphere", await pickSurface(page, "sphere", 10, 5), 10);

  const box = await page.locator("#view").boundingBox();
  const cx = box.x + box.width / 2, cy = box.y + box.height / 2;
  const cdp = await context.newCDPSession(page);
  const touch = function (type, points) {
    return cdp.send("Input.dispatchTouchEvent", { type: type, touchPoints: points.map(function (p, i) { return { x: p[0], y: p[1], id: i }; }) });
  };

  // a finger on a body grabs and drags it (backing-store pixels are twice the CSS ones)
  const start = await page.evaluate(function () {
    const m = window.manifold, st = m.stats();
    const p = m.pick(st.width / 2, st.height / 2);
    return m.loadScene({ space: "sphere", gravity: false, bodies: [{ shape: "circle", size: 0.25, p: p }] }).then(function () {
      return m.project(m.bodies()[0].p);
    });
  });
  const tx = box.x + start[0] / 2, ty = box.y + start[1] / 2;
  await touch("touchStart", [[tx, ty]]);
  const held = await page.evaluate(function () { return window.manifold.grabbed(); });
  for (let i = 1; i <= 4; i++) await touch("touchMove", [[tx - 10 * i, ty]]);
  await page.waitForFunction(function (x0) {
    const m = window.manifold;
    return m.project(m.bodies()[0].p)[0] < x0 - 40;
  }, start[0], { timeout: 8000 }).catch(function () {});
  const dragged = await page.evaluate(function () { const m = window.manifold; return m.project(m.bodies()[0].p); });
  await touch("touchEnd", []);
  const let_go = await page.evaluate(function () { return window.manifold.grabbed(); });
  check("touch: a finger on a body grabs it and drags it (80 backing-store px to the left)",
    held === 0 && let_go === -1 && start[0] - dragged[0] > 40 && Math.abs(dragged[1] - start[1]) < 20,
    "held " + held + ", centre x " + start[0].toFixed(1) + " → " + dragged[0].toFixed(1) + ", after lifting " + let_go);
  await page.evaluate(function () { window.manifold.clear(); }); // one finger on a body would grab it
  const cam = function () { return page.evaluate(function () { return window.manifold.camera(); }); };
  const dist = function (c) { return Math.hypot(c.eye[0] - c.target[0], c.eye[1] - c.target[1], c.eye[2] - c.target[2]); };
  const bodyCount = function () { return page.evaluate(function () { return window.manifold.stats().bodies; }); };
  const c0 = await cam();
  const bx = box.x + 6, by = box.y + 6; // off the sphere
  const offSurface = await page.evaluate(function () { return window.manifold.pick(12, 12) === null; });
  await touch("touchStart", [[bx, by]]);
  for (let i = 1; i <= 4; i++) await touch("touchMove", [[bx + 12 * i, by]]);
  await touch("touchEnd", []);
  const c1 = await cam();
  check("touch: one finger off the surface orbits", offSurface && Math.abs(c1.eye[0] - c0.eye[0]) > 1e-3 && Math.abs(dist(c1) - dist(c0)) < 1e-6,
    "corner off the surface " + offSurface + ", eye x " + c0.eye[0].toFixed(3) + " → " + c1.eye[0].toFixed(3));
  await touch("touchStart", [[cx - 20, cy], [cx + 20, cy]]);
  for (let i = 1; i <= 4; i++) await touch("touchMove", [[cx - 20 - 10 * i, cy], [cx + 20 + 10 * i, cy]]);
  await touch("touchEnd", []);
  const c2 = await cam();
  const afterPinch = await bodyCount();
  check("touch: spreading two fingers zooms in (the first finger's throw dropped)", dist(c2) < dist(c1) - 1e-3 && afterPinch === 0,
    dist(c1).toFixed(3) + " → " + dist(c2).toFixed(3) + ", bodies " + afterPinch);
  await touch("touchStart", [[cx, cy]]);
  for (let i = 1; i <= 4; i++) await touch("touchMove", [[cx + 8 * i, cy]]);
  await touch("touchEnd", []);
  const thrown = await page.evaluate(function () { const b = window.manifold.bodies(); return b.length ? Math.hypot(b[0].v[0], b[0].v[1], b[0].v[2]) : -1; });
  check("touch: one finger on empty surface throws a body", thrown > 0, "speed of the thrown body " + thrown);
  check("HiDPI: no console errors", errors.length === 0, errors.join("; "));
  await context.close();
}

// ---- file:// ----
async function testFileUrl(context) {
  const address = url.pathToFileURL(path.join(WEB, "index.html")).href + "#space=hemisphere";
  const { page, errors, failure } = await openPage(context, address);
  const r = await page.evaluate(function () {
    return { space: window.manifold.space(), error: window.manifold.error(), hash: location.hash,
      scripts: Array.from(document.scripts).map(function (s) { return s.getAttribute("src"); }).filter(Boolean) };
  });
  check("file:// load works (shader compiles, no console errors)",
    failure === null && r.error === null && r.space === "hemisphere" && errors.length === 0,
    failure || r.error || errors.join("; ") || r.space);
  check("file://: the space script was added as a <script> tag", r.scripts.indexOf("gen/space-hemisphere.js") >= 0, r.scripts.join(" "));
  pickReport("file:// hemisphere", await pickSurface(page, "hemisphere", 10, 11), 10);
  await page.close();
}

// ---- web/embed.html: one space in a page of its own, through the public objects, served and from file:// ----
async function testEmbed(context, base) {
  const text = fs.readFileSync(path.join(WEB, "embed.html"), "utf8");
  const lines = text.split("\n").filter(function (l, i, all) { return i < all.length - 1 || l !== ""; }).length;
  check("web/embed.html is a page of under 60 lines", lines < 60, lines + " lines");
  for (const address of [base + "embed.html", url.pathToFileURL(path.join(WEB, "embed.html")).href]) {
    const page = await context.newPage();
    const errors = [];
    page.on("console", function (m) { if (m.type() === "error") errors.push("console: " + m.text()); });
    page.on("pageerror", function (e) { errors.push("pageerror: " + e.message); });
    await page.goto(address);
    await page.waitForTimeout(1000);
    const a = await canvasShot(page);
    await page.waitForTimeout(1000);
    const b = await canvasShot(page);
    let moved = 0;
    for (let y = 0; y < a.height; y += 2) {
      for (let x = 0; x < a.width; x += 2) {
        const p = a.at(x, y), q = b.at(x, y);
        if (Math.abs(p[0] - q[0]) + Math.abs(p[1] - q[1]) + Math.abs(p[2] - q[2]) > 30) moved++;
      }
    }
    const centre = a.at(a.width / 2, a.height / 2), corner = a.at(2, 2);
    const lit = Math.abs(centre[0] - corner[0]) + Math.abs(centre[1] - corner[1]) + Math.abs(centre[2] - corner[2]) > 60;
    check("web/embed.html (" + (address.startsWith("file:") ? "file://" : "served") + ") draws the sphere and its bodies falling, with no console errors",
      lit && moved > 20 && errors.length === 0, "centre " + centre + " vs corner " + corner + ", " + moved + " sampled pixels changed in 1 s; " + errors.join("; "));
    await page.close();
  }
}

// ---- error paths: a visible message, never a blank canvas ----
async function messageState(page) {
  return page.evaluate(function () {
    const m = document.getElementById("message");
    const vis = function (el) { const b = el.getBoundingClientRect(); return !el.hidden && b.width > 0 && b.height > 0 && getComputedStyle(el).visibility !== "hidden"; };
    return {
      visible: vis(m), title: document.getElementById("message-title").textContent,
      text: document.getElementById("message-text").textContent, log: document.getElementById("message-log").textContent,
      canvasVisible: getComputedStyle(document.getElementById("view")).visibility !== "hidden",
      error: window.manifold ? window.manifold.error() : null,
    };
  });
}

async function testErrors(context, base) {
  // forced broken shader from the URL
  {
    const { page, failure } = await openPage(context, base + "#space=torus&debugBrokenShader=1");
    const s = await messageState(page);
    const shot = await canvasShot(page, path.join(OUT, "broken-shader.png"));
    check("#debugBrokenShader=1: setSpace rejects with the compile error", typeof failure === "string" && /compile/.test(failure), failure);
    check("#debugBrokenShader=1: the page shows the message and the compiler log",
      s.visible && /failed to compile/.test(s.text) && /ERROR/.test(s.log) && /debugBrokenShader/.test(s.log + s.text) &&
        !s.canvasVisible && typeof s.error === "string",
      JSON.stringify({ visible: s.visible, text: s.text, log: s.log.slice(0, 200) }));
    const c = shot.at(8, 8); // the panel's padding
    check("#debugBrokenShader=1: the message panel, not a blank canvas, is on screen", c[0] > c[2] + 5 || c[0] > 20, "pixel 8,8: " + c.join(","));
    await page.close();
  }
  // broken GLSL through the API, then restored
  {
    const { page, errors } = await openPage(context, base + "#space=torus");
    const rej = await page.evaluate(function () {
      return window.manifold.setSpaceGlsl("torus", "float field(vec3 p) { return undefinedThing; }")
        .then(function () { return null; }, function (e) { return e.message; });
    });
    const s = await messageState(page);
    check("setSpaceGlsl(broken): rejects with the log and shows it",
      typeof rej === "string" && /undefinedThing/.test(rej) && s.visible && /undefinedThing/.test(s.log) && /undefinedThing/.test(s.error),
      String(rej).slice(0, 200));
    const pickWhileBroken = await page.evaluate(function () { return window.manifold.pick(320, 200); });
    check("while the shader is broken, pick returns null", pickWhileBroken === null);
    const ok = await page.evaluate(function () {
      return window.manifold.setSpaceGlsl("torus", null).then(function () { return null; }, function (e) { return e.message; });
    });
    const s2 = await messageState(page);
    check("setSpaceGlsl(null) restores the generated GLSL and clears the message", ok === null && !s2.visible && s2.canvasVisible && s2.error === null,
      ok || JSON.stringify(s2).slice(0, 200));
    check("error-path page: the only console errors are none", errors.length === 0, errors.join("; "));
    await page.close();
  }
  // no WebGL2
  {
    const page = await context.newPage();
    await page.addInitScript(function () {
      const orig = HTMLCanvasElement.prototype.getContext;
      HTMLCanvasElement.prototype.getContext = function (kind) { return kind === "webgl2" ? null : orig.apply(this, arguments); };
    });
    await page.goto(base + "#space=torus");
    await page.waitForFunction(function () { return !!window.manifold; });
    const s = await messageState(page);
    check("without WebGL2 the page says so", s.visible && /WebGL2/.test(s.title + s.text), s.title + " / " + s.text);
    await page.close();
  }
  // no float framebuffers
  {
    const page = await context.newPage();
    await page.addInitScript(function () {
      const orig = WebGL2RenderingContext.prototype.getExtension;
      WebGL2RenderingContext.prototype.getExtension = function (name) { return name === "EXT_color_buffer_float" ? null : orig.call(this, name); };
    });
    await page.goto(base + "#space=torus");
    await page.waitForFunction(function () { return !!window.manifold; });
    const s = await messageState(page);
    check("without EXT_color_buffer_float the page says so", s.visible && /EXT_color_buffer_float/.test(s.text), s.text);
    await page.close();
  }
  // generated scripts missing
  {
    const page = await context.newPage();
    await page.route("**/gen/spaces.js", function (route) { return route.fulfill({ status: 404, body: "" }); });
    await page.goto(base);
    await page.waitForFunction(function () { return !!window.manifold; });
    const s = await messageState(page);
    check("without web/gen the page says to run manifold build", s.visible && /manifold build/.test(s.text), s.text);
    await page.close();
  }
  // unknown space in the URL: a notice and the first space
  {
    const { page, failure } = await openPage(context, base + "#space=nowhere");
    const r = await page.evaluate(function () {
      return { space: window.manifold.space(), notice: document.getElementById("notice").hidden ? "" : document.getElementById("notice-text").textContent };
    });
    check("#space=nowhere shows a notice and the first space", failure === null && /nowhere/.test(r.notice) && r.space === "plane", JSON.stringify(r));
    await page.close();
  }
}

async function main() {
  const server = await serve();
  const browser = await launchBrowser();
  const stats = {};
  try {
    const context = await browser.newContext({ viewport: VIEWPORT, deviceScaleFactor: 1 });
    const names = await (async function () {
      const { page, failure } = await openPage(context, server.url);
      check("the page loads from manifold serve at " + server.url, failure === null, failure || "");
      const n = await page.evaluate(function () { return window.manifold.spaces(); });
      const idx = await page.evaluate(function () { return window.Manifold.spaceIndex.map(function (s) { return s.name; }); });
      const opts = await page.evaluate(function () { return Array.from(document.querySelectorAll("#space option")).map(function (o) { return o.value; }); });
      check("spaces() and the selector list every space of Manifold.spaceIndex (the selector then the comparison view)",
        n.length > 0 && JSON.stringify(n) === JSON.stringify(idx) && JSON.stringify(opts) === JSON.stringify(idx.concat(["compare-torus"])), n.join(" "));
      await page.close();
      return n;
    })();
    const missing = (onlySpaces || []).filter(function (n) { return names.indexOf(n) < 0; });
    if (missing.length) check("--spaces names spaces of the page", false, "no such space: " + missing.join(", "));
    for (const name of names) {
      if (!spaceWanted(name)) continue;
      const t = Date.now();
      const r = await testSpace(context, server.url, name);
      if (r) stats[name] = { maxField: r.maxField, maxErr: r.maxErr, ms: Date.now() - t, fans: r.fans };
    }
    // (the forms check above can fail only where some body is drawn coarser than its mesh)
    if (Object.keys(stats).length > 1) {
      check("some space's default scene has bodies drawn as fans", Object.keys(stats).some(function (k) { return stats[k].fans > 0; }),
        JSON.stringify(Object.keys(stats).map(function (k) { return k + " " + stats[k].fans; })));
    }
    // each part in turn, its time printed as it ends (the suite has a time budget)
    const parts = {
      interaction: function () { return testInteraction(context, server.url); },
      performance: function () { return testPerformance(check, context, server.url); },
      bodies: function () { return testBodies(check, context, server.url); },
      controls: function () { return testControls(check, context, server.url); },
      keys: function () { return testKeys(check, context, server.url); },
      tools: function () { return testTools(check, context, server.url); },
      joints: function () { return testJoints(check, context, server.url); },
      capture: function () { return testCapture(check, context, server.url); },
      errors: function () { return testErrors(context, server.url); },
      file: async function () { await testFileUrl(context); await testEmbed(context, server.url); },
      hidpi: function () { return testHiDPI(browser, server.url); },
      compare: function () { return testCompare(check, browser, server.url); },
      types: function () { return testTypes(check, context, server.url); },
      layout: function () { return testLayout(check, browser, server.url); },
      thread: function () { return testThread(check, context, server.url); },
      disc: function () { return testDisc(check, context, server.url); },
      benchmarks: function () { return testBenchScripts(check); },
    };
    for (const name of PARTS) {
      if (!partWanted(name)) continue;
      const t = Date.now();
      await parts[name]();
      console.log("part " + name + " took " + ((Date.now() - t) / 1000).toFixed(1) + " s");
    }
    await context.close();
  } catch (e) {
    check("browser tests ran to the end", false, e && e.stack || String(e));
  } finally {
    await browser.close();
    await server.stop();
  }
  const names = Object.keys(stats);
  if (names.length) {
    console.log("\nper space: max |field| at picks, max pick→project error, time");
    for (const n of names) {
      console.log("  " + n.padEnd(18) + stats[n].maxField.toExponential(2).padStart(10) + stats[n].maxErr.toFixed(3).padStart(8) + " px" +
        String(stats[n].ms).padStart(7) + " ms");
    }
  }
  const s = summary();
  console.log("\nbrowser tests took " + ((Date.now() - started) / 1000).toFixed(1) + " s; screenshots in " + path.relative(process.cwd(), OUT));
  if (s.failed) console.log("failed: " + s.failures.join("; "));
  console.log(s.passed + " passed, " + s.failed + " failed");
  process.exit(s.failed ? 1 : 0);
}

main().catch(function (e) {
  console.error(e && e.stack || e);
  console.log("0 passed, 1 failed");
  process.exit(1);
});
