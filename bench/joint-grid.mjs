// Box2D's joint_grid in the page's engine, under node and in the page
// (web/) in headless Chromium: an N × N grid of circles on the plane, each
// joined by revolute joints to its right and lower neighbours (pins midway
// between them), the top row static, hanging under gravity, every body
// awake (sleeping off); and, in the same run, the rectangle's pyramid of R
// rows of boxes, so that the grid's time per body-step is reported beside
// the pyramid's. The scale is Box2D's (circles of radius 0.4 m one metre
// apart, boxes of half-side 0.5 m, 60 Hz, g = 10) made alike here: g·dt²/L
// the same, with dt = 1/300 and the plane's g = 4.
//
//   node bench/joint-grid.mjs [--size N] [--rows R] [--steps K] [--warmup W] [--browser|--node] [--json]
//
// The same scene JSON runs in both: under node in a World of web/js/world.js
// (as bench/worlds.mjs loads it), in the page through window.manifold
// (loadScene, paused; step), its World read for the joints' anchors. Only
// the steps are timed (performance.now() around them, in the page inside
// page.evaluate, nothing drawn): W steps of warm-up, then K timed. Prints,
// for each environment, ms a step, µs a body-step, the joints' worst anchor
// gap (in spacings), the pyramid's sideways spread (in half-sides) and the
// grid's body-step over the pyramid's; --browser or --node for one of them
// (neither: both, node first); --json for one JSON object with both.
// MANIFOLD_WEB serves another copy of web/ to the page.
import path from "node:path";
import url from "node:url";
import { loadSpace } from "./worlds.mjs";
import { commandLine } from "./options.mjs";
import { openBenchPage, loadPaused } from "./page.mjs";

const { count, flag } = commandLine({
  usage: "node bench/joint-grid.mjs [--size N] [--rows R] [--steps K] [--warmup W] [--browser|--node] [--json]",
  known: ["--size", "--rows", "--steps", "--warmup"], flags: ["--json", "--browser", "--node"],
});
const N = count("--size", 100, 2), R = count("--rows", 40, 1), STEPS = count("--steps", 100, 1), WARMUP = count("--warmup", 20, 0);
const json = flag("--json");
if (flag("--browser") && flag("--node")) { console.error("--browser and --node: give one of them, or neither for both"); process.exit(2); }
const where = flag("--browser") ? ["browser"] : flag("--node") ? ["node"] : ["node", "browser"];
const WEB = process.env.MANIFOLD_WEB ? path.resolve(process.env.MANIFOLD_WEB) : path.join(path.dirname(url.fileURLToPath(import.meta.url)), "..", "web");
// steps per timed call (a few seconds of the grid's in the page, so that the page stays answerable)
const CHUNK = 10;
const log = (s) => process.stderr.write(s + "\n");

const DT = 1 / 300;
// g·dt²/L as Box2D's 60 Hz grid of 1 m spacing under g = 10
const SPACING = 4 * DT * DT / (10 / 3600 / 1);
const HALF = 0.5 * SPACING;

// The grid of n × n circles and its joints, as a scene (JSON value).
function gridScene(n) {
  const bodies = [], joints = [];
  const at = (i, k) => [(i - (n - 1) / 2) * SPACING, 0, -k * SPACING];
  for (let k = 0; k < n; k++) {
    for (let i = 0; i < n; i++) bodies.push({ shape: "circle", size: 0.4 * SPACING, p: at(i, k), static: k === 0 });
  }
  const index = (i, k) => k * n + i;
  for (let k = 0; k < n; k++) {
    for (let i = 0; i < n; i++) {
      const p = at(i, k);
      if (i + 1 < n && k > 0) joints.push({ type: "revolute", a: index(i, k), b: index(i + 1, k), anchor: [p[0] + HALF, 0, p[2]] });
      if (k + 1 < n) joints.push({ type: "revolute", a: index(i, k), b: index(i, k + 1), anchor: [p[0], 0, p[2] - HALF] });
    }
  }
  return { space: "plane", dt: DT, sleep: false, bodies: bodies, joints: joints };
}

// The pyramid of `rows` rows of boxes on the rectangle, as a scene (JSON value).
function pyramidScene(rows) {
  const h = HALF, bodies = [];
  for (let r = 0; r < rows; r++) {
    for (let i = 0; i < rows - r; i++) {
      bodies.push({ shape: "square", size: h * Math.SQRT2, p: [(i - (rows - r - 1) / 2) * 2 * h, 0, -1 + h + 2 * h * r] });
    }
  }
  return { space: "rectangle", dt: DT, friction: 0.6, sleep: false, bodies: bodies };
}

