// The simulation's settings, all in this file: the clock (paused, speed) and
// the engine parameters the controls and window.manifold show and set
// (simulation(), setSimulation(), pause(), resume()), with the values
// setSimulation accepts, and the handlers of the controls that change them
// (Pause, Step, Speed, Gravity, Friction, Restitution). Another engine
// parameter offered as a control is a row of ENGINE_SETTINGS and a handler
// below, its element in index.html and its binding in ui.js (createUI's
// handlers and setSimulation).
/* exported ManifoldWebSimulationSettings */
var ManifoldWebSimulationSettings = (function (W) {
  "use strict";
  const MW = W.ManifoldWeb;
  const P = MW.page, state = P.state;

  // The engine parameters offered, in the order simulation() lists them: the
  // name setSimulation and simulation() use, the engine's parameter it sets
  // (Lib/Manifold/Params.hs), and either a switch (true/false as 1/0) or the
  // range of numbers setSimulation accepts.
  /** @type {{ key: "gravity" | "friction" | "restitution", param: Manifold.ParamName, kind: "switch" | "number", lo?: number, hi?: number }[]} */
  const ENGINE_SETTINGS = [
    { key: "gravity", param: "gravityOn", kind: "switch" },
    { key: "friction", param: "friction", kind: "number", lo: 0, hi: 10 },
    { key: "restitution", param: "restitution", kind: "number", lo: 0, hi: 1 },
  ];
  // simulated time per real second that setSimulation accepts
  const TIME_SCALE = { lo: 0, hi: 10 };

  // {paused, timeScale, gravity, friction, restitution}: the clock and the
  // current world's parameters (without a world, gravity shows as on and the
  // numbers as null).
  /** @returns {Manifold.Simulation} */
  function simulationSettings() {
    const w = state.world;
    /** @type {Record<string, boolean | number | null>} */
    const out = { paused: state.clock.paused, timeScale: state.clock.timeScale };
    ENGINE_SETTINGS.forEach(function (s) {
      if (s.kind === "switch") out[s.key] = w ? w.param(s.param) > 0 : true;
      else out[s.key] = w ? w.param(s.param) : null;
    });
    return /** @type {Manifold.Simulation} */ (/** @type {unknown} */ (out));
  }

  // {paused, timeScale, gravity, friction, restitution}: any subset; throws on bad values.
  /** @param {Manifold.SimulationChange} o @returns {Manifold.Simulation} */
  function setSimulation(o) {
    if (!o || typeof o !== "object") {
      throw new TypeError("setSimulation expects {" + ["paused", "timeScale"].concat(ENGINE_SETTINGS.map(function (s) { return s.key; })).join(", ") + "}");
    }
    /** @param {keyof Manifold.SimulationChange} k @param {number} lo @param {number} hi */
    const num = function (k, lo, hi) {
      const x = o[k];
      if (typeof x !== "number" || !isFinite(x) || x < lo || x > hi) throw new RangeError(k + " must be a number from " + lo + " to " + hi);
      return /** @type {number} */ (x);
    };
    if (o.timeScale !== undefined) num("timeScale", TIME_SCALE.lo, TIME_SCALE.hi);
    /** @type {ManifoldWeb.Params} */
    const p = {};
    ENGINE_SETTINGS.forEach(function (s) {
      if (o[s.key] === undefined) return;
      p[s.param] = s.kind === "switch" ? (o[s.key] ? 1 : 0) : num(s.key, s.lo, s.hi);
    });
    if (Object.keys(p).length) P.requireWorld().setParams(p);
    if (o.timeScale !== undefined) state.clock.timeScale = o.timeScale;
    if (o.paused !== undefined) {
      state.clock.paused = !!o.paused;
      state.clock.reset();
    }
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
      onGravity: guarded(function (/** @type {boolean} */ on) { setSimulation({ gravity: on }); }),
      onFriction: guarded(function (/** @type {number} */ x) { setSimulation({ friction: x }); }),
      onRestitution: guarded(function (/** @type {number} */ x) { setSimulation({ restitution: x }); }),
    };
  }

  const exported = {
    ENGINE_SETTINGS: ENGINE_SETTINGS,
    simulationSettings: simulationSettings,
    setSimulation: setSimulation,
    controlHandlers: controlHandlers,
  };
  W.ManifoldWeb = W.ManifoldWeb || /** @type {ManifoldWebModules} */ ({});
  W.ManifoldWeb.simulationSettings = exported;
  return exported;
})(globalThis);
