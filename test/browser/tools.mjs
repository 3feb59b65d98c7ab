// Browser tests of the tools and curves (part "tools" of run.mjs), with a
// real mouse and keyboard: the geodesic on the sphere closes after 2π and is
// drawn where it faces the camera (pixels of its colour at its projected
// points, none where it runs behind the sphere); on the flat torus it winds
// back to its start through the square's edge, on the projective plane it
// comes back through the antipode; g switches the geodesic tool, with which
// a press and drag draws the geodesic from the pressed point; a throw shows
// its preview while dragged and the body thrown is 0.5 s later within 2 % of
// the preview's point; a click on empty surface adds the new body there at
// rest, with the size, shape, density and static chosen in the controls; a
// grabbed body let go keeps its speed; t switches trails, which appear
// (pixels differ from the same view without them) and fade (their oldest
// end transparent, gone 4 s later). The preset scenes: loaded by URL and
// by the select, each whole and stepping without warnings (a picture of
// each), an unknown name refused. The plot (p): for a free body on the
// torus its energy and axial momentum lines are flat; on the cube, which
// has no axis, there is no axial momentum. The inspector: Alt and the
// pointer on a body describe it.
import path from "node:path";
import { OUT, canvasShot, decodePNG } from "./lib.mjs";
import { openSpace } from "./bodies.mjs";

function sleep(ms) { return new Promise(function (resolve) { setTimeout(resolve, ms); }); }
function dist(a, b) { return Math.hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]); }

// the client (CSS) pixel of the canvas's centre and the canvas's box
async function viewBox(page) {
  return page.locator("#view").boundingBox();
}

// pixels of the geodesic's colour (a warm yellow) within 2 px of (x, y)
function yellowNear(shot, x, y) {
  for (let dy = -2; dy <= 2; dy++) {
    for (let dx = -2; dx <= 2; dx++) {
      const X = x + dx, Y = y + dy;
      if (X < 0 || Y < 0 || X >= shot.width || Y >= shot.height) continue;
      const c = shot.at(X, Y);
      if (c[0] > 180 && c[1] > 150 && c[2] < 120 && c[0] - c[2] > 100) return true;
    }
  }
  return false;
}

// (1) the geodesic on the sphere: closed after 2π, drawn in front, hidden behind
async function testSphereGeodesic(check, page) {
  const r = await page.evaluate(function () {
    const m = window.manifold, st = m.stats();
    return m.loadScene({ space: "sphere", gravity: false, bodies: [] }).then(function () {
      m.pause();
      // above the centre, so that the circle's far half runs below it (an ellipse, not a line)
      const p = m.pick(st.width / 2, st.height / 2 - 0.25 * st.height);
      const cam = m.camera();
      // a tangent direction: across the view (the camera's right, as the eye sees it)
      const e = cam.eye, t = cam.target, f = [t[0] - e[0], t[1] - e[1], t[2] - e[2]];
      const d = [f[2], 0, -f[0]];
      const g = m.geodesic(p, d);
      m.render();
      const front = [], back = [];
      g.points.forEach(function (q, k) {
        const facing = (q[0] - e[0]) * q[0] + (q[1] - e[1]) * q[1] + (q[2] - e[2]) * q[2] < -0.2;
        const behind = (q[0] - e[0]) * q[0] + (q[1] - e[1]) * q[1] + (q[2] - e[2]) * q[2] > 0.2;
        const px = m.project(q);
        if (k % 8 === 0 && px && facing) front.push(px);
        if (k % 8 === 0 && px && behind) back.push(px);
      });
      return { p: p, n: g.points.length, first: g.points[0], last: g.points[g.points.length - 1], breaks: g.breaks.length,
        radius: g.points.reduce(function (worst, q) { return Math.max(worst, Math.abs(Math.hypot(q[0], q[1], q[2]) - 1)); }, 0),
        front: front, back: back, drawn: m.curves().geodesic !== null };
    });
  });
  const shot = await canvasShot(page, path.join(OUT, "tools-geodesic-sphere.png"));
  const frontHit = r.front.filter(function (px) { return yellowNear(shot, px[0], px[1]); }).length;
  const backHit = r.back.filter(function (px) { return yellowNear(shot, px[0], px[1]); }).length;
  check("geodesic(p, d) on the sphere: 513 points on the unit sphere, from p back to p after 2π (a closed great circle), no break",
    r.n === 513 && dist(r.first, r.p) < 1e-9 && dist(r.last, r.p) < 2e-3 && r.radius < 1e-6 && r.breaks === 0 && r.drawn,
    "end " + dist(r.last, r.p).toExponential(2) + " from the start, |p| - 1 up to " + r.radius.toExponential(2));
  check("the geodesic is drawn where it faces the camera and hidden where it runs behind the sphere (its colour at its projected points)",
    r.front.length > 10 && frontHit >= 0.9 * r.front.length && r.back.length > 10 && backHit <= 0.1 * r.back.length,
    "in front " + frontHit + " of " + r.front.length + ", behind " + backHit + " of " + r.back.length);
}

