// The page's shared state (the one object the page's scripts read and
// change: the WebGL renderers, the camera and the flat views' viewer, the current space and world, the
// display options, the error shown), the display constants (background,
// curvature colour scale, grid spacing, default options), and the helpers
// every part of the page uses: the current space's name and catalogue entry,
// the world or an error, a failure shown on the page, a control that reports
// its errors as a notice. The parts, loaded after this file: frame.js,
// input.js, space.js, hash.js, compare-setup.js, simulation-settings.js,
// scenes.js, tools.js, plot.js, inspector.js, api.js, capture.js, and
// app.js, which starts them.
/* exported ManifoldWebPage */
var ManifoldWebPage = (function (W) {
  "use strict";
  const MW = W.ManifoldWeb;
  const PageError = MW.gl.PageError;

  // Display-space RGB (0..1) of the background gradient.
  /** @type {{ top: Manifold.Rgb, bottom: Manifold.Rgb }} */
  const BACKGROUND = { top: [0.17, 0.20, 0.27], bottom: [0.035, 0.04, 0.055] };
  // tanh(K * scale) saturates the curvature colours; K = 1 (the unit sphere) is a strong red.
  const CURVATURE_SCALE = 1.0;
  // World units between the lines of the (optional) coordinate grid drawn on the surface.
  const GRID_SPACING = 0.25;
  /** @type {Manifold.DisplayOptions} */
  const DEFAULT_OPTIONS = { curvature: false, grid: true, antialias: "fxaa", bodyDetail: "auto", dimSleeping: true, model: "poincare" };
  // The comparison view's name in the space list and the URL (#space=compare-torus).
  const COMPARE = "compare-torus";

  // (without web/gen/spaces.js there is no catalogue: start() says so)
  const Manifold = W.Manifold = W.Manifold || /** @type {Manifold.Generated} */ ({ spaces: {} });
  Manifold.spaces = Manifold.spaces || {};

  /**
   * The page's state, shared by its scripts. Null where the page has not
   * made the thing yet (or lost it).
   * @typedef {object} PageState
   * @property {ManifoldWeb.UI | null} ui
   * @property {WebGL2RenderingContext | null} gl
   * @property {ManifoldWeb.Tracer | null} tracer
   * @property {ManifoldWeb.BodyRenderer | null} bodyRenderer
   * @property {ManifoldWeb.CurveRenderer | null} curveRenderer
   * @property {ManifoldWeb.Camera} camera
   * @property {ManifoldWeb.DiscView} disc the viewer of the flat views (hyperbolic spaces)
   * @property {Manifold.SpaceEntry[]} index the catalogue (Manifold.spaceIndex)
   * @property {string | null} spaceName
   * @property {Manifold.Space | null} space
   * @property {Manifold.DisplayOptions} options
   * @property {Record<string, string>} glslOverrides
   * @property {boolean} debugBrokenShader
   * @property {ManifoldWeb.PageError | null} error
   * @property {boolean} contextLost
   * @property {number} width
   * @property {number} height
   * @property {boolean} dirty
   * @property {boolean} preview
   * @property {Promise<unknown>} queue
   * @property {Promise<string> | null} current
   * @property {ManifoldWeb.World | null} world
   * @property {string | null} preset
   * @property {ManifoldWeb.Clock} clock
   * @property {ManifoldWeb.Comparison | null} compare
   */
  /** @type {PageState} */
  const state = {
    ui: null,
    gl: null,
    tracer: null,
    bodyRenderer: null,
    curveRenderer: null,    // geodesics, throw previews and trails (web/js/curves.js)
    camera: new MW.camera.Camera(),
    disc: new MW.disc.DiscView(),   // where the flat views of a hyperbolic space look (web/js/disc.js)
    index: [],
    spaceName: null,
    space: null,            // Manifold.spaces[spaceName]
    options: Object.assign({}, DEFAULT_OPTIONS),
    glslOverrides: {},      // name → GLSL text set by setSpaceGlsl
    debugBrokenShader: false,
    error: null,            // the PageError shown, or null
    contextLost: false,
    width: 1,               // the canvas's backing store
    height: 1,
    dirty: true,            // the traced surface must be drawn again (space, options, size changed)
    preview: false,         // the last frame was a half-resolution preview
    queue: Promise.resolve(),
    current: null,          // the promise of the latest space switch
    world: null,            // the bodies (web/js/world.js) of the current space
    preset: null,           // the preset scene the world was loaded from (until something else replaces it), or null
    clock: new MW.world.Clock(),
    compare: null,          // the comparison view (web/js/compare.js) when it is shown, or null
  };

  // Shows a failure on the page (the error panel); returns the Error a promise rejects with.
  /** @param {string} title @param {unknown} err */
  function fail(title, err) {
    const e = err instanceof PageError ? err : new PageError("internal", String(err && /** @type {Error} */ (err).message || err));
    state.error = e;
    state.ui.showError(title, e);
    return new Error(e.text());
  }

  // the current space's name ("compare-torus" in the comparison view)
  function currentName() { return state.compare ? COMPARE : state.spaceName; }

  /** @param {string} name */
  function entryOf(name) {
    return state.index.find(function (s) { return s.name === name; }) || null;
  }

  // The flat picture the current space is drawn as ("poincare" or "klein": a
  // hyperbolic space not shown as its hyperboloid; web/js/disc.js), or null
  // (the traced surface in 3-D).
  /** @returns {"poincare" | "klein" | null} */
  function flatModel() {
    const s = state.space, m = state.options.model;
    return s && s.metric === "minkowski" && !state.compare && m !== "hyperboloid" ? m : null;
  }

  function requireWorld() {
    if (!state.world) {
      throw new Error(state.space ? "the space " + state.spaceName + " has no engine (rebuild web/gen with `manifold build`)"
        : "no space is loaded yet");
    }
    return state.world;
  }

  // Reports an error of a control as a notice (the controls never throw into the page).
  /** @template {unknown[]} A @param {(...args: A) => unknown} f @returns {(...args: A) => unknown} */
  function guarded(f) {
    return function (...args) {
      try {
        return f.apply(null, args);
      } catch (err) {
        state.ui.showNotice(err.message || String(err));
        return undefined;
      }
    };
  }

  const exported = {
    BACKGROUND: BACKGROUND,
    CURVATURE_SCALE: CURVATURE_SCALE,
    GRID_SPACING: GRID_SPACING,
    DEFAULT_OPTIONS: DEFAULT_OPTIONS,
    COMPARE: COMPARE,
    state: state,
    fail: fail,
    currentName: currentName,
    entryOf: entryOf,
    flatModel: flatModel,
    requireWorld: requireWorld,
    guarded: guarded,
  };
  W.ManifoldWeb = W.ManifoldWeb || /** @type {ManifoldWebModules} */ ({});
  W.ManifoldWeb.page = exported;
  return exported;
})(globalThis);
