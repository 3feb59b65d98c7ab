// Erin Catto's Solver2D scenes (erincatto/solver2d's samples: their numbers,
// not their code) rebuilt in the scene format on the plane, at the
// sandbox's scale: 1 m becomes 0.05 units and the step keeps Box2D's
// g·dt²/h at 60 Hz (dt = (1/60)·√(10·0.05/4), gravity here being 4), so
// that 10 s of Box2D are 600 steps. Each scene runs natively (`manifold sim`)
// and in the page's engine under node (web/gen, web/js/world.js), and is
// judged by what Box2D v3 does with it, in Box2D's units; prints a line a
// scene and engine: pass or fail, and the numbers judged.
//
//   node bench/solver2d.mjs [--scenes a,b] [--manifold EXE] [--squares] [--json]
//                           [--box2d-hertz H] [--params JSON] [--scale K] [--boxes N]
//                           [--trace FROM:TO]
//
// --scale K puts K units in a metre instead of 0.05 (the step still keeps
// g·dt²/h: dt = (1/60)·√(10·K/4)), to see whether a scene behaves alike at
// every scale. --boxes N stacks N boxes in the vertical stack instead of 15;
// its height is then judged by Solver2D's 0.1 scaled by (N/15)², as a stack
// of springs sags (Box2D v3's own stacks sag 0.07 with 15 boxes, 0.30 with
// 30: bench/box2d/vertical-stack.c, BOXES=30). --trace FROM:TO prints, for
// each step from FROM to TO of the page's run, a line a movable body: step,
// body, x, y, angle, vx, vy in Box2D's units (the format of
// bench/box2d/high-mass-ratio.c's trace, to compare the two step by step).
//
// --squares builds the stacking scenes (vertical stack, large pyramid) of
// squares, which collide by their sampled outlines, instead of boxes.
// --box2d-hertz H sets the contacts' frequency as Box2D's H in Box2D's time
// (H / TIME here: 20 is 56.6 Hz), to compare with bench/box2d/vertical-stack.c
// at the same stiffness; --params adds scene keys to every scene
// ('{"sleep": false}').
// Needs web/gen (`manifold build --out web/gen`).
import fs from "node:fs";
import os from "node:os";
import path from "node:path";
import { execFileSync } from "node:child_process";
import { loadSpace } from "./worlds.mjs";
import { commandLine } from "./options.mjs";

const USAGE = "node bench/solver2d.mjs [--scenes a,b] [--manifold EXE] [--squares] [--json] [--box2d-hertz H] [--params JSON] [--scale K] [--boxes N] [--trace FROM:TO]";
const line = commandLine({
  usage: USAGE,
  known: ["--scenes", "--manifold", "--box2d-hertz", "--params", "--scale", "--boxes", "--trace"], flags: ["--squares", "--json"],
});
const exe = line.text("--manifold", process.env.MANIFOLD_EXE || "manifold");
const squares = line.flag("--squares"), json = line.flag("--json");
const box2dHertz = line.positive("--box2d-hertz", null);
const SCALE = line.positive("--scale", 0.05), BOXES = line.count("--boxes", 15, 1);
const traceText = line.text("--trace", "0:-1"), traceMatch = /^(\d+):(\d+)$/.exec(traceText);
if (traceText !== "0:-1" && (!traceMatch || Number(traceMatch[1]) > Number(traceMatch[2]))) {
  console.error("--trace must be FROM:TO, two step numbers, FROM at most TO (not " + JSON.stringify(traceText) + ")\nusage: " + USAGE);
  process.exit(2);
}
const [traceFrom, traceTo] = traceMatch ? [Number(traceMatch[1]), Number(traceMatch[2])] : [1, 0];
let extraKeys = {};
try {
  extraKeys = JSON.parse(line.text("--params", "{}"));
} catch (err) {
  extraKeys = null;
}
if (extraKeys === null || typeof extraKeys !== "object" || Array.isArray(extraKeys)) {
  console.error("--params must be a JSON object of scene keys, such as '{\"sleep\": false}'\nusage: " + USAGE);
  process.exit(2);
}

// Box2D's units to the sandbox's: lengths, times, speeds, angles (Box2D's
// turn x toward y, up; here up is +z and a positive angle turns x toward
// -z: the sign changes)
const TIME = Math.sqrt(10 * SCALE / 4), DT = TIME / 60;
const STEPS_10S = 600;
const at = (x, y) => [SCALE * x, 0, SCALE * y];
const box = (hx, hy) => ({ box: [SCALE * hx, SCALE * hy] });
const speedOf = (b) => Math.hypot(b.v[0], b.v[1], b.v[2]) * TIME / SCALE;
const xOf = (b) => b.p[0] / SCALE, yOf = (b) => b.p[2] / SCALE, angleOf = (b) => -b.angle;
const ground = { shape: box(100, 1), static: true, p: at(0, -1) };
// a square box of half-side h, as a box or (--squares) as a square
const cube = (h) => (squares ? { shape: "square", size: SCALE * h * Math.SQRT2 } : { shape: box(h, h) });