// (2) quotients: the flat torus winds back through the edge, the projective plane through the antipode
async function testQuotientGeodesics(check, page) {
  const flat = await page.evaluate(function () {
    const m = window.manifold;
    return m.setSpace("flat-torus").then(function () {
      const images = window.Manifold.spaces["flat-torus"].images;
      const period = Math.min.apply(null, images.map(function (g) { return Math.hypot(g[9], g[10], g[11]); }).filter(function (t) { return t > 0; }));
      const p = [0.1, 0, 0.2];
      const g = m.geodesic(p, [1, 0, 0], period);
      return { period: period, end: g.points[g.points.length - 1], p: p, breaks: g.breaks };
    });
  });
  check("on the flat torus the geodesic of one period's length along x winds back to its start, breaking once at the square's edge",
    dist(flat.end, flat.p) < 1e-6 && flat.breaks.length === 1,
    "period " + flat.period + ", end " + dist(flat.end, flat.p).toExponential(2) + " from the start, breaks at " + JSON.stringify(flat.breaks));
  const rp = await page.evaluate(function () {
    const m = window.manifold;
    return m.setSpace("projective-plane").then(function () {
      const st = m.stats(), p = m.pick(st.width / 2, st.height / 2), R = Math.hypot(p[0], p[1], p[2]);
      const d = [p[1] * 0.8 - p[2] * 0.5, p[2] * 0.3 - p[0] * 0.8, p[0] * 0.5 - p[1] * 0.3]; // p × (0.3, 0.5, 0.8): tangent
      const half = m.geodesic(p, d, Math.PI * R), whole = m.geodesic(p, d, 2 * Math.PI * R);
      const h = half.points[half.points.length - 1], w = whole.points[whole.points.length - 1];
      return { p: p, toAntipode: Math.hypot(h[0] + p[0], h[1] + p[1], h[2] + p[2]), toP: Math.hypot(h[0] - p[0], h[1] - p[1], h[2] - p[2]),
        wholeBack: Math.hypot(w[0] - p[0], w[1] - p[1], w[2] - p[2]) };
    });
  });
  check("on the projective plane the geodesic of length π reaches the antipode, the point itself there, and 2π comes round again",
    Math.min(rp.toAntipode, rp.toP) < 2e-3 && rp.wholeBack < 4e-3,
    "after π: " + Math.min(rp.toAntipode, rp.toP).toExponential(2) + " from ±p; after 2π: " + rp.wholeBack.toExponential(2));
}

// (3) g switches the geodesic tool; a press and drag draws the geodesic from the pressed point
async function testGeodesicTool(check, page) {
  await page.evaluate(function () {
    const m = window.manifold;
    return m.setSpace("sphere").then(function () { return m.loadScene({ space: "sphere", gravity: false, bodies: [] }); }).then(function () { m.pause(); });
  });
  await page.mouse.click(5, 5); // the page has the focus, not a control
  await page.keyboard.press("g");
  const tool = await page.evaluate(function () { return { tool: window.manifold.tool(), select: document.getElementById("tool").value }; });
  const box = await viewBox(page);
  const x = box.x + box.width / 2, y = box.y + box.height / 2;
  const pressed = await page.evaluate(function () { const st = window.manifold.stats(); return window.manifold.pick(st.width / 2, st.height / 2); });
  await page.mouse.move(x, y);
  await page.mouse.down();
  await page.mouse.move(x + 40, y - 10, { steps: 5 });
  await page.mouse.up();
  const g = await page.evaluate(function () { return window.manifold.curves().geodesic; });
  const bodies = await page.evaluate(function () { return window.manifold.stats().bodies; });
  await page.keyboard.press("g");
  const back = await page.evaluate(function () { return window.manifold.tool(); });
  check("g switches to the geodesic tool (its select follows); a drag from a surface point draws the closed geodesic from there, adds no body; g again: grab",
    tool.tool === "geodesic" && tool.select === "geodesic" && g !== null && g.points.length === 513 &&
      dist(g.points[0], pressed) < 0.02 && dist(g.points[512], g.points[0]) < 2e-3 && bodies === 0 && back === "grab",
    JSON.stringify({ tool: tool, points: g && g.points.length, start: g && dist(g.points[0], pressed), bodies: bodies, back: back }));
}

