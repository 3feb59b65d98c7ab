// Switching the page to a space: the generated space scripts loaded as
// <script> tags (so the page works from file:// too), the trace shader
// compiled from the space's GLSL (or a replacement set by setSpaceGlsl, or
// one broken on purpose by #debugBrokenShader=1), the camera and the world
// reset, one switch after another. And the WebGL context lost and given back.
/* exported ManifoldWebSpace */
var ManifoldWebSpace = (function (W) {
  "use strict";
  const MW = W.ManifoldWeb;
  const P = MW.page, state = P.state;
  const PageError = MW.gl.PageError;
  const Manifold = W.Manifold;

  // What #debugBrokenShader=1 appends to the space's GLSL: an undeclared identifier.
  const BROKEN_GLSL = "\nfloat brokenOnPurpose = debugBrokenShader; // #debugBrokenShader=1 in the URL\n";

  /** @type {Record<string, Promise<void>>} */
  const loading = {}; // script → Promise

  // Loads a generated space script with a <script> tag (works from file:// too);
  // rejects when it cannot be fetched or throws while it runs.
  /** @param {string} src */
  function loadScript(src) {
    if (!loading[src]) {
      loading[src] = /** @type {Promise<void>} */ (new Promise(function (resolve, reject) {
        const s = document.createElement("script");
        /** @type {string | null} */
        let thrown = null;
        /** @param {ErrorEvent} e */
        const onError = function (e) {
          if (e.filename && e.filename.slice(-src.length) === src) {
            thrown = (e.message || "an error") + " (line " + e.lineno + ")";
          }
        };
        W.addEventListener("error", onError);
        const done = function () {
          W.removeEventListener("error", onError);
        };
        s.src = src;
        s.onload = function () {
          done();
          if (!thrown) return resolve();
          delete loading[src];
          reject(new PageError("load", "The generated script " + src + " failed while it ran; rebuild web/gen with " +
            "`manifold build`.", thrown));
        };
        s.onerror = function () {
          done();
          delete loading[src];
          s.remove();
          reject(new PageError("load", "Could not load " + src + ". Build the generated scripts with " +
            "`manifold build` (it writes web/gen) and reload."));
        };
        document.head.appendChild(s);
      }));
    }
    return loading[src];
  }

  /** @param {string} name */
  function glslFor(name) {
    const text = Object.prototype.hasOwnProperty.call(state.glslOverrides, name)
      ? state.glslOverrides[name] : Manifold.spaces[name].glsl;
    return state.debugBrokenShader ? text + BROKEN_GLSL : text;
  }

  // Switches to a space: loads its script, resets the camera, compiles its
  // trace shader, loads the space's default scene (or `how.scene`, or the
  // default cut or filled to `how.bodies` bodies; `how.keep`: keeps the world
  // and the camera when the space is the current one) and draws a frame. Returns the space's name.
  /**
   * How a space switch goes: `scene`, a parsed scene to load; `bodies`, the
   * default scene cut or filled to that many; `keep`, the world and camera
   * kept when the space is the current one.
   * @typedef {{ scene?: ManifoldWeb.ParsedScene | null, bodies?: number | null, keep?: boolean }} How
   */
  /** @param {string} name @param {How} [how] @returns {Promise<string>} */
  async function applySpace(name, how) {
    how = how || {};
    const entry = P.entryOf(name);
    if (!entry) {
      throw new Error("unknown space " + JSON.stringify(name) + "; the spaces are: " +
        state.index.map(function (s) { return s.name; }).join(", "));
    }
    if (!state.tracer) throw new Error(state.error ? state.error.text() : "the page has no WebGL2 renderer");
    try {
      await loadScript("gen/" + entry.script);
    } catch (err) {
      throw P.fail("The space could not be loaded", err);
    }
    const space = Manifold.spaces[name];
    if (!space || typeof space.glsl !== "string" || !space.camera) {
      throw P.fail("The space could not be loaded",
        new PageError("load", "gen/" + entry.script + " did not register the space " + JSON.stringify(name) +
          "; rebuild web/gen with `manifold build`."));
    }
    const keep = how.keep && state.world && state.world.name === name && state.space === space;
    state.spaceName = name;
    state.space = space;
    state.ui.setSpace(entry);
    if (!keep) {
      state.camera.set(space.camera);
      state.camera.maxDistance = 8 * space.bounds;
      state.disc.reset();
      // (the flat views are the hyperbolic spaces': a lattice's wrap is not a boost's)
      state.disc.setWrap(space.metric === "minkowski" ? space.wrapIntoDomain : null);
      MW.tools.spaceChanged();
      try {
        MW.scenes.newWorld(how.scene || null, how.bodies);
      } catch (err) {
        state.world = null;
        state.ui.showNotice("The scene could not be loaded: " + err.message);
      }
    }
    MW.hash.updateHash();
    try {
      state.tracer.setSpaceGlsl(glslFor(name), "sphere tracer for space \"" + name + "\"", space.metric === "minkowski", space.wrapJump !== null);
    } catch (err) {
      if (state.debugBrokenShader && err instanceof PageError) {
        err.message += " The URL has debugBrokenShader=1, which breaks the shader on purpose; remove it to draw the space.";
      }
      throw P.fail("The surface cannot be drawn", err);
    }
    state.error = null;
    state.ui.clearError();
    state.dirty = true;
    MW.frame.renderNow();
    return name;
  }

  // Space switches run one after another; each call's promise settles with its own outcome.
  /** @param {string} name @param {How} [how] @returns {Promise<string>} */
  function setSpace(name, how) {
    const job = state.queue.then(function () {
      MW.compareSetup.leaveComparison();
      return name === P.COMPARE ? MW.compareSetup.applyComparison() : applySpace(name, how);
    });
    state.queue = job.catch(function () {});
    state.current = job;
    return job;
  }

  // ---- context loss ------------------------------------------------------------------------
  /** @param {HTMLCanvasElement} canvas */
  function watchContext(canvas) {
    canvas.addEventListener("webglcontextlost", function (e) {
      e.preventDefault();
      state.contextLost = true;
      P.fail("The graphics context was lost",
        new PageError("context-lost", "The browser took the WebGL context away (a driver reset, or too many " +
          "pages using the GPU). The page will redraw if it is given back."));
    });
    canvas.addEventListener("webglcontextrestored", function () {
      state.contextLost = false;
      try {
        state.tracer = new MW.tracer.Tracer(state.gl);
        state.bodyRenderer = new MW.bodies.BodyRenderer(state.gl);
        state.curveRenderer = new MW.curves.CurveRenderer(state.gl);
      } catch (err) {
        state.tracer = null;
        P.fail("The surface cannot be drawn", err);
        return;
      }
      if (state.spaceName) setSpace(state.spaceName, { keep: true }).catch(function () {});
    });
  }

  const exported = {
    loadScript: loadScript,
    applySpace: applySpace,
    setSpace: setSpace,
    watchContext: watchContext,
  };
  W.ManifoldWeb = W.ManifoldWeb || /** @type {ManifoldWebModules} */ ({});
  W.ManifoldWeb.space = exported;
  return exported;
})(globalThis);
