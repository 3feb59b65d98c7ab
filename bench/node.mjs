// The generated engine (web/gen) under node, on the scenes `manifold bench
// --scenes DIR` writes: the JavaScript half of "native vs JS" without a
// browser, and how long each scene took to load (read, checked, its bodies
// added). Usage: node bench/node.mjs DIR [--warmup W] [--steps S]
import { commandLine, worlds } from "./worlds.mjs";

const { dir, count } = commandLine("node bench/node.mjs DIR [--warmup W] [--steps S]", ["--warmup", "--steps"]);
const warmup = count("--warmup", 50, 0), steps = count("--steps", 50, 1);

const results = [];
for (const { scene, world, loadMs } of worlds(dir)) {
  world.step(warmup);
  // each phase timed on its own, as `manifold bench` does; the step is their sum
  const phases = world.engine.phases, arrays = world.arrays;
  const times = [], phaseTimes = phases.map(() => []);
  for (let k = 0; k < steps; k++) {
    let total = 0;
    phases.forEach(([, run], j) => {
      const t0 = performance.now();
      run.apply(null, arrays);
      const ms = performance.now() - t0;
      phaseTimes[j].push(ms);
      total += ms;
    });
    times.push(total);
  }
  const quantile = (xs, x) => { const s = xs.slice().sort((a, b) => a - b); return s[Math.min(s.length - 1, Math.floor(x * s.length))]; };
  const q = (x) => quantile(times, x);
  const phaseMedianMs = Object.fromEntries(phases.map(([name], j) => [name, quantile(phaseTimes[j], 0.5)]));
  const r = { space: scene.space, bodies: world.count(), loadMs, medianMs: q(0.5), p10Ms: q(0.1), p90Ms: q(0.9), steps, phaseMedianMs };
  results.push(r);
  console.error(`${r.space} ${r.bodies}: loaded in ${r.loadMs.toFixed(0)} ms, median ${r.medianMs.toFixed(3)} ms (p10 ${r.p10Ms.toFixed(3)}, p90 ${r.p90Ms.toFixed(3)}) ` +
    Object.entries(phaseMedianMs).map(([k, v]) => `${k} ${v.toFixed(3)}`).join(", "));
}
console.log(JSON.stringify(results));
