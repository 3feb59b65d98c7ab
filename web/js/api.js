// The scripting API, window.manifold (web/README.md lists its calls, and
// web/manifold.d.ts declares them): spaces, picking and projecting, frames,
// stats, the camera, display options, bodies, the simulation's settings,
// grabbing, scenes, the comparison view. Each call checks its arguments and
// goes to the part of the page that does it.
/* exported ManifoldWebApi */
var ManifoldWebApi = (function (W) {
  "use strict";
  const MW = W.ManifoldWeb;
  const P = MW.page, state = P.state;

  /** @type {Manifold.Pane[]} */
  const PANES = ["torus-embedded", "torus-flat", "square-embedded", "square-flat"];

  /** @param {Manifold.Rgb} c @returns {Manifold.Rgb} */
  function copy(c) { return [c[0], c[1], c[2]]; }

  /** @returns {Manifold.Api} */
  function scriptingApi() {
    const frame = MW.frame, input = MW.input, scenes = MW.scenes, settings = MW.simulationSettings;
    return {
      // names of every space, in catalogue order
      spaces: function () { return state.index.map(function (s) { return s.name; }); },
      // the current space's name ("compare-torus" in the comparison view)
      space: P.currentName,
      // switch space; resolves with its name when its shader is compiled and drawn,
      // rejects with an Error whose message is the error text
      setSpace: MW.space.setSpace,
      // settles like the latest setSpace (the first one is the page's own)
      ready: function () { return state.current || Promise.reject(new Error(state.error ? state.error.text() : "not started")); },
      // surface point [x, y, z] under backing-store pixel (x, y), origin top-left, or null
      pick: function (x, y) {
        MW.picking.checkPixel(x, y);
        if (P.flatModel() !== null) return input.surfacePoint(x, y);
        if ((frame.surfaceStale() || state.preview) && !state.error) frame.renderNow(false);
        return MW.picking.pick(state.error ? null : state.tracer, x, y);
      },
      // draw one full-resolution frame now (synchronously)
      render: function () {
        if (!state.error) frame.renderNow(false);
      },
      // draw a frame and wait for the GPU to finish it; returns its time in ms (also in stats().frameMs)
      measureFrame: frame.measureFrame,
      // world point → [px, py] continuous backing-store pixels (pixel (i, j) spans [i, i+1) × [j, j+1)), or null behind the eye
      project: function (p) {
        if (!MW.camera.isVec3(p)) throw new TypeError("project expects [x, y, z]");
        const model = P.flatModel();
        if (model !== null) return state.disc.project(model, p, state.width, state.height);
        return state.camera.project(p, state.width, state.height);
      },
      stats: frame.statsObject,
      camera: function () { return state.camera.get(); },
      setCamera: function (c) {
        state.camera.set(c);
        return state.camera.get();
      },
      // where the flat views of a hyperbolic space look: {boost (nine numbers, world → view, row by row), zoom}
      discView: function () { return state.disc.get(); },
      setDiscView: function (v) {
        state.disc.set(v);
        return state.disc.get();
      },
      // walks the flat view as a drag from the canvas's centre by (dx, dy) backing-store pixels does
      walk: function (dx, dy) {
        if (typeof dx !== "number" || typeof dy !== "number" || !isFinite(dx) || !isFinite(dy)) throw new TypeError("walk(dx, dy) expects pixels");
        const model = P.flatModel();
        if (model === null) throw new Error("walk: the space is not shown in a flat view (a hyperbolic space with the model poincare or klein)");
        const c = [0.5 * state.width, 0.5 * state.height];
        state.disc.walk(model, [c[0], c[1]], [c[0] + dx, c[1] + dy], state.width, state.height);
        return state.disc.get();
      },
      // the error text shown on the page, or null
      error: function () { return state.error ? state.error.text() : null; },
      options: function () {
        return Object.assign({}, state.options, {
          background: { top: copy(P.BACKGROUND.top), bottom: copy(P.BACKGROUND.bottom) },
          curvatureScale: P.CURVATURE_SCALE,
          gridSpacing: P.GRID_SPACING,
        });
      },
      // {curvature: bool, grid: bool, antialias: "fxaa" | "ssaa" | "off", bodyDetail: "auto" | "mesh"}
      setOptions: MW.hash.setOptions,
      // ---- bodies (the engine of the current space) ----
      // add a body from a scene body {shape, size, density, static, p, v, angle, omega}; returns its index or throws
      addBody: scenes.addBody,
      // remove every body
      clear: scenes.clearBodies,
      // the space's default scene again (default parameters), cut or filled to n bodies (at most the engine's maxBodies); returns the count
      resetScene: scenes.resetScene,
      // n physics steps now, synchronously (the polygons are then current); returns the body count
      step: function (n) {
        n = n === undefined ? 1 : n;
        if (!Number.isInteger(n) || n < 0 || n > 1e6) throw new RangeError("step(n) expects a whole number of steps from 0 to 1000000");
        const w = P.requireWorld();
        w.step(n);
        if (state.compare) state.compare.flat.step(n);
        return w.count();
      },
      // the bodies in the scene format
      bodies: function () { return state.world ? state.world.bodies() : []; },
      addJoint: function (spec) { return P.requireWorld().addJoint(spec); },
      joints: function () { return state.world ? state.world.jointsSaved() : []; },
      removeJoint: function (i) { P.requireWorld().removeJoint(i); },
      // the hash of the world's state (16 hex digits): manifold sim --hash prints the same for the same run
      hash: function () { return P.requireWorld().hash(); },
      // the comparison view (setSpace("compare-torus")), or null: both worlds' bodies,
      // the held pane, frames drawn, the curvature note
      comparison: function () {
        const c = state.compare;
        if (!c) return null;
        return {
          name: P.COMPARE,
          panes: PANES.slice(),
          embedded: c.embedded.bodies(),
          flat: c.flat.bodies(),
          grabbed: { embedded: c.embedded.grabbed, flat: c.flat.grabbed },
          frames: c.frames,
          note: document.getElementById("compare-note").textContent,
        };
      },
      // where body i of a comparison pane's world is drawn, as client (CSS) pixels [x, y], or null
      comparisonPoint: function (pane, i) {
        if (!state.compare) throw new Error("the comparison view is not shown");
        if (PANES.indexOf(pane) < 0) throw new RangeError("unknown pane " + JSON.stringify(pane));
        if (pane === "torus-embedded" && frame.surfaceStale()) frame.renderNow(false);
        state.compare.render(true);
        return state.compare.clientPoint(pane, i);
      },
      pause: function () { settings.setSimulation({ paused: true }); },
      resume: function () { settings.setSimulation({ paused: false }); },
      // {paused, timeScale, gravity, substeps, friction, …}: the clock and every
      // engine parameter with a control (the generated scene keys)
      simulation: settings.simulationSettings,
      setSimulation: settings.setSimulation,
      // grab the body under backing-store pixel (x, y) with the mouse joint; true if one was grabbed
      grab: function (x, y) {
        if (typeof x !== "number" || typeof y !== "number") throw new TypeError("grab(x, y) expects canvas backing-store pixels");
        input.releaseGrab();
        return input.grabAt(x, y);
      },
      // move the grabbed body's target to the surface under (x, y); false off the surface or when nothing is held
      drag: function (x, y) {
        if (typeof x !== "number" || typeof y !== "number") throw new TypeError("drag(x, y) expects canvas backing-store pixels");
        return input.dragTo(x, y);
      },
      release: input.releaseGrab,
      // the index of the grabbed body, or -1
      grabbed: function () { return state.world ? state.world.grabbed : -1; },
      // ---- tools and curves (web/js/tools.js) ----
      // what a press on empty surface does: "grab" (grab a body, else throw a new one) or "geodesic"
      tool: function () { return MW.tools.tools.tool; },
      setTool: MW.tools.setTool,
      // the body the Add button, a click and a throw make: {shape, size, density, static} (size: the space's own unless set)
      newBody: MW.tools.newBody,
      // change some of it ({size: null}: the space's own again); throws naming the field of a bad value; returns the template
      setNewBody: MW.tools.setNewBody,
      // add the new body at a free point of the view; returns its index or throws
      addAtView: scenes.addAtView,
      // draw the geodesic from surface point p in the tangent direction d, `length` long (default: the tool's);
      // returns {points, breaks} (breaks: indices of points the curve jumps to, through a quotient's edge)
      geodesic: function (p, d, length) {
        if (!MW.camera.isVec3(p) || !MW.camera.isVec3(d)) throw new TypeError("geodesic(p, d, length) expects points [x, y, z]");
        if (length !== undefined && !(typeof length === "number" && isFinite(length) && length > 0)) throw new RangeError("geodesic's length must be a positive number");
        MW.tools.showGeodesic(p, d, length);
        return MW.tools.curves().geodesic;
      },
      clearGeodesic: MW.tools.clearGeodesic,
      trails: function () { return MW.tools.tools.trailsOn; },
      setTrails: MW.tools.setTrails,
      // the live plot: plot() its samples {on, seconds, every, samples: {time, kineticEnergy, axialMomentum (null without an axis), contacts, stepMs}}
      plot: MW.plot.samples,
      setPlot: MW.plot.setPlot,
      // what the inspector says of the body under backing-store pixel (x, y), or null
      inspect: function (x, y) {
        if (typeof x !== "number" || typeof y !== "number") throw new TypeError("inspect(x, y) expects canvas backing-store pixels");
        const q = input.surfacePoint(x, y), hit = q && state.world ? state.world.pick(q) : null;
        return hit ? MW.inspector.describe(hit.index) : null;
      },
      // what is drawn over the bodies: {geodesic, preview (a throw's, a point per step), trails: {on, samples, segments}}
      curves: MW.tools.curves,
      // load a scene (JSON text or value); a Promise of the body count, rejected with the problem
      loadScene: scenes.loadScene,
      // the preset scenes (scenes/): [{name, space, title}]; loadPreset(name): a Promise of the body count; preset(): the one loaded, or null
      presets: scenes.presets,
      loadPreset: function (name) {
        if (typeof name !== "string") return Promise.reject(new TypeError("loadPreset expects a preset's name"));
        return scenes.loadPreset(name);
      },
      preset: function () { return state.preset; },
      // the current scene as a JSON value (what saveScene downloads)
      scene: scenes.currentScene,
      // Replace a space's GLSL (null restores the generated one); rebuilds the
      // shader when it is the current space. For experiments and the error-path test.
      setSpaceGlsl: function (name, text) {
        if (!P.entryOf(name)) return Promise.reject(new Error("unknown space " + JSON.stringify(name)));
        if (text === null || text === undefined) delete state.glslOverrides[name];
        else if (typeof text !== "string") return Promise.reject(new TypeError("setSpaceGlsl expects GLSL text or null"));
        else state.glslOverrides[name] = text;
        return name === state.spaceName ? MW.space.setSpace(name, { keep: true }) : Promise.resolve(name);
      },
    };
  }

  const exported = { scriptingApi: scriptingApi };
  W.ManifoldWeb = W.ManifoldWeb || /** @type {ManifoldWebModules} */ ({});
  W.ManifoldWeb.api = exported;
  return exported;
})(globalThis);
