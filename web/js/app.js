// The page: wires the generated spaces (web/gen) to the tracer, the camera,
// picking and the controls, runs the frame loop, and exposes the scripting
// API on window.manifold. See web/README.md for the API and URL parameters.
(function (W) {
  "use strict";
  const MW = W.ManifoldWeb;
  const PageError = MW.gl.PageError;

  // Display-space RGB (0..1) of the background gradient.
  const BACKGROUND = { top: [0.17, 0.20, 0.27], bottom: [0.035, 0.04, 0.055] };
  // tanh(K * scale) saturates the curvature colours; K = 1 (the unit sphere) is a strong red.
  const CURVATURE_SCALE = 1.0;
  // World units between the lines of the (optional) coordinate grid drawn on the surface.
  const GRID_SPACING = 0.25;
  const DEFAULT_OPTIONS = { curvature: false, grid: true, antialias: "fxaa" };
  // What #debugBrokenShader=1 appends to the space's GLSL: an undeclared identifier.
  const BROKEN_GLSL = "\nfloat brokenOnPurpose = debugBrokenShader; // #debugBrokenShader=1 in the URL\n";

  const Manifold = W.Manifold = W.Manifold || { spaces: {} };
  Manifold.spaces = Manifold.spaces || {};

  const state = {
    ui: null,
    gl: null,
    tracer: null,
    camera: new MW.camera.Camera(),
    index: [],
    spaceName: null,
    space: null,            // Manifold.spaces[spaceName]
    options: Object.assign({}, DEFAULT_OPTIONS),
    glslOverrides: {},      // name → GLSL text set by setSpaceGlsl
    debugBrokenShader: false,
    error: null,            // the PageError shown, or null
    contextLost: false,
    width: 1,
    height: 1,
    dirty: true,
    cameraVersion: -1,
    frameTimes: [],         // performance.now() of recent frames
    frameCount: 0,
    gpuFrameMs: null,       // GPU time of the last timed full frame
    fence: null,
    fenceAt: 0,
    preview: false,         // the last frame was a half-resolution preview
    interactUntil: 0,       // the view counts as moving until then (performance.now())
    queue: Promise.resolve(),
    current: null,          // the promise of the latest space switch
    statsShownAt: 0,
  };

  // ---- bodies: the engine's hook -------------------------------------------------
  // The physics engine is emitted from the Haskell World step into each space script
  // (Manifold.spaces[NAME].engine); the page does not run it yet, so there are no
  // bodies and this hook draws nothing. When it does: keep the world here in
  // `engine`, step it in `frame` while it runs (and keep the loop drawing while it
  // does), count its bodies in bodyCount(), and draw its body polygons in drawBodies.
  // `frame` is called after the surface is shaded, with the colour buffer bound:
  //   frame.gl, frame.framebuffer, frame.width, frame.height (pixels of that buffer),
  //   frame.scale (buffer pixels per canvas pixel),
  //   frame.positionTexture (RGBA32F: traced x, y, z and distance from the eye, -1 on
  //     background) to hide polygon fragments behind the surface (distance test with a
  //     small offset, as in the paper), frame.viewProjection (column-major 4×4 of the
  //     same camera), frame.eye.
  const engine = null;
  function drawBodies(frame) {
    if (!engine) return;
  }
  function bodyCount() { return 0; }

  // ---- rendering ------------------------------------------------------------------
  // A frame whose GPU time exceeds this makes the view draw half-resolution previews
  // while it moves (software rendering, weak GPUs); a sharp frame follows when it stops.
  const SLOW_FRAME_MS = 40;
  const INTERACTION_MS = 300;

  function canRender() {
    return state.tracer && !state.contextLost;
  }

  // Draws a frame now; preview = half resolution (while the view moves on a slow GPU).
  function renderNow(preview) {
    if (!canRender()) return false;
    const gl = state.gl;
    state.tracer.configure(state.width, state.height, state.options.antialias, !!preview);
    const camera = state.camera;
    state.tracer.render({
      camera: camera,
      bounds: state.space ? state.space.bounds : 1,
      curvature: state.options.curvature,
      curvatureScale: CURVATURE_SCALE,
      grid: state.options.grid,
      gridSpacing: GRID_SPACING,
      background: BACKGROUND,
    }, function (frame) {
      frame.viewProjection = camera.viewProjection(state.width / state.height, 0.01, 100);
      frame.eye = camera.eye.slice();
      drawBodies(frame);
    });
    const now = performance.now();
    // time the GPU work of full frames with a fence, polled by the frame loop
    if (!preview && !state.fence) {
      state.fence = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
      state.fenceAt = now;
      gl.flush();
    }
    state.dirty = false;
    state.preview = !!preview;
    state.cameraVersion = camera.version;
    state.frameCount++;
    state.frameTimes.push(now);
    return true;
  }

  function pollFence(now) {
    const gl = state.gl;
    if (!state.fence || !gl) return;
    if (gl.isContextLost()) { state.fence = null; return; }
    if (gl.getSyncParameter(state.fence, gl.SYNC_STATUS) !== gl.SIGNALED) return;
    gl.deleteSync(state.fence);
    state.fence = null;
    state.gpuFrameMs = now - state.fenceAt;
  }

  // GPU time of a full frame measured by a one-pixel read-back (which waits for it).
  function measureFrame() {
    if (!canRender() || state.error) return null;
    const t0 = performance.now();
    renderNow(false);
    if (state.tracer.hasFrame) state.tracer.readTexel(0, 0);
    state.gpuFrameMs = performance.now() - t0;
    if (state.fence) {
      state.gl.deleteSync(state.fence);
      state.fence = null;
    }
    return state.gpuFrameMs;
  }

  function needsFrame() {
    return state.dirty || state.cameraVersion !== state.camera.version;
  }

  function fps(now) {
    const times = state.frameTimes;
    while (times.length && now - times[0] > 1000) times.shift();
    if (times.length < 2) return 0;
    return (times.length - 1) * 1000 / (times[times.length - 1] - times[0]);
  }

  function statsObject() {
    return {
      fps: Math.round(fps(performance.now()) * 10) / 10,
      frameMs: state.gpuFrameMs === null ? null : Math.round(state.gpuFrameMs * 10) / 10,
      frames: state.frameCount,
      preview: state.preview,
      bodies: bodyCount(),
      width: state.width,
      height: state.height,
      space: state.spaceName,
      antialias: state.options.antialias,
      curvature: state.options.curvature,
      grid: state.options.grid,
    };
  }

  function showStats(now) {
    if (now - state.statsShownAt < 250) return;
    state.statsShownAt = now;
    const s = statsObject();
    const rate = s.fps > 0 ? s.fps.toFixed(1) + " fps" : "idle";
    const cost = s.frameMs === null ? "" : " · frame " + Math.round(s.frameMs) + " ms";
    state.ui.setStats(rate + cost + (s.preview ? " (preview)" : "") + " · " + s.width + "×" + s.height +
      " px · bodies " + s.bodies);
  }

  // Marks the view as moving (input changed the camera).
  function interacted() {
    state.interactUntil = performance.now() + INTERACTION_MS;
  }

  function frame(now) {
    W.requestAnimationFrame(frame);
    pollFence(now);
    if (!state.error) {
      const moving = now < state.interactUntil;
      const slow = state.gpuFrameMs !== null && state.gpuFrameMs > SLOW_FRAME_MS;
      if (needsFrame()) renderNow(moving && slow);
      else if (state.preview && !moving) renderNow(false); // the sharp frame once the view stops
    }
    showStats(now);
  }

  // ---- canvas size (HiDPI) ------------------------------------------------------------
  function setCanvasSize(w, h) {
    w = Math.max(1, Math.round(w));
    h = Math.max(1, Math.round(h));
    const canvas = state.ui.canvas;
    if (canvas.width === w && canvas.height === h && state.width === w && state.height === h) return;
    canvas.width = w;
    canvas.height = h;
    state.width = w;
    state.height = h;
    state.dirty = true;
    // resizing clears the canvas: draw again before the browser paints
    if (!state.error) renderNow();
  }

  function watchSize(canvas) {
    const measure = function () {
      const r = canvas.getBoundingClientRect();
      const dpr = W.devicePixelRatio || 1;
      setCanvasSize(r.width * dpr, r.height * dpr);
    };
    measure();
    if (typeof W.ResizeObserver !== "function") {
      W.addEventListener("resize", measure);
      return;
    }
    const ro = new W.ResizeObserver(function (entries) {
      const e = entries[entries.length - 1];
      const box = e.devicePixelContentBoxSize && e.devicePixelContentBoxSize[0];
      const dpr = W.devicePixelRatio || 1;
      const w = e.contentRect.width * dpr, h = e.contentRect.height * dpr;
      // the exact device-pixel size where the browser gives it (and it agrees with
      // CSS size × devicePixelRatio: emulated ratios in some headless setups do not)
      if (box && Math.abs(box.inlineSize - w) <= 1 && Math.abs(box.blockSize - h) <= 1) {
        setCanvasSize(box.inlineSize, box.blockSize);
      } else {
        setCanvasSize(w, h);
      }
    });
    try {
      ro.observe(canvas, { box: "device-pixel-content-box" });
    } catch (err) {
      ro.observe(canvas); // browsers without device-pixel-content-box
    }
    // a change of devicePixelRatio alone (browser zoom, another screen)
    W.addEventListener("resize", measure);
  }

  // ---- input: orbit, zoom, pan (pointer events: mouse, pen and touch alike) ---------
  function watchInput(canvas) {
    const pointers = new Map(); // pointerId → {x, y} (CSS pixels)
    let pinch = 0;              // distance between two touches
    let panning = false;

    function cssHeight() { return Math.max(1, canvas.getBoundingClientRect().height); }
    function spread() {
      const p = Array.from(pointers.values());
      return Math.hypot(p[0].x - p[1].x, p[0].y - p[1].y);
    }

    canvas.addEventListener("pointerdown", function (e) {
      if (!state.space) return;
      try {
        canvas.setPointerCapture(e.pointerId);
      } catch (err) {
        // synthetic or already-released pointers cannot be captured; dragging still works inside the canvas
      }
      pointers.set(e.pointerId, { x: e.clientX, y: e.clientY });
      panning = e.button === 1 || e.button === 2 || e.shiftKey;
      if (pointers.size === 2) pinch = spread();
      canvas.classList.add("dragging");
      e.preventDefault();
    });
    canvas.addEventListener("pointermove", function (e) {
      const p = pointers.get(e.pointerId);
      if (!p) return;
      const dx = e.clientX - p.x, dy = e.clientY - p.y;
      p.x = e.clientX;
      p.y = e.clientY;
      if (pointers.size === 1) {
        if (panning) state.camera.pan(dx, dy, cssHeight());
        else state.camera.orbit(dx, dy, cssHeight());
      } else if (pointers.size === 2) {
        const d = spread();
        if (pinch > 0 && d > 0) state.camera.zoom(pinch / d);
        pinch = d;
      }
      interacted();
    });
    function end(e) {
      if (!pointers.delete(e.pointerId)) return;
      if (pointers.size < 2) pinch = 0;
      if (pointers.size === 0) canvas.classList.remove("dragging");
    }
    canvas.addEventListener("pointerup", end);
    canvas.addEventListener("pointercancel", end);
    canvas.addEventListener("lostpointercapture", end);
    canvas.addEventListener("wheel", function (e) {
      if (!state.space) return;
      e.preventDefault();
      const lines = e.deltaMode === 1 ? 16 : e.deltaMode === 2 ? 400 : 1;
      state.camera.zoom(Math.exp(Math.max(-200, Math.min(200, e.deltaY * lines)) * 0.0015));
      interacted();
    }, { passive: false });
    canvas.addEventListener("contextmenu", function (e) { e.preventDefault(); });
  }

  // ---- spaces ----------------------------------------------------------------------------
  const loading = {}; // script → Promise

  // Loads a generated space script with a <script> tag (works from file:// too);
  // rejects when it cannot be fetched or throws while it runs.
  function loadScript(src) {
    if (!loading[src]) {
      loading[src] = new Promise(function (resolve, reject) {
        const s = document.createElement("script");
        let thrown = null;
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
      });
    }
    return loading[src];
  }

  function entryOf(name) {
    return state.index.find(function (s) { return s.name === name; }) || null;
  }

  function glslFor(name) {
    const text = Object.prototype.hasOwnProperty.call(state.glslOverrides, name)
      ? state.glslOverrides[name] : Manifold.spaces[name].glsl;
    return state.debugBrokenShader ? text + BROKEN_GLSL : text;
  }

  function fail(title, err) {
    const e = err instanceof PageError ? err : new PageError("internal", String(err && err.message || err));
    state.error = e;
    state.ui.showError(title, e);
    return new Error(e.text());
  }

  function updateHash() {
    const params = { space: state.spaceName };
    if (state.options.curvature) params.curvature = 1;
    if (!state.options.grid) params.grid = 0;
    if (state.options.antialias !== DEFAULT_OPTIONS.antialias) params.aa = state.options.antialias;
    if (state.debugBrokenShader) params.debugBrokenShader = 1;
    const hash = MW.ui.formatHash(params);
    if (W.location.hash === hash) return;
    try {
      W.history.replaceState(null, "", hash);
    } catch (err) {
      W.location.hash = hash;
    }
  }

  // Switches to a space: loads its script, resets the camera, compiles its
  // trace shader and draws a frame. Returns the space's name.
  async function applySpace(name) {
    const entry = entryOf(name);
    if (!entry) {
      throw new Error("unknown space " + JSON.stringify(name) + "; the spaces are: " +
        state.index.map(function (s) { return s.name; }).join(", "));
    }
    if (!state.tracer) throw new Error(state.error ? state.error.text() : "the page has no WebGL2 renderer");
    try {
      await loadScript("gen/" + entry.script);
    } catch (err) {
      throw fail("The space could not be loaded", err);
    }
    const space = Manifold.spaces[name];
    if (!space || typeof space.glsl !== "string" || !space.camera) {
      throw fail("The space could not be loaded",
        new PageError("load", "gen/" + entry.script + " did not register the space " + JSON.stringify(name) +
          "; rebuild web/gen with `manifold build`."));
    }
    state.spaceName = name;
    state.space = space;
    state.ui.setSpace(entry);
    state.camera.set(space.camera);
    state.camera.maxDistance = 8 * space.bounds;
    updateHash();
    try {
      state.tracer.setSpaceGlsl(glslFor(name), "sphere tracer for space \"" + name + "\"");
    } catch (err) {
      if (state.debugBrokenShader && err instanceof PageError) {
        err.message += " The URL has debugBrokenShader=1, which breaks the shader on purpose; remove it to draw the space.";
      }
      throw fail("The surface cannot be drawn", err);
    }
    state.error = null;
    state.ui.clearError();
    state.dirty = true;
    renderNow();
    return name;
  }

  // Space switches run one after another; each call's promise settles with its own outcome.
  function setSpace(name) {
    const job = state.queue.then(function () { return applySpace(name); });
    state.queue = job.catch(function () {});
    state.current = job;
    return job;
  }

  function setOptions(o) {
    if (!o || typeof o !== "object") throw new TypeError("setOptions expects {curvature, grid, antialias}");
    if (o.antialias !== undefined && MW.tracer.ANTIALIAS_MODES.indexOf(o.antialias) < 0) {
      throw new TypeError("antialias must be one of " + MW.tracer.ANTIALIAS_MODES.join(", "));
    }
    if (o.curvature !== undefined) state.options.curvature = !!o.curvature;
    if (o.grid !== undefined) state.options.grid = !!o.grid;
    if (o.antialias !== undefined) state.options.antialias = o.antialias;
    state.ui.setCurvature(state.options.curvature);
    state.ui.setGrid(state.options.grid);
    state.ui.setAntialias(state.options.antialias);
    state.dirty = true;
    if (state.spaceName) updateHash();
    return Object.assign({}, state.options);
  }

  function optionsFromHash(params) {
    const o = {};
    if (params.curvature !== undefined) o.curvature = params.curvature === "1" || params.curvature === "true";
    if (params.grid !== undefined) o.grid = !(params.grid === "0" || params.grid === "false");
    if (params.aa !== undefined && MW.tracer.ANTIALIAS_MODES.indexOf(params.aa) >= 0) o.antialias = params.aa;
    return o;
  }

  // The space a hash asks for, or the first one (with a notice for an unknown name).
  function spaceFromHash(params) {
    if (params.space && entryOf(params.space)) return params.space;
    if (params.space) {
      state.ui.showNotice("There is no space " + JSON.stringify(params.space) + "; showing " +
        state.index[0].name + " instead.");
    }
    return state.index[0].name;
  }

  function onHashChange() {
    const params = MW.ui.parseHash(W.location.hash);
    const broken = params.debugBrokenShader === "1";
    setOptions(optionsFromHash(params));
    const name = spaceFromHash(params);
    if (name !== state.spaceName || broken !== state.debugBrokenShader) {
      state.debugBrokenShader = broken;
      setSpace(name).catch(function () {});
    }
  }

  // ---- context loss ------------------------------------------------------------------------
  function watchContext(canvas) {
    canvas.addEventListener("webglcontextlost", function (e) {
      e.preventDefault();
      state.contextLost = true;
      fail("The graphics context was lost",
        new PageError("context-lost", "The browser took the WebGL context away (a driver reset, or too many " +
          "pages using the GPU). The page will redraw if it is given back."));
    });
    canvas.addEventListener("webglcontextrestored", function () {
      state.contextLost = false;
      try {
        state.tracer = new MW.tracer.Tracer(state.gl);
      } catch (err) {
        state.tracer = null;
        fail("The surface cannot be drawn", err);
        return;
      }
      if (state.spaceName) setSpace(state.spaceName).catch(function () {});
    });
  }

  // ---- the scripting API ----------------------------------------------------------------
  function api() {
    return {
      // names of every space, in catalogue order
      spaces: function () { return state.index.map(function (s) { return s.name; }); },
      // the current space's name
      space: function () { return state.spaceName; },
      // switch space; resolves with its name when its shader is compiled and drawn,
      // rejects with an Error whose message is the error text
      setSpace: setSpace,
      // settles like the latest setSpace (the first one is the page's own)
      ready: function () { return state.current || Promise.reject(new Error(state.error ? state.error.text() : "not started")); },
      // surface point [x, y, z] under backing-store pixel (x, y), origin top-left, or null
      pick: function (x, y) {
        if ((needsFrame() || state.preview) && !state.error) renderNow(false);
        return MW.picking.pick(state.error ? null : state.tracer, x, y);
      },
      // draw one full-resolution frame now (synchronously)
      render: function () {
        if (!state.error) renderNow(false);
      },
      // draw a frame and wait for the GPU to finish it; returns its time in ms (also in stats().frameMs)
      measureFrame: measureFrame,
      // world point → [px, py] continuous backing-store pixels (pixel (i, j) spans [i, i+1) × [j, j+1)), or null behind the eye
      project: function (p) {
        if (!MW.camera.isVec3(p)) throw new TypeError("project expects [x, y, z]");
        return state.camera.project(p, state.width, state.height);
      },
      stats: statsObject,
      camera: function () { return state.camera.get(); },
      setCamera: function (c) {
        state.camera.set(c);
        return state.camera.get();
      },
      // the error text shown on the page, or null
      error: function () { return state.error ? state.error.text() : null; },
      options: function () {
        return Object.assign({}, state.options, {
          background: { top: BACKGROUND.top.slice(), bottom: BACKGROUND.bottom.slice() },
          curvatureScale: CURVATURE_SCALE,
          gridSpacing: GRID_SPACING,
        });
      },
      // {curvature: bool, grid: bool, antialias: "fxaa" | "ssaa" | "off"}
      setOptions: setOptions,
      // Replace a space's GLSL (null restores the generated one); rebuilds the
      // shader when it is the current space. For experiments and the error-path test.
      setSpaceGlsl: function (name, text) {
        if (!entryOf(name)) return Promise.reject(new Error("unknown space " + JSON.stringify(name)));
        if (text === null || text === undefined) delete state.glslOverrides[name];
        else if (typeof text !== "string") return Promise.reject(new TypeError("setSpaceGlsl expects GLSL text or null"));
        else state.glslOverrides[name] = text;
        return name === state.spaceName ? setSpace(name) : Promise.resolve(name);
      },
    };
  }

  // ---- start ---------------------------------------------------------------------------------
  function start() {
    state.ui = MW.ui.createUI({
      onSpace: function (name) { setSpace(name).catch(function () {}); },
      onCurvature: function (on) { setOptions({ curvature: on }); },
      onGrid: function (on) { setOptions({ grid: on }); },
      onAntialias: function (mode) { setOptions({ antialias: mode }); },
      onResetView: function () { if (state.space) state.camera.set(state.space.camera); },
    });
    W.manifold = api();
    const canvas = state.ui.canvas;

    const index = Manifold.spaceIndex;
    if (!Array.isArray(index) || index.length === 0) {
      state.current = Promise.reject(fail("The generated scripts are missing",
        new PageError("load", "web/gen/spaces.js was not found or lists no space. Build it with `manifold build` " +
          "(from the repository root) and reload.")));
      state.current.catch(function () {});
      return;
    }
    state.index = index.slice();
    state.ui.setSpaces(state.index);

    const params = MW.ui.parseHash(W.location.hash);
    state.debugBrokenShader = params.debugBrokenShader === "1";
    setOptions(optionsFromHash(params));
    const first = spaceFromHash(params);

    try {
      state.gl = MW.gl.createContext(canvas);
      state.tracer = new MW.tracer.Tracer(state.gl);
    } catch (err) {
      state.tracer = null;
      state.current = Promise.reject(fail(err.kind === "shader" ? "The surface cannot be drawn" : "WebGL2 is not available", err));
      state.current.catch(function () {});
      return;
    }
    watchContext(canvas);
    watchSize(canvas);
    watchInput(canvas);
    W.addEventListener("hashchange", onHashChange);
    setSpace(first).catch(function () {});
    W.requestAnimationFrame(frame);
  }

  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})(globalThis);
