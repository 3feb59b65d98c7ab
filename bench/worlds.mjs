// The generated engine (web/gen, web/js/world.js) under node, on the scenes
// `manifold bench --scenes DIR` writes: what bench/node.mjs, pile.mjs,
// cells.mjs and peers.mjs share.
import fs from "node:fs";
import path from "node:path";
import vm from "node:vm";
import { fileURLToPath } from "node:url";
import { commandLine as parse } from "./options.mjs";

const root = path.resolve(path.dirname(fileURLToPath(import.meta.url)), "..");

function load(file) { vm.runInThisContext(fs.readFileSync(file, "utf8"), { filename: file }); }

// The script's arguments: the scene directory first, then the options of
// the list `known` (see options.mjs): { dir, count, positive, nonNegative }.
export function commandLine(usage, known) {
  const line = parse({ usage, positional: 1, known });
  return { dir: line.positional[0], count: line.count, positive: line.positive, nonNegative: line.nonNegative };
}

// The page's engine for the space `name` as globals, as the page has them:
// Manifold (the index and Manifold.spaces[name]) and ManifoldWeb.world.
export function loadSpace(name) {
  globalThis.performance = globalThis.performance || performance;
  // the index first (it lists the scene keys the page's reader checks), then the world
  if (!globalThis.Manifold || !globalThis.Manifold.sceneKeys) load(path.join(root, "web/gen/spaces.js"));
  if (!globalThis.ManifoldWeb) load(path.join(root, "web/js/world.js"));
  if (!globalThis.Manifold.spaces[name]) load(path.join(root, "web/gen", "space-" + name + ".js"));
}

// Every scene DIR/*.json in name order, loaded into a fresh World of the
// page's engine: { file, scene, world, loadMs } (loadMs: how long checking
// and loading the scene took).
export function* worlds(dir) {
  for (const file of fs.readdirSync(dir).filter((f) => f.endsWith(".json")).sort()) {
    const scene = JSON.parse(fs.readFileSync(path.join(dir, file), "utf8"));
    loadSpace(scene.space);
    const W = globalThis.ManifoldWeb.world;
    const world = new W.World(scene.space, globalThis.Manifold.spaces[scene.space]);
    const t0 = performance.now();
    world.load(W.parseScene(scene, Object.keys(globalThis.Manifold.spaces)));
    yield { file, scene, world, loadMs: performance.now() - t0 };
  }
}
