// Browser tests of the flat views of a hyperbolic space (part "disc" of
// run.mjs; web/js/disc.js): the Poincaré disc is the hyperbolic plane's
// default picture; every pixel of it picks a point of the hyperboloid, and
// project() takes it back to the pixel; a body dragged with the real mouse
// in a walked view ends under the pointer; a right-button drag walks (the
// picture follows the pointer) and the drag back returns the view to where
// it was; the wheel sizes the disc; the Klein disc and the hyperboloid in
// 3-D are chosen by the Model control, setOptions and the URL, and the
// control shows only for hyperbolic spaces. The Bolza surface is drawn as
// its tiling: the octagon lighter than its images, their edges dark, and a
// body drawn again where the side pairing puts it.
import path from "node:path";
import { OUT, canvasShot } from "./lib.mjs";
import { openSpace } from "./bodies.mjs";

// |y² − x² − z² − 1| at a picked point, where y ≤ FAR (within acosh 1000 = 7.6
// of the vertex); farther out (a pixel centre a hair inside the rim can be at
// y ~ 1e6) coordinates of size y carry round-off of y² times the double's
// epsilon, so there the bound is relative: SHEET_REL · y².
const SHEET_TOL = 1e-6, FAR = 1000, SHEET_REL = 1e-12;
const IDENTITY = [1, 0, 0, 0, 1, 0, 0, 0, 1];

/** The largest |y² − x² − z² − 1| over picks of a pixel grid (absolute where y ≤ FAR, relative to y² everywhere), and project's largest error in pixels. */
async function pickGrid(page, stride) {
  return page.evaluate(function (a) {
    const m = window.manifold, st = m.stats(), stride = a.stride;
    let sheet = 0, relative = 0, back = 0, picked = 0, offDisc = 0, far = 0;
    for (let y = 0.5; y < st.height; y += stride) {
      for (let x = 0.5; x < st.width; x += stride) {
        const p = m.pick(x, y);
        if (!p) { offDisc++; continue; }
        picked++;
        const e = Math.abs(p[1] * p[1] - p[0] * p[0] - p[2] * p[2] - 1);
        relative = Math.max(relative, e / (p[1] * p[1]));
        if (p[1] <= a.far) sheet = Math.max(sheet, e);
        else far++;
        const q = m.project(p);
        back = Math.max(back, Math.hypot(q[0] - x, q[1] - y));
      }
    }
    return { sheet: sheet, relative: relative, back: back, picked: picked, offDisc: offDisc, far: far };
  }, { stride: stride, far: FAR });
}

function maxDiff(a, b) {
  let d = 0;
  for (let k = 0; k < a.length; k++) d = Math.max(d, Math.abs(a[k] - b[k]));
  return d;
}

// ---- every pixel picks a point of the sheet, before and after a walk ----
async function testPicking(check, page) {
  const first = await page.evaluate(function () {
    const m = window.manifold;
    return { model: m.options().model, disc: m.discView(), centre: m.pick(m.stats().width / 2, m.stats().height / 2), corner: m.pick(1, 1),
      help: document.getElementById("help").textContent };
  });
  check("the help line under the disc says that a drag walks", /walk/.test(first.help) && !/orbit/.test(first.help), first.help);
  check("hyperbolic-plane is drawn in the Poincaré disc by default, centred on the vertex; a corner is off the disc",
    first.model === "poincare" && maxDiff(first.disc.boost, IDENTITY) === 0 && first.centre !== null &&
    Math.abs(first.centre[1] - 1) < 1e-9 && first.corner === null,
    JSON.stringify({ model: first.model, centre: first.centre, corner: first.corner }));
  for (const walked of [false, true]) {
    if (walked) await page.evaluate(function () { window.manifold.walk(60, -25); window.manifold.walk(-15, 50); });
    const r = await pickGrid(page, 3);
    const away = await page.evaluate(function () { return Math.acosh(window.manifold.discView().boost[4]); });
    check("every third pixel of the disc" + (walked ? " after a walk of " + away.toFixed(2) + " from the vertex" : "") + " picks a point of the hyperboloid (|y² − x² − z² − 1| < " +
      SHEET_TOL + " where y ≤ " + FAR + ", < " + SHEET_REL + " y² beyond) that project() puts back on the pixel (1e-6 px)",
      r.picked > 5000 && r.sheet < SHEET_TOL && r.relative < SHEET_REL && r.back < 1e-6,
      r.picked + " picked (" + r.far + " beyond y = " + FAR + "), " + r.offDisc + " off the disc; max |y² − x² − z² − 1| " + r.sheet.toExponential(2) +
      ", relative " + r.relative.toExponential(2) + ", max project error " + r.back.toExponential(2) + " px");
  }
}