// (4) a throw: the preview while dragging, and the body on it 0.5 s later; a click adds a body at rest
async function testThrow(check, page) {
  await page.evaluate(function () {
    const m = window.manifold;
    return m.loadScene({ space: "sphere", gravity: true, bodies: [] }).then(function () { m.pause(); });
  });
  const box = await viewBox(page);
  const x = box.x + box.width / 2, y = box.y + box.height / 2;
  await page.mouse.move(x, y);
  await page.mouse.down();
  await page.mouse.move(x + 60, y - 25, { steps: 6 });
  await sleep(100);
  const during = await page.evaluate(function () { return { preview: window.manifold.curves().preview, bodies: window.manifold.stats().bodies }; });
  await page.mouse.up();
  const after = await page.evaluate(function () {
    const m = window.manifold, b0 = m.bodies();
    const preview = m.curves().preview;
    m.step(50);
    return { count: b0.length, v: b0.length ? b0[0].v : null, p0: b0.length ? b0[0].p : null, p50: m.bodies()[0] ? m.bodies()[0].p : null, previewAfter: preview };
  });
  const pv = during.preview;
  const ok = pv && after.p50 && pv.points.length === 101;
  const err = ok ? dist(after.p50, pv.points[50]) : Infinity, travelled = ok ? dist(pv.points[50], pv.points[0]) : 0;
  check("a drag on empty surface shows the throw's preview (101 points: 1 s of steps, the body alone) and adds nothing before the release",
    ok && during.bodies === 0 && dist(pv.points[0], after.p0) < 1e-9 && travelled > 0.1,
    JSON.stringify({ points: pv && pv.points.length, bodies: during.bodies, travelled: travelled }));
  check("the release launches the body from the press point; 0.5 s later it is within 2 % of the preview's point (of the way it went); the preview is gone",
    ok && after.count === 1 && Math.hypot.apply(null, after.v) > 0 && err <= 0.02 * travelled && after.previewAfter === null,
    "off the preview by " + err.toExponential(2) + " after " + travelled.toFixed(3) + " travelled");

  // the new body's controls, then a click: a body there at rest
  await page.evaluate(function () { window.manifold.clear(); });
  await page.selectOption("#body-shape", "square");
  await page.evaluate(function () {
    const s = document.getElementById("body-size");
    s.value = String(Number(s.min) + 2 * Number(s.step));
    s.dispatchEvent(new Event("input", { bubbles: true }));
  });
  await page.fill("#body-density", "2.5");
  await page.dispatchEvent("#body-density", "change");
  await page.check("#body-static");
  const chosen = await page.evaluate(function () { return window.manifold.newBody(); });
  const at = await page.evaluate(function () { const st = window.manifold.stats(); return window.manifold.pick(st.width / 2 - 30, st.height / 2); });
  await page.mouse.click(x - 30, y);
  const clicked = await page.evaluate(function () { return window.manifold.bodies(); });
  const b = clicked[0];
  check("a click on empty surface adds the new body there at rest, with the shape, size, density and static chosen in the controls",
    clicked.length === 1 && dist(b.p, at) < 0.02 && Math.hypot.apply(null, b.v) === 0 && b.shape === "square" && b.static === true &&
      b.density === 2.5 && Math.abs(b.size - chosen.size) < 1e-12 && chosen.size < 0.2,
    JSON.stringify({ n: clicked.length, chosen: chosen, body: b && { p: b.p, v: b.v, shape: b.shape, size: b.size, density: b.density, static: b.static } }));
  const refused = await page.evaluate(function () {
    const m = window.manifold, out = [];
    [{ size: -1 }, { shape: { polygon: 2 } }, { density: "heavy" }, { colour: 1 }].forEach(function (o) {
      try { m.setNewBody(o); out.push("accepted"); } catch (e) { out.push(e.message); }
    });
    const kept = m.newBody();
    m.setNewBody({ size: null, shape: "circle", static: false, density: 1 });
    return { out: out, kept: kept, own: m.newBody().size };
  });
  check("setNewBody refuses a bad value naming its field and changes nothing; size null is the space's own again",
    /newBody\.size/.test(refused.out[0]) && /newBody\.shape/.test(refused.out[1]) && /newBody\.density/.test(refused.out[2]) &&
      /colour/.test(refused.out[3]) && refused.kept.density === 2.5 && refused.own === 0.2,
    JSON.stringify(refused));
}

