// The browser half of the benchmarks: the scenes of `manifold bench --scenes`
// through the page (web/) in headless Chromium (Debian's, software WebGL2),
// driven by playwright-core.
//
//   node bench/browser.mjs [--scenes DIR] [--settle K] [--spaces A,B] [--sizes N,M] [--warmup W] [--steps S]
//                          [--rounds R] [--fps-spaces torus|all|none|A,B] [--fps-seconds T] [--out FILE.json]
//
// Without --scenes it runs `manifold bench --scenes TMPDIR [--settle K]`
// itself (the executable: $MANIFOLD_EXE, else `cabal list-bin
// exe:manifold`): the scenes as the native benchmark times them, run natively
// until their piles have settled and saved.
//
// 1. Step time, per scene: the settled scene is loaded into the page with
//    manifold.loadScene (paused). Inside the page, as bench/node.mjs does
//    under node, a World (web/js/world.js) is made on the same generated
//    engine and the same scene (with its contacts' impulses), run for W
//    steps (default 50: the JIT and the caches), and each phase of S steps is timed on its own
//    with performance.now(); the step is their sum (as `manifold bench`
//    times the native step). The page's own world, run for W steps too,
//    takes a step manifold.step(1) before each of those, timed whole
//    (`apiMedianMs`). Every scene is timed in each of R rounds (all scenes,
//    then all again; default 3), loaded afresh each time, and reported by
//    its round with the lowest median, as `manifold bench --rounds` does:
//    what else runs on the machine only adds time. Every round's median
//    is kept too (`roundMediansMs`), and a scene whose rounds differ more
//    than twofold (and by more than 1 ms) is warned of.
//    The page is served cross-origin isolated (COOP/COEP headers), so
//    performance.now() ticks in 5 µs rather than 100 µs.
// 2. Frame rate with rendering on, 800×600 viewport: first, paused, the
//    median time of 21 frames that each follow a step and reuse the traced
//    surface (manifold.measureFrame(false): the bodies drawn, then the post
//    pass, waited for), and the triangles the bodies took; then the page's
//    world runs the scene unpaused for T seconds; fps, physics steps per
//    second and ms per step are read from manifold.stats().
//
// Progress goes to stderr, a table to stdout, everything as JSON to --out.
import { execFileSync } from "node:child_process";
import fs from "node:fs";
import os from "node:os";
import path from "node:path";
import url from "node:url";
import { launchBrowser, manifoldExe, chromiumPath } from "../test/browser/lib.mjs";
import { serveWeb, loadPaused } from "./page.mjs";
import { commandLine } from "./options.mjs";

const ROOT = path.resolve(path.dirname(url.fileURLToPath(import.meta.url)), "..");
const WEB = process.env.MANIFOLD_WEB ? path.resolve(process.env.MANIFOLD_WEB) : path.join(ROOT, "web");
const SPACES = ["plane", "sphere", "torus", "trumpet", "projective-plane", "rectangle"];
const SIZES = [10, 100, 300, 1000, 3000];
const VIEWPORT = { width: 800, height: 600 };

// ---- arguments -------------------------------------------------------------------------
const { text: arg, count, positive } = commandLine({
  usage: "node bench/browser.mjs [--scenes DIR] [--settle K] [--spaces A,B] [--sizes N,M] [--warmup W] [--steps S]\n" +
    "                              [--rounds R] [--fps-spaces torus|all|none|A,B] [--fps-seconds T] [--out FILE.json]",
  known: ["--scenes", "--settle", "--spaces", "--sizes", "--warmup", "--steps", "--rounds", "--fps-spaces", "--fps-seconds", "--out"],
});
const list = (s) => s.split(",").map((x) => x.trim()).filter((x) => x);
const spaces = list(arg("--spaces", SPACES.join(",")));
const sizes = list(arg("--sizes", SIZES.join(","))).map(Number);
if (sizes.some((n) => !Number.isInteger(n) || n < 1)) { console.error("--sizes must be whole numbers"); process.exit(2); }
const warmup = count("--warmup", 50, 0);
// null: manifold bench's default (or, with --scenes, however DIR's scenes were written)
const settle = count("--settle", null, 0);
const steps = count("--steps", 50, 1);
const rounds = count("--rounds", 3, 1);
const fpsSeconds = positive("--fps-seconds", 3);
const fpsArg = arg("--fps-spaces", "torus");
const fpsSpaces = fpsArg === "none" ? [] : fpsArg === "all" ? spaces : list(fpsArg);
const outFile = arg("--out", null);

