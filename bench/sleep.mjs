// What sleeping saves, in the page's engine under node: N boxes in stacks
// on a floor settle and fall asleep; then the same settled scene is timed awake
// (sleeping off: every body moved, walked and solved) and asleep, and the
// asleep step's cost is reported as a share of the awake one's. Prints the
// steps it took to fall asleep, ms a step both ways and the share; --json
// for a JSON line.
import { loadSpace } from "./worlds.mjs";
import { commandLine } from "./options.mjs";

const { count, flag } = commandLine({
  usage: "node bench/sleep.mjs [--bodies N] [--stack S] [--settle K] [--steps K] [--json]",
  known: ["--bodies", "--stack", "--settle", "--steps"], flags: ["--json"],
});
const N = count("--bodies", 1000, 1), STACK = count("--stack", 3, 1), SETTLE = count("--settle", 1500, 1), STEPS = count("--steps", 200, 1);
const json = flag("--json");

// stacks of STACK boxes (side 0.1) on a static floor on the plane (gravity
// along −z), 0.2 apart: islands of their own. (A pile of 1000 in one island
// does not come to rest: the engine's piles jitter, see docs/engine.md.)
const SIDE = 0.1, STACKS = Math.ceil(N / STACK);
const FLOOR = 0.6 * 0.2 * STACKS; // the floor square's circumradius: wider than the row of stacks

function pileScene() {
  const top = -FLOOR + FLOOR / Math.SQRT2;
  const bodies = [{ shape: "square", size: FLOOR, static: true, p: [0, 0, -FLOOR] }];
  for (let k = 0; k < N; k++) {
    const s = Math.floor(k / STACK), r = k % STACK;
    bodies.push({ shape: "square", size: SIDE / Math.SQRT2, p: [(s - (STACKS - 1) / 2) * 0.2, 0, top + (r + 0.5) * SIDE] });
  }
  return { space: "plane", bodies: bodies };
}

loadSpace("plane");
const W = globalThis.ManifoldWeb.world;
const w = new W.World("plane", globalThis.Manifold.spaces.plane);
w.load(W.parseScene(pileScene(), Object.keys(globalThis.Manifold.spaces)));

// drop the boxes and let them fall asleep (every stack that comes to rest)
let fellAsleep = null;
for (let k = 1; k <= SETTLE && fellAsleep === null; k++) {
  w.step(1);
  if (k % 10 === 0 && w.counters().awake === 0) fellAsleep = k;
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
const awakeWorld = new W.World("plane", globalThis.Manifold.spaces.plane);
awakeWorld.load(W.parseScene(Object.assign({}, settled, { sleep: false }), Object.keys(globalThis.Manifold.spaces)));
const awakeMs = time(awakeWorld);
const asleepMs = time(w);
const result = {
  bodies: N, stack: STACK, fellAsleepAtStep: fellAsleep, bodiesAsleep: asleepShare, awakeMsPerStep: awakeMs, asleepMsPerStep: asleepMs,
  share: asleepMs / awakeMs, steps: STEPS,
};
if (json) {
  console.log(JSON.stringify(result));
} else {
  console.log(`${N} boxes in stacks of ${STACK} on the plane: ` + (fellAsleep === null
    ? `${(100 * asleepShare).toFixed(1)} % of them asleep after ${SETTLE} steps`
    : `all asleep after ${fellAsleep} steps (${(fellAsleep * 0.01).toFixed(1)} s)`));
  console.log(`a step: awake ${awakeMs.toFixed(3)} ms, with sleeping ${asleepMs.toFixed(4)} ms: ${(100 * result.share).toFixed(2)} % of the awake step`);
}
