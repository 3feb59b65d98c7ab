// The golden runs in the page's engine under node: for each NAME:STEPS,
// the scene DIR/NAME.json (as `manifold hashes --scenes DIR` writes it) is
// loaded into the page's World (web/js/world.js, the generated engine from
// GEN), run STEPS steps and hashed; one line "NAME STEPS HASH" each, the
// format of test/golden/hashes and of `manifold hashes`. With
// NAME:STEPS:SPLIT the run is saved after SPLIT steps (the page's scene(),
// through JSON text), loaded into a new World and run on to STEPS.
//
//   node test/hashes.mjs GEN DIR NAME:STEPS[:SPLIT] ...
import fs from "node:fs";
import path from "node:path";
import vm from "node:vm";
import { fileURLToPath } from "node:url";

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), "..");
const [gen, dir, ...runs] = process.argv.slice(2);
if (!gen || !dir || runs.length === 0) {
  process.stderr.write("usage: node test/hashes.mjs GEN DIR NAME:STEPS [NAME:STEPS ...]\n");
  process.exit(2);
}

function load(file) { vm.runInThisContext(fs.readFileSync(file, "utf8"), { filename: file }); }

globalThis.performance = globalThis.performance || performance;
load(path.join(gen, "spaces.js"));
load(path.join(root, "web/js/world.js"));
const W = globalThis.ManifoldWeb.world;

for (const run of runs) {
  const m = /^([^:]+):(\d+)(?::(\d+))?$/.exec(run);
  if (!m) {
    process.stderr.write("hashes.mjs: " + JSON.stringify(run) + " is not NAME:STEPS or NAME:STEPS:SPLIT\n");
    process.exit(2);
  }
  const [, name, steps, split] = m;
  const scene = JSON.parse(fs.readFileSync(path.join(dir, name + ".json"), "utf8"));
  if (!globalThis.Manifold.spaces[scene.space]) load(path.join(gen, "space-" + scene.space + ".js"));
  const names = Object.keys(globalThis.Manifold.spaces);
  const loaded = function (s) {
    const w = new W.World(s.space, globalThis.Manifold.spaces[s.space]);
    w.load(W.parseScene(s, names));
    return w;
  };
  let world = loaded(scene);
  if (split !== undefined) {
    world.step(Number(split));
    world = loaded(JSON.parse(JSON.stringify(world.scene())));
    world.step(Number(steps) - Number(split));
  } else {
    world.step(Number(steps));
  }
  process.stdout.write(name + " " + steps + " " + world.hash() + "\n");
}
