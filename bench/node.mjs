// The generated engine (web/gen) under node, on the scenes `manifold bench
// --scenes DIR` writes: the JavaScript half of "native vs JS" without a
// browser. Usage: node bench/node.mjs DIR [--warmup W] [--steps S]
import fs from "node:fs";
import path from "node:path";
import vm from "node:vm";
import { fileURLToPath } from "node:url";

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), "..");
const args = process.argv.slice(2);
const dir = args[0];
if (!dir) { console.error("usage: node bench/node.mjs DIR [--warmup W] [--steps S]"); process.exit(2); }
const opt = (name, dflt) => { const k = args.indexOf(name); return k >= 0 ? Number(args[k + 1]) : dflt; };
const warmup = opt("--warmup", 50), steps = opt("--steps", 50);

function load(file) { vm.runInThisContext(fs.readFileSync(file, "utf8"), { filename: file }); }
globalThis.performance = globalThis.performance || performance;
load(path.join(root, "web/js/world.js"));

const results = [];
for (const f of fs.readdirSync(dir).filter((f) => f.endsWith(".json")).sort()) {
  const scene = JSON.parse(fs.readFileSync(path.join(dir, f), "utf8"));
  const script = path.join(root, "web/gen", "space-" + scene.space + ".js");
  if (!globalThis.Manifold || !globalThis.Manifold.spaces[scene.space]) load(script);
  const W = globalThis.ManifoldWeb.world;
  const world = new W.World(scene.space, globalThis.Manifold.spaces[scene.space]);
  world.load(W.parseScene(scene, Object.keys(globalThis.Manifold.spaces)));
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
  const r = { space: scene.space, bodies: world.count(), medianMs: q(0.5), p10Ms: q(0.1), p90Ms: q(0.9), steps, phaseMedianMs };
  results.push(r);
  console.error(`${r.space} ${r.bodies}: median ${r.medianMs.toFixed(3)} ms (p10 ${r.p10Ms.toFixed(3)}, p90 ${r.p90Ms.toFixed(3)}) ` +
    Object.entries(phaseMedianMs).map(([k, v]) => `${k} ${v.toFixed(3)}`).join(", "));
}
console.log(JSON.stringify(results));
