// Browser tests of the page's performance guards (part "performance" of
// run.mjs): what the running page allocates a frame with many bodies
// (bytes per frame, by V8's sampling heap profiler). The timings themselves
// are benchmarks (bench/), not checks: they depend on the machine.
import { openSpace, torusBodies } from "./bodies.mjs";

const BODIES = 300;
const BYTES_PER_FRAME = 8192;
// Samples taken at most. Right after a scene loads the engine's step runs
// before V8 has optimised it, and the unoptimised step boxes its numbers
// (tens of KB a frame); on a loaded machine the optimising compiler, which
// runs beside the page, can take longer than the warm-up. The guard is on
// the steady state: the least of the samples, taken until one is within it.
const SAMPLES = 3;

// What the running page allocates a frame (V8's sampling heap profiler, counting
// what was collected too), with n bodies falling on the torus: steps, drawing, stats;
// and the functions that allocated most (bytes a frame).
async function garbagePerFrame(page, client, n) {
  const bodies = torusBodies(n, 0.04);
  await page.evaluate(function (b) {
    const m = window.manifold;
    return m.loadScene({ space: "torus", gravity: true, bodies: b }).then(function () { m.resume(); });
  }, bodies);
  await page.waitForTimeout(1500); // the first frames trace the surface; the engine warms up
  const s0 = await page.evaluate(function () { return window.manifold.stats(); });
  await client.send("HeapProfiler.startSampling", { samplingInterval: 256, includeObjectsCollectedByMinorGC: true, includeObjectsCollectedByMajorGC: true });
  await page.waitForTimeout(2500);
  const { profile } = await client.send("HeapProfiler.stopSampling");
  const s1 = await page.evaluate(function () { return window.manifold.stats(); });
  const frames = Math.max(1, s1.frames - s0.frames);
  const bySite = {};
  let total = 0;
  (function walk(node) {
    total += node.selfSize;
    if (node.selfSize > 0) {
      const f = node.callFrame, site = (f.functionName || "(anonymous)") + " " + f.url.split("/").pop() + ":" + f.lineNumber;
      bySite[site] = (bySite[site] || 0) + node.selfSize;
    }
    node.children.forEach(walk);
  })(profile.head);
  const top = Object.entries(bySite).sort(function (a, b) { return b[1] - a[1]; }).slice(0, 3)
    .map(function (e) { return [e[0], Math.round(e[1] / frames)]; });
  return { bytes: total / frames, frames: s1.frames - s0.frames, steps: s1.steps - s0.steps, bodies: s1.bodies, top: top };
}

// The running page's garbage does not grow with its bodies: the emitted step
// allocates nothing, and the drawing checks the bodies' colours without
// building a key (a string of every colour, about 30 KB a frame with 300
// bodies). What is left is the frame's own (camera, stats), a few KB.
async function testFrameGarbage(check, context, base) {
  const errors = [];
  const page = await openSpace(context, base, "#space=torus", errors);
  const client = await context.newCDPSession(page);
  await client.send("HeapProfiler.enable");
  const samples = [];
  let best = null;
  while (samples.length < SAMPLES && !(best && best.bytes <= BYTES_PER_FRAME)) {
    const r = await garbagePerFrame(page, client, BODIES);
    samples.push(Math.round(r.bytes));
    if (!best || r.bytes < best.bytes) best = r;
  }
  check("the running page allocates at most 8 KB a frame with " + BODIES + " bodies (torus, stepping and drawing; the least of up to " + SAMPLES + " samples)",
    best.frames > 5 && best.steps > 0 && best.bodies === BODIES && best.bytes <= BYTES_PER_FRAME && errors.length === 0,
    JSON.stringify({ bytesPerFrame: Math.round(best.bytes), samples: samples, frames: best.frames, steps: best.steps, bodies: best.bodies,
      mostAllocating: best.top, errors: errors }));
  await page.close();
}

export async function testPerformance(check, context, base) {
  await testFrameGarbage(check, context, base);
}
