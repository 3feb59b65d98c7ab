// Box2D's joint_grid in the page's engine under node: an N × N grid of
// circles on the plane, each joined by revolute joints to its right and
// lower neighbours (pins midway between them), the top row static, hanging
// under gravity, every body awake (sleeping off); and, in the same run, the rectangle's
// pyramid of R rows of boxes, so that the grid's time per body-step is
// reported beside the pyramid's. The scale is Box2D's (circles of radius
// 0.4 m one metre apart, boxes of half-side 0.5 m, 60 Hz, g = 10) made
// alike here: g·dt²/L the same, with dt = 1/300 and the plane's g = 4.
// Prints ms a step, µs a body-step, the joints' worst anchor gap (in
// spacings) and the pyramid's sideways spread (in half-sides); --json for a
// JSON line.
import { loadSpace } from "./worlds.mjs";
import { commandLine } from "./options.mjs";

const { count, flag } = commandLine({
  usage: "node bench/joint-grid.mjs [--size N] [--rows R] [--steps K] [--warmup W] [--json]",
  known: ["--size", "--rows", "--steps", "--warmup"], flags: ["--json"],
});
const N = count("--size", 100, 2), R = count("--rows", 40, 1), STEPS = count("--steps", 100, 1), WARMUP = count("--warmup", 20, 0);
const json = flag("--json");

const DT = 1 / 300;
// g·dt²/L as Box2D's 60 Hz grid of 1 m spacing under g = 10
const SPACING = 4 * DT * DT / (10 / 3600 / 1);
const HALF = 0.5 * SPACING;

function world(scene) {
  loadSpace(scene.space);
  const W = globalThis.ManifoldWeb.world;
  const w = new W.World(scene.space, globalThis.Manifold.spaces[scene.space]);
  w.load(W.parseScene(scene, Object.keys(globalThis.Manifold.spaces)));
  return w;
}

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

function pyramidScene(rows) {
  const h = HALF, bodies = [];
  for (let r = 0; r < rows; r++) {
    for (let i = 0; i < rows - r; i++) {
      bodies.push({ shape: "square", size: h * Math.SQRT2, p: [(i - (rows - r - 1) / 2) * 2 * h, 0, -1 + h + 2 * h * r] });
    }
  }
  return { space: "rectangle", dt: DT, friction: 0.6, sleep: false, bodies: bodies };
}

function time(w) {
  w.step(WARMUP);
  const t0 = performance.now();
  w.step(STEPS);
  return (performance.now() - t0) / STEPS;
}

function worstGap(w) {
  const xyz = w.jointAnchors();
  let worst = 0;
  for (let j = 0; j < w.jointCount(); j++) {
    worst = Math.max(worst, Math.hypot(xyz[6 * j] - xyz[6 * j + 3], xyz[6 * j + 1] - xyz[6 * j + 4], xyz[6 * j + 2] - xyz[6 * j + 5]));
  }
  return worst / SPACING;
}

const grid = world(gridScene(N));
const gridMs = time(grid);
const gridGap = worstGap(grid);
const pyramid = world(pyramidScene(R));
const x0 = pyramid.bodies().map((b) => b.p[0]);
const pyramidMs = time(pyramid);
const spread = Math.max(...pyramid.bodies().map((b, k) => Math.abs(b.p[0] - x0[k]))) / HALF;
const result = {
  grid: { size: N, bodies: grid.count(), joints: grid.jointCount(), msPerStep: gridMs, usPerBodyStep: 1000 * gridMs / grid.count(), worstGap: gridGap, warnings: grid.counters().warnings },
  pyramid: { rows: R, bodies: pyramid.count(), msPerStep: pyramidMs, usPerBodyStep: 1000 * pyramidMs / pyramid.count(), spread: spread },
  dt: DT, steps: STEPS, warmup: WARMUP,
};
if (json) {
  console.log(JSON.stringify(result));
} else {
  const g = result.grid, p = result.pyramid;
  console.log(`joint grid ${N}×${N}: ${g.bodies} bodies, ${g.joints} joints: ${g.msPerStep.toFixed(1)} ms a step, ${g.usPerBodyStep.toFixed(2)} µs a body-step; worst anchor gap ${(100 * g.worstGap).toFixed(2)} % of a spacing after ${WARMUP + STEPS} steps; ${g.warnings} warnings`);
  console.log(`pyramid of ${R} rows: ${p.bodies} boxes: ${p.msPerStep.toFixed(1)} ms a step, ${p.usPerBodyStep.toFixed(2)} µs a body-step; spread ${p.spread.toFixed(2)} half-sides`);
  console.log(`grid / pyramid per body-step: ${(g.usPerBodyStep / p.usPerBodyStep).toFixed(2)}`);
}