// ---- the right button walks; the same drag back returns the view ----
async function testWalk(check, page) {
  const box = await page.locator("#view").boundingBox();
  const st = await page.evaluate(function () {
    const m = window.manifold;
    m.setDiscView({ boost: [1, 0, 0, 0, 1, 0, 0, 0, 1], zoom: 0.95 });
    m.loadScene({ space: m.space(), gravity: false, bodies: [{ shape: "circle", size: 0.2, p: [0, 1, 0] }] });
    m.pause();
    m.render();
    return m.stats();
  });
  const centre = [box.x + st.width / 2, box.y + st.height / 2];
  const before = await page.evaluate(function () { return window.manifold.project(window.manifold.bodies()[0].p); });
  await page.mouse.move(centre[0], centre[1]);
  await page.mouse.down({ button: "right" });
  await page.mouse.move(centre[0] + 120, centre[1] - 60, { steps: 10 });
  const mid = await page.evaluate(function () {
    const m = window.manifold;
    return { pixel: m.project(m.bodies()[0].p), disc: m.discView() };
  });
  await page.mouse.move(centre[0], centre[1], { steps: 10 });
  await page.mouse.up({ button: "right" });
  const after = await page.evaluate(function () { return window.manifold.discView(); });
  check("a right-button drag of (120, −60) px walks: the body under the pointer stays under it (within 0.01 px)",
    Math.hypot(mid.pixel[0] - before[0] - 120, mid.pixel[1] - before[1] + 60) < 0.01 && maxDiff(mid.disc.boost, IDENTITY) > 0.1,
    "from " + before.map(function (v) { return v.toFixed(2); }) + " to " + mid.pixel.map(function (v) { return v.toFixed(2); }));
  check("dragging back along the same line returns the view to where it was (boost within 1e-9 of the identity)",
    maxDiff(after.boost, IDENTITY) < 1e-9, "largest difference " + maxDiff(after.boost, IDENTITY).toExponential(2));
  // the wheel sizes the disc
  await page.mouse.move(centre[0], centre[1]);
  await page.mouse.wheel(0, -200);
  const zoomed = await page.waitForFunction(function () { return window.manifold.discView().zoom > 0.95; }, null, { timeout: 3000 })
    .then(function () { return page.evaluate(function () { return window.manifold.discView().zoom; }); }).catch(function () { return null; });
  check("the wheel makes the disc larger", zoomed !== null && zoomed > 0.95, "zoom " + zoomed);
}

// ---- a body dragged in a walked view ends under the pointer ----
async function testDrag(check, page) {
  const box = await page.locator("#view").boundingBox();
  const placed = await page.evaluate(function () {
    const m = window.manifold;
    m.setDiscView({ zoom: 0.95 });
    m.walk(-150, 90); // the vertex is off centre: picking goes through the boost
    const st = m.stats(), p = m.pick(st.width * 0.4, st.height * 0.45);
    m.loadScene({ space: m.space(), gravity: false, bodies: [{ shape: "circle", size: 0.15, p: p }] });
    m.resume();
    m.render();
    return m.project(m.bodies()[0].p);
  });
  const to = [placed[0] + 110, placed[1] + 70];
  await page.mouse.move(box.x + placed[0], box.y + placed[1]);
  await page.mouse.down();
  const grabbed = await page.evaluate(function () { return window.manifold.grabbed(); });
  await page.mouse.move(box.x + to[0], box.y + to[1], { steps: 8 });
  let gap = Infinity;
  const t0 = Date.now();
  while (Date.now() - t0 < 8000) {
    const px = await page.evaluate(function () { return window.manifold.project(window.manifold.bodies()[0].p); });
    gap = Math.hypot(px[0] - to[0], px[1] - to[1]);
    if (gap < 1.5) break;
    await page.waitForTimeout(150);
  }
  await page.mouse.up();
  await canvasShot(page, path.join(OUT, "hyperbolic-plane-disc-drag.png"));
  check("a body grabbed with the mouse in a walked disc and dragged 130 px ends under the pointer (within 1.5 px)",
    grabbed === 0 && gap < 1.5, "grabbed " + grabbed + ", " + gap.toFixed(2) + " px from the pointer after " + ((Date.now() - t0) / 1000).toFixed(1) + " s");
}

