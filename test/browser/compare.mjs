// Browser tests of the comparison view "Torus: embedded vs flat"
// (#space=compare-torus): it loads without console errors, all four panes
// draw the bodies (pixels at each body change when the bodies are cleared;
// the squares' panes draw polygons by their corners),
// and a body can be dragged in each pane (it follows the pointer).
import path from "node:path";
import { OUT, decodePNG } from "./lib.mjs";

const PANES = ["torus-embedded", "torus-flat", "square-embedded", "square-flat"];
const DRAGGED = 3; // a circle on top of the tube, in view of the default camera
const CHANGED = 40; // per-channel change that counts as "a body is drawn here"

async function shot(page, file) {
  const buf = await page.screenshot();
  if (file) {
    const fs = await import("node:fs");
    fs.mkdirSync(path.dirname(file), { recursive: true });
    fs.writeFileSync(file, buf);
  }
  return decodePNG(buf);
}

// pixels of a (2r+1)² window at p whose colour changed between two shots
function changedAround(a, b, p, r) {
  let n = 0;
  for (let dy = -r; dy <= r; dy++) {
    for (let dx = -r; dx <= r; dx++) {
      const x = Math.round(p[0] + dx), y = Math.round(p[1] + dy);
      const u = a.at(x, y), v = b.at(x, y);
      if (Math.max(Math.abs(u[0] - v[0]), Math.abs(u[1] - v[1]), Math.abs(u[2] - v[2])) > CHANGED) n++;
    }
  }
  return n;
}

export async function testCompare(check, browser, base) {
  const context = await browser.newContext({ viewport: { width: 960, height: 720 }, deviceScaleFactor: 1 });
  const page = await context.newPage();
  const errors = [];
  page.on("console", function (m) { if (m.type() === "error") errors.push("console: " + m.text()); });
  page.on("pageerror", function (e) { errors.push("pageerror: " + e.message); });
  await page.goto(base + "#space=compare-torus");
  await page.waitForFunction(function () { return !!window.manifold; });
  const failure = await page.evaluate(function () {
    return window.manifold.ready().then(function () { return null; }, function (e) { return String(e && e.message || e); });
  });
  check("compare: the comparison view loads", failure === null, failure);
  const info = await page.evaluate(function () {
    const m = window.manifold;
    m.pause();
    const c = m.comparison();
    return c && { space: m.space(), embedded: c.embedded.length, flat: c.flat.length, note: c.note,
      gravity: [c.embedded.length && m.simulation().gravity] };
  });
  check("compare: manifold.space() is compare-torus and both worlds hold the scene's bodies",
    info && info.space === "compare-torus" && info.embedded === 5 && info.flat === 5, JSON.stringify(info));
  // K = cos φ / (r (R + r cos φ)) on the torus R = 0.8, r = 0.5: 1/(0.5·1.3) outside, −1/(0.5·0.3) inside
  check("compare: the curvature line says the embedded torus is curved both ways and the flat one is 0",
    info && /K = \+1\.54/.test(info.note) && /\u22126\.67 on its inner/.test(info.note) && /K = 0\.00 everywhere/.test(info.note), info && info.note);

  // the squares' panes draw a polygon of corners by its corners (as walked), a circle by its outline
  const drawnPoints = await page.evaluate(function () {
    const c = window.ManifoldWeb.page.state.compare;
    return [c.flat, c.embedded].map(function (w, k) {
      return [0, 1, 2].map(function (i) { return c.outlineInSquare(w, i, k === 1).outline.length; });
    });
  });
  check("compare: the square panes draw the square by its 4 corners and the pentagon by its 5 (the circle by its 24-point outline), flat and unrolled",
    JSON.stringify(drawnPoints) === JSON.stringify([[4, 24, 5], [4, 24, 5]]), JSON.stringify(drawnPoints));

  // every pane draws the bodies: the pixels round each body change when the bodies go
  const points = await page.evaluate(function (panes) {
    const m = window.manifold, out = {};
    panes.forEach(function (p) { out[p] = [0, 2, 3, 4].map(function (i) { return m.comparisonPoint(p, i); }); });
    return out;
  }, PANES);
  const withBodies = await shot(page, path.join(OUT, "compare-torus.png"));
  await page.evaluate(function () { window.manifold.clear(); window.manifold.render(); window.manifold.comparisonPoint("torus-flat", 0); });
  const without = await shot(page, path.join(OUT, "compare-torus-empty.png"));
  for (const pane of PANES) {
    const drawn = points[pane].filter(function (p) { return p && changedAround(withBodies, without, p, 3) >= 10; }).length;
    check("compare: the " + pane + " pane draws the bodies (of 4 in view, drawn where they are)", drawn >= 3,
      "bodies found drawn: " + drawn + " at " + JSON.stringify(points[pane]));
  }

  // dragging works in each pane: the grabbed body follows the pointer
  for (const pane of PANES) {
    const p0 = await page.evaluate(function (a) {
      const m = window.manifold;
      m.resetScene();
      m.pause();
      m.render();
      return m.comparisonPoint(a.pane, a.i);
    }, { pane: pane, i: DRAGGED });
    if (!p0) {
      check("compare: drag in " + pane, false, "body " + DRAGGED + " is not in view");
      continue;
    }
    const world = pane.endsWith("embedded") ? "embedded" : "flat";
    const goal = [p0[0] + 45, p0[1] - 30];
    await page.mouse.move(p0[0], p0[1]);
    await page.mouse.down();
    const held = await page.evaluate(function (w) { return window.manifold.comparison().grabbed[w]; }, world);
    for (let k = 1; k <= 5; k++) await page.mouse.move(p0[0] + 9 * k, p0[1] - 6 * k);
    await page.evaluate(function () { window.manifold.step(120); });
    const p1 = await page.evaluate(function (a) { return window.manifold.comparisonPoint(a.pane, a.i); }, { pane: pane, i: DRAGGED });
    await page.mouse.up();
    const released = await page.evaluate(function (w) { return window.manifold.comparison().grabbed[w]; }, world);
    const before = Math.hypot(p0[0] - goal[0], p0[1] - goal[1]);
    const after = p1 ? Math.hypot(p1[0] - goal[0], p1[1] - goal[1]) : Infinity;
    check("compare: dragging in the " + pane + " pane holds the body, it follows the pointer, and lets go",
      held === DRAGGED && after < 0.35 * before && released === -1,
      "held " + held + ", distance to the pointer " + before.toFixed(1) + " px -> " + after.toFixed(1) + " px, after release " + released);
  }
  check("compare: no console errors", errors.length === 0, errors.join("\n"));
  await context.close();
}