const log = (s) => process.stderr.write(s + "\n");

// ---- scenes ----------------------------------------------------------------------------
let scenesDir = arg("--scenes", null);
let tmpDir = null;
if (!scenesDir) {
  tmpDir = fs.mkdtempSync(path.join(os.tmpdir(), "manifold-bench-"));
  scenesDir = tmpDir;
  const exe = manifoldExe();
  const settleArgs = settle === null ? [] : ["--settle", String(settle)];
  log("writing the settled scenes: " + [exe, "bench", "--scenes", tmpDir].concat(settleArgs).join(" "));
  execFileSync(exe, ["bench", "--scenes", tmpDir, "--spaces", spaces.join(","), "--sizes", sizes.join(",")].concat(settleArgs),
    { cwd: ROOT, stdio: ["ignore", "ignore", "inherit"] });
}
const cases = [];
for (const space of spaces) {
  for (const n of sizes) {
    const file = path.join(scenesDir, space + "-" + n + ".json");
    if (!fs.existsSync(file)) { log("no scene " + file + ": skipped"); continue; }
    cases.push({ space, n, file });
  }
}
if (!cases.length) { console.error("no scenes for " + spaces.join(",") + " × " + sizes.join(",") + " in " + scenesDir); process.exit(2); }

// ---- in the page ---------------------------------------------------------------------------
// Times the step inside the page (one synchronous evaluate: no frame runs in between).
function timeSteps(page, scene, warmup, steps) {
  return page.evaluate(function (a) {
    const m = window.manifold, MW = window.ManifoldWeb, scene = a.scene;
    const quantile = function (xs, x) {
      const s = xs.slice().sort(function (p, q) { return p - q; });
      return s[Math.min(s.length - 1, Math.floor(x * s.length))];
    };
    // a World on the page's engine and scene, as bench/node.mjs does: each phase timed on its own
    const world = new MW.world.World(scene.space, window.Manifold.spaces[scene.space]);
    world.load(MW.world.parseScene(scene, m.spaces()));
    world.step(a.warmup);
    m.step(a.warmup); // the page's own world, through the API
    const phases = world.engine.phases, arrays = world.arrays;
    const times = [], phaseTimes = phases.map(function () { return []; }), api = [];
    let contactSum = 0;
    // interleaved, so that both see the same state of the JIT
    for (let k = 0; k < a.steps; k++) {
      const t1 = performance.now();
      m.step(1);
      api.push(performance.now() - t1);
      let total = 0;
      for (let j = 0; j < phases.length; j++) {
        const t0 = performance.now();
        phases[j][1].apply(null, arrays);
        const ms = performance.now() - t0;
        phaseTimes[j].push(ms);
        total += ms;
      }
      times.push(total);
      contactSum += world.meta("contactCount");
    }
    const counters = world.counters();
    const phaseMedianMs = {};
    phases.forEach(function (p, j) { phaseMedianMs[p[0]] = quantile(phaseTimes[j], 0.5); });
    return {
      // contact rows: the mean over the timed steps, as manifold bench reports them
      bodies: counters.bodies, contacts: contactSum / a.steps, warnings: counters.warnings, droppedContacts: counters.droppedContacts,
      medianMs: quantile(times, 0.5), p10Ms: quantile(times, 0.1), p90Ms: quantile(times, 0.9), phaseMedianMs: phaseMedianMs,
      apiMedianMs: quantile(api, 0.5), apiP10Ms: quantile(api, 0.1), apiP90Ms: quantile(api, 0.9),
      apiBodies: m.stats().bodies,
    };
  }, { scene, warmup, steps });
}