// (5) a grabbed body let go keeps its speed
async function testLetGo(check, page) {
  const start = await page.evaluate(function () {
    const m = window.manifold, st = m.stats();
    const p = m.pick(st.width / 2, st.height / 2);
    return m.loadScene({ space: "sphere", gravity: false, bodies: [{ shape: "circle", size: 0.2, p: p }] }).then(function () {
      m.resume();
      return m.project(m.bodies()[0].p);
    });
  });
  const box = await viewBox(page);
  const x = box.x + start[0], y = box.y + start[1];
  await page.mouse.move(x, y);
  await page.mouse.down();
  for (let i = 1; i <= 8; i++) {
    await page.mouse.move(x + 10 * i, y);
    await sleep(40);
  }
  // still moving the pointer: the joint pulls the body along at the pointer's pace
  await page.mouse.move(x + 90, y);
  const before = await page.evaluate(function () { const m = window.manifold; m.pause(); return { grabbed: m.grabbed(), v: m.bodies()[0].v }; });
  await page.mouse.up();
  const v = await page.evaluate(function () { const m = window.manifold; m.step(1); return { grabbed: m.grabbed(), v: m.bodies()[0].v }; });
  const s0 = Math.hypot.apply(null, before.v), s1 = Math.hypot.apply(null, v.v);
  check("a grabbed body dragged and let go keeps the velocity the joint gave it (a step later)",
    before.grabbed === 0 && v.grabbed === -1 && s0 > 0.01 && Math.abs(s1 / s0 - 1) < 0.05,
    "held " + before.grabbed + ", speed held " + s0.toFixed(4) + ", a step after release " + s1.toFixed(4));
}

// (6) trails: t switches them; they appear and fade
async function testTrails(check, page) {
  await page.evaluate(function () {
    const m = window.manifold, st = m.stats();
    const p = m.pick(st.width / 2, st.height / 2), cam = m.camera();
    const f = [cam.target[0] - cam.eye[0], cam.target[1] - cam.eye[1], cam.target[2] - cam.eye[2]], s = Math.hypot(f[0], f[2]);
    return m.loadScene({ space: "sphere", gravity: false, bodies: [{ shape: "circle", size: 0.1, p: p, v: [f[2] / s, 0, -f[0] / s] }] }).then(function () { m.resume(); });
  });
  await page.mouse.click(5, 5);
  await page.keyboard.press("t");
  await sleep(1500);
  const on = await page.evaluate(function () { const m = window.manifold; m.pause(); m.render(); return { trails: m.trails(), box: document.getElementById("trails").checked, c: m.curves().trails }; });
  const withTrails = await canvasShot(page, path.join(OUT, "tools-trails-sphere.png"));
  await page.evaluate(function () { window.manifold.setTrails(false); window.manifold.render(); });
  const without = await canvasShot(page);
  let differ = 0;
  for (let y = 0; y < without.height; y++) {
    for (let x = 0; x < without.width; x++) {
      const a = withTrails.at(x, y), b = without.at(x, y);
      if (Math.abs(a[0] - b[0]) + Math.abs(a[1] - b[1]) + Math.abs(a[2] - b[2]) > 30) differ++;
    }
  }
  check("t turns trails on (its checkbox follows): a moving body leaves one, drawn (pixels differ from the same view without it)",
    on.trails && on.box && on.c.samples >= 10 && on.c.segments >= 9 && differ > 100,
    JSON.stringify(on.c) + ", " + differ + " pixels differ");
  // fading: after 4 s more only the last samples are drawn, the oldest end transparent
  const faded = await page.evaluate(function () {
    const m = window.manifold;
    m.setTrails(true);
    m.resume();
    return new Promise(function (r) { setTimeout(r, 4000); }).then(function () {
      m.pause();
      const c = m.curves().trails;
      m.step(400); // 4 s at once: every sample older than the trail's 3 s
      return new Promise(function (r) { requestAnimationFrame(function () { requestAnimationFrame(function () { r([c, m.curves().trails]); }); }); });
    });
  });
  check("trails fade: the oldest drawn end is nearly transparent, the newest opaque, and 4 s on nothing old is drawn",
    faded[0].segments > 30 && faded[0].oldest < 0.1 && faded[0].newest > 0.9 && faded[1].segments === 0,
    JSON.stringify(faded));
  await page.evaluate(function () { window.manifold.setTrails(false); });
}

