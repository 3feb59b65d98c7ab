// The simulation's settings, all in this file: the clock (paused, speed) and
// the engine parameters the controls and window.manifold show and set
// (simulation(), setSimulation(), pause(), resume()), with the values
// setSimulation accepts, and the handlers of the controls that change them
// (Pause, Step, Speed, and one handler for every engine parameter's control).
// Which engine parameters are offered, their controls' labels, help and
// slider extents and the values they take are generated (Manifold.sceneKeys,
// from Lib/Manifold/Params.hs: the keys with a `control`); nothing here or in
// index.html names them.
/* exported ManifoldWebSimulationSettings */
var ManifoldWebSimulationSettings = (function (W) {
  "use strict";
  const MW = W.ManifoldWeb;
  const P = MW.page, state = P.state;

  // simulated time per real second that setSimulation accepts
  const TIME_SCALE = { lo: 0, hi: 10 };

  // The engine parameters offered, in the generated order (the order
  // simulation() lists them and the page shows their controls): the scene
  // keys with a control. A number's slider extent (control.lo … control.hi)
  // is only the slider's: setSimulation takes what the key's range takes.
  /** @returns {ManifoldWeb.ControlledKey[]} */
  function engineSettings() {
    const keys = (W.Manifold && W.Manifold.sceneKeys) || [];
    return /** @type {ManifoldWeb.ControlledKey[]} */ (keys.filter(function (k) { return !!k.control; }));
  }

  // {paused, timeScale, gravity, substeps, friction, …}: the clock and the
  // current world's parameters (without a world, a switch shows its default
  // and a number null).
  /** @returns {Manifold.Simulation} */
  function simulationSettings() {
    const w = state.world;
    /** @type {Record<string, boolean | number | string | null>} */
    const out = { paused: state.clock.paused, timeScale: state.clock.timeScale, thread: MW.physicsThread.thread.setting };
    engineSettings().forEach(function (k) {
      if (k.kind === "switch") out[k.key] = w ? w.param(k.param) > 0 : !!k.default;
      else out[k.key] = w ? w.param(k.param) : null;
    });
    return /** @type {Manifold.Simulation} */ (/** @type {unknown} */ (out));
  }

  // {paused, timeScale, gravity, substeps, friction, …}: any subset; throws on
  // bad values (an engine parameter's message is its scene key's, generated:
  // "friction must not be negative") and then changes nothing.
  /** @param {Manifold.SimulationChange} o @returns {Manifold.Simulation} */
  function setSimulation(o) {
    const settings = engineSettings();
    if (!o || typeof o !== "object") {
      throw new TypeError("setSimulation expects {" + ["paused", "timeScale", "thread"].concat(settings.map(function (k) { return k.key; })).join(", ") + "}");
    }
    const given = /** @type {Record<string, unknown>} */ (/** @type {unknown} */ (o));
    if (o.timeScale !== undefined) {
      const x = o.timeScale;
      if (typeof x !== "number" || !isFinite(x) || x < TIME_SCALE.lo || x > TIME_SCALE.hi) {
        throw new RangeError("timeScale must be a number from " + TIME_SCALE.lo + " to " + TIME_SCALE.hi);
      }
    }
    /** @type {ManifoldWeb.Params} */
    const p = {};
    settings.forEach(function (k) {
      const v = given[k.key];
      if (v === undefined) return;
      const why = MW.world.keyProblem(k, v);
      if (why !== null) throw new RangeError(k.key + " " + why);
      p[k.param] = k.kind === "switch" ? (v ? 1 : 0) : /** @type {number} */ (v);
    });
    const threadProblem = o.thread === undefined ? null : MW.physicsThread.settingProblem(o.thread);
    if (threadProblem !== null) throw new RangeError(threadProblem);
    if (Object.keys(p).length) P.requireWorld().setParams(p);
    if (o.timeScale !== undefined) state.clock.timeScale = o.timeScale;
    if (o.paused !== undefined) {
      state.clock.paused = !!o.paused;
      state.clock.reset();
      // a worker stepping the world hears of it now, not at the next frame:
      // paused, the world stays where pause() left it (its hash, its
      // picture), not a few steps on
      MW.physicsThread.update();
    }
    if (o.thread !== undefined) MW.physicsThread.setSetting(o.thread);
    const out = simulationSettings();
    state.ui.setSimulation(out);
    return out;
  }

  // The handlers of the simulation controls (ui.js's createUI).
  function controlHandlers() {
    const guarded = P.guarded;
    return {
      onPause: guarded(function () { setSimulation({ paused: !state.clock.paused }); }),
      onStep: guarded(function () { setSimulation({ paused: true }); P.requireWorld().step(1); }),
      onTimeScale: guarded(function (/** @type {number} */ x) { setSimulation({ timeScale: x }); }),
      onThread: guarded(function (/** @type {string} */ t) { setSimulation({ thread: /** @type {Manifold.ThreadSetting} */ (t) }); }),
      // an engine parameter's control: its scene key and the value it shows
      onSetting: guarded(function (/** @type {string} */ key, /** @type {number | boolean} */ value) {
        /** @type {Record<string, number | boolean>} */
        const change = {};
        change[key] = value;
        setSimulation(/** @type {Manifold.SimulationChange} */ (change));
      }),
    };
  }

  const exported = {
    engineSettings: engineSettings,
    simulationSettings: simulationSettings,
    setSimulation: setSimulation,
    controlHandlers: controlHandlers,
  };
  W.ManifoldWeb = W.ManifoldWeb || /** @type {ManifoldWebModules} */ ({});
  W.ManifoldWeb.simulationSettings = exported;
  return exported;
})(globalThis);
