// Browser tests of the physics worker (part "thread" of run.mjs): the page
// served by `manifold serve` is cross-origin isolated and steps its physics
// in a Web Worker on shared memory (setSimulation's thread "worker", and
// "auto" from 1000 bodies on); the worker's steps are the main thread's bit
// for bit (the same hash after the same steps, the same picture); a body is
// grabbed and dragged with the real mouse while the worker steps it; opened
// from disk the page steps on the main thread and says so.
import path from "node:path";
import url from "node:url";
import { WEB, OUT, canvasShot } from "./lib.mjs";
import { openSpace, torusBodies } from "./bodies.mjs";

// A pixel is body-coloured when strongly saturated (the palette is; the surface and background are not).
const SATURATED = 80;

/** Body-coloured pixels of a screenshot. */
function bodyPixels(shot) {
  let n = 0;
  for (let y = 0; y < shot.height; y++) {
    for (let x = 0; x < shot.width; x++) {
      const c = shot.at(x, y);
      if (Math.max(c[0], c[1], c[2]) - Math.min(c[0], c[1], c[2]) > SATURATED) n++;
    }
  }
  return n;
}

/** Pixels of two screenshots of one size that differ at all. */
function differing(a, b) {
  let n = 0;
  for (let y = 0; y < a.height; y++) {
    for (let x = 0; x < a.width; x++) {
      const p = a.at(x, y), q = b.at(x, y);
      if (p[0] !== q[0] || p[1] !== q[1] || p[2] !== q[2]) n++;
    }
  }
  return n;
}

// The worker steps the sphere's default scene, filled, while the clock runs;
// the main thread then steps the same start as many steps: the same hash,
// the same picture.
async function testSameSteps(check, context, base) {
  const errors = [];
  const page = await openSpace(context, base, "#space=sphere", errors);
  const start = await page.evaluate(function () {
    const m = window.manifold;
    m.setSimulation({ paused: true, thread: "worker" });
    m.resetScene(60);
    return { isolated: window.crossOriginIsolated, steps: m.stats().steps, bodies: m.stats().bodies };
  });
  check("the served page is cross-origin isolated (manifold serve sends COOP and COEP)", start.isolated === true, String(start.isolated));
  // (a liveness check, not a speed test: the worker's first steps run its
  // engine unoptimised, and on a loaded machine it has taken seconds to
  // reach twenty)
  const began = Date.now();
  await page.evaluate(function () { window.manifold.resume(); });
  await page.waitForTimeout(2000);
  await page.waitForFunction(function (s) { return window.manifold.stats().steps - s >= 20; }, start.steps, { timeout: 15000 }).catch(function () {});
  const waited = Date.now() - began;
  const run = await page.evaluate(function () {
    const m = window.manifold;
    m.pause();
    // (one task: the lock the hash takes holds the worker until both are read)
    const hash = m.hash(), s = m.stats();
    return { hash: hash, steps: s.steps, thread: s.thread, line: document.getElementById("stats").textContent };
  });
  const steps = run.steps - start.steps;
  check("thread \"worker\": the worker steps the physics while the clock runs",
    run.thread === "worker" && steps >= 20 && /\(worker\)/.test(run.line), steps + " steps in " + (waited / 1000).toFixed(1) + " s on the " + run.thread + "; " + run.line);
  await page.waitForTimeout(300);
  await page.evaluate(function () { window.manifold.render(); });
  const onWorker = await canvasShot(page, path.join(OUT, "thread-worker.png"));
  const main = await page.evaluate(function (n) {
    const m = window.manifold;
    m.setSimulation({ thread: "main" });
    m.resetScene(60);
    m.step(n);
    m.render();
    return { hash: m.hash(), thread: m.stats().thread };
  }, steps);
  const onMain = await canvasShot(page, path.join(OUT, "thread-main.png"));
  check("the worker's " + steps + " steps are the main thread's bit for bit (the same hash)",
    main.thread === "main" && main.hash === run.hash, run.hash + " on the worker, " + main.hash + " on the " + main.thread);
  const bodies = bodyPixels(onWorker), differ = differing(onWorker, onMain);
  check("the worker's world is drawn as the main thread's (the same picture)", bodies > 300 && differ === 0,
    bodies + " body-coloured pixels, " + differ + " pixels differ");
  check("worker pages: no console errors", errors.length === 0, errors.join("; "));
  await page.close();
}

// "auto" hands a world of 1000 bodies to the worker, keeps a small one on the main thread.
async function testAuto(check, context, base) {
  const errors = [];
  const page = await openSpace(context, base, "#space=torus", errors);
  const seen = {};
  for (const n of [200, 1000]) {
    await page.evaluate(function (b) {
      const m = window.manifold;
      m.setSimulation({ thread: "auto" });
      return m.loadScene({ space: "torus", gravity: true, bodies: b }).then(function () { m.resume(); });
    }, torusBodies(n, 0.02));
    await page.waitForTimeout(600);
    seen[n] = await page.evaluate(function () { const s = window.manifold.stats(); return { thread: s.thread, bodies: s.bodies }; });
  }
  check("thread \"auto\": 200 bodies step on the main thread, 1000 on the worker",
    seen[200].thread === "main" && seen[1000].thread === "worker" && seen[1000].bodies === 1000, JSON.stringify(seen));
  // the Simulation group's Physics control: chosen with the mouse, and showing what setSimulation set
  await page.selectOption("#physics-thread", "main");
  await page.waitForTimeout(300);
  const chosen = await page.evaluate(function () { const m = window.manifold; return { setting: m.simulation().thread, thread: m.stats().thread }; });
  const shown = await page.evaluate(function () { window.manifold.setSimulation({ thread: "worker" }); return document.getElementById("physics-thread").value; });
  check("the Physics control chooses the thread (main: the 1000 bodies back on the main thread) and shows setSimulation's",
    chosen.setting === "main" && chosen.thread === "main" && shown === "worker", JSON.stringify({ chosen, shown }));
  check("auto pages: no console errors", errors.length === 0, errors.join("; "));
  await page.close();
}