// (8) the plot: p shows it; for a free body on the torus the energy and the axial momentum are flat lines
async function testPlot(check, page) {
  await page.evaluate(function () {
    const m = window.manifold;
    return m.setSpace("torus").then(function () {
      return m.loadScene({ space: "torus", gravity: false, bodies: [{ shape: "circle", size: 0.15, p: [1.3, 0, 0], v: [0, 0.4, 0.5], omega: 1 }] });
    }).then(function () { m.resume(); });
  });
  await page.mouse.click(5, 5);
  await page.keyboard.press("p");
  await sleep(3500);
  const r = await page.evaluate(function () {
    const m = window.manifold;
    m.pause();
    const p = m.plot();
    const spread = function (v) { return (Math.max.apply(null, v) - Math.min.apply(null, v)) / Math.abs(v[0]); };
    return { on: p.on, box: document.getElementById("plot-toggle").checked, n: p.samples.time.length,
      energy: spread(p.samples.kineticEnergy), axial: spread(p.samples.axialMomentum), first: p.samples.kineticEnergy[0] };
  });
  await sleep(200);
  const shot = await page.locator("#plot").screenshot();
  const img = decodePNG(shot);
  // The energy line's pixels (its colour #ffd75e, antialiased over the dark
  // plot: below the legend), by row. Where two other lines cross (contacts'
  // red over ms/step's green) the blend can look the same, so the line is
  // judged by where its pixels lie: flat is most of them in a band of 4 rows.
  const perRow = new Map();
  const columns = new Set();
  let count = 0;
  for (let y = 36; y < img.height; y++) {
    for (let x = 0; x < img.width; x++) {
      const c = img.at(x, y);
      if (c[0] > 200 && c[1] > 170 && c[1] < 235 && c[2] < 140) {
        perRow.set(y, (perRow.get(y) || 0) + 1); columns.add(x); count++;
      }
    }
  }
  let band = 0, bandTop = -1;
  for (const y of perRow.keys()) {
    let inBand = 0;
    for (let k = 0; k < 4; k++) inBand += perRow.get(y + k) || 0;
    if (inBand > band) { band = inBand; bandTop = y; }
  }
  const flat = { rows: bandTop + "–" + (bandTop + 3), pixels: count, share: count ? +(band / count).toFixed(3) : 0, columns: columns.size };
  check("p shows the plot (its checkbox follows); for a free body on the torus its energy and axial momentum stay flat (Clairaut), and the energy line is drawn flat",
    r.on && r.box && r.n >= 20 && r.energy < 1e-6 && r.axial < 1e-5 && flat.columns >= 10 && flat.share >= 0.8,
    JSON.stringify(r) + ", energy line: " + JSON.stringify(flat));
  const cube = await page.evaluate(function () {
    const m = window.manifold;
    return m.setSpace("cube").then(function () { m.resume(); return new Promise(function (res) { setTimeout(res, 600); }); }).then(function () {
      const p = m.plot();
      return { axial: p.samples.axialMomentum, n: p.samples.time.length };
    });
  });
  check("on the cube, which has no axis, the plot has no axial momentum, and starts again with the new world",
    cube.axial === null && cube.n >= 1 && cube.n < 20, JSON.stringify(cube));
  await page.evaluate(function () { window.manifold.setPlot(false); });
}

// (9) the inspector: Alt and the pointer on a body describe it; letting go of Alt hides it
async function testInspector(check, page) {
  const at = await page.evaluate(function () {
    const m = window.manifold, st = m.stats();
    const p = m.pick(st.width / 2, st.height / 2);
    return m.loadScene({ space: m.space(), gravity: false, bodies: [{ shape: { polygon: 5 }, size: 0.2, p: p, v: [0.1, 0, 0], omega: 0.5 }] }).then(function () {
      m.pause();
      m.render();
      return m.project(m.bodies()[0].p);
    });
  });
  const box = await page.locator("#view").boundingBox();
  await page.keyboard.down("Alt");
  await page.mouse.move(box.x + at[0] + 2, box.y + at[1] + 1);
  await sleep(200);
  const shown = await page.evaluate(function (a) {
    const el = document.getElementById("inspector");
    const v = window.manifold.bodies()[0].v;
    return { hidden: el.hidden, text: el.textContent, api: window.manifold.inspect(a[0], a[1]), speed: Math.hypot(v[0], v[1], v[2]) };
  }, at);
  await page.keyboard.up("Alt");
  await sleep(100);
  const after = await page.evaluate(function () { return document.getElementById("inspector").hidden; });
  const d = shown.api;
  check("Alt and the pointer on a body show the inspector (its shape, speed, spin, energy, contacts), as inspect(x, y) gives them; letting go of Alt hides it",
    !shown.hidden && /body 0 · 5-gon 0\.200 · speed [0-9.]+ · ω 0\.500 · energy [0-9.e-]+ · contacts 0/.test(shown.text) && d && d.index === 0 &&
      Math.abs(d.speed - shown.speed) < 1e-12 && d.speed > 0.05 && d.energy > 0 && d.contacts === 0 && after,
    JSON.stringify({ text: shown.text, api: d, hiddenAfter: after }));
}

