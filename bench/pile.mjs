// How well the generated engine holds a pile: on scenes written by
// `manifold bench --scenes DIR`, run under node, after W steps: contact rows
// per body and per touching pair, how far circles overlap one another (a
// measure independent of how contacts are made: two circles overlap by
// r1 + r2 − |p1 − p2|), the pairs whose bounds overlap and the edge lookups
// their narrow phase makes, per body, and how many rows find last step's row of the same
// key for warm starting over the next 20 steps; by kind of pair (circles
// are a bench scene's even-numbered bodies), the touching pairs per body and
// the share of them with two rows. --mean M adds the rows per body averaged
// over the last M of the W steps; --slop F sets the engine's slop (a
// fraction of the smaller body's size), --substeps N and --iterations K the
// solver's sub-steps and its solves a sub-step, before the steps (what
// firmer contacts do to the rows, as `manifold bench` with the same flags).
// Usage: node bench/pile.mjs DIR [--steps W] [--mean M] [--slop F] [--substeps N] [--iterations K]   (JSON lines on stdout)
import { commandLine, worlds } from "./worlds.mjs";

const { dir, count, nonNegative } = commandLine("node bench/pile.mjs DIR [--steps W] [--mean M] [--slop F] [--substeps N] [--iterations K]",
  ["--steps", "--mean", "--slop", "--substeps", "--iterations"]);
const settle = count("--steps", 400, 0), meanOver = count("--mean", 0, 0), slop = nonNegative("--slop", 0);
const substeps = count("--substeps", 0, 0), iterations = count("--iterations", 0, 0); // 0: the scene's