// A body grabbed with the mouse and dragged while the worker steps it follows the pointer.
async function testDrag(check, context, base) {
  const errors = [];
  const page = await openSpace(context, base, "#space=sphere", errors);
  const placed = await page.evaluate(function () {
    const m = window.manifold, st = m.stats();
    m.setSimulation({ thread: "worker" });
    const p = m.pick(Math.round(st.width * 0.45), Math.round(st.height * 0.5));
    return m.loadScene({ space: "sphere", gravity: false, bodies: [{ shape: "circle", size: 0.2, p: p }] }).then(function () {
      m.resume();
      return m.bodies()[0].p;
    });
  });
  await page.waitForTimeout(300);
  const c0 = await page.evaluate(function (q) { return window.manifold.project(q); }, placed);
  const box = await page.locator("#view").boundingBox();
  await page.mouse.move(box.x + c0[0], box.y + c0[1]);
  await page.mouse.down();
  const grabbed = await page.evaluate(function () { return { i: window.manifold.grabbed(), thread: window.manifold.stats().thread }; });
  const drag = 60;
  await page.mouse.move(box.x + c0[0] + drag, box.y + c0[1], { steps: 5 });
  let along = 0;
  const t0 = Date.now();
  while (Date.now() - t0 < 8000 && along < 0.8 * drag) {
    await page.waitForTimeout(200);
    along = await page.evaluate(function (c) {
      const m = window.manifold, q = m.project(m.bodies()[0].p);
      return q[0] - c[0];
    }, c0);
  }
  await page.mouse.up();
  check("a body grabbed with the mouse while the worker steps follows a " + drag + " px drag",
    grabbed.i === 0 && grabbed.thread === "worker" && along > 0.5 * drag,
    "grabbed " + grabbed.i + " on the " + grabbed.thread + ", moved " + along.toFixed(1) + " px along the drag");
  check("drag-on-worker page: no console errors", errors.length === 0, errors.join("; "));
  await page.close();
}

// A worker that holds the world and never lets go (here: the lock set as if
// it held it, the clock paused so the real one is idle) is taken for dead
// after World.hold's patience: the call goes on, and the world goes back to
// the main thread with a notice.
async function testUnanswered(check, context, base) {
  const errors = [];
  const page = await openSpace(context, base, "#space=sphere", errors);
  await page.evaluate(function () { const m = window.manifold; m.setSimulation({ thread: "worker", paused: true }); m.resetScene(20); });
  await page.waitForTimeout(300);
  const r = await page.evaluate(function () {
    const m = window.manifold, w = window.ManifoldWeb.page.state.world, SHARED = window.ManifoldWeb.world.SHARED;
    const before = m.stats().thread;
    Atomics.store(w.shared.control, SHARED.LOCK, SHARED.WORKER);
    const t0 = performance.now(), hash = m.hash();
    return { before: before, ms: performance.now() - t0, hash: hash };
  });
  await page.waitForTimeout(300);
  const after = await page.evaluate(function () {
    const m = window.manifold;
    m.step(5);
    return { thread: m.stats().thread, notice: document.getElementById("notice-text").textContent };
  });
  check("a worker that never lets go of the world is taken for dead after 5 s: the call returns, the main thread steps on",
    r.before === "worker" && r.ms >= 5000 && r.ms < 8000 && /^[0-9a-f]{16}$/.test(r.hash) && after.thread === "main" && /stopped answering/.test(after.notice) && errors.length === 0,
    JSON.stringify({ r, after, errors }));
  await page.close();
}

// From disk nothing is isolated: the page steps on the main thread, and its stats line says why.
async function testFromDisk(check, context) {
  const errors = [];
  const address = url.pathToFileURL(path.join(WEB, "index.html")).href;
  const page = await openSpace(context, address, "#space=sphere", errors);
  await page.evaluate(function () { window.manifold.setSimulation({ thread: "worker", paused: false }); });
  await page.waitForTimeout(800);
  const r = await page.evaluate(function () {
    return { thread: window.manifold.stats().thread, line: document.getElementById("stats").textContent, steps: window.manifold.stats().steps };
  });
  check("file://: thread \"worker\" steps on the main thread, and the stats line says it is not isolated",
    r.thread === "main" && r.steps > 0 && /main thread, not isolated/.test(r.line) && errors.length === 0, r.line + " " + errors.join("; "));
  await page.close();
}

export async function testThread(check, context, base) {
  await testSameSteps(check, context, base);
  await testAuto(check, context, base);
  await testDrag(check, context, base);
  await testUnanswered(check, context, base);
  await testFromDisk(check, context);
}
