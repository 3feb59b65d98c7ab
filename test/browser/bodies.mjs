// Browser tests of the bodies: drawn from the engine's polygons, hidden behind
// the surface, grabbed and dragged with real mouse events, stepped
// deterministically, saved and loaded as scenes. Run by run.mjs (part "bodies";
// the per-space visibility check runs with each space; what the running page
// allocates with many bodies is in performance.mjs).
import fs from "node:fs";
import path from "node:path";
import { execFileSync } from "node:child_process";
import { OUT, ROOT, canvasShot, manifoldExe } from "./lib.mjs";

// A pixel is "body-coloured" when it is strongly saturated: the page's body
// palette is, the beige surface, its grid and the background are not.
const SATURATED = 80;
const FIELD_ON_SURFACE = 1e-6;

function saturation(c) { return Math.max(c[0], c[1], c[2]) - Math.min(c[0], c[1], c[2]); }

// The fraction of body-coloured pixels in the (2r+1)² square about (x, y).
export function bodyFraction(shot, x, y, r) {
  r = r === undefined ? 4 : r;
  let n = 0, hit = 0;
  for (let dy = -r; dy <= r; dy++) {
    for (let dx = -r; dx <= r; dx++) {
      const px = Math.floor(x) + dx, py = Math.floor(y) + dy;
      if (px < 0 || py < 0 || px >= shot.width || py >= shot.height) continue;
      n++;
      if (saturation(shot.at(px, py)) > SATURATED) hit++;
    }
  }
  return n ? hit / n : 0;
}

// The bodies (and, on antipodal quotients, their images) whose centre is the
// surface point seen at its projected pixel: [{ index, image, p, pixel }].
async function visibleCentres(page) {
  return page.evaluate(function () {
    const m = window.manifold, st = m.stats();
    const space = window.Manifold.spaces[m.space()];
    const out = [];
    m.bodies().forEach(function (b, i) {
      const images = space.quotient === "antipodal" ? [1, -1] : [1];
      images.forEach(function (s) {
        const p = b.p.map(function (x) { return s * x; });
        const q = m.project(p);
        if (!q || q[0] < 6 || q[1] < 6 || q[0] > st.width - 6 || q[1] > st.height - 6) return;
        const seen = m.pick(q[0], q[1]);
        if (seen && Math.hypot(seen[0] - p[0], seen[1] - p[1], seen[2] - p[2]) < 0.01 * b.size + 0.01) {
          out.push({ index: i, image: s < 0, p: p, pixel: q });
        }
      });
    });
    return out;
  });
}

// Per space, on the page just loaded: the default scene's bodies are drawn —
// at a visible body's projected centre the screenshot is body-coloured. The
// scene is reloaded as it starts (the page has run it for a moment, and gravity
// carries some spaces' bodies to the side the camera does not see), then paused.
export async function checkVisibleBodies(check, page, name) {
  const n = await page.evaluate(function () {
    const m = window.manifold;
    m.pause();
    return m.loadScene({ space: m.space(), bodies: window.Manifold.spaces[m.space()].scene }).then(function (count) {
      m.render();
      return count;
    });
  });
  const shot = await canvasShot(page, path.join(OUT, name + "-bodies.png"));
  const seen = await visibleCentres(page);
  const shown = seen.map(function (v) { return Object.assign({ fraction: bodyFraction(shot, v.pixel[0], v.pixel[1]) }, v); });
  const drawn = shown.filter(function (v) { return v.fraction >= 0.4; });
  check(name + ": the default scene's bodies are drawn (body colour at a visible body's projected centre)",
    n > 0 && seen.length > 0 && drawn.length > 0,
    n + " bodies, " + seen.length + " centres on the visible side, " + drawn.length + " body-coloured" +
    (shown.length ? " (" + shown.map(function (v) { return v.index + (v.image ? "'" : "") + ":" + v.fraction.toFixed(2); }).join(" ") + ")" : ""));
}

export async function openSpace(context, base, hash, errors) {
  const page = await context.newPage();
  page.on("console", function (m) { if (m.type() === "error") errors.push("console: " + m.text()); });
  page.on("pageerror", function (e) { errors.push("pageerror: " + e.message); });
  await page.goto(base + hash);
  await page.waitForFunction(function () { return !!window.manifold; });
  await page.evaluate(function () { return window.manifold.ready(); });
  return page;
}

// One body of `size` at surface point p of the current space, nothing moving, no gravity.
async function single(page, p, size, paused) {
  return page.evaluate(function (a) {
    const m = window.manifold;
    return m.loadScene({ space: m.space(), gravity: false, bodies: [{ shape: "circle", size: a.size, p: a.p }] }).then(function () {
      if (a.paused) m.pause(); else m.resume();
      m.render();
      return m.bodies()[0].p;
    });
  }, { p: p, size: size, paused: paused });
}