// ---- the models: control, setOptions, the URL ----
async function testModels(check, context, base, page, errors) {
  const shown = await page.evaluate(function () { return !document.getElementById("model-control").hidden; });
  await page.selectOption("#model", "klein");
  const klein = await page.evaluate(function () {
    const m = window.manifold, st = m.stats();
    m.setDiscView({ boost: [1, 0, 0, 0, 1, 0, 0, 0, 1], zoom: 0.95 });
    const r = 0.95 * Math.min(st.width, st.height) / 2;
    // half-way to the rim: the Klein disc's radius 0.5 is tanh d, the Poincaré disc's tanh(d/2)
    const p = m.pick(st.width / 2 + 0.5 * r, st.height / 2);
    return { model: m.options().model, hash: location.hash, d: Math.acosh(p[1]) };
  });
  check("the Model control shows for the hyperbolic plane and picks the Klein disc (the URL says model=klein; half-way to the rim is atanh 0.5 from the centre)",
    shown && klein.model === "klein" && /model=klein/.test(klein.hash) && Math.abs(klein.d - Math.atanh(0.5)) < 1e-9,
    JSON.stringify(klein));
  const r = await pickGrid(page, 5);
  check("the Klein disc picks points of the hyperboloid that project() puts back", r.picked > 1000 && r.sheet < SHEET_TOL && r.relative < SHEET_REL && r.back < 1e-6,
    r.picked + " picked; " + r.sheet.toExponential(2) + ", relative " + r.relative.toExponential(2) + ", " + r.back.toExponential(2) + " px");
  await canvasShot(page, path.join(OUT, "hyperbolic-plane-klein.png"));
  const traced = await page.evaluate(function () {
    const m = window.manifold;
    m.setOptions({ model: "hyperboloid" });
    const st = m.stats(), before = m.camera();
    const p = m.pick(st.width / 2, st.height / 2);
    return { p: p, camera: before };
  });
  const box = await page.locator("#view").boundingBox();
  await page.mouse.move(box.x + 5, box.y + 5);
  await page.mouse.down({ button: "right" });
  await page.mouse.move(box.x + 65, box.y + 5, { steps: 4 });
  await page.mouse.up({ button: "right" });
  const orbited = await page.evaluate(function () { return Object.assign(window.manifold.camera(), { help: document.getElementById("help").textContent }); });
  check("model hyperboloid traces the surface in 3-D again: the right button orbits the camera, as the help line says",
    traced.p !== null && maxDiff(traced.camera.eye, orbited.eye) > 0.1 && /orbit/.test(orbited.help), JSON.stringify(traced.p) + "; " + orbited.help);
  let refused = null;
  try {
    await page.evaluate(function () { window.manifold.setOptions({ model: "upper-half" }); });
  } catch (err) {
    refused = err.message.split("\n")[0];
  }
  check("setOptions refuses an unknown model, naming the models", refused !== null && /model must be one of poincare, klein, hyperboloid/.test(refused), String(refused));

  const other = await openSpace(context, base, "#space=sphere", errors);
  const hidden = await other.evaluate(function () { return document.getElementById("model-control").hidden; });
  check("the Model control is hidden for a space of R³ (the sphere)", hidden === true);
  await other.close();
  const fromUrl = await openSpace(context, base, "#space=hyperbolic-plane&model=klein", errors);
  const urlModel = await fromUrl.evaluate(function () { return { model: window.manifold.options().model, select: document.getElementById("model").value }; });
  check("#space=hyperbolic-plane&model=klein opens the Klein disc", urlModel.model === "klein" && urlModel.select === "klein", JSON.stringify(urlModel));
  await fromUrl.close();
}

