// The comparison view "Torus: embedded vs flat" put on the page and taken off
// it: its generated script and both spaces loaded, the embedded world made as
// the page's own and the flat one beside it, the three extra panes shown, the
// view (web/js/compare.js, which draws the panes and routes their input) made
// with the page's camera and options, and the curvature note under the panes.
/* exported ManifoldWebCompareSetup */
var ManifoldWebCompareSetup = (function (W) {
  "use strict";
  const MW = W.ManifoldWeb;
  const P = MW.page, state = P.state;
  const PageError = MW.gl.PageError;
  const Manifold = W.Manifold;

  /** @param {boolean} show */
  function comparisonPanes(show) {
    ["view-flat", "square-embedded", "square-flat", "compare-captions"].forEach(function (id) {
      document.getElementById(id).hidden = !show;
    });
    document.getElementById("stage").classList.toggle("compare", show);
  }

  function leaveComparison() {
    if (!state.compare) return;
    state.compare.dispose();
    state.compare = null;
    comparisonPanes(false);
  }

  // The line under the panes: the curvature of each, from the generated curvature functions.
  /** @param {Manifold.ComparisonDef} def */
  function comparisonNote(def) {
    const K = Manifold.spaces[def.embedded].curvature, K0 = Manifold.spaces[def.flat].curvature;
    /** @param {number} z */
    const at = function (z) { const p = def.fromSquare(0, 0, z); return K(p[0], p[1], p[2]); };
    /** @param {number} x */
    const f = function (x) { return (x >= 0 ? "+" : "\u2212") + Math.abs(x).toFixed(2); };
    return "Curvature: the embedded torus has K = " + f(at(0)) + " on its outer equator and " + f(at(def.half)) +
      " on its inner one (Curvature colours it); the flat torus has K = " + f(K0(0, 0, 0)).replace("+", "") +
      " everywhere. One scene in the torus's angles on both: the difference in motion is the difference in metric.";
  }

  /** @returns {Promise<string>} */
  async function applyComparison() {
    if (!state.tracer) throw new Error(state.error ? state.error.text() : "the page has no WebGL2 renderer");
    try {
      await MW.space.loadScript("gen/compare-torus.js");
    } catch (err) {
      throw P.fail("The comparison could not be loaded", err);
    }
    const def = Manifold.comparisons && Manifold.comparisons.torus;
    if (!def || !P.entryOf(def.embedded) || !P.entryOf(def.flat)) {
      throw P.fail("The comparison could not be loaded", new PageError("load",
        "gen/compare-torus.js did not register the comparison, or its spaces are missing; rebuild web/gen with `manifold build`."));
    }
    try {
      await MW.space.loadScript("gen/" + P.entryOf(def.flat).script);
    } catch (err) {
      throw P.fail("The comparison could not be loaded", err);
    }
    const names = state.index.map(function (e) { return e.name; });
    await MW.space.applySpace(def.embedded, { scene: MW.world.parseScene(def.scenes.embedded, names) });
    const flat = new MW.world.World(def.flat, Manifold.spaces[def.flat]);
    flat.load(MW.world.parseScene(def.scenes.flat, names));
    comparisonPanes(true);
    try {
      state.compare = new MW.compare.Comparison(def, state.world, flat, state.camera, {
        mainCanvas: state.ui.canvas,
        flatCanvas: /** @type {HTMLCanvasElement} */ (document.getElementById("view-flat")),
        squareEmbedded: /** @type {HTMLCanvasElement} */ (document.getElementById("square-embedded")),
        squareFlat: /** @type {HTMLCanvasElement} */ (document.getElementById("square-flat")),
      }, {
        options: function () {
          return Object.assign({}, state.options, { curvatureScale: P.CURVATURE_SCALE, gridSpacing: P.GRID_SPACING, background: P.BACKGROUND });
        },
        bounds: function () { return state.space ? state.space.bounds : 1; },
        curvatureOf: function (/** @type {Manifold.Vec3} */ p) { return Manifold.spaces[def.embedded].curvature(p[0], p[1], p[2]); },
        grab: MW.input.GRAB,
        interacted: MW.frame.interacted,
      });
    } catch (err) {
      comparisonPanes(false);
      throw P.fail("The comparison cannot be drawn", err);
    }
    document.getElementById("compare-note").textContent = comparisonNote(def);
    state.ui.setSpace({ name: P.COMPARE, description: def.title + ": " + def.embedded + " and " + def.flat + " side by side (paper Fig. 17)" });
    state.clock.reset();
    MW.hash.updateHash();
    state.dirty = true;
    MW.frame.renderNow();
    state.compare.render(true);
    return P.COMPARE;
  }

  const exported = {
    leaveComparison: leaveComparison,
    applyComparison: applyComparison,
  };
  W.ManifoldWeb = W.ManifoldWeb || /** @type {ManifoldWebModules} */ ({});
  W.ManifoldWeb.compareSetup = exported;
  return exported;
})(globalThis);