// ---- hidden bodies are hidden: on the sphere a body at −(camera direction)
// is not drawn at its pixel; at +(camera direction) it is. On the projective
// plane the far body is seen through its antipodal image. ----
async function testHidden(check, context, base) {
  const errors = [];
  for (const name of ["sphere", "projective-plane"]) {
    const page = await openSpace(context, base, "#space=" + name, errors);
    const dir = await page.evaluate(function () {
      const c = window.manifold.camera();
      const d = [c.eye[0] - c.target[0], c.eye[1] - c.target[1], c.eye[2] - c.target[2]];
      const l = Math.hypot(d[0], d[1], d[2]);
      return d.map(function (x) { return x / l; });
    });
    const far = dir.map(function (x) { return -x; });
    const results = {};
    for (const [label, p] of [["far", far], ["near", dir]]) {
      const placed = await single(page, p, 0.3, true);
      const px = await page.evaluate(function (q) { return window.manifold.project(q); }, placed);
      const shot = await canvasShot(page, path.join(OUT, name + "-" + label + "-body.png"));
      results[label] = { fraction: bodyFraction(shot, px[0], px[1], 6), pixel: px };
    }
    const detail = "far side " + results.far.fraction.toFixed(2) + ", near side " + results.near.fraction.toFixed(2) +
      " of the pixels about " + results.near.pixel.map(Math.round).join(",") + " body-coloured";
    if (name === "sphere") {
      check("sphere: a body on the far side (p = −camera direction) is hidden, one on the near side is drawn",
        results.far.fraction < 0.02 && results.near.fraction > 0.6, detail);
    } else {
      check("projective-plane: a body on the far side is drawn through its antipodal image (and on the near side too)",
        results.far.fraction > 0.6 && results.near.fraction > 0.6, detail);
    }
    await page.close();
  }
  check("hidden-body pages: no console errors", errors.length === 0, errors.join("; "));
}

// ---- dragging with real mouse events moves the body along the surface ----
async function testDrag(check, context, base, name, start, drag) {
  const errors = [];
  const page = await openSpace(context, base, "#space=" + name, errors);
  const st = await page.evaluate(function () { return window.manifold.stats(); });
  const pixel = [Math.round(st.width * start[0]), Math.round(st.height * start[1])];
  const p = await page.evaluate(function (px) { return window.manifold.pick(px[0], px[1]); }, pixel);
  if (!check(name + ": a surface point to start the drag at " + pixel.join(","), p !== null)) { await page.close(); return; }
  const placed = await single(page, p, 0.2, false);
  const c0 = await page.evaluate(function (q) { return window.manifold.project(q); }, placed);
  const box = await page.locator("#view").boundingBox();
  await page.mouse.move(box.x + c0[0], box.y + c0[1]);
  await page.mouse.down();
  const grabbed = await page.evaluate(function () { return window.manifold.grabbed(); });
  await page.mouse.move(box.x + c0[0] + drag[0], box.y + c0[1] + drag[1], { steps: 5 });
  const len = Math.hypot(drag[0], drag[1]);
  let moved = null;
  const t0 = Date.now();
  while (Date.now() - t0 < 12000) {
    moved = await page.evaluate(function () {
      const m = window.manifold, b = m.bodies()[0];
      const s = window.Manifold.spaces[m.space()];
      return { p: b.p, pixel: m.project(b.p), field: s.field(b.p[0], b.p[1], b.p[2]), steps: m.stats().steps };
    });
    const d = [moved.pixel[0] - c0[0], moved.pixel[1] - c0[1]];
    moved.along = (d[0] * drag[0] + d[1] * drag[1]) / len;
    moved.distance = Math.hypot(d[0], d[1]);
    if (moved.along > 0.8 * len) break;
    await page.waitForTimeout(200);
  }
  await page.mouse.up();
  const after = await page.evaluate(function () { return window.manifold.grabbed(); });
  check(name + ": pressing the mouse on a body grabs it, releasing lets go", grabbed === 0 && after === -1,
    "grabbed " + grabbed + ", after release " + after);
  check(name + ": dragging the mouse " + len + " px moves the body's projected centre along the drag, on the surface",
    moved.along > 0.5 * len && moved.along > 0.7 * moved.distance && Math.abs(moved.field) < FIELD_ON_SURFACE,
    "moved " + moved.distance.toFixed(1) + " px, " + moved.along.toFixed(1) + " px along the drag, |field| " +
    Math.abs(moved.field).toExponential(2) + " after " + ((Date.now() - t0) / 1000).toFixed(1) + " s");
  await canvasShot(page, path.join(OUT, name + "-drag.png"));
  check(name + " drag page: no console errors", errors.length === 0, errors.join("; "));
  await page.close();
}

