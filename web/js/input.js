// Input on the page's canvas: the left button (one finger, a pen) on a body
// grabs it with the engine's mouse joint and drags it along the surface
// under the pointer; on empty surface it does what the tool says (tools.js:
// throw a body, draw a geodesic); on the background, off the surface, it
// orbits. The right button orbits anywhere, the middle button or shift pans,
// the wheel and a two-finger pinch zoom. In a flat view of a hyperbolic
// space (web/js/disc.js) every drag that orbits or pans walks instead, two
// fingers walk by their middle, and the wheel and a pinch size the disc.
// Pointer events: mouse, pen and touch alike. Also the surface point under a pixel, and grab/drag/release
// by pixel for window.manifold.
/* exported ManifoldWebInput */
var ManifoldWebInput = (function (W) {
  "use strict";
  const MW = W.ManifoldWeb;
  const state = MW.page.state;

  // ---- grabbing bodies ------------------------------------------------------------------
  // Mouse joint settings: a 5 Hz spring, 0.7 of critical damping, and a force
  // limit of 1000 × the body's mass (world.grab).
  const GRAB = { frequency: 5, damping: 0.7 };

  // The surface point under backing-store pixel (x, y) of the frame on screen, or null.
  /** @param {number} x @param {number} y */
  function surfacePoint(x, y) {
    if (state.error || !state.tracer) return null;
    const model = MW.page.flatModel();
    if (model !== null) {
      // a flat view: the point from the disc's map, in double precision
      const q = state.disc.unproject(model, x, y, state.width, state.height);
      const boundary = state.space.boundary;
      return q && (!boundary || boundary(q[0], q[1], q[2]) >= 0) ? q : null;
    }
    if (MW.frame.surfaceStale()) MW.frame.renderNow(false);
    return MW.picking.pick(state.tracer, x, y);
  }

  // Grabs the body under pixel (x, y), if any; returns whether one was grabbed.
  /** @param {number} x @param {number} y */
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
  /** @param {number} x @param {number} y */
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

  // ---- input: grab bodies, tools, orbit, zoom, pan (pointer events: mouse, pen and touch alike) ---
  /** @param {HTMLCanvasElement} canvas */
  function watchInput(canvas) {
    /** @type {Map<number, { x: number, y: number }>} */
    const pointers = new Map(); // pointerId → {x, y} (CSS pixels)
    let pinch = 0;              // distance between two touches
    let panning = false;
    /** @type {number | null} */
    let grabPointer = null;     // the pointer holding a body, or null
    /** @type {{ id: number, x: number, y: number } | null} */
    let toolPointer = null;     // the pointer of a tool's gesture on the surface (CSS pixels), or null

    function cssHeight() { return Math.max(1, canvas.getBoundingClientRect().height); }
    // the pointers' middle, in backing-store pixels
    function middle() {
      let x = 0, y = 0;
      pointers.forEach(function (q) { x += q.x / pointers.size; y += q.y / pointers.size; });
      return MW.picking.clientToPixel(canvas, x, y);
    }
    function spread() {
      const p = Array.from(pointers.values());
      return Math.hypot(p[0].x - p[1].x, p[0].y - p[1].y);
    }

    /** @param {PointerEvent} e */
    function capture(e) {
      try {
        canvas.setPointerCapture(e.pointerId);
      } catch (err) {
        // synthetic or already-released pointers cannot be captured; dragging still works inside the canvas
      }
    }
    /** @param {PointerEvent} e */
    function pixelOf(e) { return MW.picking.clientToPixel(canvas, e.clientX, e.clientY); }

    canvas.addEventListener("pointerdown", function (e) {
      if (!state.space) return;
      if (grabPointer !== null) { e.preventDefault(); return; } // one body at a time; other fingers wait
      if (toolPointer !== null) {
        // a second finger: the gesture is dropped, and the two fingers orbit and pinch
        MW.tools.cancel();
        pointers.set(toolPointer.id, { x: toolPointer.x, y: toolPointer.y });
        toolPointer = null;
        panning = false;
      }
      // a first primary press on a body grabs it; on empty surface the tool acts
      // (not in the comparison view, whose panes drag bodies only); off the surface the view orbits
      if (pointers.size === 0 && e.button === 0 && !e.shiftKey) {
        const px = pixelOf(e);
        // (the joint tool presses on bodies: it joins them)
        if (MW.tools.tool() !== "joint" && grabAt(px[0], px[1])) {
          capture(e);
          grabPointer = e.pointerId;
          canvas.classList.add("holding");
          e.preventDefault();
          return;
        }
        const q = state.compare || !state.world ? null : surfacePoint(px[0], px[1]);
        if (q) {
          capture(e);
          toolPointer = { id: e.pointerId, x: e.clientX, y: e.clientY };
          MW.tools.press(q, [e.clientX, e.clientY]);
          e.preventDefault();
          return;
        }
      }
      capture(e);
      pointers.set(e.pointerId, { x: e.clientX, y: e.clientY });
      panning = e.button === 1 || e.shiftKey;
      if (pointers.size === 2) pinch = spread();
      canvas.classList.add("dragging");
      e.preventDefault();
    });
    canvas.addEventListener("pointermove", function (e) {
      if (e.pointerId === grabPointer) {
        const px = pixelOf(e);
        dragTo(px[0], px[1]);
        return;
      }
      if (toolPointer && e.pointerId === toolPointer.id) {
        const px = pixelOf(e);
        toolPointer.x = e.clientX;
        toolPointer.y = e.clientY;
        MW.tools.move(surfacePoint(px[0], px[1]), [e.clientX, e.clientY]);
        return;
      }
      const p = pointers.get(e.pointerId);
      if (!p) return;
      const dx = e.clientX - p.x, dy = e.clientY - p.y;
      const from = middle();
      p.x = e.clientX;
      p.y = e.clientY;
      const model = MW.page.flatModel();
      if (model !== null) {
        // a flat view: a drag walks, keeping the point under the pointer (two fingers: under their middle)
        if (pointers.size <= 2) state.disc.walk(model, from, middle(), state.width, state.height);
        if (pointers.size === 2) {
          const d = spread();
          if (pinch > 0 && d > 0) state.disc.zoomBy(pinch / d);
          pinch = d;
        }
      } else if (pointers.size === 1) {
        if (panning) state.camera.pan(dx, dy, cssHeight());
        else state.camera.orbit(dx, dy, cssHeight());
      } else if (pointers.size === 2) {
        const d = spread();
        if (pinch > 0 && d > 0) state.camera.zoom(pinch / d);
        pinch = d;
      }
      MW.frame.interacted();
    });
    /** @param {PointerEvent} e */
    function end(e) {
      if (e.pointerId === grabPointer) {
        grabPointer = null;
        canvas.classList.remove("holding");
        releaseGrab();
        return;
      }
      if (toolPointer && e.pointerId === toolPointer.id) {
        toolPointer = null;
        if (e.type !== "pointerup") MW.tools.cancel();
        else MW.page.guarded(function () { return MW.tools.release(e.ctrlKey); })();
        return;
      }
      if (!pointers.delete(e.pointerId)) return;
      if (pointers.size < 2) pinch = 0;
      if (pointers.size === 0) canvas.classList.remove("dragging");
    }
    // the inspector: with Alt held, the body under a pointer that presses nothing
    canvas.addEventListener("pointermove", function (e) {
      if (pointers.size || grabPointer !== null || toolPointer) return;
      if (e.altKey) MW.inspector.hover(e.clientX, e.clientY, pixelOf(e));
      else MW.inspector.hide();
    });
    canvas.addEventListener("pointerleave", function () { MW.inspector.hide(); });
    W.addEventListener("keyup", function (e) { if (e.key === "Alt") MW.inspector.hide(); });
    canvas.addEventListener("pointerup", end);
    canvas.addEventListener("pointercancel", end);
    canvas.addEventListener("lostpointercapture", end);
    canvas.addEventListener("wheel", function (e) {
      if (!state.space) return;
      e.preventDefault();
      const lines = e.deltaMode === 1 ? 16 : e.deltaMode === 2 ? 400 : 1;
      const factor = Math.exp(Math.max(-200, Math.min(200, e.deltaY * lines)) * 0.0015);
      if (MW.page.flatModel() !== null) state.disc.zoomBy(factor);
      else state.camera.zoom(factor);
      MW.frame.interacted();
    }, { passive: false });
    canvas.addEventListener("contextmenu", function (e) { e.preventDefault(); });
  }

  const exported = {
    GRAB: GRAB,
    surfacePoint: surfacePoint,
    grabAt: grabAt,
    dragTo: dragTo,
    releaseGrab: releaseGrab,
    watchInput: watchInput,
  };
  W.ManifoldWeb = W.ManifoldWeb || /** @type {ManifoldWebModules} */ ({});
  W.ManifoldWeb.input = exported;
  return exported;
})(globalThis);