// ---- the Bolza surface's tiling: the octagon (inradius acosh(1 + √2)) lighter than
// its images, the edge between them dark, and a body near side 0 drawn again
// across side 4, where pairing 4 (the translation by twice the inradius along
// −x) puts it ----
async function testBolza(check, context, base, errors) {
  const page = await openSpace(context, base, "#space=bolza", errors);
  const r = Math.acosh(1 + Math.SQRT2);
  const polar = function (d, a) { return [Math.sinh(d) * Math.cos(a), Math.cosh(d), Math.sinh(d) * Math.sin(a)]; };
  // the translation by t along x (pairing 0 for t = 2r)
  const along = function (t, p) { return [p[0] * Math.cosh(t) + p[1] * Math.sinh(t), p[0] * Math.sinh(t) + p[1] * Math.cosh(t), p[2]]; };
  const at = { body: polar(1.2, 0), image: polar(2 * r - 1.2, Math.PI), // the body and its image across side 4
    inside: polar(1.0, 2.0), outside: along(2 * r, polar(1.0, 2.0)), // a point of the octagon (off the grid lines), and its image by pairing 0
    edge: polar(r, Math.PI / 2), nearEdge: polar(r - 0.25, Math.PI / 2) };
  const px = await page.evaluate(function (a) {
    const m = window.manifold;
    return m.loadScene({ space: "bolza", gravity: false, bodies: [{ shape: "circle", size: 0.25, p: a.body }] }).then(function () {
      m.pause();
      m.render();
      const out = { model: m.options().model, images: window.Manifold.spaces.bolza.images.length };
      for (const k of Object.keys(a)) out[k] = m.project(a[k]);
      return out;
    });
  }, at);
  const shot = await canvasShot(page, path.join(OUT, "bolza-disc.png"));
  // the mean colour of a 5-pixel square about a pixel
  const mean = function (q) {
    const c = [0, 0, 0];
    for (let dy = -2; dy <= 2; dy++) for (let dx = -2; dx <= 2; dx++) shot.at(q[0] + dx, q[1] + dy).forEach(function (v, k) { c[k] += v / 25; });
    return c;
  };
  const luma = function (c) { return 0.299 * c[0] + 0.587 * c[1] + 0.114 * c[2]; };
  const colourGap = function (a, b) { return Math.max(Math.abs(a[0] - b[0]), Math.abs(a[1] - b[1]), Math.abs(a[2] - b[2])); };
  check("bolza opens in the Poincaré disc with its 48 images", px.model === "poincare" && px.images === 48, JSON.stringify({ model: px.model, images: px.images }));
  const lIn = luma(mean(px.inside)), lOut = luma(mean(px.outside));
  check("the octagon is lighter than its image across a side (luma " + lIn.toFixed(1) + " against " + lOut.toFixed(1) + ")", lIn > lOut + 10, "");
  let lEdge = Infinity;
  for (let dy = -1; dy <= 1; dy++) for (let dx = -1; dx <= 1; dx++) lEdge = Math.min(lEdge, luma(shot.at(px.edge[0] + dx, px.edge[1] + dy)));
  const lNear = luma(mean(px.nearEdge));
  check("the octagon's side is drawn darker (luma " + lEdge.toFixed(1) + " on it, " + lNear.toFixed(1) + " a quarter inside)", lEdge < 0.8 * lNear, "");
  const body = mean(px.body), image = mean(px.image), ground = mean(px.outside);
  check("a body near side 0 is drawn again where pairing 4 puts it, across side 4 (colours " + JSON.stringify(body.map(Math.round)) + ", " +
    JSON.stringify(image.map(Math.round)) + "; the tile's ground " + JSON.stringify(ground.map(Math.round)) + ")",
    colourGap(body, image) < 40 && colourGap(image, ground) > 40, "");
  await testBolzaWalk(check, page);
  await testBolzaHyperboloid(check, page);
  await testBolzaJoints(check, page);
  await page.close();
}