// ---- the API, determinism, scenes, the URL, the controls ----
async function testApi(check, context, base) {
  const errors = [];
  const page = await openSpace(context, base, "#space=torus&bodies=12", errors);
  const first = await page.evaluate(function () {
    return { n: window.manifold.bodies().length, hash: location.hash, stats: window.manifold.stats() };
  });
  check("#space=torus&bodies=12 loads twelve bodies (the default six and six more)",
    first.n === 12 && first.hash === "#space=torus&bodies=12", JSON.stringify({ n: first.n, hash: first.hash }));
  const st = first.stats;
  check("stats() reports bodies, contacts, physics ms per step and warnings",
    st.bodies === 12 && typeof st.contacts === "number" && typeof st.warnings === "number" &&
      (st.physicsMsPerStep === null || st.physicsMsPerStep > 0), JSON.stringify(st));

  // step(n) is deterministic: the same scene twice gives the same bodies
  const det = await page.evaluate(function () {
    const m = window.manifold;
    m.pause();
    const scene = m.scene();
    const run = function () {
      return m.loadScene(scene).then(function () {
        m.step(150);
        return JSON.stringify(m.bodies());
      });
    };
    return run().then(function (a) {
      return run().then(function (b) { return { same: a === b, moved: a !== JSON.stringify(scene.bodies), n: JSON.parse(a).length }; });
    });
  });
  check("step(150) twice from the same scene gives the same bodies (and they moved)", det.same && det.moved && det.n === 12,
    JSON.stringify(det));

  // hash(): what `manifold sim --hash` prints for the same scene and steps,
  // the golden file's hash for a golden scene
  const goldenDir = path.join(OUT, "golden-scenes");
  fs.mkdirSync(goldenDir, { recursive: true });
  execFileSync(manifoldExe(), ["hashes", "--scenes", goldenDir], { encoding: "utf8" });
  const golden = fs.readFileSync(path.join(ROOT, "test/golden/hashes"), "utf8").split("\n")
    .map(function (l) { return l.split(" "); }).filter(function (w) { return w[0] === "torus-default"; })[0];
  const goldenScene = fs.readFileSync(path.join(goldenDir, "torus-default.json"), "utf8");
  const native = execFileSync(manifoldExe(), ["sim", path.join(goldenDir, "torus-default.json"), "--steps", golden[1], "--hash"], { encoding: "utf8" }).trim();
  const paged = await page.evaluate(function (a) {
    const m = window.manifold;
    return m.loadScene(a.scene).then(function () {
      m.step(a.steps);
      const h = m.hash();
      m.step(1);
      return { hash: h, later: m.hash() };
    });
  }, { scene: goldenScene, steps: Number(golden[1]) });
  check("hash() after " + golden[1] + " steps of the torus's golden scene is manifold sim --hash's and the golden file's (and one step later another)",
    /^[0-9a-f]{16}$/.test(paged.hash) && paged.hash === native && paged.hash === golden[2] && paged.later !== paged.hash,
    JSON.stringify({ page: paged, native: native, golden: golden[2] }));

  // addBody, clear, errors in words
  const api = await page.evaluate(function () {
    const m = window.manifold;
    const out = {};
    m.clear();
    out.cleared = m.bodies().length;
    out.hashAfterClear = location.hash;
    out.index = m.addBody({ shape: { polygon: 5 }, size: 0.2, p: [1.3, 0.2, 0.1], v: [0, 0, 1], omega: 2 });
    const b = m.bodies()[0];
    const s = window.Manifold.spaces.torus;
    out.field = s.field(b.p[0], b.p[1], b.p[2]);
    out.shape = b.shape;
    out.density = b.density;
    out.omega = b.omega;
    const err = function (f) { try { f(); return null; } catch (e) { return e.message; } };
    out.badShape = err(function () { m.addBody({ shape: "blob", size: 0.2, p: [1, 0, 0] }); });
    out.badSize = err(function () { m.addBody({ shape: "circle", size: -1, p: [1, 0, 0] }); });
    out.badKey = err(function () { m.addBody({ shape: "circle", size: 0.1, p: [1, 0, 0], colour: 1 }); });
    // on the torus's axis the gradient is undefined
    out.offSurface = err(function () { m.addBody({ shape: "circle", size: 0.1, p: [0, 0.3, 0] }); });
    out.count = m.bodies().length;
    out.hash = location.hash;
    return out;
  });
  check("clear() removes every body and the hash says bodies=0", api.cleared === 0 && api.hashAfterClear === "#space=torus&bodies=0",
    JSON.stringify({ n: api.cleared, hash: api.hashAfterClear }));
  check("addBody(spec) returns its index and puts the body on the surface with its shape, density and spin",
    api.index === 0 && Math.abs(api.field) < FIELD_ON_SURFACE && JSON.stringify(api.shape) === '{"polygon":5}' &&
      api.density === 1 && api.omega === 2 && api.hash === "#space=torus&bodies=1", JSON.stringify(api));
  check("addBody refuses bad bodies in words (shape, size, unknown key, a point off the surface)",
    /unknown shape "blob"/.test(api.badShape) && /body\.size: must be positive/.test(api.badSize) &&
      /body\.colour: unknown key/.test(api.badKey) && /does not project onto the surface/.test(api.offSurface) && api.count === 1,
    [api.badShape, api.badSize, api.badKey, api.offSurface].join(" | "));

  // save and load: the scene JSON round-trips, through the API and through the page's buttons
  const round = await page.evaluate(function () {
    const m = window.manifold;
    m.clear();
    m.addBody({ shape: "square", size: 0.18, density: 2, p: [1.3, 0, 0], v: [0, 0.5, 0.2], angle: 0.4, omega: -1 });
    m.addBody({ shape: "circle", size: 0.15, static: true, friction: 0.9, p: [-1.3, 0, 0] });
    m.addBody({ shape: { polygon: 7 }, size: 0.12, restitution: 0.8, p: [0, 0.4, 1.0] });
    m.setSimulation({ friction: 0.7, restitution: 0.3, gravity: false });
    m.step(20);
    const saved = JSON.stringify(m.scene());
    m.clear();
    let badMaterial = null;
    try { m.addBody({ shape: "circle", size: 0.1, friction: -0.2, p: [1.3, 0, 0] }); } catch (e) { badMaterial = e.message; }
    return m.loadScene(saved).then(function (n) {
      const bodies = m.scene().bodies;
      return { n: n, saved: saved, again: JSON.stringify(m.scene()), sim: m.simulation(), badMaterial: badMaterial,
        materials: bodies.map(function (b) { return [b.friction, b.restitution]; }) };
    });
  });
  check("scene() → loadScene() round-trips the scene (bodies, shapes, static, a body's own friction and restitution, the scene's, gravity)",
    round.n === 3 && round.saved === round.again && round.sim.friction === 0.7 && round.sim.restitution === 0.3 && !round.sim.gravity &&
      JSON.stringify(round.materials) === "[[null,null],[0.9,null],[null,0.8]]",
    round.saved === round.again ? round.n + " bodies, materials " + JSON.stringify(round.materials) : round.saved.slice(0, 200) + " vs " + round.again.slice(0, 200));
  check("addBody refuses a body's negative friction in the scene key's words", /body\.friction: must not be negative/.test(String(round.badMaterial)),
    String(round.badMaterial));

  const downloadP = page.waitForEvent("download");
  await page.click("#save-scene");
  const download = await downloadP;
  const file = path.join(OUT, "saved-scene.json");
  await download.saveAs(file);
  const text = fs.readFileSync(file, "utf8");
  const shownCamera = await page.evaluate(function () { return window.manifold.camera(); });
  const savedFile = JSON.parse(text), savedCamera = savedFile.camera;
  delete savedFile.camera;
  check("the Save scene button downloads the scene JSON with the view it is shown in (camera)", JSON.stringify(savedFile) === round.saved &&
    JSON.stringify(savedCamera) === JSON.stringify(shownCamera) && download.suggestedFilename() === "manifold-torus.json",
    download.suggestedFilename() + ", " + text.length + " bytes, camera " + JSON.stringify(savedCamera));

  // loading a file through the page's control, into another space
  const other = JSON.parse(text);
  other.space = "sphere";
  // bodies moved to another space are placed anew: without their saved frame
  other.bodies.forEach(function (b) { b.v = [0, 0, 0]; delete b.axis; delete b.normal; });
  // and a view of its own: up and fov left to the space's camera
  other.camera = { eye: [0.4, 0.9, 2.5], target: [0, 0.1, 0] };
  await page.setInputFiles("#scene-file", { name: "scene.json", mimeType: "application/json", buffer: Buffer.from(JSON.stringify(other)) });
  const loaded = await page.waitForFunction(function () {
    const m = window.manifold;
    return m.space() === "sphere" && m.bodies().length === 3 ? { hash: location.hash, sizes: m.bodies().map(function (b) { return b.size; }), camera: m.camera(),
      own: window.Manifold.spaces.sphere.camera } : null;
  }, null, { timeout: 10000 }).then(function (h) { return h.jsonValue(); }, function () { return null; });
  check("Load scene… reads a file; a scene of another space switches to it, shown from the scene's camera (up and fov the space's)",
    loaded !== null && loaded.hash === "#space=sphere&bodies=3" && JSON.stringify(loaded.camera.eye) === "[0.4,0.9,2.5]" &&
      JSON.stringify(loaded.camera.target) === "[0,0.1,0]" && JSON.stringify(loaded.camera.up) === JSON.stringify(loaded.own.up) && loaded.camera.fov === loaded.own.fov,
    JSON.stringify(loaded));

  // a bad scene: a clear message on the page, the world unchanged
  const bad = await page.evaluate(function () {
    const m = window.manifold;
    return m.loadScene('{"space": "sphere", "bodies": [{"shape": "circle", "size": 0.1, "p": [1, 0]}]}').then(function () { return null; },
      function (e) { return { message: e.message, notice: document.getElementById("notice").hidden ? "" : document.getElementById("notice-text").textContent, n: m.bodies().length }; });
  });
  check("a bad scene is refused with its JSON path, shown on the page, and the world is kept",
    bad !== null && /\$\.bodies\[0\]\.p: must be an array of three numbers/.test(bad.message) && bad.notice === bad.message && bad.n === 3,
    JSON.stringify(bad));
  const notJson = await page.evaluate(function () {
    return window.manifold.loadScene("{oops").then(function () { return null; }, function (e) { return e.message; });
  });
  check("a scene that is not JSON is refused in words", /not JSON/.test(notJson || ""), notJson);

  // a saved pile goes on as if never saved, flat or curved: each body restored
  // with the axis it carried and its normal (its angle from that axis), and
  // with what it remembers of its contacts' impulses; the state's hash says so.
  const resume = await page.evaluate(async function () {
    const m = window.manifold;
    const out = {};
    const positions = function () { return m.bodies().map(function (b) { return b.p; }); };
    const apart = function (ps, qs) {
      let d = 0;
      ps.forEach(function (p, i) { for (let k = 0; k < 3; k++) d = Math.max(d, Math.abs(p[k] - qs[i][k])); });
      return d;
    };
    const variant = function (scene, change) {
      const s = JSON.parse(JSON.stringify(scene));
      s.bodies.forEach(change);
      return s;
    };
    for (const [name, steps] of [["rectangle", 60], ["torus", 60]]) {
      await m.setSpace(name);
      m.pause();
      m.resetScene(60);
      // (awake: the rectangle's pile would be asleep, and remember nothing, by step 300)
      m.setSimulation({ sleep: false });
      m.step(300);
      const saved = m.scene();
      m.step(steps);
      const on = positions();
      const r = { n: saved.bodies.length, steps: steps, hashOn: m.hash() };
      r.remembered = saved.bodies.reduce(function (t, b) { return t + (b.impulses ? b.impulses.length : 0); }, 0);
      await m.loadScene(saved);
      const back = m.scene();
      r.angleBack = Math.max.apply(null, back.bodies.map(function (b, i) { return Math.abs(b.angle - saved.bodies[i].angle); }));
      r.impulsesBack = JSON.stringify(back.bodies.map(function (b) { return b.impulses; })) ===
        JSON.stringify(saved.bodies.map(function (b) { return b.impulses; }));
      m.step(steps);
      r.kept = apart(on, positions());
      r.hashKept = m.hash();
      await m.loadScene(variant(saved, function (b) { delete b.impulses; }));
      m.step(steps);
      r.forgetting = apart(on, positions());
      await m.loadScene(variant(saved, function (b) { b.angle += 0.3; }));
      m.step(steps);
      r.turned = apart(on, positions());
      r.moved = await m.loadScene(variant(saved, function (b, i) { if (i === 0) b.p = saved.bodies[1].p; }))
        .then(function () { return null; }, function (e) { return e.message; });
      out[name] = r;
      m.setSimulation({ sleep: true });
    }
    out.badImpulse = await m.loadScene(JSON.stringify({ space: "torus", bodies: [{ shape: "circle", size: 0.1, p: [1.3, 0, 0], impulses: [[64, 0.1, 0], [65, -1, 0]] }] }))
      .then(function () { return null; }, function (e) { return e.message; });
    const nine = [];
    for (let k = 0; k < 9; k++) nine.push([64 + k, 0.1, 0]);
    out.tooMany = await m.loadScene({ space: "torus", bodies: [{ shape: "circle", size: 0.1, p: [1.3, 0, 0], impulses: nine }] })
      .then(function () { return null; }, function (e) { return e.message; });
    out.bodiesAfter = m.bodies().length;
    try { m.addBody({ shape: "circle", size: 0.1, p: [1.3, 0, 0], impulses: [[64, 0.1, 0]] }); out.addWithImpulses = null; } catch (e) { out.addWithImpulses = e.message; }
    return out;
  });
  const rect = resume.rectangle, tor = resume.torus;
  check("a saved pile (the rectangle's) loads back with its contacts' impulses and goes on bit for bit as if never saved (60 steps, the same hash(); without the impulses it sags)",
    rect.remembered > rect.n && rect.impulsesBack && rect.angleBack === 0 && rect.kept === 0 && rect.hashKept === rect.hashOn &&
      rect.forgetting > 1e-4, JSON.stringify(rect));
  check("on the torus too a saved pile goes on bit for bit (60 steps, the same hash(); outlines turned 0.3 rad do not)",
    tor.remembered > tor.n && tor.impulsesBack && tor.angleBack === 0 && tor.kept === 0 && tor.hashKept === tor.hashOn && tor.turned > 1e-4,
    JSON.stringify(tor));
  check("a saved body moved by hand (p changed, its saved axis and normal kept) is refused in words, naming its axis",
    /\$\.bodies\[0\]\.axis: the saved axis and normal do not fit the surface at p/.test(tor.moved || ""), tor.moved);
  check("remembered impulses are checked like the rest of a scene, and addBody takes none",
    /\$\.bodies\[0\]\.impulses\[1\]\[1\]: must not be negative/.test(resume.badImpulse || "") &&
      /\$\.bodies: 9 remembered contact impulses, more than 1 bodies remember \(8 a body\)/.test(resume.tooMany || "") &&
      resume.bodiesAfter === 60 && /body\.impulses: only a scene's bodies carry contact impulses/.test(resume.addWithImpulses || ""),
    [resume.badImpulse, resume.tooMany, resume.bodiesAfter + " bodies kept", resume.addWithImpulses].join(" | "));

  // the controls
  await page.evaluate(function () { window.manifold.clear(); window.manifold.resume(); });
  await page.selectOption("#body-shape", "circle");
  await page.click("#add-body");
  await page.selectOption("#body-shape", "square");
  await page.click("#add-body");
  // (the sides show with the polygon chosen)
  await page.selectOption("#body-shape", "polygon");
  await page.fill("#polygon-sides", "6");
  await page.dispatchEvent("#polygon-sides", "change");
  await page.click("#add-body");
  const added = await page.evaluate(function () { return window.manifold.bodies().map(function (b) { return b.shape; }); });
  check("Add makes a body of the shape chosen: circle, square, polygon of the sides given",
    JSON.stringify(added) === '["circle","square",{"polygon":6}]', JSON.stringify(added));
  await page.click("#pause");
  const paused = await page.evaluate(function () { return { p: window.manifold.simulation().paused, label: document.getElementById("pause").textContent }; });
  await page.click("#step");
  const stepped = await page.evaluate(function () { return window.manifold.stats().steps; });
  await page.click("#step");
  const stepped2 = await page.evaluate(function () { return window.manifold.stats().steps; });
  const gravityBefore = await page.evaluate(function () { return window.manifold.simulation().gravity; });
  await page.click("#gravity");
  await page.selectOption("#time-scale", "0.5");
  await page.evaluate(function () {
    [["friction", "0.25"], ["restitution", "0.5"]].forEach(function (kv) {
      const el = document.getElementById(kv[0]);
      el.value = kv[1];
      el.dispatchEvent(new Event("input", { bubbles: true }));
    });
  });
  const sim = await page.evaluate(function () { return window.manifold.simulation(); });
  check("Pause, Step, Speed, Gravity, Friction and Restitution control the simulation",
    paused.p && paused.label === "Resume" && stepped2 === stepped + 1 && sim.gravity === !gravityBefore && sim.timeScale === 0.5 &&
      sim.friction === 0.25 && sim.restitution === 0.5, JSON.stringify({ paused: paused, steps: [stepped, stepped2], sim: sim }));
  await page.click("#clear");
  await page.waitForFunction(function () { return /bodies 0/.test(document.getElementById("stats").textContent); }, null, { timeout: 3000 })
    .catch(function () {});
  const line = await page.textContent("#stats");
  check("Clear empties the world; the stats line shows bodies, contacts and physics time",
    /bodies 0/.test(line) && /contacts \d+/.test(line) && /physics [\d.]+ ms\/step/.test(line) && /paused/.test(line), line);
  check("API and scene page: no console errors", errors.length === 0, errors.join("; "));
  await page.close();
}

