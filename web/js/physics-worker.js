// The physics worker: steps one world whose arrays live in shared memory
// (World.share, web/js/world.js) by the clock, with the same generated
// engine as the page (web/gen), and publishes what a frame draws after each
// batch of steps. The main thread keeps the world's bodies, input and
// drawing; the protocol (lock, snapshots, shared clock) is SHARED and CLOCK
// in web/js/world.js. Messages in: {type: "attach", id, scripts, space,
// arrays, snapshots, control, counts} and {type: "detach"}; out:
// {type: "failed", id, message} when a step throws.
/* global importScripts */
importScripts("world.js");

(function (G) {
  "use strict";
  const MWW = G.ManifoldWeb.world, SHARED = MWW.SHARED, CLOCK = MWW.CLOCK;
  // how long the worker sleeps when the clock is paused or no step is due (ms)
  const IDLE_MS = 8;
  /** @type {Set<string>} */
  const loaded = new Set();

  /**
   * @typedef {object} Stepped
   * @property {number} id
   * @property {Manifold.Engine} engine
   * @property {Float64Array[]} arrays
   * @property {Record<string, Float64Array>} byName
   * @property {ManifoldWeb.View[]} snapshots
   * @property {Int32Array} control
   * @property {Float64Array} counts
   * @property {number} generation
   * @property {number} back the snapshot buffer the worker writes
   */
  /** @type {Stepped | null} */
  let world = null;
  const clock = new MWW.Clock();
  clock.maxMsPerFrame = 50;
  /** @type {ReturnType<typeof setTimeout> | null} */
  let timer = null;

  /** @param {number} ms */
  function schedule(ms) {
    if (timer !== null) clearTimeout(timer);
    timer = setTimeout(tick, ms);
  }

  // The lock, unless the main thread wants it (then it waits for the main
  // thread to be done, at most IDLE_MS, and tries again later).
  /** @param {Int32Array} c */
  function acquire(c) {
    if (Atomics.load(c, SHARED.WANT) !== 0) {
      Atomics.wait(c, SHARED.WANT, 1, IDLE_MS);
      return false;
    }
    return Atomics.compareExchange(c, SHARED.LOCK, 0, SHARED.WORKER) === 0;
  }

  /** @param {Stepped} w */
  function publish(w) {
    const E = w.engine;
    if (E.countIslands) E.countIslands.apply(null, w.arrays);
    MWW.copyView(E, /** @type {ManifoldWeb.View} */ (/** @type {unknown} */ (w.byName)), w.snapshots[w.back]);
    w.back = Atomics.exchange(w.control, SHARED.MIDDLE, w.back | SHARED.FRESH) & 3;
  }

  function tick() {
    timer = null;
    const w = world;
    if (!w) return;
    const c = w.control;
    if (Atomics.load(c, SHARED.GENERATION) !== w.generation) return;  // new arrays come by message
    if (!Atomics.load(c, SHARED.RUNNING)) {
      clock.reset();
      schedule(IDLE_MS);
      return;
    }
    if (!acquire(c)) {
      schedule(0);
      return;
    }
    let next = 0;
    try {
      if (Atomics.load(c, SHARED.GENERATION) !== w.generation) return;
      const E = w.engine, dt = w.byName.params[E.params.dt];
      const count = w.byName.meta[E.meta.bodyCount];
      clock.timeScale = w.counts[CLOCK.TIME_SCALE];
      const stepMs = w.counts[CLOCK.STEP_MS];
      const n = count > 0 ? clock.due(performance.now(), dt, isNaN(stepMs) ? null : stepMs) : 0;
      let k = 0;
      const t0 = performance.now();
      while (k < n && Atomics.load(c, SHARED.WANT) === 0) {
        E.step.apply(null, w.arrays);
        k++;
      }
      if (k > 0) {
        const per = (performance.now() - t0) / k;
        w.counts[CLOCK.STEP_MS] = isNaN(stepMs) ? per : stepMs + (per - stepMs) * Math.min(1, k / 20);
        w.counts[CLOCK.STEPS] += k;
        publish(w);
      }
      // the next step is due about a step's simulated time later
      if (k === n) next = Math.min(IDLE_MS, 1000 * dt / Math.max(clock.timeScale, 1e-3) / 2);
    } catch (err) {
      G.postMessage({ type: "failed", id: w.id, message: String(err && /** @type {Error} */ (err).message || err) });
      world = null;
      return;
    } finally {
      Atomics.store(c, SHARED.LOCK, 0);
    }
    schedule(next);
  }

  G.onmessage = function (/** @type {MessageEvent} */ e) {
    const m = e.data;
    if (m.type === "detach") {
      world = null;
      return;
    }
    if (m.type !== "attach") return;
    m.scripts.forEach(function (/** @type {string} */ src) {
      if (!loaded.has(src)) {
        importScripts(src);
        loaded.add(src);
      }
    });
    const engine = G.Manifold.spaces[m.space].engine;
    /** @type {Record<string, Float64Array>} */
    const byName = {};
    engine.arrays.forEach(function (/** @type {string} */ n, /** @type {number} */ i) { byName[n] = m.arrays[i]; });
    world = {
      id: m.id, engine: engine, arrays: m.arrays, byName: byName, snapshots: m.snapshots,
      control: m.control, counts: m.counts, generation: m.generation, back: 0,
    };
    clock.reset();
    schedule(0);
  };
})(/** @type {any} */ (globalThis));