// What is measured of a World now: its counts, warnings, the joints' worst
// anchor gap and every body's x. Self-contained: it runs in the page too.
function snapshot(w) {
  const n = w.jointCount(), xyz = w.jointAnchors();
  let gap = 0;
  for (let j = 0; j < n; j++) gap = Math.max(gap, Math.hypot(xyz[6 * j] - xyz[6 * j + 3], xyz[6 * j + 1] - xyz[6 * j + 4], xyz[6 * j + 2] - xyz[6 * j + 5]));
  return { bodies: w.count(), joints: n, warnings: w.counters().warnings, gap: gap, x: w.bodies().map((b) => b.p[0]) };
}

// Under node: the scene in a fresh World of the page's engine, as { step(n) → ms, snapshot() }.
function nodeWorld(scene) {
  loadSpace(scene.space);
  const W = globalThis.ManifoldWeb.world;
  const w = new W.World(scene.space, globalThis.Manifold.spaces[scene.space]);
  w.load(W.parseScene(scene, Object.keys(globalThis.Manifold.spaces)));
  return { step: (n) => w.step(n), snapshot: () => snapshot(w) };
}

// In the page: the scene loaded with manifold.loadScene (paused), stepped by manifold.step, as nodeWorld's.
async function pageWorld(page, scene) {
  await loadPaused(page, scene);
  const w = await page.evaluateHandle(() => window.ManifoldWeb.page.requireWorld());
  return {
    step: (n) => page.evaluate((n) => {
      const t0 = performance.now();
      window.manifold.step(n);
      return performance.now() - t0;
    }, n),
    snapshot: () => page.evaluate(snapshot, w),
  };
}

// One scene's run in one environment (a world as nodeWorld's): warm-up, timed steps, what became of it.
async function measure(w) {
  const run = async (n) => {
    let ms = 0;
    for (let k = 0; k < n; k += CHUNK) ms += await w.step(Math.min(CHUNK, n - k));
    return ms;
  };
  const before = await w.snapshot();
  await run(WARMUP);
  const ms = (await run(STEPS)) / STEPS, after = await w.snapshot();
  return {
    bodies: after.bodies, joints: after.joints, msPerStep: ms, usPerBodyStep: 1000 * ms / after.bodies,
    worstGap: after.gap / SPACING, spread: Math.max(...after.x.map((x, k) => Math.abs(x - before.x[k]))) / HALF, warnings: after.warnings,
  };
}

// Both scenes in one environment, each world made by open(scene): { grid, pyramid, ratio }.
async function runScenes(open) {
  const grid = await measure(await open(gridScene(N)));
  const pyramid = await measure(await open(pyramidScene(R)));
  return { grid: { size: N, ...grid }, pyramid: { rows: R, ...pyramid }, ratio: grid.usPerBodyStep / pyramid.usPerBodyStep };
}

// Both scenes in one Chromium page (the page of web/, served cross-origin isolated).
async function runBrowser() {
  const { browser, page, pageErrors, close } = await openBenchPage(WEB, "#space=plane");
  try {
    log("Chromium " + browser.version());
    const out = await runScenes((scene) => pageWorld(page, scene));
    if (pageErrors.length) log("errors in the page:\n  " + pageErrors.join("\n  "));
    return { environment: { chromium: browser.version() }, ...out };
  } finally {
    await close();
  }
}

const result = { dt: DT, steps: STEPS, warmup: WARMUP };
for (const env of where) {
  log(`joint grid: ${env}`);
  result[env] = env === "browser" ? await runBrowser() : { environment: { node: process.version }, ...await runScenes(nodeWorld) };
}
if (json) {
  console.log(JSON.stringify(result));
} else {
  for (const env of where) {
    const { environment, grid: g, pyramid: p, ratio } = result[env];
    console.log(env === "browser" ? `in Chromium ${environment.chromium} (one page):` : `under node ${environment.node}:`);
    console.log(`  joint grid ${N}×${N}: ${g.bodies} bodies, ${g.joints} joints: ${g.msPerStep.toFixed(1)} ms a step, ${g.usPerBodyStep.toFixed(2)} µs a body-step; worst anchor gap ${(100 * g.worstGap).toFixed(2)} % of a spacing after ${WARMUP + STEPS} steps; ${g.warnings} warnings`);
    console.log(`  pyramid of ${R} rows: ${p.bodies} boxes: ${p.msPerStep.toFixed(1)} ms a step, ${p.usPerBodyStep.toFixed(2)} µs a body-step; spread ${p.spread.toFixed(2)} half-sides`);
    console.log(`  grid / pyramid per body-step: ${ratio.toFixed(2)}`);
  }
  if (result.node && result.browser) {
    const per = (k) => (result.browser[k].usPerBodyStep / result.node[k].usPerBodyStep).toFixed(2);
    console.log(`Chromium / node per body-step: grid ${per("grid")}, pyramid ${per("pyramid")}`);
  }
}