// n small bodies round the torus (R = 0.8, r = 0.5 about the y axis), on a grid of 20 turns
export function torusBodies(n, size) {
  const bodies = [];
  for (let k = 0; k < n; k++) {
    const u = 2 * Math.PI * (k % 20) / 20, v = 2 * Math.PI * Math.floor(k / 20) / Math.ceil(n / 20), rho = 0.8 + 0.5 * Math.cos(v);
    bodies.push({ shape: k % 2 ? "square" : "circle", size: size, p: [rho * Math.cos(u), 0.5 * Math.sin(v), rho * Math.sin(u)] });
  }
  return bodies;
}

// Pixels of two screenshots of one size differing by more than `by` in a channel, and body-coloured pixels of each.
// (Where a coarser form and the mesh differ, it is pixels along the bodies' edges: a coarser form may
// move an edge by up to half a pixel, and the outline's width comes from the derivatives of the marks,
// which larger triangles interpolate a little differently, most where the surface is seen edge on.)
export function shotDifference(a, b, by) {
  let differ = 0, bodyA = 0, bodyB = 0;
  for (let y = 0; y < a.height; y++) {
    for (let x = 0; x < a.width; x++) {
      const p = a.at(x, y), q = b.at(x, y);
      if (Math.max(Math.abs(p[0] - q[0]), Math.abs(p[1] - q[1]), Math.abs(p[2] - q[2])) > by) differ++;
      if (saturation(p) > SATURATED) bodyA++;
      if (saturation(q) > SATURATED) bodyB++;
    }
  }
  return { differ: differ, pixels: a.width * a.height, bodyA: bodyA, bodyB: bodyB };
}

