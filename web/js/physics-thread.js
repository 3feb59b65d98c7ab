// Which thread steps the page's physics: the main thread, or the physics
// worker (web/js/physics-worker.js) when the page is cross-origin isolated
// (`manifold serve` sends COOP and COEP; a page opened from disk is not, and
// steps on the main thread). The setting is "auto" (the worker once the world
// holds AUTO_BODIES bodies: a step of a smaller world takes less than a
// frame's budget), "main" or "worker". Each frame the current world is moved
// into shared memory or out of it as the setting says, the worker is told
// the clock (paused, speed), and the newest snapshot it published is taken
// for drawing. The world itself, every change to it and window.manifold stay
// on the main thread (World.hold pauses the worker while they run).
/* exported ManifoldWebPhysicsThread */
var ManifoldWebPhysicsThread = (function (W) {
  "use strict";
  const MW = W.ManifoldWeb;
  const P = MW.page, state = P.state;
  const SHARED = MW.world.SHARED, CLOCK = MW.world.CLOCK;

  // "auto" steps a world of at least this many bodies in the worker
  const AUTO_BODIES = 1000;
  /** @type {ManifoldWeb.ThreadSetting[]} */
  const SETTINGS = ["auto", "main", "worker"];

  const thread = {
    /** @type {ManifoldWeb.ThreadSetting} */
    setting: "auto",
    /** @type {Worker | null} */
    worker: null,
    /** @type {ManifoldWeb.World | null} */
    world: null,       // the world the worker steps
    id: 0,             // the worker's current attachment
    /** @type {ManifoldWeb.World | null} */
    failed: null,      // a world whose step threw in the worker: it stays on the main thread
  };

  // Why the worker cannot step the physics here, or null.
  /** @returns {string | null} */
  function unavailable() {
    if (typeof W.Worker !== "function") return "this browser has no Web Workers";
    if (!W.crossOriginIsolated) return "the page is not cross-origin isolated (opened from disk, or served without the COOP and COEP headers `manifold serve` sends)";
    return null;
  }

  /** @param {ManifoldWeb.World} w */
  // Whether the setting hands world w to the worker (whether or not one can be had here).
  /** @param {ManifoldWeb.World} w */
  function asked(w) {
    if (thread.setting === "main") return false;
    // "auto" keeps a world the worker steps there (no back and forth about the threshold)
    return thread.setting === "worker" || w.shared !== null || w.viewCount() >= AUTO_BODIES;
  }

  // Whether the worker steps world w: asked for, and to be had.
  /** @param {ManifoldWeb.World} w */
  function wanted(w) {
    return !state.compare && thread.failed !== w && unavailable() === null && asked(w);
  }

  function theWorker() {
    if (thread.worker) return thread.worker;
    const worker = new W.Worker("js/physics-worker.js");
    worker.onmessage = function (e) {
      const m = e.data;
      if (m.type !== "failed" || m.id !== thread.id || !thread.world) return;
      const w = thread.world;
      thread.failed = w;
      stop();
      state.ui.showNotice("The physics worker stopped (" + m.message + "); the main thread steps the physics.");
    };
    worker.onerror = function (e) {
      thread.failed = thread.world;
      stop();
      state.ui.showNotice("The physics worker could not start (" + (e.message || "an error") + "); the main thread steps the physics.");
    };
    thread.worker = worker;
    return worker;
  }

  // Gives the worker world w's (new) shared arrays.
  /** @param {ManifoldWeb.World} w */
  function attach(w) {
    const s = w.shared, entry = P.entryOf(w.name);
    thread.world = w;
    thread.id++;
    const base = W.document.baseURI;
    theWorker().postMessage({
      type: "attach", id: thread.id, space: w.name,
      scripts: [new URL("gen/spaces.js", base).href, new URL("gen/" + entry.script, base).href],
      arrays: w.list, snapshots: s.snapshots, control: s.control, counts: w.counts,
      generation: Atomics.load(s.control, SHARED.GENERATION),
    });
  }

  // The worker lets go of its world: the page's world goes back to the main
  // thread; one the page has replaced is only left (its generation moves on,
  // so the worker takes no step more of it).
  function stop() {
    const w = thread.world;
    thread.world = null;
    if (thread.worker) thread.worker.postMessage({ type: "detach" });
    if (!w || !w.shared) return;
    if (w === state.world) w.share(false);
    else Atomics.add(w.shared.control, SHARED.GENERATION, 1);
  }

  // Once a frame, before it steps or draws (the worker steps while the
  // clock runs and no error is shown, as the frame would).
  function update() {
    const w = state.world;
    if (thread.world && thread.world !== w) stop();
    if (!w) return;
    if (w.shared && w.shared.unanswered && thread.worker) {
      // a worker that held the world past World.hold's patience: a new one for the next world, this one on the main thread
      thread.worker.terminate();
      thread.worker = null;
      thread.failed = w;
      stop();
      state.ui.showNotice("The physics worker stopped answering; the main thread steps the physics.");
    }
    const want = wanted(w);
    if (want && !w.shared) w.share(true, attach);
    else if (!want && w.shared) stop();
    if (!w.shared) return;
    Atomics.store(w.shared.control, SHARED.RUNNING, state.clock.paused || state.error ? 0 : 1);
    w.counts[CLOCK.TIME_SCALE] = state.clock.timeScale;
    w.takeSnapshot();
  }

  // A hidden page draws no frames, and on the main thread steps nothing;
  // the worker stops too (the next frame tells it the clock again).
  if (W.document) {
    W.document.addEventListener("visibilitychange", function () {
      const w = thread.world;
      if (W.document.hidden && w && w.shared) Atomics.store(w.shared.control, SHARED.RUNNING, 0);
    });
  }

  // Why `s` is no thread setting, or null.
  /** @param {unknown} s @returns {string | null} */
  function settingProblem(s) {
    return SETTINGS.indexOf(/** @type {ManifoldWeb.ThreadSetting} */ (s)) >= 0 ? null
      : "thread must be one of " + SETTINGS.map(function (x) { return JSON.stringify(x); }).join(", ");
  }

  // "auto", "main" or "worker" (see the top of this file).
  /** @param {unknown} s */
  function setSetting(s) {
    const why = settingProblem(s);
    if (why !== null) throw new RangeError(why);
    thread.setting = /** @type {ManifoldWeb.ThreadSetting} */ (s);
    thread.failed = null;
    update();
  }

  // which thread steps the current world now: "worker" or "main"
  /** @returns {"main" | "worker"} */
  function inUse() { return state.world && state.world.shared ? "worker" : "main"; }

  // What the stats line says of it: the worker; or the main thread and why,
  // where the worker was wanted (asked for, or a world as big as "auto"
  // hands it) and cannot be had here or failed; else null (nothing to say).
  /** @returns {string | null} */
  function describe() {
    if (inUse() === "worker") return "worker";
    const w = state.world;
    if (!w || state.compare || !asked(w)) return null;
    if (unavailable() !== null) return W.crossOriginIsolated ? "main thread, no workers" : "main thread, not isolated";
    return thread.failed !== null && thread.failed === w ? "main thread, the worker failed" : null;
  }

  const exported = {
    AUTO_BODIES: AUTO_BODIES,
    SETTINGS: SETTINGS,
    thread: thread,
    unavailable: unavailable,
    update: update,
    settingProblem: settingProblem,
    setSetting: setSetting,
    inUse: inUse,
    describe: describe,
  };
  W.ManifoldWeb = W.ManifoldWeb || /** @type {ManifoldWebModules} */ ({});
  W.ManifoldWeb.physicsThread = exported;
  return exported;
})(globalThis);
