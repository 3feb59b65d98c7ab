// The generated engine (web/gen, web/js/world.js) under node, on the scenes
// `manifold bench --scenes DIR` writes: what bench/node.mjs, pile.mjs and
// cells.mjs share.
import fs from "node:fs";
import path from "node:path";
import vm from "node:vm";
import { fileURLToPath } from "node:url";

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), "..");

function load(file) { vm.runInThisContext(fs.readFileSync(file, "utf8"), { filename: file }); }

// The script's arguments: the scene directory first (else the usage line and
// exit 2), then `--name value` options read as numbers.
export function commandLine(usage) {
  const args = process.argv.slice(2);
  if (!args[0]) { console.error("usage: " + usage); process.exit(2); }
  const option = (name, dflt) => { const k = args.indexOf(name); return k >= 0 ? Number(args[k + 1]) : dflt; };
  return { dir: args[0], option };
}

// Every scene DIR/*.json in name order, loaded into a fresh World of the
// page's engine: { file, scene, world }.
export function* worlds(dir) {
  globalThis.performance = globalThis.performance || performance;
  if (!globalThis.ManifoldWeb) load(path.join(root, "web/js/world.js"));
  for (const file of fs.readdirSync(dir).filter((f) => f.endsWith(".json")).sort()) {
    const scene = JSON.parse(fs.readFileSync(path.join(dir, file), "utf8"));
    if (!globalThis.Manifold || !globalThis.Manifold.spaces[scene.space]) load(path.join(root, "web/gen", "space-" + scene.space + ".js"));
    const W = globalThis.ManifoldWeb.world;
    const world = new W.World(scene.space, globalThis.Manifold.spaces[scene.space]);
    world.load(W.parseScene(scene, Object.keys(globalThis.Manifold.spaces)));
    yield { file, scene, world };
  }
}