// (6b) boxes and capsules: the Body control makes them from the size and the
// length over width; a click adds one; a scene's box is drawn and collides
async function testBoxBody(check, page) {
  await page.evaluate(function () { window.manifold.clear(); window.manifold.pause(); });
  await page.uncheck("#body-static");
  await page.selectOption("#body-shape", "box");
  const shown = await page.evaluate(function () {
    return { aspect: !document.getElementById("body-aspect").hidden, sides: !document.getElementById("polygon-sides").hidden };
  });
  await page.fill("#body-aspect", "3");
  await page.dispatchEvent("#body-aspect", "change");
  const chosen = await page.evaluate(function () {
    const s = /** @type {HTMLInputElement} */ (document.getElementById("body-size"));
    return { body: window.manifold.newBody(), slider: Number(s.value) };
  });
  const box = await page.locator("#view").boundingBox();
  await page.mouse.click(box.x + box.width / 2, box.y + box.height / 2);
  const added = await page.evaluate(function () { return window.manifold.bodies(); });
  const sh = chosen.body.shape, b = added[0];
  check("the Body control makes a box from the size and its length over width (3), showing that number and not the sides; a click adds it, its size its numbers'",
    shown.aspect && !shown.sides && sh && sh.box && Math.abs(sh.box[0] / sh.box[1] - 3) < 1e-9 &&
      Math.abs(Math.hypot(sh.box[0], sh.box[1]) - chosen.slider) < 1e-9 && Math.abs(chosen.body.size - chosen.slider) < 1e-9 &&
      added.length === 1 && b.shape.box && b.shape.box[0] === sh.box[0] && b.shape.box[1] === sh.box[1] && !("size" in b),
    JSON.stringify({ shown: shown, chosen: chosen, added: added.map(function (x) { return { shape: x.shape, size: x.size }; }) }));
  // the slider moved by the keyboard: the box made anew, its length over width kept
  await page.focus("#body-size");
  for (let i = 0; i < 5; i++) await page.keyboard.press("ArrowRight");
  const grown = await page.evaluate(function () {
    const s = /** @type {HTMLInputElement} */ (document.getElementById("body-size"));
    return { body: window.manifold.newBody(), slider: Number(s.value), step: Number(s.step) };
  });
  const gb = grown.body.shape && grown.body.shape.box;
  check("the size slider moved five steps by the keyboard makes the box anew at that size, its length over width kept",
    gb && Math.abs(grown.slider - (chosen.slider + 5 * grown.step)) < 1e-9 && Math.abs(Math.hypot(gb[0], gb[1]) - grown.slider) < 1e-9 &&
      Math.abs(gb[0] / gb[1] - 3) < 1e-9, JSON.stringify({ chosen: chosen.slider, grown: grown }));
  await page.selectOption("#body-shape", "capsule");
  const capsule = await page.evaluate(function () { return window.manifold.newBody().shape; });
  check("and a capsule: half its length and its radius from the size and the aspect",
    capsule && capsule.capsule && Math.abs((capsule.capsule[0] + capsule.capsule[1]) / capsule.capsule[1] - 3) < 1e-9 &&
      Math.abs(capsule.capsule[0] + capsule.capsule[1] - grown.slider) < 1e-9, JSON.stringify(capsule));
  // a polygon of its own corners as the new body: the control offers it, its slider scales it
  await page.evaluate(function () { window.manifold.setNewBody({ shape: { vertices: [[0, 0], [0.1, 0], [0.05, 0.08]], radius: 0.005 } }); });
  const own = await page.evaluate(function () {
    const s = /** @type {HTMLInputElement} */ (document.getElementById("body-size"));
    const option = /** @type {HTMLOptionElement} */ (document.getElementById("body-shape-vertices"));
    return { select: /** @type {HTMLSelectElement} */ (document.getElementById("body-shape")).value, offered: !option.hidden, slider: Number(s.value),
      reach: window.ManifoldWeb.world.reachOf({ vertices: [[0, 0], [0.1, 0], [0.05, 0.08]], radius: 0.005 }, 0),
      min: Number(s.min), max: Number(s.max), step: Number(s.step) };
  });
  // the slider moved by the keyboard, eight steps up
  await page.focus("#body-size");
  for (let i = 0; i < 8; i++) await page.keyboard.press("ArrowRight");
  const scaled = await page.evaluate(function () {
    const s = /** @type {HTMLInputElement} */ (document.getElementById("body-size"));
    return { body: window.manifold.newBody(), slider: Number(s.value) };
  });
  const v = scaled.body.shape && scaled.body.shape.vertices;
  const k = v ? v[1][0] / 0.1 : 0;
  check("a convex polygon as the new body: the Body control offers it, its slider at how far it reaches, and scales it (corners and radius alike) to the slider",
    own.select === "vertices" && own.offered && own.reach > 0.06 && own.reach < 0.065 &&
      Math.abs(own.slider - Math.min(own.max, Math.max(own.min, own.reach))) <= own.step && v && v.length === 3 &&
      Math.abs(k - scaled.slider / own.reach) < 1e-9 && Math.abs(v[2][1] - 0.08 * k) < 1e-9 && Math.abs(scaled.body.shape.radius - 0.005 * k) < 1e-9 &&
      Math.abs(scaled.body.size - scaled.slider) < 1e-9 && Math.abs(scaled.slider - (own.slider + 8 * own.step)) < 1e-9,
    JSON.stringify({ own: own, scaled: scaled }));
  await page.selectOption("#body-shape", "circle");
  const hiddenAgain = await page.evaluate(function () { return document.getElementById("body-shape-vertices").hidden; });
  const hiddenByApi = await page.evaluate(function () {
    window.manifold.setNewBody({ shape: { vertices: [[0, 0], [0.1, 0], [0.05, 0.08]] } });
    const offered = !document.getElementById("body-shape-vertices").hidden;
    window.manifold.setNewBody({ shape: "square" });
    return { offered: offered, hidden: document.getElementById("body-shape-vertices").hidden,
      select: /** @type {HTMLSelectElement} */ (document.getElementById("body-shape")).value };
  });
  check("and a circle chosen, or a square given by setNewBody, the polygon is no longer offered",
    hiddenAgain && hiddenByApi.offered && hiddenByApi.hidden && hiddenByApi.select === "square", JSON.stringify({ hiddenAgain: hiddenAgain, api: hiddenByApi }));
  await page.selectOption("#body-shape", "circle");
  // a plank on two boxes at the sphere's south pole: it stays up
  const plank = await page.evaluate(function () {
    const m = window.manifold;
    const at = function (a, b) { const r = Math.hypot(a, b); return r === 0 ? [0, -1, 0] : [Math.sin(r) * a / r, -Math.cos(r), Math.sin(r) * b / r]; };
    return m.loadScene({ space: "sphere", bodies: [
      { shape: { box: [0.3, 0.05] }, static: true, p: at(0, 0) },
      { shape: { capsule: [0.05, 0.03] }, p: at(0.2, 0.09) },
      { shape: { box: [0.04, 0.04] }, p: at(-0.2, 0.1) } ] }).then(function () {
      m.step(200);
      return m.bodies().map(function (x) { return x.p; });
    });
  });
  const lifted = plank.slice(1).map(function (p) { return Math.acos(-p[1]); });
  check("a capsule and a box dropped onto a static box at the sphere's south pole come to rest against it, not through it",
    lifted.every(function (d) { return d > 0.07 && d < 0.3; }), JSON.stringify(lifted));
  await page.selectOption("#body-shape", "circle");
  await page.evaluate(function () { window.manifold.resume(); });
}

