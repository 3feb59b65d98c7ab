// The frame loop and what it draws: each animation frame runs the physics
// steps the clock says are due, then redraws the view when the camera, the
// scenery or the bodies changed (reusing the traced surface when only bodies
// moved; half-resolution previews while the view moves on a slow GPU), times
// the GPU with a fence, and shows the stats line. Also the canvas's size in
// device pixels (HiDPI), measureFrame, and afterDraw (the canvas read right
// after a draw, for the capture buttons).
/* exported ManifoldWebFrame */
var ManifoldWebFrame = (function (W) {
  "use strict";
  const MW = W.ManifoldWeb;
  const P = MW.page, state = P.state;

  // A frame whose GPU time exceeds this makes the view draw half-resolution previews
  // while it moves (software rendering, weak GPUs); a sharp frame follows when it stops.
  const SLOW_FRAME_MS = 40;
  const INTERACTION_MS = 300;

  // What the frames drawn so far were, and their timing (this file's own).
  const drawn = {
    cameraVersion: -1,      // the camera's, the flat view's viewer's and the flat model of the last frame drawn
    viewerVersion: -1,
    model: /** @type {string | null} */ (null),
    discVersion: -1,        // the flat view's boost (world → view) and its inverse, as floats, at this version
    boost: new Float32Array(9),
    toWorld: new Float32Array(9),
    frameTimes: /** @type {number[]} */ ([]), // performance.now() of recent frames
    frameCount: 0,
    gpuFrameMs: /** @type {number | null} */ (null), // GPU time of the last timed full frame
    fence: /** @type {WebGLSync | null} */ (null),
    syncPixel: new Uint8Array(4), // measureFrame reads one pixel back into it
    fenceAt: 0,
    interactUntil: 0,       // the view counts as moving until then (performance.now())
    statsShownAt: 0,
    surfaceGen: 0,          // bumped whenever the traced picture must be redrawn (with the camera's version)
    worldVersion: -1,       // world.version of the last frame drawn
    toolsVersion: -1,       // tools.version of the last frame drawn (the curves)
    world: /** @type {ManifoldWeb.World | null} */ (null),
    // what afterDraw was asked for since the last frame
    captures: /** @type {((canvas: HTMLCanvasElement | null) => void)[]} */ ([]),
  };

  // ---- bodies ------------------------------------------------------------------------
  // The world (web/js/world.js) runs the engine generated into each space script
  // (Manifold.spaces[NAME].engine); web/js/bodies.js draws its polygons over the
  // traced surface, and web/js/tools.js the curves over them (geodesic, a
  // throw's preview, trails). drawBodies is the tracer's overlay hook, called after the
  // surface is shaded with the colour buffer bound (frame: gl, width, height,
  // scale, pixelAngle, positionTexture, normalTexture, viewProjection, eye, bounds).
  /** @param {ManifoldWeb.OverlayFrame} frame */
  function drawBodies(frame) {
    frame.bodyDetail = state.options.bodyDetail;
    if (state.world && state.bodyRenderer) state.bodyRenderer.draw(state.world.drawn(), frame, state.options.dimSleeping);
    MW.tools.draw(frame);
  }

  // ---- rendering ------------------------------------------------------------------
  function canRender() {
    return state.tracer && !state.contextLost;
  }

  // Draws a frame now; preview = half resolution (while the view moves on a slow GPU).
  // The traced surface is reused when neither the camera nor the scenery changed
  // (moving bodies are drawn over it), unless retrace is true.
  /** @param {boolean} [preview] @param {boolean} [retrace] */
  function renderNow(preview, retrace) {
    if (!canRender()) return false;
    const gl = state.gl;
    if (state.dirty) drawn.surfaceGen++;
    state.tracer.configure(state.width, state.height, state.options.antialias, !!preview);
    const camera = state.camera;
    const model = P.flatModel(), disc = state.disc;
    state.ui.setFlatHelp(model !== null);
    const key = retrace ? null : camera.version + "/" + disc.version + "/" + model + ":" + drawn.surfaceGen;
    const traced = retrace || state.tracer.current.surfaceKey !== key;
    const radius = disc.radius(state.width, state.height);
    if (model !== null && drawn.discVersion !== disc.version) {
      drawn.boost.set(disc.boost);
      drawn.toWorld.set(W.Manifold.hyperbolic.inverse(...disc.boost));
      drawn.discVersion = disc.version;
    }
    state.tracer.render({
      camera: camera,
      bounds: state.space ? state.space.bounds : 1,
      curvature: state.options.curvature,
      curvatureScale: P.CURVATURE_SCALE,
      grid: state.options.grid,
      gridSpacing: P.GRID_SPACING,
      background: P.BACKGROUND,
      flat: model === null ? null : { model: model, toWorld: drawn.toWorld, radius: radius },
    }, function (frame) {
      frame.viewProjection = camera.viewProjection(state.width / state.height, 0.01, 100);
      frame.eye = /** @type {Manifold.Vec3} */ (camera.eye.slice());
      frame.bounds = state.space ? state.space.bounds : 0;
      if (model !== null) {
        frame.flat = { model: model, boost: drawn.boost, radius: radius * frame.scale };
        frame.pixelAngle = 0; // (chooseForms: a flat view draws every body's whole mesh)
      }
      drawBodies(frame);
    }, key);
    const now = performance.now();
    // time the GPU work of full traced frames with a fence, polled by the frame loop
    if (!preview && traced && !drawn.fence) {
      drawn.fence = gl.fenceSync(gl.SYNC_GPU_COMMANDS_COMPLETE, 0);
      drawn.fenceAt = now;
      gl.flush();
    }
    state.dirty = false;
    state.preview = !!preview;
    drawn.cameraVersion = camera.version;
    drawn.viewerVersion = disc.version;
    drawn.model = model;
    drawn.world = state.world;
    drawn.worldVersion = state.world ? state.world.version : -1;
    drawn.toolsVersion = MW.tools.tools.version;
    drawn.frameCount++;
    drawn.frameTimes.push(now);
    return true;
  }

  /** @param {number} now */
  function pollFence(now) {
    const gl = state.gl;
    if (!drawn.fence || !gl) return;
    if (gl.isContextLost()) { drawn.fence = null; return; }
    if (gl.getSyncParameter(drawn.fence, gl.SYNC_STATUS) !== gl.SIGNALED) return;
    gl.deleteSync(drawn.fence);
    drawn.fence = null;
    drawn.gpuFrameMs = now - drawn.fenceAt;
  }

  // GPU time of a full frame measured by a one-pixel read-back (which waits for it).
  // retrace false: the frame reuses the traced surface when it can, as a frame
  // in which only bodies moved does (then it does not count as frameMs)
  /** @param {boolean} [retrace] */
  function measureFrame(retrace) {
    if (!canRender() || state.error) return null;
    const gl = state.gl;
    const t0 = performance.now();
    renderNow(false, retrace !== false);
    // one pixel of the canvas read back: waits for the frame's last pass
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, drawn.syncPixel);
    const ms = performance.now() - t0;
    if (retrace === false) return ms;
    drawn.gpuFrameMs = ms;
    if (drawn.fence) {
      state.gl.deleteSync(drawn.fence);
      drawn.fence = null;
    }
    return drawn.gpuFrameMs;
  }

  // the traced surface is out of date (the camera, the flat views' viewer or the flat model changed)
  function surfaceStale() {
    return state.dirty || drawn.cameraVersion !== state.camera.version || drawn.viewerVersion !== state.disc.version ||
      drawn.model !== P.flatModel();
  }
  // the bodies moved, came or went, or the curves changed, since the last frame
  function bodiesChanged() {
    return drawn.world !== state.world || (state.world !== null && state.world.version !== drawn.worldVersion) ||
      drawn.toolsVersion !== MW.tools.tools.version;
  }

  /** @param {number} now */
  function fps(now) {
    const times = drawn.frameTimes;
    while (times.length && now - times[0] > 1000) times.shift();
    if (times.length < 2) return 0;
    return (times.length - 1) * 1000 / (times[times.length - 1] - times[0]);
  }

  /** @returns {Manifold.Stats} */
  function statsObject() {
    const w = state.world;
    const counters = w ? w.counters() : { bodies: 0, awake: 0, islands: 0, joints: 0, contacts: 0, warnings: 0, droppedContacts: 0 };
    return {
      fps: Math.round(fps(performance.now()) * 10) / 10,
      frameMs: drawn.gpuFrameMs === null ? null : Math.round(drawn.gpuFrameMs * 10) / 10,
      frames: drawn.frameCount,
      preview: state.preview,
      bodies: counters.bodies,
      awake: counters.awake,
      islands: counters.islands,
      joints: counters.joints,
      contacts: counters.contacts,
      warnings: counters.warnings,
      droppedContacts: counters.droppedContacts,
      physicsMsPerStep: w && w.stepMs !== null ? Math.round(w.stepMs * 1000) / 1000 : null,
      steps: w ? w.steps : 0,
      thread: MW.physicsThread.inUse(),
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

  /** @param {number} now */
  function showStats(now) {
    if (now - drawn.statsShownAt < 250) return;
    drawn.statsShownAt = now;
    const s = statsObject();
    const rate = s.fps > 0 ? s.fps.toFixed(1) + " fps" : "idle";
    const cost = s.frameMs === null ? "" : " · frame " + Math.round(s.frameMs) + " ms";
    const thread = MW.physicsThread.describe();
    const physics = s.physicsMsPerStep === null ? "" : " · physics " + s.physicsMsPerStep.toFixed(2) + " ms/step" + (thread === null ? "" : " (" + thread + ")");
    const trouble = " · warnings " + s.warnings + (s.droppedContacts ? " · dropped contacts " + s.droppedContacts : "");
    state.ui.setStats(rate + cost + (s.preview ? " (preview)" : "") + " · " + s.width + "×" + s.height +
      " px · bodies " + s.bodies + " · contacts " + s.contacts + physics + trouble + (s.paused ? " · paused" : ""));
    state.ui.setPaused(s.paused);
  }

  // ---- reading the canvas -------------------------------------------------------------
  // The context keeps no drawing buffer once a frame is shown (preserveDrawingBuffer
  // is false: keeping it would cost a copy every frame), so the canvas can be read
  // (toBlob, a stream's first frame) only in the task that drew it. afterDraw(f)
  // calls f(canvas) in the next animation frame right after its draw, drawing a
  // sharp frame for it when the loop would draw none or only a preview; f(null)
  // when nothing can be drawn (an error shown, no renderer).
  /** @param {(canvas: HTMLCanvasElement | null) => void} f */
  function afterDraw(f) {
    drawn.captures.push(f);
  }

  /** @param {number} before drawn.frameCount before this frame's draw */
  function fulfilCaptures(before) {
    const fresh = drawn.frameCount !== before && !state.preview;
    const ok = !state.error && (fresh || renderNow(false));
    drawn.captures.splice(0).forEach(function (f) { f(ok ? state.ui.canvas : null); });
  }

  // Marks the view as moving (input changed the camera).
  function interacted() {
    drawn.interactUntil = performance.now() + INTERACTION_MS;
  }

  /** @param {number} now */
  function frame(now) {
    W.requestAnimationFrame(frame);
    pollFence(now);
    const w = state.world;
    MW.physicsThread.update();
    if (w && !state.error) {
      // (a world the worker steps is stepped by the worker's clock)
      const n = w.shared ? 0 : state.clock.due(now, w.param("dt"), w.stepMs);
      if (w.shared) state.clock.reset();
      if (n > 0 && w.count() > 0) w.step(n);
      if (n > 0 && state.compare && state.compare.flat.count() > 0) state.compare.flat.step(n);
      MW.tools.sampleTrails();
      MW.plot.sample();
    }
    const before = drawn.frameCount;
    if (!state.error) {
      const moving = now < drawn.interactUntil;
      const slow = drawn.gpuFrameMs !== null && drawn.gpuFrameMs > SLOW_FRAME_MS;
      if (surfaceStale()) renderNow(moving && slow);
      else if (state.preview && !moving) renderNow(false); // the sharp frame once the view stops
      else if (bodiesChanged()) renderNow(state.preview);
      if (state.compare) state.compare.render(false);
    }
    if (drawn.captures.length) fulfilCaptures(before);
    MW.plot.draw();
    MW.inspector.refresh();
    showStats(now);
  }

  // Starts the frame loop.
  function startLoop() {
    W.requestAnimationFrame(frame);
  }

  // ---- canvas size (HiDPI) ------------------------------------------------------------
  /** @param {number} w @param {number} h */
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

  /** @param {HTMLCanvasElement} canvas */
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

  const exported = {
    renderNow: renderNow,
    measureFrame: measureFrame,
    surfaceStale: surfaceStale,
    statsObject: statsObject,
    interacted: interacted,
    afterDraw: afterDraw,
    startLoop: startLoop,
    watchSize: watchSize,
  };
  W.ManifoldWeb = W.ManifoldWeb || /** @type {ManifoldWebModules} */ ({});
  W.ManifoldWeb.frame = exported;
  return exported;
})(globalThis);
