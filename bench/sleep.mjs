// What sleeping saves, in the page's engine under node: N boxes in stacks
// on a floor settle and fall asleep; then the same settled scene is timed awake
// (sleeping off: every body moved, walked and solved) and asleep, and the
// asleep step's cost is reported as a share of the awake one's. Prints the
// steps it took to fall asleep, ms a step both ways and the share; --json
// for a JSON line. --sleep-speed X sets the scene key sleepSpeed (the calm
// threshold, in sizes a second; default the engine's). --pile: instead of
// the stacks, N circles and squares in turn (the benchmark piles' bodies, of
// their size on the rectangle) in a lattice 50 wide dropped into the
// rectangle, one island once it lands: settled with sleeping off for the
// --settle steps, then sleeping on, watched for --watch steps; prints the
// bodies' calm measure max(|v|, |ω|·reach)/size at rest (median, 99th
// percentile, max), the steps after rest until all were asleep and the
// share asleep 300 steps (3 s) after rest.
import { loadSpace } from "./worlds.mjs";
import { commandLine } from "./options.mjs";

const { count, flag, nonNegative } = commandLine({
  usage: "node bench/sleep.mjs [--bodies N] [--stack S] [--pile] [--settle K] [--watch K] [--sleep-speed X] [--steps K] [--json]",
  known: ["--bodies", "--stack", "--settle", "--watch", "--sleep-speed", "--steps"], flags: ["--json", "--pile"],
});
const N = count("--bodies", 1000, 1), STACK = count("--stack", 3, 1), SETTLE = count("--settle", 1500, 1), STEPS = count("--steps", 200, 1);
const WATCH = count("--watch", 1000, 300), SLEEP_SPEED = nonNegative("--sleep-speed", -1); // -1: the engine's default
const json = flag("--json"), pile = flag("--pile");

// stacks of STACK boxes (side 0.1) on a static floor on the plane (gravity
// along −z), 0.2 apart: islands of their own. (A pile of 1000 in one island
// does not come to rest: the engine's piles jitter, see docs/engine.md and
// --pile.)
const SIDE = 0.1, STACKS = Math.ceil(N / STACK);
// the floor square's circumradius: its half side (circumradius/√2) is 0.6 of
// the row of stacks' length, so that every stack stands on it
const FLOOR = Math.SQRT2 * 0.6 * 0.2 * STACKS;

function pileScene() {
  const top = -FLOOR + FLOOR / Math.SQRT2;
  const bodies = [{ shape: "square", size: FLOOR, static: true, p: [0, 0, -FLOOR] }];
  for (let k = 0; k < N; k++) {
    const s = Math.floor(k / STACK), r = k % STACK;
    bodies.push({ shape: "square", size: SIDE / Math.SQRT2, p: [(s - (STACKS - 1) / 2) * 0.2, 0, top + (r + 0.5) * SIDE] });
  }
  return { space: "plane", bodies: bodies };
}

// --pile: a lattice of N circles and squares in turn in the rectangle (3 × 2,
// gravity 4 along −z), of the size `manifold bench` gives N bodies there,
// 2.1 sizes apart (a little offset and turned, seeded), from the floor up
function latticeScene() {
  const size = Math.sqrt(6 / (3 * N * ((Math.PI + 2) / 2))), gap = 2.1 * size, cols = Math.floor(2.95 / gap);
  let seed = 1;
  const random = () => { seed = (seed * 1664525 + 1013904223) >>> 0; return seed / 4294967296; };
  const bodies = [];
  for (let k = 0; k < N; k++) {
    const i = k % cols, j = Math.floor(k / cols);
    bodies.push({ shape: k % 2 === 0 ? "circle" : "square", size, angle: 0.5 * random(),
      p: [(i - (cols - 1) / 2) * gap + 0.1 * size * (random() - 0.5), 0, -1 + 1.05 * size + j * gap] });
  }
  return { space: "rectangle", sleep: false, bodies: bodies };
}

const SPACE = pile ? "rectangle" : "plane";
loadSpace(SPACE);
const W = globalThis.ManifoldWeb.world;
const w = new W.World(SPACE, globalThis.Manifold.spaces[SPACE]);
const scene = pile ? latticeScene() : pileScene();
if (SLEEP_SPEED >= 0) scene.sleepSpeed = SLEEP_SPEED;
w.load(W.parseScene(scene, Object.keys(globalThis.Manifold.spaces)));