// The running page (clock on, rendering on) for `seconds`: frames and steps per second; first,
// paused, the median time of a frame that reuses the traced surface and draws the bodies after a step.
async function runFps(page, scene, seconds) {
  await loadPaused(page, scene);
  const draw = await page.evaluate(function () {
    const m = window.manifold, times = [];
    for (let k = 0; k < 21; k++) {
      m.step(1);
      times.push(m.measureFrame(false));
    }
    times.sort(function (a, b) { return a - b; });
    return { drawMs: times[10], forms: m.stats().bodyForms };
  });
  await page.evaluate(function () { window.manifold.resume(); });
  await page.waitForTimeout(1000); // the first frames: the clock's step estimate settles
  const s0 = await page.evaluate(function () { return window.manifold.stats(); });
  const t0 = Date.now();
  await page.waitForTimeout(seconds * 1000);
  const s1 = await page.evaluate(function () { const m = window.manifold; const s = m.stats(); m.pause(); return s; });
  const dt = (Date.now() - t0) / 1000;
  const stepsPerSecond = (s1.steps - s0.steps) / dt;
  return {
    bodies: s1.bodies, seconds: dt,
    fps: (s1.frames - s0.frames) / dt,
    statsFps: s1.fps,
    stepsPerSecond: stepsPerSecond,
    realTime: stepsPerSecond * scene.dt, // simulated seconds per real second (1 = real time)
    physicsMsPerStep: s1.physicsMsPerStep,
    frameMs: s1.frameMs, drawMs: draw.drawMs, bodyForms: draw.forms,
    contacts: s1.contacts, width: s1.width, height: s1.height, antialias: s1.antialias,
  };
}

// ---- run -----------------------------------------------------------------------------------
const fmt = (x, d = 3) => (x === null || x === undefined ? "–" : x.toFixed(d));
const server = await serveWeb(WEB);
const browser = await launchBrowser();
const results = [], fps = [];
let environment; // the page's browser and timer, read in the try below
try {
  const context = await browser.newContext({ viewport: VIEWPORT, deviceScaleFactor: 1 });
  const page = await context.newPage();
  const pageErrors = [];
  page.on("pageerror", (e) => pageErrors.push(e.message));
  await page.goto(server.url + "#space=" + cases[0].space);
  await page.waitForFunction(function () { return !!window.manifold; });
  await page.evaluate(function () { return window.manifold.ready(); });
  environment = await page.evaluate(function () {
    // the timer's tick: the smallest non-zero difference of successive readings
    let tick = Infinity, last = performance.now();
    for (let k = 0; k < 20000; k++) {
      const t = performance.now();
      if (t > last && t - last < tick) tick = t - last;
      last = t;
    }
    const s = window.manifold.stats();
    return { userAgent: navigator.userAgent, crossOriginIsolated: window.crossOriginIsolated, timerTickMs: tick,
      canvas: s.width + "x" + s.height, antialias: s.antialias };
  });
  environment.browserVersion = browser.version();
  environment.chromium = chromiumPath();
  environment.viewport = VIEWPORT.width + "x" + VIEWPORT.height;
  log("Chromium " + environment.browserVersion + ", cross-origin isolated: " + environment.crossOriginIsolated +
    ", performance.now() tick " + (environment.timerTickMs * 1000).toFixed(1) + " µs, canvas " + environment.canvas);

  const fastest = cases.map(() => null), roundMedians = cases.map(() => []);
  for (let round = 1; round <= rounds; round++) {
    for (let i = 0; i < cases.length; i++) {
      const c = cases[i], tag = `round ${round} of ${rounds}: ${c.space} ${c.n}`;
      const scene = JSON.parse(fs.readFileSync(c.file, "utf8"));
      log(`${tag}: ${scene.bodies.length} bodies, loading`);
      await loadPaused(page, scene);
      log(`${tag}: warming up ${warmup} steps, timing ${steps}`);
      const r = await timeSteps(page, scene, warmup, steps);
      const row = Object.assign({ space: c.space, n: c.n, steps, warmup, rounds }, r);
      if (!fastest[i] || row.medianMs < fastest[i].medianMs) fastest[i] = row;
      roundMedians[i].push(r.medianMs);
      log(`${tag}: ${r.bodies} bodies, median ${fmt(r.medianMs)} ms (p10 ${fmt(r.p10Ms)}, p90 ${fmt(r.p90Ms)}), ` +
        `manifold.step ${fmt(r.apiMedianMs)} ms; ` + Object.entries(r.phaseMedianMs).map(([k, v]) => `${k} ${fmt(v)}`).join(", "));
    }
  }
  // Each scene is reported by its fastest round, which would hide a round in which V8 ran the
  // engine unoptimised (a solver it had given up on took 20 times as long,
  // docs/decisions/page-step-split-for-v8.md): every round's median is kept, and rounds far
  // apart are said.
  fastest.forEach((row, i) => { row.roundMediansMs = roundMedians[i]; });
  for (const row of fastest) {
    const slowest = Math.max(...row.roundMediansMs);
    if (slowest > 2 * row.medianMs && slowest - row.medianMs > 1) { // tiny scenes' first rounds (the JIT warming) aside
      log(`warning: ${row.space} ${row.n}: its rounds' medians differ more than twofold (` +
        row.roundMediansMs.map((x) => fmt(x)).join(", ") + " ms); the table shows the fastest");
    }
  }
  results.push(...fastest);

  for (const c of cases.filter((c) => fpsSpaces.indexOf(c.space) >= 0)) {
    const scene = JSON.parse(fs.readFileSync(c.file, "utf8"));
    log(`${c.space} ${c.n}: running with rendering for ${fpsSeconds} s`);
    const f = Object.assign({ space: c.space, n: c.n }, await runFps(page, scene, fpsSeconds));
    fps.push(f);
    log(`${c.space} ${c.n}: ${fmt(f.fps, 1)} fps, ${fmt(f.stepsPerSecond, 0)} steps/s, physics ${fmt(f.physicsMsPerStep)} ms/step`);
  }
  if (pageErrors.length) log("errors in the page:\n  " + pageErrors.join("\n  "));
} finally {
  await browser.close();
  await server.stop();
  if (tmpDir) fs.rmSync(tmpDir, { recursive: true, force: true });
}