// (7) presets: by URL (#scene=NAME), by the select, each loads (a picture of each), an unknown name refused
async function testPresets(check, context, base) {
  const errors = [];
  const page = await openSpace(context, base, "#scene=trumpet-jam", errors);
  await page.waitForFunction(function () { return window.manifold.preset() === "trumpet-jam"; }, null, { timeout: 10000 }).catch(function () {});
  const byUrl = await page.evaluate(function () {
    const m = window.manifold;
    return { space: m.space(), bodies: m.bodies().length, preset: m.preset(), hash: location.hash, select: document.getElementById("preset").value,
      want: m.presets().length };
  });
  check("#scene=trumpet-jam loads the preset: the trumpet with its 14 bodies, the select and the hash naming it",
    byUrl.space === "trumpet" && byUrl.bodies === 14 && byUrl.preset === "trumpet-jam" && /scene=trumpet-jam/.test(byUrl.hash) &&
      byUrl.select === "trumpet-jam", JSON.stringify(byUrl));
  await page.selectOption("#preset", "rectangle-pyramid");
  await page.waitForFunction(function () { return window.manifold.preset() === "rectangle-pyramid"; }, null, { timeout: 10000 }).catch(function () {});
  const bySelect = await page.evaluate(function () { const m = window.manifold; return { space: m.space(), bodies: m.bodies().length, hash: location.hash }; });
  await page.evaluate(function () { window.manifold.clear(); });
  const afterClear = await page.evaluate(function () { return { preset: window.manifold.preset(), hash: location.hash, select: document.getElementById("preset").value }; });
  check("choosing a preset in the select loads it (switching space); clearing the bodies leaves it (the hash, the select)",
    bySelect.space === "rectangle" && bySelect.bodies === 36 && /scene=rectangle-pyramid/.test(bySelect.hash) &&
      afterClear.preset === null && !/scene=/.test(afterClear.hash) && afterClear.select === "",
    JSON.stringify({ bySelect: bySelect, afterClear: afterClear }));
  const all = await page.evaluate(function () { return window.manifold.presets(); });
  const loaded = [];
  const opened = [];
  for (const p of all) {
    // as it opens: the bodies found under their own projected centres by
    // the page's picking (the float framebuffer of the drawn view), the
    // body itself or, on an antipodal quotient, its image
    const seen = await page.evaluate(function (name) {
      const m = window.manifold;
      return m.loadPreset(name).then(function (n) {
        m.pause();
        m.render();
        const st = m.stats(), space = window.Manifold.spaces[m.space()];
        const images = space.quotient === "antipodal" ? [1, -1] : [1];
        const found = m.bodies().filter(function (b, i) {
          return images.some(function (s) {
            const q = m.project(b.p.map(function (x) { return s * x; }));
            if (!q || q[0] < 0 || q[1] < 0 || q[0] >= st.width || q[1] >= st.height) return false;
            const hit = m.inspect(q[0], q[1]);
            return hit !== null && hit.index === i;
          });
        });
        return { loaded: n, n: m.bodies().length, seen: found.length };
      });
    }, p.name);
    await canvasShot(page, path.join(OUT, "preset-" + p.name + "-opened.png"));
    opened.push({ name: p.name, n: seen.n, seen: seen.seen });
    // then 1 s on
    const r = await page.evaluate(function (a) {
      const m = window.manifold;
      m.step(100);
      m.render();
      return { name: a.name, n: a.loaded, want: window.Manifold.presets.find(function (q) { return q.name === a.name; }).scene.bodies.length,
        space: m.space(), warnings: m.stats().warnings, error: m.error() };
    }, { name: p.name, loaded: seen.loaded });
    await canvasShot(page, path.join(OUT, "preset-" + p.name + ".png"));
    loaded.push(r);
  }
  const names = all.map(function (p) { return p.name; });
  const wanted = ["trumpet-jam", "projective-plane-image", "rectangle-pyramid", "sphere-rain", "cube-stack", "klein-bottle-orbit"];
  check("every preset loads whole into its space and steps 1 s without warnings (pictures: test-output/browser/preset-NAME.png)",
    wanted.every(function (n) { return names.indexOf(n) >= 0; }) &&
      loaded.every(function (r) { return r.n === r.want && r.n > 0 && r.space === r.name.slice(0, r.space.length) && r.warnings === 0 && r.error === null; }),
    loaded.map(function (r) { return r.name + " " + r.n + "/" + r.want + " w" + r.warnings; }).join(", "));
  // (most; the torus's chain loops round the tube: no view has much more
  // than 150° of it facing the camera)
  check("every preset opens with most of its bodies in the picture, the view's picking finding each under its centre (pictures: test-output/browser/preset-NAME-opened.png)",
    opened.every(function (o) { return o.seen > (o.name === "torus-chain" ? 0.4 : 0.5) * o.n; }),
    opened.map(function (o) { return o.name + " " + o.seen + "/" + o.n; }).join(", "));
  const unknown = await page.evaluate(function () {
    const m = window.manifold, before = m.space();
    return m.loadPreset("sphere-nothing").then(function () { return "loaded"; }, function (e) {
      return { message: e.message, notice: document.getElementById("notice-text").textContent, kept: m.space() === before };
    });
  });
  check("an unknown preset is refused with a notice listing the presets, the world kept",
    unknown.kept && /no preset "sphere-nothing"; the presets are .*trumpet-jam/.test(unknown.message) && unknown.notice === unknown.message,
    JSON.stringify(unknown));
  check("presets page: no console errors", errors.length === 0, errors.join("; "));
  await page.close();
}

export async function testTools(check, context, base) {
  const errors = [];
  const page = await openSpace(context, base, "#space=sphere", errors);
  await testSphereGeodesic(check, page);
  await testQuotientGeodesics(check, page);
  await testGeodesicTool(check, page);
  await testThrow(check, page);
  await testLetGo(check, page);
  await testTrails(check, page);
  await testPlot(check, page);
  await testInspector(check, page);
  await testBoxBody(check, page);
  check("tools page: no console errors", errors.length === 0, errors.join("; "));
  await page.close();
  await testPresets(check, context, base);
}