const SCENES = {
  "vertical-stack": {
    steps: STEPS_10S,
    scene: () => ({ bodies: [ground].concat(Array.from({ length: BOXES }, (_, i) =>
      Object.assign(cube(0.5), { friction: 0.3, p: at(i % 2 === 0 ? -0.01 : 0.01, 0.5 + i) }))) }),
    // the top box: |Δx| < 0.25, y 14.5 ± 0.1 (N − 0.5 ± 0.1·(N/15)² for N boxes), speed < 0.05
    judge: (frames) => {
      const first = frames[0].bodies[BOXES], top = frames[frames.length - 1].bodies[BOXES];
      const dx = Math.abs(xOf(top) - xOf(first)), y = yOf(top), v = speedOf(top);
      return { pass: dx < 0.25 && Math.abs(y - (BOXES - 0.5)) < 0.1 * (BOXES / 15) ** 2 && v < 0.05, dx, y, speed: v };
    },
  },
  "large-pyramid": {
    steps: STEPS_10S,
    scene: () => {
      const bodies = [ground];
      for (let i = 0; i < 100; i++) {
        for (let j = i; j < 100; j++) bodies.push(Object.assign(cube(0.5), { friction: 0.6, p: at(0.5 * (i + 1) + (j - i) - 50, 0.5 + i) }));
      }
      return { bodies };
    },
    // every |Δx| < 0.25, the top sinks < 1, every speed < 0.05
    judge: (frames) => {
      const a = frames[0].bodies, b = frames[frames.length - 1].bodies;
      let dx = 0, v = 0;
      for (let k = 1; k < b.length; k++) { dx = Math.max(dx, Math.abs(xOf(b[k]) - xOf(a[k]))); v = Math.max(v, speedOf(b[k])); }
      const sink = yOf(a[a.length - 1]) - yOf(b[b.length - 1]);
      return { pass: dx < 0.25 && sink < 1 && v < 0.05, dx, sink, speed: v };
    },
  },
  "high-mass-ratio-2": {
    steps: STEPS_10S,
    scene: () => ({ bodies: [ground,
      { shape: box(0.5, 0.5), friction: 0.6, p: at(-9, 0.5) }, { shape: box(0.5, 0.5), friction: 0.6, p: at(9, 0.5) },
      { shape: box(10, 10), friction: 0.6, p: at(0, 26) }] }),
    // the big box's centre y >= 10.85, tilt < 0.05
    judge: (frames) => {
      const big = frames[frames.length - 1].bodies[3];
      return { pass: yOf(big) >= 10.85 && Math.abs(angleOf(big)) < 0.05, y: yOf(big), tilt: angleOf(big) };
    },
  },
  "overlap-recovery": {
    steps: 120, every: 1,
    scene: () => {
      const bodies = [ground];
      for (let i = 0; i < 4; i++) {
        for (let j = 0; j < 4 - i; j++) bodies.push({ shape: box(0.5, 0.5), p: at(0.375 * (i - 4) + 0.75 * j, 0.5 + 0.75 * i) });
      }
      return { bodies };
    },
    // the top box at y 3.5 ± 0.05 within 2 s, the peak speed < 4
    judge: (frames) => {
      const top = frames[frames.length - 1].bodies[10];
      let peak = 0;
      for (const f of frames) for (let k = 1; k < f.bodies.length; k++) peak = Math.max(peak, speedOf(f.bodies[k]));
      return { pass: Math.abs(yOf(top) - 3.5) < 0.05 && peak < 4, y: yOf(top), peak };
    },
  },
  "double-domino": {
    steps: STEPS_10S,
    scene: () => {
      const bodies = [ground];
      for (let i = 0; i < 15; i++) bodies.push({ shape: box(0.125, 0.5), friction: 0.6, p: at(-7.5 + i, 0.5) });
      // the impulse (0.2, 0) at (-7.5, 1.0) on the first (density 1): its
      // velocity and spin, in the sandbox's units
      const m = 4 * 0.125 * 0.5, inertia = m * (0.125 * 0.125 + 0.5 * 0.5) / 3;
      bodies[1].v = [0.2 / m * SCALE / TIME, 0, 0];
      bodies[1].omega = -(-0.5 * 0.2 / inertia) / TIME;
      return { bodies };
    },
    // all 15 turned by more than 0.5 rad
    judge: (frames) => {
      const b = frames[frames.length - 1].bodies.slice(1);
      const least = Math.min.apply(null, b.map((x) => Math.abs(angleOf(x))));
      return { pass: least > 0.5, leastTurn: least };
    },
  },
  "friction-ramp": {
    steps: STEPS_10S,
    scene: () => {
      const ramp = (x, y, a) => ({ shape: box(13, 0.25), static: true, friction: 0.2, p: at(x, y), angle: -a });
      const bodies = [ground, ramp(-4, 22, -0.25), ramp(4, 14, 0.25), ramp(-4, 6, -0.25),
        { shape: box(0.25, 1), static: true, p: at(10.5, 19) }, { shape: box(0.25, 1), static: true, p: at(-10.5, 11) }];
      [0.75, 0.5, 0.35, 0.1, 0].forEach((mu, i) => bodies.push({ shape: box(0.5, 0.5), density: 25, friction: mu, p: at(-15 + 4 * i, 28) }));
      return { bodies };
    },
    // the boxes of friction 0.75 and 0.5 stop on the top ramp; 0.1 and 0 end below y = 10
    judge: (frames) => {
      const b = frames[frames.length - 1].bodies.slice(6).map(yOf);
      return { pass: b[0] > 18 && b[1] > 18 && b[3] < 10 && b[4] < 10, y: b };
    },
  },
  confined: {
    steps: STEPS_10S, gravity: false,
    scene: () => {
      const bodies = [
        { shape: box(11, 0.5), static: true, p: at(0, -0.5) }, { shape: box(11, 0.5), static: true, p: at(0, 21) },
        { shape: box(0.5, 11), static: true, p: at(-11, 10.25) }, { shape: box(0.5, 11), static: true, p: at(11, 10.25) }];
      for (let c = 0; c < 25; c++) for (let r = 0; r < 25; r++) bodies.push({ shape: "circle", size: SCALE * 0.5, p: at(-8.75 + 0.72 * c, 1.5 + 0.72 * r) });
      return { bodies };
    },
    // none leaves the walls; at rest at 10 s (every speed < 0.01)
    judge: (frames) => {
      const b = frames[frames.length - 1].bodies.slice(4);
      const out = b.filter((x) => Math.abs(xOf(x)) > 10.5 || yOf(x) < 0 || yOf(x) > 20.5).length;
      const v = Math.max.apply(null, b.map(speedOf));
      return { pass: out === 0 && v < 0.01, outside: out, speed: v };
    },
  },
};