// ---- report --------------------------------------------------------------------------------
const phaseNames = results.length ? Object.keys(results[0].phaseMedianMs) : [];
const pad = (s, n) => String(s).padStart(n);
console.log("step time in the page (ms; the step = the sum of its phases, each timed on its own; manifold.step timed whole)");
console.log(["space".padEnd(17), pad("N", 5), pad("bodies", 6), pad("median", 9), pad("p10", 9), pad("p90", 9), pad("api", 9)]
  .concat(phaseNames.map((p) => pad(p, 10))).join(" "));
for (const r of results) {
  console.log([r.space.padEnd(17), pad(r.n, 5), pad(r.bodies, 6), pad(fmt(r.medianMs), 9), pad(fmt(r.p10Ms), 9), pad(fmt(r.p90Ms), 9),
    pad(fmt(r.apiMedianMs), 9)].concat(phaseNames.map((p) => pad(fmt(r.phaseMedianMs[p]), 10))).join(" "));
}
if (fps.length) {
  console.log("\nthe running page, rendering on (" + environment.viewport + " viewport, canvas " + environment.canvas + ", " + environment.antialias + ")");
  console.log(["space".padEnd(17), pad("N", 5), pad("bodies", 6), pad("fps", 6), pad("steps/s", 8), pad("ms/step", 9), pad("real time", 9),
    pad("draw ms", 8), pad("triangles", 9)].join(" "));
  for (const f of fps) {
    console.log([f.space.padEnd(17), pad(f.n, 5), pad(f.bodies, 6), pad(fmt(f.fps, 1), 6), pad(fmt(f.stepsPerSecond, 0), 8),
      pad(fmt(f.physicsMsPerStep), 9), pad(fmt(f.realTime, 2) + "×", 9), pad(fmt(f.drawMs, 1), 8),
      pad(f.bodyForms ? f.bodyForms.triangles : "–", 9)].join(" "));
  }
}
if (outFile) {
  const out = { date: new Date().toISOString(), settle, warmup, steps, rounds, fpsSeconds, environment, results, fps };
  fs.mkdirSync(path.dirname(path.resolve(outFile)), { recursive: true });
  fs.writeFileSync(outFile, JSON.stringify(out, null, 2) + "\n");
  log("wrote " + outFile);
}