// ---- level of detail: a body whose mesh a coarser one (every 2nd, 3rd or
// 4th direction, every 2nd ring, or the fan from the centre to the outline
// alone) reproduces within half a pixel is drawn in the coarsest such form
// (as few as 6 triangles instead of 168); the picture is the one every whole
// mesh drawn gives, large bodies on a curved surface keep their whole meshes,
// and bodies seen close are drawn finer. (Bodies up to the engine's polygonStep, 0.05, have their inner
// vertices on the chords already, so these bodies are larger.) ----
async function testBodyForms(check, context, base) {
  const errors = [];
  const page = await openSpace(context, base, "#space=torus", errors);
  const forms = function () {
    return page.evaluate(function () { const m = window.manifold; m.render(); return m.stats().bodyForms; });
  };
  await page.evaluate(function (b) {
    const m = window.manifold;
    m.pause();
    return m.loadScene({ space: "torus", gravity: false, bodies: b }).then(function () { m.render(); });
  }, torusBodies(120, 0.08));
  const auto = await forms();
  const autoShot = await canvasShot(page, path.join(OUT, "torus-120-auto.png"));
  await page.evaluate(function () { window.manifold.setOptions({ bodyDetail: "mesh" }); });
  const mesh = await forms();
  const meshShot = await canvasShot(page, path.join(OUT, "torus-120-mesh.png"));
  const d = shotDifference(autoShot, meshShot, 32);
  check("small bodies are drawn as fans, and the picture is the one their meshes give (torus, 120 bodies of size 0.08)",
    auto.fans + auto.coarser === 120 && auto.meshes === 0 && mesh.meshes === 120 &&
    d.bodyB > 0.01 * d.pixels && Math.abs(d.bodyA - d.bodyB) <= 0.05 * d.bodyB && d.differ <= 0.25 * d.bodyB &&
    auto.triangles < 0.2 * mesh.triangles,
    "auto " + JSON.stringify(auto) + ", mesh " + JSON.stringify(mesh) + "; " + d.differ + " of " + d.pixels +
    " pixels differ by more than 32, body-coloured " + d.bodyA + " / " + d.bodyB);

  // one small body seen from close by: its inner rings then stray from the fan by more than half a pixel
  await page.evaluate(function () { window.manifold.setOptions({ bodyDetail: "auto" }); });
  const near = await page.evaluate(function () {
    const m = window.manifold, c0 = m.camera(), p = m.bodies()[0].p;
    const out = { far: null, near: null, back: null };
    out.far = (m.render(), m.stats().bodyForms);
    // 0.1 out from the body along the torus's normal there (its tube's centre is at 0.8 along p's direction in xz)
    const rho = Math.hypot(p[0], p[2]), centre = [0.8 * p[0] / rho, 0, 0.8 * p[2] / rho];
    const nrm = [p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]], l = Math.hypot(nrm[0], nrm[1], nrm[2]);
    m.setCamera({ eye: p.map(function (x, i) { return x + 0.1 * nrm[i] / l; }), target: p, up: [0, 1, 0.1], fov: 45 });
    m.render();
    out.near = m.stats().bodyForms;
    m.setCamera(c0);
    m.render();
    out.back = m.stats().bodyForms;
    return out;
  });
  check("bodies seen from close by are drawn finer (more of their mesh), and as before from afar",
    near.far.meshes === 0 && near.near.fans < near.far.fans && near.near.triangles > near.far.triangles &&
    JSON.stringify(near.back) === JSON.stringify(near.far), JSON.stringify(near));

  // large bodies on the sphere bend with it: meshes
  const large = await page.evaluate(function () {
    const m = window.manifold;
    return m.setSpace("sphere").then(function () {
      m.pause();
      return m.loadScene({ space: "sphere", gravity: false, bodies: [
        { shape: "circle", size: 0.6, p: [1, 0, 0] }, { shape: "square", size: 0.6, p: [0, 0, 1] }, { shape: "circle", size: 0.6, p: [0, 1, 0] }] });
    }).then(function () { m.render(); return m.stats().bodyForms; });
  });
  check("large bodies on the sphere are drawn as their whole meshes", large.meshes === 3, JSON.stringify(large));

  // (every space's default scene drawn in coarser forms against its whole
  // meshes: run.mjs's testSpace, on each space's own page)

  const bad = await page.evaluate(function () {
    try { window.manifold.setOptions({ bodyDetail: "coarse" }); return null; } catch (e) { return e.message; }
  });
  check("setOptions refuses an unknown bodyDetail in words", /bodyDetail must be one of auto, mesh/.test(bad || ""), bad);
  check("body level-of-detail page: no console errors", errors.length === 0, errors.join("; "));
  await page.close();
}