const chosen = line.text("--scenes", Object.keys(SCENES).join(",")).split(",");
for (const name of chosen) if (!SCENES[name]) { console.error("no scene " + JSON.stringify(name) + "; the scenes are " + Object.keys(SCENES).join(", ")); process.exit(2); }

function sceneJSON(def) {
  const hertz = box2dHertz === null ? {} : { contactHertz: box2dHertz / TIME };
  return Object.assign({ space: "plane", dt: DT, gravity: def.gravity !== false }, hertz, extraKeys, def.scene());
}

// frames of { bodies: [{ p, v, angle, omega }] }: the first, then every `every` steps to `steps`
function native(file, def) {
  const out = execFileSync(exe, ["sim", file, "--steps", String(def.steps), "--every", String(def.every || def.steps)], { maxBuffer: 1 << 30 });
  return JSON.parse(out.toString()).frames;
}
function page(scene, def) {
  loadSpace("plane");
  const W = globalThis.ManifoldWeb.world;
  const world = new W.World("plane", globalThis.Manifold.spaces.plane);
  world.load(W.parseScene(scene, Object.keys(globalThis.Manifold.spaces)));
  const frames = [{ bodies: world.bodies() }], every = def.every || def.steps;
  for (let k = 1; k <= def.steps; k++) {
    world.step(1);
    if (k >= traceFrom && k <= traceTo) {
      world.bodies().forEach((b, i) => {
        if (scene.bodies[i].static) return;
        const v = [b.v[0], b.v[2]].map((c) => c * TIME / SCALE);
        console.log([k, i, xOf(b), yOf(b), angleOf(b), v[0], v[1]].map((x, j) => j < 2 ? x : x.toFixed(4)).join(" "));
      });
    }
    if (k % every === 0) frames.push({ bodies: world.bodies() });
  }
  return frames;
}

const dir = fs.mkdtempSync(path.join(os.tmpdir(), "solver2d-"));
const results = [];
for (const name of chosen) {
  const def = SCENES[name], scene = sceneJSON(def), file = path.join(dir, name + ".json");
  fs.writeFileSync(file, JSON.stringify(scene));
  for (const [engine, run] of [["native", () => native(file, def)], ["page", () => page(scene, def)]]) {
    const t0 = Date.now();
    const verdict = def.judge(run());
    const r = Object.assign({ scene: name, engine, bodies: scene.bodies.length, seconds: (Date.now() - t0) / 1000 }, verdict);
    results.push(r);
    if (!json) {
      const numbers = Object.entries(verdict).filter(([k]) => k !== "pass")
        .map(([k, v]) => k + " " + (Array.isArray(v) ? "[" + v.map((x) => x.toFixed(3)).join(", ") + "]" : typeof v === "number" ? Number(v.toPrecision(4)) : v)).join(", ");
      console.log((verdict.pass ? "pass " : "FAIL ") + name.padEnd(18) + engine.padEnd(7) + numbers + "  (" + r.seconds.toFixed(1) + " s)");
    }
  }
}
fs.rmSync(dir, { recursive: true, force: true });
if (json) console.log(JSON.stringify(results));
