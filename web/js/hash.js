// The display options (curvature colouring, grid, antialiasing, body detail,
// sleeping bodies dimmed, a hyperbolic space's model)
// and the URL hash: the hash kept in step with the page (space, the preset
// scene loaded, else bodies when not the default scene's count, options),
// and a hash read back (at start and when it is edited) into a space, a
// preset or a number of bodies, and options.
/* exported ManifoldWebHash */
var ManifoldWebHash = (function (W) {
  "use strict";
  const MW = W.ManifoldWeb;
  const P = MW.page, state = P.state;

  function defaultBodyCount() {
    return state.space && Array.isArray(state.space.scene) ? state.space.scene.length : 0;
  }

  // The hash says how many bodies there are when that is not the default scene's count.
  function updateHash() {
    /** @type {Record<string, string | number>} */
    const params = { space: P.currentName() };
    const w = state.world;
    if (state.preset) params.scene = state.preset;
    else if (w && !state.compare && w.count() !== defaultBodyCount()) params.bodies = w.count();
    if (state.options.curvature) params.curvature = 1;
    if (!state.options.grid) params.grid = 0;
    if (!state.options.dimSleeping) params.dim = 0;
    if (state.options.antialias !== P.DEFAULT_OPTIONS.antialias) params.aa = state.options.antialias;
    if (state.options.model !== P.DEFAULT_OPTIONS.model) params.model = state.options.model;
    if (state.debugBrokenShader) params.debugBrokenShader = 1;
    const hash = MW.ui.formatHash(params);
    if (W.location.hash === hash) return;
    try {
      W.history.replaceState(null, "", hash);
    } catch (err) {
      W.location.hash = hash;
    }
  }

  /** @param {Partial<Manifold.DisplayOptions>} o @returns {Manifold.DisplayOptions} */
  function setOptions(o) {
    if (!o || typeof o !== "object") throw new TypeError("setOptions expects {curvature, grid, antialias, bodyDetail, dimSleeping, model}");
    if (o.model !== undefined && MW.disc.MODELS.indexOf(o.model) < 0) {
      throw new TypeError("model must be one of " + MW.disc.MODELS.join(", "));
    }
    if (o.antialias !== undefined && MW.tracer.ANTIALIAS_MODES.indexOf(o.antialias) < 0) {
      throw new TypeError("antialias must be one of " + MW.tracer.ANTIALIAS_MODES.join(", "));
    }
    if (o.bodyDetail !== undefined && MW.bodies.BODY_DETAILS.indexOf(o.bodyDetail) < 0) {
      throw new TypeError("bodyDetail must be one of " + MW.bodies.BODY_DETAILS.join(", "));
    }
    if (o.curvature !== undefined) state.options.curvature = !!o.curvature;
    if (o.grid !== undefined) state.options.grid = !!o.grid;
    if (o.dimSleeping !== undefined) state.options.dimSleeping = !!o.dimSleeping;
    if (o.antialias !== undefined) state.options.antialias = o.antialias;
    if (o.bodyDetail !== undefined) state.options.bodyDetail = o.bodyDetail;
    if (o.model !== undefined) state.options.model = o.model;
    state.ui.setCurvature(state.options.curvature);
    state.ui.setGrid(state.options.grid);
    state.ui.setDimSleeping(state.options.dimSleeping);
    state.ui.setAntialias(state.options.antialias);
    state.ui.setModel(state.options.model);
    state.dirty = true;
    if (state.spaceName) updateHash();
    return Object.assign({}, state.options);
  }

  /** @param {Record<string, string>} params */
  function optionsFromHash(params) {
    /** @type {Partial<Manifold.DisplayOptions>} */
    const o = {};
    if (params.curvature !== undefined) o.curvature = params.curvature === "1" || params.curvature === "true";
    if (params.grid !== undefined) o.grid = !(params.grid === "0" || params.grid === "false");
    if (params.dim !== undefined) o.dimSleeping = !(params.dim === "0" || params.dim === "false");
    if (params.aa !== undefined && MW.tracer.ANTIALIAS_MODES.indexOf(params.aa) >= 0) o.antialias = /** @type {Manifold.Antialias} */ (params.aa);
    if (params.model !== undefined && MW.disc.MODELS.indexOf(/** @type {Manifold.Model} */ (params.model)) >= 0) o.model = /** @type {Manifold.Model} */ (params.model);
    return o;
  }

  // The space a hash asks for, or the first one (with a notice for an unknown name).
  /** @param {Record<string, string>} params */
  function spaceFromHash(params) {
    if (params.space === P.COMPARE) return P.COMPARE;
    if (params.space && P.entryOf(params.space)) return params.space;
    if (params.space) {
      state.ui.showNotice("There is no space " + JSON.stringify(params.space) + "; showing " +
        state.index[0].name + " instead.");
    }
    return state.index[0].name;
  }

  // bodies=N from the hash: a whole number, else null (the default scene).
  // That a world holds N bodies is checked when there is one (bodiesFor):
  // the limit is the space's engine's.
  /** @param {Record<string, string>} params */
  function bodiesFromHash(params) {
    if (params.bodies === undefined) return null;
    const n = Number(params.bodies);
    if (params.bodies === "" || !Number.isInteger(n) || n < 0) {
      state.ui.showNotice("bodies=" + params.bodies + " in the link is not a whole number of bodies; showing the default scene.");
      return null;
    }
    return n;
  }

  // The hash's bodies=N for a world of this engine: N when it holds that
  // many (0 to the generated maxBodies), else null (the default scene) and a notice.
  /** @param {number | null} n @param {Manifold.Engine} engine @returns {number | null} */
  function bodiesFor(n, engine) {
    if (n === null || n <= engine.maxBodies) return n;
    state.ui.showNotice("bodies=" + n + " in the link is more than a world holds (a whole number from 0 to " +
      engine.maxBodies + "); showing the default scene.");
    return null;
  }

  function onHashChange() {
    const params = MW.ui.parseHash(W.location.hash);
    const broken = params.debugBrokenShader === "1";
    setOptions(optionsFromHash(params));
    if (params.scene !== undefined && !broken && !state.debugBrokenShader) {
      // scene=NAME: a preset (loaded unless it is the world already)
      if (params.scene !== state.preset) MW.scenes.loadPreset(params.scene).catch(function () {});
      return;
    }
    const name = spaceFromHash(params);
    const bodies = bodiesFromHash(params);
    if (name !== P.currentName() || broken !== state.debugBrokenShader) {
      state.debugBrokenShader = broken;
      MW.space.setSpace(name, { bodies: bodies }).catch(function () {});
    } else if (state.world && !state.compare && (bodies === null ? defaultBodyCount() : bodies) !== state.world.count()) {
      try {
        MW.scenes.resetScene(bodiesFor(bodies, state.world.engine));
      } catch (err) {
        state.ui.showNotice("The scene could not be loaded: " + err.message);
      }
      updateHash();
    }
  }

  const exported = {
    updateHash: updateHash,
    setOptions: setOptions,
    optionsFromHash: optionsFromHash,
    spaceFromHash: spaceFromHash,
    bodiesFromHash: bodiesFromHash,
    bodiesFor: bodiesFor,
    onHashChange: onHashChange,
  };
  W.ManifoldWeb = W.ManifoldWeb || /** @type {ManifoldWebModules} */ ({});
  W.ManifoldWeb.hash = exported;
  return exported;
})(globalThis);
