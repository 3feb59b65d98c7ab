// The peer benchmark's scenes, engines and measurements, as one classic
// script that runs unchanged under node (bench/peers.mjs loads it with
// vm.runInThisContext) and in the page (served to it as /peers/engines.js):
// the rectangle read off the generated space, the pyramid and the pile in
// its plane, one adapter per engine (Manifold's World of web/js/world.js,
// Rapier 2D, planck.js, matter.js) that builds a scene and steps it, and the
// runner that times every step and measures the scene at the end. The
// engines are the globals Manifold + ManifoldWeb, RAPIER (initialised),
// planck and Matter. Defines globalThis.ManifoldPeers.
(function (G) {
  "use strict";

  // ---- Manifold's knobs: the scene keys these scenes set, in one place ----------------
  // Everything else is the generated engine's default (Manifold.sceneKeys,
  // from Lib/Manifold/Params.hs), so the benchmark follows the engine's
  // parameters as they change; a key the generated engine does not know is
  // left out rather than refused. dt and gravity come from the scene.
  // Sleeping is off, as for every peer: a resting pyramid asleep costs
  // nothing a step and would time no solver at all.
  const MANIFOLD_KEYS = { friction: 0.6, restitution: 0, sleep: false };

  // ---- the peers' knobs: what every peer gets; the rest is its own default ---------------
  const FRICTION = 0.6, RESTITUTION = 0, DENSITY = 1;
  // Each peer's home scale, for --units home: how many of its length units a
  // box half-side is in its own examples (Box2D's, planck's and Rapier's
  // 1 m boxes; matter.js's 40 px ones). Lengths and gravity are scaled
  // together and dt kept, so g·dt²/h, and the motion in units of the box,
  // are the same as in Manifold's units.
  const HOME_HALF_SIDE = { rapier: 0.5, planck: 0.5, matter: 20 };

  // ---- the rectangle, read off the generated space -----------------------------------------
  // Lib/Manifold/Spaces.hs: the plane y = 0 with the boundary
  // min(1.5 − |x|, 1 − |z|) ≥ 0 and uniform gravity (0, 0, −4). Read from the
  // generated functions and checked, so that a changed space stops the
  // benchmark instead of comparing another world: { halfWidth, halfHeight, gravity }.
  function rectangle(space) {
    const g = space.gravity(0, 0, 0);
    const fail = (what) => { throw new Error("the rectangle is no longer " + what + ": the peers' world must change with it"); };
    [[0.3, 0, -0.2], [-1, 0, 0.7]].forEach(function (p) {
      if (space.field(p[0], p[1], p[2]) !== 0) fail("the plane y = 0");
      const q = space.gravity(p[0], p[1], p[2]);
      if (q[0] !== g[0] || q[1] !== g[1] || q[2] !== g[2]) fail("under uniform gravity");
    });
    if (g[0] !== 0 || g[1] !== 0 || !(g[2] < 0)) fail("under gravity along −z");
    const root = function (f) { // the boundary's zero along one axis, by bisection
      let lo = 0, hi = space.bounds;
      for (let k = 0; k < 200; k++) { const m = (lo + hi) / 2; if (f(m) > 0) lo = m; else hi = m; }
      return (lo + hi) / 2;
    };
    const halfWidth = root(function (x) { return space.boundary(x, 0, 0); });
    const halfHeight = root(function (z) { return space.boundary(0, 0, z); });
    for (let x = -1.4; x <= 1.4; x += 0.35) {
      for (let z = -0.9; z <= 0.9; z += 0.3) {
        const want = Math.min(halfWidth - Math.abs(x), halfHeight - Math.abs(z));
        if (Math.abs(space.boundary(x, 0, z) - want) > 1e-9) fail("a box |x| ≤ " + halfWidth + ", |z| ≤ " + halfHeight);
      }
    }
    return { halfWidth: halfWidth, halfHeight: halfHeight, gravity: -g[2] };
  }

  // ---- scenes (in the rectangle's plane: x across, y = Manifold's z, up) -------------------
  // Box2D's pyramid benchmark: 1 m boxes (h = 0.5) under g = 10 at 60 Hz.
  const BOX2D = { g: 10, dt: 1 / 60, h: 0.5 };
  // The pyramid's step: g·dt²/h as Box2D's (1/180) fixes h once dt is
  // chosen; at dt = 1/300 under g = 4, h = 0.008, and 100 rows (1.6 high and
  // wide) fit the rectangle (3 wide, 2 high).
  const PYRAMID_DT = 1 / 300;
  function pyramidHalfSide(g) { return g * PYRAMID_DT * PYRAMID_DT * BOX2D.h / (BOX2D.g * BOX2D.dt * BOX2D.dt); }

  // R rows of square boxes, row k (from the floor) of R − k boxes, sides touching.
  function pyramid(box, rows) {
    const h = pyramidHalfSide(box.gravity), bodies = [];
    if (2 * h * rows > 2 * Math.min(box.halfWidth, box.halfHeight)) throw new Error(rows + " rows of boxes of side " + 2 * h + " do not fit the rectangle");
    for (let k = 0; k < rows; k++) {
      for (let i = 0; i < rows - k; i++) {
        bodies.push({ shape: "box", half: h, x: (2 * i - (rows - k - 1)) * h, y: -box.halfHeight + h + 2 * h * k, angle: 0 });
      }
    }
    return { kind: "pyramid", name: "pyramid " + rows, rows: rows, unit: h, dt: PYRAMID_DT, box: box, bodies: bodies };
  }

  // Deterministic pseudo-random numbers in [0, 1) (web/js/world.js's generator).
  function random(seed) {
    let s = seed >>> 0;
    return function () {
      s = (Math.imul(s, 1664525) + 1013904223) >>> 0;
      return s / 4294967296;
    };
  }

  // n bodies, circles (even-numbered) and square boxes in turn, of the size
  // `manifold bench` gives n bodies in the rectangle (Lib/Manifold/Bench.hs:
  // they cover a third of it; a size is the circumradius, a circle's radius),
  // on a seeded jittered grid from the top down, at random angles, dropped
  // from rest; dt is Manifold's default.
  function pile(box, n, dt) {
    const s = Math.sqrt(4 * box.halfWidth * box.halfHeight / (3 * n * ((Math.PI + 2) / 2)));
    const gap = 2.5 * s, cols = Math.floor((2 * box.halfWidth - gap) / gap) + 1;
    const rnd = random(20261201), bodies = [];
    for (let i = 0; i < n; i++) {
      const row = Math.floor(i / cols), col = i % cols;
      const x = -box.halfWidth + gap / 2 + col * gap + (rnd() - 0.5) * 0.4 * s;
      const y = box.halfHeight - gap / 2 - row * gap + (rnd() - 0.5) * 0.4 * s;
      if (y < -box.halfHeight + gap / 2) throw new Error(n + " bodies of size " + s + " do not fit the rectangle");
      const angle = 2 * Math.PI * rnd();
      bodies.push(i % 2 === 0 ? { shape: "circle", r: s, x: x, y: y, angle: angle } : { shape: "box", half: s / Math.SQRT2, x: x, y: y, angle: angle });
    }
    return { kind: "pile", name: "pile " + n, unit: s, dt: dt, box: box, bodies: bodies };
  }

  // The rectangle's walls for a peer: four static boxes of thickness T
  // outside it (centre x, y and half-extents).
  function walls(box) {
    const T = 1, w = box.halfWidth, h = box.halfHeight;
    return [
      { x: 0, y: -h - T / 2, hx: w + T, hy: T / 2 }, { x: 0, y: h + T / 2, hx: w + T, hy: T / 2 },
      { x: -w - T / 2, y: 0, hx: T / 2, hy: h + T }, { x: w + T / 2, y: 0, hx: T / 2, hy: h + T },
    ];
  }

  // ---- the engines: make(scene, k) → { step(), position(i) → [x, y], about } ----------------
  // k: the peer's length units per Manifold unit (1, or its home scale).
  const engines = {};

  // Manifold: the scene as scene JSON (docs/scenes.md), read by the page's
  // own reader (parseScene) into a World on the generated engine; a square's
  // size is its circumradius; Manifold's angle turns from x towards −z.
  engines.manifold = {
    make: function (scene) {
      const M = G.Manifold, W = G.ManifoldWeb.world, space = M.spaces.rectangle;
      const known = M.sceneKeys ? M.sceneKeys.map(function (k) { return k.key; }) : ["dt", "friction", "restitution"];
      const json = { space: "rectangle" };
      const wanted = Object.assign({ dt: scene.dt }, MANIFOLD_KEYS);
      Object.keys(wanted).forEach(function (k) { if (known.indexOf(k) >= 0) json[k] = wanted[k]; });
      if (json.dt !== scene.dt) throw new Error("the generated engine has no scene key dt");
      json.bodies = scene.bodies.map(function (b) {
        return { shape: b.shape === "box" ? "square" : "circle", size: b.shape === "box" ? b.half * Math.SQRT2 : b.r,
          density: DENSITY, p: [b.x, 0, b.y], angle: -b.angle };
      });
      const world = new W.World("rectangle", space);
      world.load(W.parseScene(json, Object.keys(M.spaces)));
      const E = world.engine, args = world.arrays, pos = world.a.pos;
      const params = {};
      (M.sceneKeys || []).forEach(function (k) { params[k.key] = world.param(k.param); });
      return {
        step: function () { E.step.apply(null, args); },
        position: function (i) { return [pos[3 * i], pos[3 * i + 2]]; },
        about: function () { return { sceneKeys: params, engineDefaults: E.defaults, counters: world.counters() }; },
      };
    },
  };

  // Rapier 2D (@dimforge/rapier2d-compat): one fixed body holding the walls'
  // colliders, a dynamic body with one collider per body.
  engines.rapier = {
    make: function (scene, k) {
      const R = G.RAPIER, box = scene.box;
      const world = new R.World({ x: 0, y: -box.gravity * k });
      world.timestep = scene.dt;
      const fixed = world.createRigidBody(R.RigidBodyDesc.fixed());
      walls(box).forEach(function (w) {
        world.createCollider(R.ColliderDesc.cuboid(w.hx * k, w.hy * k).setTranslation(w.x * k, w.y * k)
          .setFriction(FRICTION).setRestitution(RESTITUTION), fixed);
      });
      const bodies = scene.bodies.map(function (b) {
        const rb = world.createRigidBody(R.RigidBodyDesc.dynamic().setTranslation(b.x * k, b.y * k).setRotation(b.angle).setCanSleep(false));
        const shape = b.shape === "box" ? R.ColliderDesc.cuboid(b.half * k, b.half * k) : R.ColliderDesc.ball(b.r * k);
        world.createCollider(shape.setDensity(DENSITY).setFriction(FRICTION).setRestitution(RESTITUTION), rb);
        return rb;
      });
      return {
        step: function () { world.step(); },
        position: function (i) { const t = bodies[i].translation(); return [t.x / k, t.y / k]; },
        about: function () { return { solverIterations: world.numSolverIterations, lengthUnit: world.lengthUnit }; },
        free: function () { world.free(); },
      };
    },
  };

  // planck.js: a static body with the walls' fixtures, a dynamic body with one fixture per body.
  engines.planck = {
    make: function (scene, k) {
      const P = G.planck, box = scene.box;
      const world = new P.World({ gravity: { x: 0, y: -box.gravity * k }, allowSleep: false });
      const ground = world.createBody();
      walls(box).forEach(function (w) {
        ground.createFixture(new P.Box(w.hx * k, w.hy * k, { x: w.x * k, y: w.y * k }, 0), { friction: FRICTION, restitution: RESTITUTION });
      });
      const bodies = scene.bodies.map(function (b) {
        const body = world.createBody({ type: "dynamic", position: { x: b.x * k, y: b.y * k }, angle: b.angle, allowSleep: false });
        body.createFixture(b.shape === "box" ? new P.Box(b.half * k, b.half * k) : new P.Circle(b.r * k),
          { density: DENSITY, friction: FRICTION, restitution: RESTITUTION });
        return body;
      });
      return {
        step: function () { world.step(scene.dt); },
        position: function (i) { const p = bodies[i].getPosition(); return [p.x / k, p.y / k]; },
        about: function () { return {}; },
      };
    },
  };

  // matter.js: y points down (its screen coordinates), time is in ms and
  // gravity is gravity.y × gravity.scale in length units per ms².
  engines.matter = {
    make: function (scene, k) {
      const M = G.Matter, box = scene.box;
      const engine = M.Engine.create({ enableSleeping: false, gravity: { x: 0, y: 1, scale: box.gravity * k / 1e6 } });
      const opts = function (o) { return Object.assign({ friction: FRICTION, restitution: RESTITUTION }, o); };
      const all = walls(box).map(function (w) {
        return M.Bodies.rectangle(w.x * k, -w.y * k, 2 * w.hx * k, 2 * w.hy * k, opts({ isStatic: true }));
      });
      const bodies = scene.bodies.map(function (b) {
        const o = opts({ density: DENSITY, angle: -b.angle });
        return b.shape === "box" ? M.Bodies.rectangle(b.x * k, -b.y * k, 2 * b.half * k, 2 * b.half * k, o) : M.Bodies.circle(b.x * k, -b.y * k, b.r * k, o);
      });
      M.Composite.add(engine.world, all.concat(bodies));
      const ms = scene.dt * 1000;
      const circle = bodies.find(function (b, i) { return scene.bodies[i].shape === "circle"; });
      return {
        step: function () { M.Engine.update(engine, ms); },
        position: function (i) { const p = bodies[i].position; return [p.x / k, -p.y / k]; },
        about: function () {
          return { positionIterations: engine.positionIterations, velocityIterations: engine.velocityIterations,
            slop: bodies[0].slop, frictionAir: bodies[0].frictionAir, circleSides: circle ? circle.vertices.length : null };
        },
      };
    },
  };

  // ---- measuring ------------------------------------------------------------------------------
  // A run: `steps` steps of the scene, each timed; the second half's steps
  // are the timed ones (the first half is the warm-up: the JIT, and a pile
  // forming). units: "manifold" or "home" (peers only).
  function start(engine, scene, seconds, units) {
    const k = engine === "manifold" || units !== "home" ? 1 : HOME_HALF_SIDE[engine] / scene.unit;
    const steps = Math.max(2, Math.round(seconds / scene.dt));
    const run = { engine: engine, scene: scene.name, kind: scene.kind, bodies: scene.bodies.length, dt: scene.dt, unit: scene.unit,
      units: engine === "manifold" ? "manifold" : units, scale: k, steps: steps, done: 0, times: new Float64Array(steps), spec: scene };
    try {
      run.sim = engines[engine].make(scene, k);
    } catch (e) {
      run.refused = e.message; // e.g. more bodies than Manifold's world holds
      return run;
    }
    run.start = scene.bodies.map(function (b, i) { return run.sim.position(i); });
    return run;
  }

  // Steps the run for about `ms` milliseconds of wall time; true when done.
  function advance(run, ms) {
    if (run.refused) return true;
    const until = performance.now() + ms, sim = run.sim, times = run.times;
    while (run.done < run.steps) {
      const t0 = performance.now();
      sim.step();
      const t1 = performance.now();
      times[run.done++] = t1 - t0;
      if (t1 > until) break;
    }
    return run.done >= run.steps;
  }

  function quantile(xs, q) {
    const s = Array.from(xs).sort(function (a, b) { return a - b; });
    return s[Math.min(s.length - 1, Math.floor(q * s.length))];
  }

  // How far touching circles overlap: r1 + r2 − |p1 − p2| over the radius,
  // for every pair of circles that overlaps (as bench/pile.mjs measures it).
  function circleOverlaps(scene, at) {
    const cell = 4 * scene.unit, grid = new Map(), circles = [];
    scene.bodies.forEach(function (b, i) { if (b.shape === "circle") circles.push(i); });
    const key = function (p) { return Math.floor(p[0] / cell) + "," + Math.floor(p[1] / cell); };
    circles.forEach(function (i) { const kk = key(at[i]); if (!grid.has(kk)) grid.set(kk, []); grid.get(kk).push(i); });
    let sum = 0, count = 0, worst = 0;
    circles.forEach(function (i) {
      const cx = Math.floor(at[i][0] / cell), cy = Math.floor(at[i][1] / cell);
      for (let dx = -1; dx <= 1; dx++) {
        for (let dy = -1; dy <= 1; dy++) {
          (grid.get((cx + dx) + "," + (cy + dy)) || []).forEach(function (j) {
            if (j <= i) return;
            const r1 = scene.bodies[i].r, r2 = scene.bodies[j].r;
            const overlap = (r1 + r2 - Math.hypot(at[i][0] - at[j][0], at[i][1] - at[j][1])) / Math.min(r1, r2);
            if (overlap > 0) { sum += overlap; count++; worst = Math.max(worst, overlap); }
          });
        }
      }
    });
    return { circleOverlapMean: count ? sum / count : 0, circleOverlapMax: worst, overlappingCirclePairs: count, circles: circles.length };
  }

  // The run's result: step times over the timed half, and the scene's state at the end.
  function finish(run) {
    const out = { engine: run.engine, scene: run.scene, kind: run.kind, bodies: run.bodies, dt: run.dt, unit: run.unit,
      units: run.units, scale: run.scale, steps: run.steps, seconds: run.steps * run.dt };
    if (run.refused) { out.refused = run.refused; return out; }
    const timed = run.times.subarray(Math.floor(run.steps / 2));
    out.timedSteps = timed.length;
    out.medianMs = quantile(timed, 0.5);
    out.p10Ms = quantile(timed, 0.1);
    out.p90Ms = quantile(timed, 0.9);
    out.meanMs = timed.reduce(function (a, b) { return a + b; }, 0) / timed.length;
    out.usPerBodyStep = 1000 * out.medianMs / run.bodies;
    out.totalMs = run.times.reduce(function (a, b) { return a + b; }, 0);
    const scene = run.spec, at = scene.bodies.map(function (b, i) { return run.sim.position(i); });
    out.finite = at.every(function (p) { return isFinite(p[0]) && isFinite(p[1]); });
    if (run.kind === "pyramid") {
      // stands: no box moved sideways by more than half its half-side, and
      // the top box rose or fell by less than two half-sides
      const h = scene.unit, top = at.length - 1;
      let sideways = 0;
      at.forEach(function (p, i) { sideways = Math.max(sideways, Math.abs(p[0] - run.start[i][0])); });
      out.maxSidewaysHalfSides = out.finite ? sideways / h : Infinity;
      out.topRiseHalfSides = out.finite ? (at[top][1] - run.start[top][1]) / h : -Infinity;
      out.stands = out.maxSidewaysHalfSides <= 0.5 && Math.abs(out.topRiseHalfSides) < 2;
    } else {
      Object.assign(out, circleOverlaps(scene, at));
      // bodies that left the rectangle (through a wall, or tunnelled)
      out.outside = at.filter(function (p) { return !(Math.abs(p[0]) <= scene.box.halfWidth && Math.abs(p[1]) <= scene.box.halfHeight); }).length;
    }
    out.about = run.sim.about();
    if (run.sim.free) run.sim.free();
    return out;
  }

  // The scenes by name ("pyramid R", "pile N"), in the rectangle of the generated space.
  function scene(name) {
    const box = rectangle(G.Manifold.spaces.rectangle), parts = name.split(" "), n = Number(parts[1]);
    if (parts[0] === "pyramid") return pyramid(box, n);
    const dt = G.Manifold.sceneKeys ? G.Manifold.sceneKeys.find(function (k) { return k.key === "dt"; }).default : 0.01;
    return pile(box, n, dt);
  }

  G.ManifoldPeers = {
    MANIFOLD_KEYS: MANIFOLD_KEYS, HOME_HALF_SIDE: HOME_HALF_SIDE, BOX2D: BOX2D, PYRAMID_DT: PYRAMID_DT,
    engines: Object.keys(engines), rectangle: rectangle, scene: scene, start: start, advance: advance, finish: finish,
    runs: [], // the page's runs, by index (bench/peers.mjs drives them one evaluate at a time)
  };
})(globalThis);
