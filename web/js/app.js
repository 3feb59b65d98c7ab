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
  const DEFAULT_OPTIONS = { curvature: false, grid: true, antialias: "fxaa", bodyDetail: "auto" };
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
    syncPixel: new Uint8Array(4), // measureFrame reads one pixel back into it
    fenceAt: 0,
    preview: false,         // the last frame was a half-resolution preview
    interactUntil: 0,       // the view counts as moving until then (performance.now())
    queue: Promise.resolve(),
    current: null,          // the promise of the latest space switch
    statsShownAt: 0,
    surfaceGen: 0,          // bumped whenever the traced picture must be redrawn (with the camera's version)
    world: null,            // the bodies (web/js/world.js) of the current space
    clock: new MW.world.Clock(),
    bodyRenderer: null,
    drawnWorldVersion: -1,  // world.version of the last frame drawn
    drawnWorld: null,
    grabPointer: null,      // the pointer holding a body, or null
    compare: null,          // the comparison view (web/js/compare.js) when it is shown, or null
  };

  // The comparison view's name in the space list and the URL (#space=compare-torus).
  const COMPARE = "compare-torus";

  // ---- bodies ------------------------------------------------------------------------
  // The world (web/js/world.js) runs the engine generated into each space script
  // (Manifold.spaces[NAME].engine); web/js/bodies.js draws its polygons over the
  // traced surface. drawBodies is the tracer's overlay hook, called after the
  // surface is shaded with the colour buffer bound (frame: gl, width, height,
  // scale, pixelAngle, positionTexture, normalTexture, viewProjection, eye).
  function drawBodies(frame) {
    frame.bodyDetail = state.options.bodyDetail;
    if (state.world && state.bodyRenderer) state.bodyRenderer.draw(state.world, frame);
  }

  // ---- rendering ------------------------------------------------------------------
  // A frame whose GPU time exceeds this makes the view draw half-resolution previews
  // while it moves (software rendering, weak GPUs); a sharp frame follows when it stops.
  const SLOW_FRAME_MS = 40;
  const INTERACTION_MS = 300;

  function canRender() {
    return state.tracer && !state.contextLost;
  }

  // Draws a frame now; preview = half resolution (while the view moves on a slow GPU).
  // The traced surface is reused when neither the camera nor the scenery changed
  // (moving bodies are drawn over it), unless retrace is true.
  function renderNow(preview, retrace) {
    if (!canRender()) return false;
    const gl = state.gl;
    if (state.dirty) state.surfaceGen++;
    state.tracer.configure(state.width, state.height, state.options.antialias, !!preview);
    const camera = state.camera;
    const key = retrace ? null : camera.version + ":" + state.surfaceGen;
    const traced = retrace || state.tracer.current.surfaceKey !== key;
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
    }, key);
    const now = performance.now();
    // time the GPU work of full traced frames with a fence, polled by the frame loop
    if (!preview && traced && !state.fence) {
      state.fence = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
      state.fenceAt = now;
      gl.flush();
    }
    state.dirty = false;
    state.preview = !!preview;
    state.cameraVersion = camera.version;
    state.drawnWorld = state.world;
    state.drawnWorldVersion = state.world ? state.world.version : -1;
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
  // retrace false: the frame reuses the traced surface when it can, as a frame
  // in which only bodies moved does (then it does not count as frameMs)
  function measureFrame(retrace) {
    if (!canRender() || state.error) return null;
    const gl = state.gl;
    const t0 = performance.now();
    renderNow(false, retrace !== false);
    // one pixel of the canvas read back: waits for the frame's last pass
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, state.syncPixel);
    const ms = performance.now() - t0;
    if (retrace === false) return ms;
    state.gpuFrameMs = ms;
    if (state.fence) {
      state.gl.deleteSync(state.fence);
      state.fence = null;
    }
    return state.gpuFrameMs;
  }

  // the traced surface is out of date
  function surfaceStale() {
    return state.dirty || state.cameraVersion !== state.camera.version;
  }
  // the bodies moved, came or went since the last frame
  function bodiesChanged() {
    return state.drawnWorld !== state.world || (state.world !== null && state.world.version !== state.drawnWorldVersion);
  }
  function needsFrame() {
    return surfaceStale() || bodiesChanged();
  }

  function fps(now) {
    const times = state.frameTimes;
    while (times.length && now - times[0] > 1000) times.shift();
    if (times.length < 2) return 0;
    return (times.length - 1) * 1000 / (times[times.length - 1] - times[0]);
  }

  function statsObject() {
    const w = state.world;
    const counters = w ? w.counters() : { bodies: 0, contacts: 0, warnings: 0, droppedContacts: 0 };
    return {
      fps: Math.round(fps(performance.now()) * 10) / 10,
      frameMs: state.gpuFrameMs === null ? null : Math.round(state.gpuFrameMs * 10) / 10,
      frames: state.frameCount,
      preview: state.preview,
      bodies: counters.bodies,
      contacts: counters.contacts,
      warnings: counters.warnings,
      droppedContacts: counters.droppedContacts,
      physicsMsPerStep: w && w.stepMs !== null ? Math.round(w.stepMs * 1000) / 1000 : null,
      steps: w ? w.steps : 0,
      paused: state.clock.paused,
      timeScale: state.clock.timeScale,
      width: state.width,
      height: state.height,
      space: state.spaceName,
      antialias: state.options.antialias,
      curvature: state.options.curvature,
      grid: state.options.grid,
      bodyDetail: state.options.bodyDetail,
      // how the last frame drew the bodies: as fans from the centre, coarser meshes, whole meshes
      bodyForms: state.bodyRenderer ? state.bodyRenderer.formCounts() : { fans: 0, coarser: 0, meshes: 0, triangles: 0 },
    };
  }

  function showStats(now) {
    if (now - state.statsShownAt < 250) return;
    state.statsShownAt = now;
    const s = statsObject();
    const rate = s.fps > 0 ? s.fps.toFixed(1) + " fps" : "idle";
    const cost = s.frameMs === null ? "" : " · frame " + Math.round(s.frameMs) + " ms";
    const physics = s.physicsMsPerStep === null ? "" : " · physics " + s.physicsMsPerStep.toFixed(2) + " ms/step";
    const trouble = " · warnings " + s.warnings + (s.droppedContacts ? " · dropped contacts " + s.droppedContacts : "");
    state.ui.setStats(rate + cost + (s.preview ? " (preview)" : "") + " · " + s.width + "×" + s.height +
      " px · bodies " + s.bodies + " · contacts " + s.contacts + physics + trouble + (s.paused ? " · paused" : ""));
    state.ui.setPaused(s.paused);
  }

  // Marks the view as moving (input changed the camera).
  function interacted() {
    state.interactUntil = performance.now() + INTERACTION_MS;
  }

  function frame(now) {
    W.requestAnimationFrame(frame);
    pollFence(now);
    const w = state.world;
    if (w && !state.error) {
      const n = state.clock.due(now, w.param("dt"), w.stepMs);
      if (n > 0 && w.count() > 0) w.step(n);
      if (n > 0 && state.compare && state.compare.flat.count() > 0) state.compare.flat.step(n);
    }
    if (!state.error) {
      const moving = now < state.interactUntil;
      const slow = state.gpuFrameMs !== null && state.gpuFrameMs > SLOW_FRAME_MS;
      if (surfaceStale()) renderNow(moving && slow);
      else if (state.preview && !moving) renderNow(false); // the sharp frame once the view stops
      else if (bodiesChanged()) renderNow(state.preview);
      if (state.compare) state.compare.render(false);
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

  // ---- grabbing bodies ------------------------------------------------------------------
  // Mouse joint settings: a 5 Hz spring, 0.7 of critical damping, and a force
  // limit of 1000 × the body's mass (world.grab).
  const GRAB = { frequency: 5, damping: 0.7 };

  // The surface point under backing-store pixel (x, y) of the frame on screen, or null.
  function surfacePoint(x, y) {
    if (state.error || !state.tracer) return null;
    if (surfaceStale()) renderNow(false);
    return MW.picking.pick(state.tracer, x, y);
  }

  // Grabs the body under pixel (x, y), if any; returns whether one was grabbed.
  function grabAt(x, y) {
    const w = state.world;
    if (!w) return false;
    const q = surfacePoint(x, y);
    if (!q) return false;
    const hit = w.pick(q);
    if (!hit) return false;
    w.grab(hit.index, hit.sign, q, GRAB);
    return true;
  }

  // Moves the grabbed body's target to the surface under pixel (x, y); false
  // (and the target stays) off the surface or when nothing is held.
  function dragTo(x, y) {
    const w = state.world;
    if (!w || w.grabbed < 0) return false;
    const q = surfacePoint(x, y);
    if (!q) return false;
    w.drag(q);
    return true;
  }

  function releaseGrab() {
    if (state.world && state.world.grabbed >= 0) state.world.release();
  }

  // ---- input: grab bodies, orbit, zoom, pan (pointer events: mouse, pen and touch alike) ---
  function watchInput(canvas) {
    const pointers = new Map(); // pointerId → {x, y} (CSS pixels)
    let pinch = 0;              // distance between two touches
    let panning = false;

    function cssHeight() { return Math.max(1, canvas.getBoundingClientRect().height); }
    function spread() {
      const p = Array.from(pointers.values());
      return Math.hypot(p[0].x - p[1].x, p[0].y - p[1].y);
    }

    function capture(e) {
      try {
        canvas.setPointerCapture(e.pointerId);
      } catch (err) {
        // synthetic or already-released pointers cannot be captured; dragging still works inside the canvas
      }
    }
    function pixelOf(e) { return MW.picking.clientToPixel(canvas, e.clientX, e.clientY); }

    canvas.addEventListener("pointerdown", function (e) {
      if (!state.space) return;
      if (state.grabPointer !== null) { e.preventDefault(); return; } // one body at a time; other fingers wait
      // a first primary press on a body grabs it; anywhere else the view orbits
      if (pointers.size === 0 && e.button === 0 && !e.shiftKey) {
        const px = pixelOf(e);
        if (grabAt(px[0], px[1])) {
          capture(e);
          state.grabPointer = e.pointerId;
          canvas.classList.add("holding");
          e.preventDefault();
          return;
        }
      }
      capture(e);
      pointers.set(e.pointerId, { x: e.clientX, y: e.clientY });
      panning = e.button === 1 || e.button === 2 || e.shiftKey;
      if (pointers.size === 2) pinch = spread();
      canvas.classList.add("dragging");
      e.preventDefault();
    });
    canvas.addEventListener("pointermove", function (e) {
      if (e.pointerId === state.grabPointer) {
        const px = pixelOf(e);
        dragTo(px[0], px[1]);
        return;
      }
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
      if (e.pointerId === state.grabPointer) {
        state.grabPointer = null;
        canvas.classList.remove("holding");
        releaseGrab();
        return;
      }
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

  // The hash says how many bodies there are when that is not the default scene's count.
  function updateHash() {
    const params = { space: currentName() };
    const w = state.world;
    if (w && !state.compare && w.count() !== defaultBodyCount()) params.bodies = w.count();
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

  function defaultBodyCount() {
    return state.space && Array.isArray(state.space.scene) ? state.space.scene.length : 0;
  }

  // A new world for the current space holding `scene` (parsed), or the default
  // scene cut or filled to `bodies` bodies (null: as it is). A space script
  // without an engine (an old web/gen) gets no world and a notice.
  function newWorld(scene, bodies) {
    releaseGrab();
    state.world = null;
    state.clock.reset();
    if (!state.space.engine) {
      state.ui.showNotice("gen/" + entryOf(state.spaceName).script + " has no engine: rebuild web/gen with `manifold build` to get bodies.");
      return;
    }
    const w = new MW.world.World(state.spaceName, state.space);
    if (scene) w.load(scene);
    else w.loadDefault(bodies === null || bodies === undefined ? undefined : bodies);
    state.world = w;
    state.ui.setSimulation(simulationSettings());
  }

  // Switches to a space: loads its script, resets the camera, compiles its
  // trace shader, loads the space's default scene (or `how.scene`, or the
  // default cut or filled to `how.bodies` bodies; `how.keep`: keeps the world
  // and the camera when the space is the current one) and draws a frame. Returns the space's name.
  async function applySpace(name, how) {
    how = how || {};
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
    const keep = how.keep && state.world && state.world.name === name && state.space === space;
    state.spaceName = name;
    state.space = space;
    state.ui.setSpace(entry);
    if (!keep) {
      state.camera.set(space.camera);
      state.camera.maxDistance = 8 * space.bounds;
      try {
        newWorld(how.scene || null, how.bodies);
      } catch (err) {
        state.world = null;
        state.ui.showNotice("The scene could not be loaded: " + err.message);
      }
    }
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

  // ---- the comparison view "Torus: embedded vs flat" (web/js/compare.js) ----
  function currentName() { return state.compare ? COMPARE : state.spaceName; }

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
  function comparisonNote(def) {
    const K = Manifold.spaces[def.embedded].curvature, K0 = Manifold.spaces[def.flat].curvature;
    const at = function (z) { const p = def.fromSquare(0, 0, z); return K(p[0], p[1], p[2]); };
    const f = function (x) { return (x >= 0 ? "+" : "\u2212") + Math.abs(x).toFixed(2); };
    return "Curvature: the embedded torus has K = " + f(at(0)) + " on its outer equator and " + f(at(def.half)) +
      " on its inner one (Curvature colours it); the flat torus has K = " + f(K0(0, 0, 0)).replace("+", "") +
      " everywhere. One scene in the torus's angles on both: the difference in motion is the difference in metric.";
  }

  async function applyComparison() {
    if (!state.tracer) throw new Error(state.error ? state.error.text() : "the page has no WebGL2 renderer");
    try {
      await loadScript("gen/compare-torus.js");
    } catch (err) {
      throw fail("The comparison could not be loaded", err);
    }
    const def = Manifold.comparisons && Manifold.comparisons.torus;
    if (!def || !entryOf(def.embedded) || !entryOf(def.flat)) {
      throw fail("The comparison could not be loaded", new PageError("load",
        "gen/compare-torus.js did not register the comparison, or its spaces are missing; rebuild web/gen with `manifold build`."));
    }
    try {
      await loadScript("gen/" + entryOf(def.flat).script);
    } catch (err) {
      throw fail("The comparison could not be loaded", err);
    }
    const names = state.index.map(function (e) { return e.name; });
    await applySpace(def.embedded, { scene: MW.world.parseScene(def.scenes.embedded, names) });
    const flat = new MW.world.World(def.flat, Manifold.spaces[def.flat]);
    flat.load(MW.world.parseScene(def.scenes.flat, names));
    comparisonPanes(true);
    try {
      state.compare = new MW.compare.Comparison(def, state.world, flat, state.camera, {
        mainCanvas: state.ui.canvas,
        flatCanvas: document.getElementById("view-flat"),
        squareEmbedded: document.getElementById("square-embedded"),
        squareFlat: document.getElementById("square-flat"),
      }, {
        options: function () {
          return Object.assign({}, state.options, { curvatureScale: CURVATURE_SCALE, gridSpacing: GRID_SPACING, background: BACKGROUND });
        },
        bounds: function () { return state.space ? state.space.bounds : 1; },
        curvatureOf: function (p) { return Manifold.spaces[def.embedded].curvature(p[0], p[1], p[2]); },
        grab: GRAB,
        interacted: interacted,
      });
    } catch (err) {
      comparisonPanes(false);
      throw fail("The comparison cannot be drawn", err);
    }
    document.getElementById("compare-note").textContent = comparisonNote(def);
    state.ui.setSpace({ name: COMPARE, description: def.title + ": " + def.embedded + " and " + def.flat + " side by side (paper Fig. 17)" });
    state.clock.reset();
    updateHash();
    state.dirty = true;
    renderNow();
    state.compare.render(true);
    return COMPARE;
  }

  // Space switches run one after another; each call's promise settles with its own outcome.
  function setSpace(name, how) {
    const job = state.queue.then(function () {
      leaveComparison();
      return name === COMPARE ? applyComparison() : applySpace(name, how);
    });
    state.queue = job.catch(function () {});
    state.current = job;
    return job;
  }

  function setOptions(o) {
    if (!o || typeof o !== "object") throw new TypeError("setOptions expects {curvature, grid, antialias, bodyDetail}");
    if (o.antialias !== undefined && MW.tracer.ANTIALIAS_MODES.indexOf(o.antialias) < 0) {
      throw new TypeError("antialias must be one of " + MW.tracer.ANTIALIAS_MODES.join(", "));
    }
    if (o.bodyDetail !== undefined && MW.bodies.BODY_DETAILS.indexOf(o.bodyDetail) < 0) {
      throw new TypeError("bodyDetail must be one of " + MW.bodies.BODY_DETAILS.join(", "));
    }
    if (o.curvature !== undefined) state.options.curvature = !!o.curvature;
    if (o.grid !== undefined) state.options.grid = !!o.grid;
    if (o.antialias !== undefined) state.options.antialias = o.antialias;
    if (o.bodyDetail !== undefined) state.options.bodyDetail = o.bodyDetail;
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
    if (params.space === COMPARE) return COMPARE;
    if (params.space && entryOf(params.space)) return params.space;
    if (params.space) {
      state.ui.showNotice("There is no space " + JSON.stringify(params.space) + "; showing " +
        state.index[0].name + " instead.");
    }
    return state.index[0].name;
  }

  // bodies=N from the hash: a whole number from 0 to 1000, else null (the default scene)
  function bodiesFromHash(params) {
    if (params.bodies === undefined) return null;
    const n = Number(params.bodies);
    if (params.bodies === "" || !Number.isInteger(n) || n < 0 || n > 1000) {
      state.ui.showNotice("bodies=" + params.bodies + " in the link is not a whole number from 0 to 1000; showing the default scene.");
      return null;
    }
    return n;
  }

  function onHashChange() {
    const params = MW.ui.parseHash(W.location.hash);
    const broken = params.debugBrokenShader === "1";
    setOptions(optionsFromHash(params));
    const name = spaceFromHash(params);
    const bodies = bodiesFromHash(params);
    if (name !== currentName() || broken !== state.debugBrokenShader) {
      state.debugBrokenShader = broken;
      setSpace(name, { bodies: bodies }).catch(function () {});
    } else if (state.world && !state.compare && (bodies === null ? defaultBodyCount() : bodies) !== state.world.count()) {
      try {
        releaseGrab();
        state.world.loadDefault(bodies === null ? undefined : bodies);
      } catch (err) {
        state.ui.showNotice("The scene could not be loaded: " + err.message);
      }
      updateHash();
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
        state.bodyRenderer = new MW.bodies.BodyRenderer(state.gl);
      } catch (err) {
        state.tracer = null;
        fail("The surface cannot be drawn", err);
        return;
      }
      if (state.spaceName) setSpace(state.spaceName, { keep: true }).catch(function () {});
    });
  }

  // ---- the simulation: scenes, bodies, settings ------------------------------------------
  function requireWorld() {
    if (!state.world) {
      throw new Error(state.space ? "the space " + state.spaceName + " has no engine (rebuild web/gen with `manifold build`)"
        : "no space is loaded yet");
    }
    return state.world;
  }

  function simulationSettings() {
    const w = state.world;
    return {
      paused: state.clock.paused,
      timeScale: state.clock.timeScale,
      gravity: w ? w.param("gravityOn") > 0 : true,
      friction: w ? w.param("friction") : null,
      restitution: w ? w.param("restitution") : null,
    };
  }

  // {paused, timeScale, gravity, friction, restitution}: any subset; throws on bad values.
  function setSimulation(o) {
    if (!o || typeof o !== "object") throw new TypeError("setSimulation expects {paused, timeScale, gravity, friction, restitution}");
    const num = function (k, lo, hi) {
      const x = o[k];
      if (typeof x !== "number" || !isFinite(x) || x < lo || x > hi) throw new RangeError(k + " must be a number from " + lo + " to " + hi);
      return x;
    };
    const p = {};
    if (o.timeScale !== undefined) num("timeScale", 0, 10);
    if (o.friction !== undefined) p.friction = num("friction", 0, 10);
    if (o.restitution !== undefined) p.restitution = num("restitution", 0, 1);
    if (o.gravity !== undefined) p.gravityOn = o.gravity ? 1 : 0;
    if (Object.keys(p).length) requireWorld().setParams(p);
    if (o.timeScale !== undefined) state.clock.timeScale = o.timeScale;
    if (o.paused !== undefined) {
      state.clock.paused = !!o.paused;
      state.clock.reset();
    }
    const out = simulationSettings();
    state.ui.setSimulation(out);
    return out;
  }

  function bodiesChangedCount() {
    updateHash();
  }

  // Adds a body from a scene body (JSON value); returns its index or throws.
  function addBody(spec) {
    const i = requireWorld().add(spec);
    bodiesChangedCount();
    return i;
  }

  // A body of the given shape at a free visible surface point: the view's
  // centre if free, else random pixels of the view's middle; else a seeded
  // random point of the space.
  function addAtView(shape) {
    const w = requireWorld();
    const scene = state.space.scene || [];
    const size = scene.length ? scene[0].size : 0.15;
    const W0 = state.width, H0 = state.height;
    for (let k = 0; k < 60; k++) {
      const x = k === 0 ? W0 / 2 : W0 * (0.2 + 0.6 * Math.random());
      const y = k === 0 ? H0 / 2 : H0 * (0.2 + 0.6 * Math.random());
      const q = surfacePoint(x, y);
      if (!q || w.pick(q)) continue;
      const boundary = state.space.boundary;
      if (boundary && boundary(q[0], q[1], q[2]) < size) continue;
      const i = w.addFree({ shape: shape, size: size, p: q, angle: 2 * Math.PI * Math.random() });
      if (i < 0) continue;
      bodiesChangedCount();
      return i;
    }
    const before = w.count();
    w.fill(before + 1, [{ shape: shape, size: size }]);
    bodiesChangedCount();
    if (w.count() === before) throw new Error("no free place for another body was found");
    return before;
  }

  // The space's default scene again, cut or filled to n bodies (default: as it is).
  function resetScene(n) {
    if (n !== undefined && n !== null && !(Number.isInteger(n) && n >= 0 && n <= 1000)) {
      throw new RangeError("resetScene(n) expects a whole number of bodies from 0 to 1000");
    }
    const w = requireWorld();
    releaseGrab();
    if (state.compare) {
      // the comparison's own scene on both
      const def = state.compare.def, names = state.index.map(function (e) { return e.name; });
      if (state.compare.held) state.compare.held.world.release();
      w.load(MW.world.parseScene(def.scenes.embedded, names));
      state.compare.flat.load(MW.world.parseScene(def.scenes.flat, names));
      state.clock.reset();
      state.ui.setSimulation(simulationSettings());
      return w.count();
    }
    w.loadDefault(n === null ? undefined : n);
    state.clock.reset();
    state.ui.setSimulation(simulationSettings());
    bodiesChangedCount();
    return w.count();
  }

  function clearBodies() {
    requireWorld().clear();
    if (state.compare) state.compare.flat.clear();
    bodiesChangedCount();
  }

  // Loads a scene (JSON text or value); a scene of another space switches to it.
  // Resolves with the number of bodies; rejects (and shows why on the page) on bad input.
  function loadScene(json) {
    if (state.compare) {
      // a scene is one space's: show that space alone
      const parsed = (function () { try { return MW.world.parseScene(json, state.index.map(function (e) { return e.name; })); } catch (err) { return null; } })();
      if (parsed) return setSpace(parsed.space, { scene: parsed }).then(function () { return state.world ? state.world.count() : 0; });
    }
    let scene;
    try {
      scene = MW.world.parseScene(json, state.index.map(function (e) { return e.name; }));
    } catch (err) {
      const e = new Error("The scene could not be loaded: " + err.message);
      state.ui.showNotice(e.message);
      return Promise.reject(e);
    }
    const done = function () {
      state.ui.setSimulation(simulationSettings());
      updateHash();
      return state.world ? state.world.count() : 0;
    };
    if (scene.space !== state.spaceName) {
      return setSpace(scene.space, { scene: scene }).then(function () {
        if (!state.world || state.world.count() !== scene.bodies.length) {
          throw new Error("The scene could not be loaded into " + scene.space + (state.ui ? "; see the notice on the page" : ""));
        }
        return done();
      });
    }
    try {
      requireWorld();
      // all or nothing: the world is only replaced when every body fits
      const w = new MW.world.World(state.spaceName, state.space);
      w.load(scene);
      releaseGrab();
      state.world = w;
      state.clock.reset();
    } catch (err) {
      const e = new Error("The scene could not be loaded: " + err.message);
      state.ui.showNotice(e.message);
      return Promise.reject(e);
    }
    state.ui.hideNotice();
    return Promise.resolve(done());
  }

  function currentScene() {
    return requireWorld().scene();
  }

  // The current scene as a download (manifold-SPACE.json).
  function saveSceneFile() {
    const text = JSON.stringify(currentScene(), null, 2) + "\n";
    const blob = new Blob([text], { type: "application/json" });
    const a = document.createElement("a");
    a.href = URL.createObjectURL(blob);
    a.download = "manifold-" + state.spaceName + ".json";
    document.body.appendChild(a);
    a.click();
    a.remove();
    setTimeout(function () { URL.revokeObjectURL(a.href); }, 1000);
  }

  function loadSceneFile(file) {
    const reader = new FileReader();
    reader.onload = function () { loadScene(String(reader.result)).catch(function () {}); };
    reader.onerror = function () { state.ui.showNotice("The file " + file.name + " could not be read."); };
    reader.readAsText(file);
  }

  // Reports an error of a control as a notice (the controls never throw into the page).
  function guarded(f) {
    return function () {
      try {
        return f.apply(null, arguments);
      } catch (err) {
        state.ui.showNotice(err.message || String(err));
        return undefined;
      }
    };
  }

  // ---- the scripting API ----------------------------------------------------------------
  function api() {
    return {
      // names of every space, in catalogue order
      spaces: function () { return state.index.map(function (s) { return s.name; }); },
      // the current space's name ("compare-torus" in the comparison view)
      space: currentName,
      // switch space; resolves with its name when its shader is compiled and drawn,
      // rejects with an Error whose message is the error text
      setSpace: setSpace,
      // settles like the latest setSpace (the first one is the page's own)
      ready: function () { return state.current || Promise.reject(new Error(state.error ? state.error.text() : "not started")); },
      // surface point [x, y, z] under backing-store pixel (x, y), origin top-left, or null
      pick: function (x, y) {
        if ((surfaceStale() || state.preview) && !state.error) renderNow(false);
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
      // {curvature: bool, grid: bool, antialias: "fxaa" | "ssaa" | "off", bodyDetail: "auto" | "mesh"}
      setOptions: setOptions,
      // Replace a space's GLSL (null restores the generated one); rebuilds the
      // shader when it is the current space. For experiments and the error-path test.
      // ---- bodies (the engine of the current space) ----
      // add a body from a scene body {shape, size, density, static, p, v, angle, omega}; returns its index or throws
      addBody: addBody,
      // remove every body
      clear: clearBodies,
      // the space's default scene again (default parameters), cut or filled to n bodies; returns the count
      resetScene: resetScene,
      // n physics steps now, synchronously (the polygons are then current); returns the body count
      step: function (n) {
        n = n === undefined ? 1 : n;
        if (!Number.isInteger(n) || n < 0 || n > 1e6) throw new RangeError("step(n) expects a whole number of steps from 0 to 1000000");
        const w = requireWorld();
        w.step(n);
        if (state.compare) state.compare.flat.step(n);
        return w.count();
      },
      // the bodies in the scene format
      bodies: function () { return state.world ? state.world.bodies() : []; },
      // the comparison view (setSpace("compare-torus")), or null: both worlds' bodies,
      // the held pane, frames drawn, the curvature note
      comparison: function () {
        const c = state.compare;
        if (!c) return null;
        return {
          name: COMPARE,
          panes: ["torus-embedded", "torus-flat", "square-embedded", "square-flat"],
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
        if (["torus-embedded", "torus-flat", "square-embedded", "square-flat"].indexOf(pane) < 0) throw new RangeError("unknown pane " + JSON.stringify(pane));
        if (pane === "torus-embedded" && surfaceStale()) renderNow(false);
        state.compare.render(true);
        return state.compare.clientPoint(pane, i);
      },
      pause: function () { setSimulation({ paused: true }); },
      resume: function () { setSimulation({ paused: false }); },
      // {paused, timeScale, gravity, friction, restitution}
      simulation: simulationSettings,
      setSimulation: setSimulation,
      // grab the body under backing-store pixel (x, y) with the mouse joint; true if one was grabbed
      grab: function (x, y) {
        if (typeof x !== "number" || typeof y !== "number") throw new TypeError("grab(x, y) expects canvas backing-store pixels");
        releaseGrab();
        return grabAt(x, y);
      },
      // move the grabbed body's target to the surface under (x, y); false off the surface or when nothing is held
      drag: function (x, y) {
        if (typeof x !== "number" || typeof y !== "number") throw new TypeError("drag(x, y) expects canvas backing-store pixels");
        return dragTo(x, y);
      },
      release: releaseGrab,
      // the index of the grabbed body, or -1
      grabbed: function () { return state.world ? state.world.grabbed : -1; },
      // load a scene (JSON text or value); a Promise of the body count, rejected with the problem
      loadScene: loadScene,
      // the current scene as a JSON value (what saveScene downloads)
      scene: currentScene,
      setSpaceGlsl: function (name, text) {
        if (!entryOf(name)) return Promise.reject(new Error("unknown space " + JSON.stringify(name)));
        if (text === null || text === undefined) delete state.glslOverrides[name];
        else if (typeof text !== "string") return Promise.reject(new TypeError("setSpaceGlsl expects GLSL text or null"));
        else state.glslOverrides[name] = text;
        return name === state.spaceName ? setSpace(name, { keep: true }) : Promise.resolve(name);
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
      onAdd: guarded(function (shape) { addAtView(shape); }),
      onClear: guarded(clearBodies),
      onReset: guarded(function () { resetScene(); }),
      onPause: guarded(function () { setSimulation({ paused: !state.clock.paused }); }),
      onStep: guarded(function () { setSimulation({ paused: true }); requireWorld().step(1); }),
      onTimeScale: guarded(function (x) { setSimulation({ timeScale: x }); }),
      onGravity: guarded(function (on) { setSimulation({ gravity: on }); }),
      onFriction: guarded(function (x) { setSimulation({ friction: x }); }),
      onRestitution: guarded(function (x) { setSimulation({ restitution: x }); }),
      onSave: guarded(saveSceneFile),
      onLoad: guarded(loadSceneFile),
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
    state.ui.setSpaces(state.index.concat([{ name: COMPARE, label: "Torus: embedded vs flat", description: "the embedded and the flat torus side by side" }]));

    const params = MW.ui.parseHash(W.location.hash);
    state.debugBrokenShader = params.debugBrokenShader === "1";
    setOptions(optionsFromHash(params));
    const first = spaceFromHash(params);
    const firstBodies = bodiesFromHash(params);

    try {
      state.gl = MW.gl.createContext(canvas);
      state.tracer = new MW.tracer.Tracer(state.gl);
      state.bodyRenderer = new MW.bodies.BodyRenderer(state.gl);
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
    setSpace(first, { bodies: firstBodies }).catch(function () {});
    W.requestAnimationFrame(frame);
  }

  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})(globalThis);
