// How much the broad phase reads: on scenes written by `manifold bench
// --scenes DIR`, run under node for W steps, the bodies the 27-cell scan of
// each body reads (every body in the buckets it probes) against those really
// in the 27 cells, per body, for the engine's hash table and for tables of
// two and four buckets per body.
//
// The cell and bucket of a body are recomputed here the way the engine's
// broad phase (Manifold.Collide.buildGrid) computes them; the script checks
// that the counts per bucket it gets equal the engine's own table for the
// same step, and stops if they differ.
// Usage: node bench/cells.mjs DIR [--steps W]   (JSON lines on stdout)
import { commandLine, worlds } from "./worlds.mjs";

const { dir, count } = commandLine("node bench/cells.mjs DIR [--steps W]", ["--steps"]);
const steps = count("--steps", 1, 0);

const hash = ([x, y, z]) => x * 73856093 + y * 19349663 + z * 83492791;
const bucketOf = (buckets, c) => { const h = hash(c); return h - buckets * Math.floor(h / buckets); };
const same = (a, b) => a[0] === b[0] && a[1] === b[1] && a[2] === b[2];

for (const { file: f, scene, world } of worlds(dir)) {
  world.step(steps);
  // the broad phase once more, on the positions as they are now (a step
  // moves the bodies after it has built its table)
  world.engine.phases.find(([name]) => name === "collide")[1].apply(null, world.arrays);
  const a = world.a, n = world.count();
  const buckets = world.meta("gridBuckets"), cell = world.meta("cellSize");
  const cells = Array.from({ length: n }, (_, i) => [0, 1, 2].map((d) => Math.floor(a.pos[3 * i + d] / cell)));

  const scan = (size) => {
    const table = new Map();
    cells.forEach((c, i) => { const b = bucketOf(size, c); if (!table.has(b)) table.set(b, []); table.get(b).push(i); });
    let read = 0, inCells = 0;
    for (const c of cells)
      for (let dx = -1; dx <= 1; dx++) for (let dy = -1; dy <= 1; dy++) for (let dz = -1; dz <= 1; dz++) {
        const nc = [c[0] + dx, c[1] + dy, c[2] + dz];
        for (const j of table.get(bucketOf(size, nc)) || []) { read++; if (same(cells[j], nc)) inCells++; }
      }
    return { table, read: read / n, inCells: inCells / n };
  };

  const engine = scan(buckets);
  for (let b = 0; b < buckets; b++) {
    const count = a.grid[b] - a.grid[buckets + b]; // end, start
    const mine = (engine.table.get(b) || []).length;
    if (count !== mine) { console.error(`${f}: bucket ${b} holds ${count} bodies in the engine, ${mine} here: the engine's hash has changed`); process.exit(1); }
  }
  const result = { space: scene.space, bodies: n, steps, cellSize: cell, bucketsPerBody: buckets / n, readPerBody: engine.read, inCellsPerBody: engine.inCells };
  for (const per of [2, 4]) result["readPerBodyWith" + per] = scan(Math.min(Math.max(per * n, 1), 65536)).read;
  console.log(JSON.stringify(result));
}