for (const { scene, world } of worlds(dir)) {
  if (slop > 0) world.setParams({ slop });
  if (substeps > 0) world.setParams({ substeps });
  if (iterations > 0) world.setParams({ iterations });
  let rowSum = 0;
  for (let s = 0; s < settle; s++) {
    world.step(1);
    if (s >= settle - meanOver) rowSum += world.meta("contactCount");
  }
  const E = world.engine, C = E.contact, stride = E.contactStride, slots = world.stride();
  const a = world.a, n = world.count();

  const rows = () => {
    const out = [];
    for (let c = 0; c < world.meta("contactCount"); c++) {
      const at = (field) => a.contacts[c * stride + C[field]];
      out.push({ owner: at("cOwner"), key: at("cKey"), a: at("cA"), b: at("cB") });
    }
    return out;
  };
  // a pair (through one image) has one group of keys under its owner (E.keys, generated)
  const now = rows(), perPair = new Map();
  for (const r of now) if (r.b >= 0) {
    const p = r.owner + ":" + Math.floor(r.key / E.keys.perGroup);
    const kind = ["circleCircle", "circleSquare", "squareSquare"][(r.a % 2) + (r.b % 2)];
    const e = perPair.get(p) || { kind, rows: 0 };
    e.rows++;
    perPair.set(p, e);
  }
  const histogram = {}, byKind = {};
  for (const { kind, rows: m } of perPair.values()) {
    histogram[m] = (histogram[m] || 0) + 1;
    const k = byKind[kind] || (byKind[kind] = { pairsPerBody: 0, twoRowShare: 0 });
    k.pairsPerBody++;
    if (m === 2) k.twoRowShare++;
  }
  for (const k of Object.values(byKind)) { k.twoRowShare /= k.pairsPerBody; k.pairsPerBody /= n; }

  // circles are the even-numbered bodies of a bench scene
  const radius = (i) => a.scalars[i * slots + E.slots.boundRadius];
  const p3 = (i) => [a.pos[3 * i], a.pos[3 * i + 1], a.pos[3 * i + 2]];
  const cell = 4 * Math.max(...Array.from({ length: n }, (_, i) => radius(i))), grid = new Map();
  const key = (p) => p.map((x) => Math.floor(x / cell)).join(",");
  for (let i = 0; i < n; i += 2) { const kk = key(p3(i)); if (!grid.has(kk)) grid.set(kk, []); grid.get(kk).push(i); }
  let sum = 0, count = 0, worst = 0;
  for (let i = 0; i < n; i += 2) {
    const c = p3(i).map((x) => Math.floor(x / cell));
    for (let dx = -1; dx <= 1; dx++) for (let dy = -1; dy <= 1; dy++) for (let dz = -1; dz <= 1; dz++)
      for (const j of grid.get([c[0] + dx, c[1] + dy, c[2] + dz].join(",")) || []) {
        if (j <= i) continue;
        const pi = p3(i), pj = p3(j);
        const overlap = (radius(i) + radius(j) - Math.hypot(pi[0] - pj[0], pi[1] - pj[1], pi[2] - pj[2])) / radius(i);
        if (overlap > 0) { sum += overlap; count++; worst = Math.max(worst, overlap); }
      }
  }

  // the narrow phase's work: pairs whose bounding circles overlap (not
  // through an image), and the edge lookups they make (a vertex of either
  // body within the other's bounding radius)
  const ne = E.directions, ns = E.steps, per = E.verticesPerBody;
  const vertex = (i, d) => { const v = 3 * (per * i + E.vertexIndex(d, ns)); return [a.verts[v], a.verts[v + 1], a.verts[v + 2]]; };
  const dist2 = (p, q) => (p[0] - q[0]) ** 2 + (p[1] - q[1]) ** 2 + (p[2] - q[2]) ** 2;
  const reach = 2 * Math.max(...Array.from({ length: n }, (_, i) => radius(i))), near = new Map();
  const cellOf = (p) => p.map((x) => Math.floor(x / reach));
  for (let i = 0; i < n; i++) { const kk = cellOf(p3(i)).join(","); if (!near.has(kk)) near.set(kk, []); near.get(kk).push(i); }
  let candidates = 0, lookups = 0;
  for (let i = 0; i < n; i++) {
    const c = cellOf(p3(i));
    for (let dx = -1; dx <= 1; dx++) for (let dy = -1; dy <= 1; dy++) for (let dz = -1; dz <= 1; dz++)
      for (const j of near.get([c[0] + dx, c[1] + dy, c[2] + dz].join(",")) || []) {
        if (j <= i || dist2(p3(i), p3(j)) >= (radius(i) + radius(j)) ** 2) continue;
        candidates++;
        for (let d = 0; d < ne; d++) {
          if (dist2(vertex(i, d), p3(j)) < radius(j) ** 2) lookups++;
          if (dist2(vertex(j, d), p3(i)) < radius(i) ** 2) lookups++;
        }
      }
  }

  let hits = 0, total = 0, last = new Set(now.map((r) => r.owner + ":" + r.key));
  for (let s = 0; s < 20; s++) {
    world.step(1);
    const next = rows();
    for (const r of next) { total++; if (last.has(r.owner + ":" + r.key)) hits++; }
    last = new Set(next.map((r) => r.owner + ":" + r.key));
  }

  const result = {
    space: scene.space, bodies: n, steps: settle,
    rowsPerBody: now.length / n, rowsPerPair: histogram, pairsByKind: byKind,
    ...(meanOver > 0 ? { rowsPerBodyMean: rowSum / Math.min(meanOver, settle) / n } : {}),
    ...(slop > 0 ? { slop: world.param("slop") } : {}),
    ...(substeps > 0 ? { substeps: world.param("substeps") } : {}),
    ...(iterations > 0 ? { iterations: world.param("iterations") } : {}),
    candidatePairsPerBody: candidates / n, edgeLookupsPerBody: lookups / n,
    circleOverlapMean: count ? sum / count : 0, circleOverlapMax: worst, touchingCirclePairs: count,
    warmStartHits: total ? hits / total : 1,
  };
  console.log(JSON.stringify(result));
}