// Pixels of a shot whose colour is a body's (saturated: the tiles' ground
// is a pale beige, the background a dark blue) within `reach` of pixel c.
function bodyPixels(shot, c, reach) {
  let n = 0;
  for (let y = Math.ceil(c[1] - reach); y <= c[1] + reach; y++) {
    for (let x = Math.ceil(c[0] - reach); x <= c[0] + reach; x++) {
      if (Math.hypot(x - c[0], y - c[1]) > reach) continue;
      const q = shot.at(x, y);
      if (Math.max(q[0], q[1], q[2]) - Math.min(q[0], q[1], q[2]) > 90) n++;
    }
  }
  return n;
}

// Walking on the Bolza surface: the view's centre stays in the octagon (the
// boost is recentred by the group), so the bodies are drawn about the view
// however far it goes, and walking back returns the boost to where it was.
async function testBolzaWalk(check, page) {
  const before = await page.evaluate(function () {
    const m = window.manifold;
    return m.loadScene({ space: "bolza", bodies: window.Manifold.spaces.bolza.scene.map(function (b) {
      return { shape: b.shape, size: b.size, p: b.p };
    }) }).then(function () {
      m.pause();
      m.render();
      const canvas = document.getElementById("view");
      return { width: canvas.width, height: canvas.height, r: 0.5 * m.discView().zoom * Math.min(canvas.width, canvas.height) };
    });
  });
  const centre = [before.width / 2, before.height / 2], reach = 0.6 * before.r;
  const shot0 = await canvasShot(page, null);
  const walked = await page.evaluate(function (a) {
    const m = window.manifold, S = window.Manifold.spaces.bolza;
    const out = { outside: 0, centre: [], back: null, steps: 0 };
    // the centre's point folded into the octagon: how far its wrap is from the identity
    const offDomain = function () {
      const c = m.pick(a.w / 2, a.h / 2);
      const w = S.wrapIntoDomain(c[0], c[1], c[2]);
      return Math.max(...[1, 0, 0, 0, 1, 0, 0, 0, 1].map(function (x, i) { return Math.abs(w[i] - x); }));
    };
    for (let k = 0; k < 10; k++) { m.walk(-a.step, 0.3 * a.step); out.outside = Math.max(out.outside, offDomain()); out.steps++; }
    m.render();
    out.far = m.discView().boost;
    return out;
  }, { w: before.width, h: before.height, step: 0.45 * before.r });
  const shot1 = await canvasShot(page, path.join(OUT, "bolza-walked.png"));
  const back = await page.evaluate(function (a) {
    const m = window.manifold;
    for (let k = 0; k < 10; k++) m.walk(a.step, -0.3 * a.step);
    return m.discView().boost;
  }, { step: 0.45 * before.r });
  const n0 = bodyPixels(shot0, centre, reach), n1 = bodyPixels(shot1, centre, reach);
  // the hyperbolic distance walked: ten steps of 2 atanh(0.45 √1.09) each, about 10
  check("walking ten steps (several tiles) keeps the view's centre in the octagon (its wrap the identity to " + walked.outside.toExponential(1) + ")",
    walked.outside < 1e-9, "");
  check("after the walk the bodies are drawn about the view (" + n1 + " body pixels in the middle of the disc, " + n0 + " before the walk)",
    n0 > 200 && n1 > 0.3 * n0, "");
  const backGap = Math.max(...back.map(function (x, i) { return Math.abs(x - [1, 0, 0, 0, 1, 0, 0, 0, 1][i]); }));
  // (the same walk on hyperbolic-plane, never recentred, comes back to 2e-8)
  check("walking back returns the boost to the identity (" + backGap.toExponential(1) + ", the far boost's largest entry " +
    Math.max(...walked.far.map(Math.abs)).toFixed(1) + ")", backGap < 1e-6, "");
}