// ---- a polygon is drawn with its corners: its outline's 24 directions
// sample its edges and would cut each corner off (a 2:1 box's corners lie
// between them); a few pixels inside each corner, from both its edges, the
// picture is the body's colour, and a few pixels beyond it is not, as a
// coarser form and as the whole mesh, flat and on the sphere ----
const CORNER_PIXELS = 3.5;
async function testCorners(check, context, base) {
  const errors = [];
  for (const [space, p, size] of [["plane", [0, 0, 0], 0.1], ["sphere", [0, 1, 0], 0.06]]) {
    const page = await openSpace(context, base, "#space=" + space, errors);
    const results = [];
    for (const detail of ["auto", "mesh"]) {
      // the body's centre and its corners as the engine walked them (the hull array), projected
      const r = await page.evaluate(async function (a) {
        const m = window.manifold;
        m.pause();
        m.setOptions({ bodyDetail: a.detail });
        await m.loadScene({ space: a.space, gravity: false, bodies: [{ shape: { box: [2 * a.size, a.size] }, p: a.p, angle: 0.3 }] });
        // from afar a coarser form, from close by (and bodyDetail "mesh") the whole mesh
        const far = a.detail === "auto" ? 16 : 8;
        m.setCamera({ eye: [a.p[0], a.p[1] + far * a.size, a.p[2] + 0.5 * a.size], target: a.p, up: [0, 0, -1], fov: 45 });
        const w = window.ManifoldWeb.page.state.world, H = w.engine.hull, hull = w.view().hull;
        const corner = function (k) { const o = H.world + 3 * ((k + 4) % 4); return m.project([hull[o], hull[o + 1], hull[o + 2]]); };
        const c = m.project(m.bodies()[0].p), out = [];
        for (let k = 0; k < 4; k++) {
          const q = corner(k), prev = corner(k - 1), next = corner(k + 1);
          const unit = function (v) { const l = Math.hypot(v[0], v[1]); return [v[0] / l, v[1] / l]; };
          const u = unit([prev[0] - q[0], prev[1] - q[1]]), v = unit([next[0] - q[0], next[1] - q[1]]), o = unit([q[0] - c[0], q[1] - c[1]]);
          // in from both edges, and out along the line from the centre
          out.push({ inside: [q[0] + a.px * (u[0] + v[0]), q[1] + a.px * (u[1] + v[1])], outside: [q[0] + a.px * o[0], q[1] + a.px * o[1]] });
        }
        m.render();
        return { points: out, forms: m.stats().bodyForms };
      }, { space, p, size, detail, px: CORNER_PIXELS });
      const shot = await canvasShot(page, path.join(OUT, space + "-box-corners-" + detail + ".png"));
      const inside = r.points.map(function (q) { return bodyFraction(shot, q.inside[0], q.inside[1], 1); });
      const outside = r.points.map(function (q) { return bodyFraction(shot, q.outside[0], q.outside[1], 1); });
      // a press where a corner is drawn grabs the box; beyond it, nothing
      const grabs = await page.evaluate(function (points) {
        const m = window.manifold, at = function (q) { const ok = m.grab(q[0], q[1]); m.release(); return ok; };
        return { inside: points.map(function (q) { return at(q.inside); }), outside: points.map(function (q) { return at(q.outside); }) };
      }, r.points);
      results.push({ detail, forms: r.forms, inside, outside, grabs });
    }
    check(space + ": a 2:1 box is drawn with its corners (body-coloured " + CORNER_PIXELS + " px in from both edges at each, not " + CORNER_PIXELS + " px beyond it), as a coarser form and as its mesh",
      results.every(function (x) { return x.inside.every(function (f) { return f === 1; }) && x.outside.every(function (f) { return f === 0; }); }) &&
        results[0].forms.meshes === 0 && results[1].forms.meshes === 1,
      JSON.stringify(results));
    check(space + ": pressing where a corner is drawn grabs the box, " + CORNER_PIXELS + " px beyond it nothing (picking by the hull)",
      results.every(function (x) { return x.grabs.inside.every(Boolean) && !x.grabs.outside.some(Boolean); }),
      JSON.stringify(results.map(function (x) { return x.grabs; })));
    await page.close();
  }
  check("corner pages: no console errors", errors.length === 0, errors.join("; "));
}

export async function testBodies(check, context, base) {
  await testCorners(check, context, base);
  await testBodyForms(check, context, base);
  await testHidden(check, context, base);
  await testDrag(check, context, base, "sphere", [0.5, 0.5], [-100, 0]);
  await testDrag(check, context, base, "torus", [0.5, 0.8], [100, -10]);
  await testApi(check, context, base);
}