// the bodies' calm measure, max(|v|, |ω|·reach)/size, as Manifold.Sleep takes it
function calm() {
  const S = w.engine.slots, k = w.stride(), a = w.a, out = [];
  for (let i = 0; i < w.count(); i++) {
    const v = Math.hypot(a.vel[3 * i], a.vel[3 * i + 1], a.vel[3 * i + 2]);
    out.push(Math.max(v, Math.abs(a.scalars[i * k + S.omega]) * a.scalars[i * k + S.boundRadius]) / a.scalars[i * k + S.size]);
  }
  out.sort((x, y) => x - y);
  const at = (q) => out[Math.round(q * (out.length - 1))];
  return { median: at(0.5), p99: at(0.99), max: at(1) };
}

// stacks: drop the boxes and let them fall asleep (every stack that comes to
// rest); the pile: let it come to rest awake, then sleeping on
let fellAsleep = null, atRest = null, asleepAt3s = null;
if (pile) {
  w.step(SETTLE);
  atRest = calm();
  w.setParams({ sleep: 1 }); // a parameter changed: every timer starts from 0
  for (let k = 1; k <= WATCH && (fellAsleep === null || k <= 300); k++) {
    w.step(1);
    if (k % 10 === 0 && fellAsleep === null && w.counters().awake === 0) fellAsleep = k;
    if (k === 300) asleepAt3s = 1 - w.counters().awake / N;
  }
} else {
  for (let k = 1; k <= SETTLE && fellAsleep === null; k++) {
    w.step(1);
    if (k % 10 === 0 && w.counters().awake === 0) fellAsleep = k;
  }
}
const asleepShare = 1 - w.counters().awake / N;
const settled = w.scene();

function time(world) {
  world.step(10); // warm-up
  const t0 = performance.now();
  world.step(STEPS);
  return (performance.now() - t0) / STEPS;
}

// awake: the settled pile with sleeping off
const awakeWorld = new W.World(SPACE, globalThis.Manifold.spaces[SPACE]);
awakeWorld.load(W.parseScene(Object.assign({}, settled, { sleep: false }), Object.keys(globalThis.Manifold.spaces)));
const awakeMs = time(awakeWorld);
const asleepMs = time(w);
const sleepSpeed = w.param("sleepSpeed");
const result = pile
  ? { pile: true, bodies: N, sleepSpeed, settle: SETTLE, atRest, fellAsleepAfterRestStep: fellAsleep, bodiesAsleepAt3s: asleepAt3s, bodiesAsleep: asleepShare,
      awakeMsPerStep: awakeMs, asleepMsPerStep: asleepMs, share: asleepMs / awakeMs, steps: STEPS }
  : { bodies: N, stack: STACK, sleepSpeed, fellAsleepAtStep: fellAsleep, bodiesAsleep: asleepShare, awakeMsPerStep: awakeMs, asleepMsPerStep: asleepMs,
      share: asleepMs / awakeMs, steps: STEPS };
const f = (x) => x.toPrecision(3);
if (json) {
  console.log(JSON.stringify(result));
} else if (pile) {
  console.log(`${N} circles and squares in a pile in the rectangle, sleepSpeed ${sleepSpeed}: after ${SETTLE} steps awake, max(|v|, |ω|·reach)/size`
    + ` median ${f(atRest.median)}, 99th percentile ${f(atRest.p99)}, max ${f(atRest.max)} a second; then sleeping on: ` + (fellAsleep === null
    ? `${(100 * asleepAt3s).toFixed(1)} % asleep after 300 steps, ${(100 * asleepShare).toFixed(1)} % after ${WATCH}`
    : `all asleep ${fellAsleep} steps (${(fellAsleep * 0.01).toFixed(1)} s) after; ${(100 * asleepAt3s).toFixed(1)} % asleep after 300 steps`));
} else {
  console.log(`${N} boxes in stacks of ${STACK} on the plane, sleepSpeed ${sleepSpeed}: ` + (fellAsleep === null
    ? `${(100 * asleepShare).toFixed(1)} % of them asleep after ${SETTLE} steps`
    : `all asleep after ${fellAsleep} steps (${(fellAsleep * 0.01).toFixed(1)} s)`));
  console.log(`a step: awake ${awakeMs.toFixed(3)} ms, with sleeping ${asleepMs.toFixed(4)} ms: ${(100 * result.share).toFixed(2)} % of the awake step`);
}