// In the hyperboloid model (3-D) bodies' images are drawn only where the
// sheet is traced: nothing drawn over the background.
async function testBolzaHyperboloid(check, page) {
  await page.evaluate(function () {
    const m = window.manifold;
    m.setOptions({ model: "hyperboloid" });
    m.render();
  });
  const withBodies = await canvasShot(page, path.join(OUT, "bolza-hyperboloid.png"));
  await page.evaluate(function () {
    const m = window.manifold;
    m.clear();
    m.render();
  });
  const bare = await canvasShot(page, null);
  let floating = 0, drawn = 0;
  for (let y = 0; y < bare.height; y++) {
    for (let x = 0; x < bare.width; x++) {
      const a = withBodies.at(x, y), b = bare.at(x, y);
      if (Math.max(Math.abs(a[0] - b[0]), Math.abs(a[1] - b[1]), Math.abs(a[2] - b[2])) < 40) continue;
      drawn++;
      // the background is dark blue; the sheet pale
      if (0.299 * b[0] + 0.587 * b[1] + 0.114 * b[2] < 90) floating++;
    }
  }
  check("in the hyperboloid model no body is drawn over the background beyond the traced sheet (" + floating + " of " + drawn + " body pixels)",
    drawn > 500 && floating < 0.01 * drawn, "");
  await page.evaluate(function () { window.manifold.setOptions({ model: "poincare" }); });
}

// Joints are refused on bolza, by the scene reader and by the joint tool.
async function testBolzaJoints(check, page) {
  const r = await page.evaluate(function () {
    const m = window.manifold;
    const body = function (x) { return { shape: "circle", size: 0.2, p: [x, Math.sqrt(1 + x * x), 0] }; };
    return m.loadScene({ space: "bolza", bodies: [body(0), body(0.5)], joints: [{ type: "revolute", a: 0, b: 1, anchor: [0.25, Math.sqrt(1.0625), 0] }] })
      .then(function () { return "loaded"; }, function (e) { return e.message; })
      .then(function (scene) {
        return m.loadScene({ space: "bolza", bodies: [body(0), body(0.5)] }).then(function () {
          let added;
          try { added = m.addJoint({ type: "revolute", a: 0, b: 1, anchor: [0.25, Math.sqrt(1.0625), 0] }); } catch (e) { added = e.message; }
          return { scene: scene, added: added, joints: m.joints().length };
        });
      });
  });
  const named = function (t) { return typeof t === "string" && t.indexOf("joints are not supported on bolza") >= 0; };
  check("bolza refuses a scene with a joint and a joint added (" + JSON.stringify(r) + ")", named(r.scene) && named(r.added) && r.joints === 0, "");
  // the joint tool: a press on body 0 and a release on body 1 with the mouse
  const ends = await page.evaluate(function () {
    const m = window.manifold, b = m.bodies();
    m.setTool("joint");
    m.render();
    const box = document.getElementById("view").getBoundingClientRect(), k = box.width / document.getElementById("view").width;
    return [0, 1].map(function (i) { const q = m.project(b[i].p); return [box.left + k * q[0], box.top + k * q[1]]; });
  });
  await page.mouse.move(ends[0][0], ends[0][1]);
  await page.mouse.down();
  await page.mouse.move(ends[1][0], ends[1][1], { steps: 5 });
  await page.mouse.up();
  const tool = await page.evaluate(function () {
    const m = window.manifold;
    const out = { joints: m.joints().length, notice: document.getElementById("notice").hidden ? "" : document.getElementById("notice-text").textContent };
    m.setTool("grab");
    return out;
  });
  check("the joint tool on bolza makes no joint and says why (" + JSON.stringify(tool) + ")", tool.joints === 0 && named(tool.notice), "");
}

export async function testDisc(check, context, base) {
  const errors = [];
  const page = await openSpace(context, base, "#space=hyperbolic-plane", errors);
  await testPicking(check, page);
  await testWalk(check, page);
  await testDrag(check, page);
  await testModels(check, context, base, page, errors);
  await page.close();
  await testBolza(check, context, base, errors);
  check("disc pages: no console errors", errors.length === 0, errors.join("; "));
}
