// The comparison view "Torus: embedded vs flat" (the paper's Fig. 17): the
// embedded torus's simulation and the flat torus's, started from one scene,
// each drawn on the sphere-traced torus and on the unrolled square.
//
//   top left     the embedded world on the traced torus (the page's own canvas)
//   top right    the flat world on the traced torus, through the torus's angle
//                coordinates (every polygon vertex mapped by the generated chart)
//   bottom left  the embedded world unrolled onto the square (by the chart)
//   bottom right the flat world on its square
//
// The chart (toSquare, fromSquare), the flat curvature pulled back onto the
// torus (flatGlsl) and the two scenes come from web/gen/compare-torus.js
// (Lib/Manifold/Chart.hs); this file only draws and routes input.
/* exported ManifoldWebCompare */
var ManifoldWebCompare = (function (W) {
  "use strict";
  const MW = W.ManifoldWeb;

  // the square's colours (display RGB 0..1): K = 0, K > 0, K < 0, as the tracer's
  /** @type {Manifold.Rgb} */ const WHITE = [0.93, 0.93, 0.93];
  /** @type {Manifold.Rgb} */ const RED = [0.86, 0.12, 0.10];
  /** @type {Manifold.Rgb} */ const BLUE = [0.12, 0.30, 0.90];
  /** @type {Manifold.Rgb} */ const PLAIN = [0.86, 0.80, 0.70];

  /**
   * The canvases of the panes: the page's own (top left) and the three this view draws.
   * @typedef {{ mainCanvas: HTMLCanvasElement, flatCanvas: HTMLCanvasElement,
   *   squareEmbedded: HTMLCanvasElement, squareFlat: HTMLCanvasElement }} Panes
   */
  /**
   * What the view asks of the page.
   * @typedef {object} Hooks
   * @property {() => Manifold.OptionsShown} options the display options
   * @property {() => number} bounds the traced space's bounds
   * @property {(p: Manifold.Vec3) => number} curvatureOf the embedded torus's Gaussian curvature
   * @property {{ frequency: number, damping: number }} grab the mouse joint's settings
   * @property {() => void} interacted the view moved
   */
  /** A pane's square: its size in pixels, the scale, and the maps between the square and pixels.
   * @typedef {{ w: number, h: number, s: number, toPixel: (x: number, z: number) => [number, number],
   *   fromPixel: (px: number, py: number) => [number, number] }} SquareFrame
   */

  /** @param {Manifold.Rgb} a @param {Manifold.Rgb} b @param {number} t @returns {Manifold.Rgb} */
  function mix(a, b, t) { return /** @type {Manifold.Rgb} */ ([0, 1, 2].map(function (k) { return a[k] + (b[k] - a[k]) * t; })); }
  /** @param {number} K @param {number} scale */
  function curvatureColour(K, scale) {
    const c = Math.tanh(K * scale);
    return c >= 0 ? mix(WHITE, RED, c) : mix(WHITE, BLUE, -c);
  }
  /** @param {Manifold.Rgb} c */
  function css(c) { return "rgb(" + c.map(function (x) { return Math.round(255 * Math.max(0, Math.min(1, x))); }).join(",") + ")"; }

  class Comparison {
    // def: Manifold.comparisons.torus; embedded, flat: World; camera: the shared camera;
    // els: {flatCanvas, squareEmbedded, squareFlat}; hooks: {options(), grab: {frequency, damping}, interacted(), curvatureOf(p)}
    /**
     * @param {Manifold.ComparisonDef} def @param {ManifoldWeb.World} embedded @param {ManifoldWeb.World} flat
     * @param {ManifoldWeb.Camera} camera @param {Panes} els @param {Hooks} hooks
     */
    constructor(def, embedded, flat, camera, els, hooks) {
      this.def = def;
      this.embedded = embedded;
      this.flat = flat;
      this.camera = camera;
      this.els = els;
      this.hooks = hooks;
      this.gl = MW.gl.createContext(els.flatCanvas);
      this.tracer = new MW.tracer.Tracer(this.gl);
      this.tracer.setSpaceGlsl(def.flatGlsl, "sphere tracer for the flat torus drawn on the torus");
      this.renderer = new MW.bodies.BodyRenderer(this.gl);
      /** @type {Float64Array | null} */
      this.mapped = null;         // the flat world's polygons on the torus
      /** @type {Float64Array | null} */
      this.mappedHull = null;     // and its hull array, the corners mapped
      /** @type {string | null} */
      this.drawnKey = null;       // what the panes show (camera, worlds, options)
      /** @type {Record<string, [string, ImageData]>} */
      this.background = {};      // pane → [key, ImageData]
      /** @type {{ pane: string, world: ManifoldWeb.World, pointerId: number } | null} */
      this.held = null;           // {pane, world, pointerId}
      this.frames = 0;
      /** @type {[HTMLElement, string, EventListener][]} */
      this.listeners = [];
      this.watch();
    }

    // ---- geometry (all of it from the generated chart) ----
    // the flat world's polygons mapped onto the torus, as a world for the body renderer
    /** @returns {ManifoldWeb.DrawnWorld} */
    flatOnTorus() {
      const f = this.flat, E = f.engine, n = f.count();
      const len = 3 * E.verticesPerBody * n;
      if (!this.mapped || this.mapped.length < 3 * E.verticesPerBody * f.capacity) {
        this.mapped = new Float64Array(3 * E.verticesPerBody * Math.max(1, f.capacity));
      }
      const v = f.a.verts, m = this.mapped, C = this.def;
      for (let o = 0; o < len; o += 3) {
        const q = C.fromSquare(v[o], v[o + 1], v[o + 2]);
        m[o] = q[0]; m[o + 1] = q[1]; m[o + 2] = q[2];
      }
      // the polygons' corners, walked on the square, mapped too (drawn with their corners)
      const H = E.hull, hull = f.a.hull, S = E.slots, k = E.sizes.scalars[1];
      if (!this.mappedHull || this.mappedHull.length < hull.length) this.mappedHull = new Float64Array(hull.length);
      const mh = this.mappedHull;
      mh.set(hull.subarray(0, H.stride * n));
      for (let i = 0; i < n; i++) {
        for (let c = 0; c < f.a.scalars[i * k + S.corners]; c++) {
          const o = H.stride * i + H.world + 3 * c, q = C.fromSquare(hull[o], hull[o + 1], hull[o + 2]);
          mh[o] = q[0]; mh[o + 1] = q[1]; mh[o + 2] = q[2];
        }
      }
      return {
        engine: E, info: f.info, capacity: f.capacity, images: [],
        count: function () { return n; },
        a: { verts: m, scalars: f.a.scalars, hull: mh },
        target: f.target ? C.fromSquare(f.target[0], f.target[1], f.target[2]) : null,
      };
    }

    // body i's outline in the square's coordinates, unwrapped round its centre
    // (a polygon's corners), and the end of its axis mark
    /** @param {ManifoldWeb.World} world @param {number} i @param {boolean} viaChart */
    outlineInSquare(world, i, viaChart) {
      const E = world.engine, v = world.a.verts, vpb = E.verticesPerBody, C = this.def;
      const L = 2 * C.half;
      /** @param {number} k @returns {Manifold.Vec3} */
      const at = function (k) {
        const o = 3 * (vpb * i + k);
        return viaChart ? C.toSquare(v[o], v[o + 1], v[o + 2]) : [v[o], v[o + 1], v[o + 2]];
      };
      const c = at(0);
      /** @param {Manifold.Vec3} q @returns {[number, number]} */
      const unwrap = function (q) {
        return [c[0] + wrap(q[0] - c[0]), c[2] + wrap(q[2] - c[2])];
      };
      /** @param {number} d */
      function wrap(d) { return d - L * Math.round(d / L); }
      const pts = [];
      // a polygon of corners (not rounded) by its corners, as walked, else the sampled outline
      const H = E.hull, hull = world.a.hull, corners = world.a.scalars[i * E.sizes.scalars[1] + E.slots.corners];
      if (corners >= 3 && hull[H.stride * i + H.radius] === 0) {
        for (let k = 0; k < corners; k++) {
          const o = H.stride * i + H.world + 3 * k;
          pts.push(unwrap(viaChart ? C.toSquare(hull[o], hull[o + 1], hull[o + 2]) : [hull[o], hull[o + 1], hull[o + 2]]));
        }
      } else {
        for (let d = 0; d < E.directions; d++) pts.push(unwrap(at(E.vertexIndex(d, E.steps))));
      }
      return { centre: /** @type {[number, number]} */ ([c[0], c[2]]), outline: pts, axis: unwrap(at(E.vertexIndex(0, E.steps))) };
    }

    // ---- the unrolled squares (2D canvas) ----
    /** @param {HTMLCanvasElement} canvas @returns {SquareFrame} */
    squareFrame(canvas) {
      const w = canvas.width, h = canvas.height, half = this.def.half;
      const s = 0.92 * Math.min(w, h) / (2 * half);
      return {
        w: w, h: h, s: s,
        toPixel: function (x, z) { return [w / 2 + s * x, h / 2 - s * z]; },
        fromPixel: function (px, py) { return [(px - w / 2) / s, -(py - h / 2) / s]; },
      };
    }

    /** @param {HTMLCanvasElement} canvas */
    sizeCanvas(canvas) {
      const r = canvas.getBoundingClientRect();
      const dpr = W.devicePixelRatio || 1;
      const w = Math.max(1, Math.round(r.width * dpr)), h = Math.max(1, Math.round(r.height * dpr));
      if (canvas.width !== w || canvas.height !== h) {
        canvas.width = w;
        canvas.height = h;
        return true;
      }
      return false;
    }

    // the square's fill: the curvature of the surface the world lives on (the
    // embedded torus's through the chart; the flat torus's is 0), or plain
    /**
     * @param {string} pane @param {HTMLCanvasElement} canvas @param {SquareFrame} F
     * @param {(x: number, z: number) => number} curvatureOf
     */
    squareBackground(pane, canvas, F, curvatureOf) {
      const o = this.hooks.options();
      const key = [F.w, F.h, o.curvature, o.curvatureScale].join(":");
      const cached = this.background[pane];
      if (cached && cached[0] === key) return cached[1];
      const ctx = canvas.getContext("2d");
      const img = ctx.createImageData(F.w, F.h);
      const half = this.def.half;
      for (let py = 0; py < F.h; py++) {
        for (let px = 0; px < F.w; px++) {
          const q = F.fromPixel(px + 0.5, py + 0.5);
          const inside = Math.abs(q[0]) <= half && Math.abs(q[1]) <= half;
          const k = 4 * (py * F.w + px);
          /** @type {Manifold.Rgb} */
          let c;
          if (!inside) c = [0.06, 0.07, 0.09];
          else if (o.curvature) c = curvatureColour(curvatureOf(q[0], q[1]), o.curvatureScale);
          else c = PLAIN;
          img.data[k] = 255 * c[0]; img.data[k + 1] = 255 * c[1]; img.data[k + 2] = 255 * c[2]; img.data[k + 3] = 255;
        }
      }
      this.background[pane] = [key, img];
      return img;
    }

    /**
     * @param {string} pane @param {HTMLCanvasElement} canvas @param {ManifoldWeb.World} world @param {boolean} viaChart
     * @param {(x: number, z: number) => number} curvatureOf
     */
    drawSquare(pane, canvas, world, viaChart, curvatureOf) {
      this.sizeCanvas(canvas);
      const F = this.squareFrame(canvas);
      const ctx = canvas.getContext("2d");
      ctx.putImageData(this.squareBackground(pane, canvas, F, curvatureOf), 0, 0);
      const half = this.def.half;
      const a = F.toPixel(-half, half), b = F.toPixel(half, -half);
      ctx.save();
      ctx.beginPath();
      ctx.rect(a[0], a[1], b[0] - a[0], b[1] - a[1]);
      ctx.clip();
      // grid every 0.25 of the square
      ctx.strokeStyle = "rgba(0,0,0,0.12)";
      ctx.lineWidth = 1;
      for (let t = -half; t <= half + 1e-9; t += 0.25) {
        const p = F.toPixel(t, -half), q = F.toPixel(t, half), r = F.toPixel(-half, t), s = F.toPixel(half, t);
        ctx.beginPath(); ctx.moveTo(p[0], p[1]); ctx.lineTo(q[0], q[1]); ctx.moveTo(r[0], r[1]); ctx.lineTo(s[0], s[1]); ctx.stroke();
      }
      const n = world.count();
      const lw = Math.max(1, (W.devicePixelRatio || 1) * 1.2);
      const shifts = [[0, 0]].concat(W.Manifold.spaces[this.def.flat].images.map(function (g) { return [g[9], g[11]]; }));
      for (let i = 0; i < n; i++) {
        const o = this.outlineInSquare(world, i, viaChart);
        /** @type {Manifold.Rgb} */
        const colour = world.info[i] ? world.info[i].colour : [0.8, 0.8, 0.8];
        // the body and its images across the edges (the flat torus's
        // quotient images, generated: translations of the square's side)
        for (const [dx, dz] of shifts) {
          ctx.beginPath();
          o.outline.forEach(function (q, k) {
            const p = F.toPixel(q[0] + dx, q[1] + dz);
            if (k === 0) ctx.moveTo(p[0], p[1]); else ctx.lineTo(p[0], p[1]);
          });
          ctx.closePath();
          ctx.fillStyle = css(colour);
          ctx.fill();
          ctx.strokeStyle = "rgba(10,10,10,0.9)";
          ctx.lineWidth = lw;
          ctx.stroke();
          const c = F.toPixel(o.centre[0] + dx, o.centre[1] + dz), e = F.toPixel(o.axis[0] + dx, o.axis[1] + dz);
          ctx.strokeStyle = "rgba(255,255,255,0.85)";
          ctx.beginPath(); ctx.moveTo(c[0], c[1]); ctx.lineTo(e[0], e[1]); ctx.stroke();
        }
      }
      ctx.restore();
      // the square's edges: opposite edges are glued
      ctx.strokeStyle = "#6fa3ff";
      ctx.lineWidth = 2 * lw;
      ctx.strokeRect(a[0], a[1], b[0] - a[0], b[1] - a[1]);
      if (world.target) {
        const t = viaChart ? this.def.toSquare(world.target[0], world.target[1], world.target[2]) : world.target;
        const p = F.toPixel(t[0], t[2]);
        ctx.fillStyle = "#fff";
        ctx.strokeStyle = "#111";
        ctx.beginPath(); ctx.arc(p[0], p[1], 4 * lw, 0, 2 * Math.PI); ctx.fill(); ctx.stroke();
      }
    }

    // ---- the flat world on the traced torus ----
    /** @param {boolean} [force] */
    drawTorus(force) {
      const canvas = this.els.flatCanvas;
      const resized = this.sizeCanvas(canvas);
      const o = this.hooks.options();
      const w = canvas.width, h = canvas.height;
      this.tracer.configure(w, h, o.antialias, false);
      const key = this.camera.version + ":" + w + "x" + h + ":" + o.curvature + ":" + o.grid;
      const camera = this.camera;
      const self = this;
      this.tracer.render({
        camera: camera, bounds: this.hooks.bounds(), curvature: o.curvature, curvatureScale: o.curvatureScale,
        grid: o.grid, gridSpacing: o.gridSpacing, background: o.background,
      }, function (frame) {
        frame.viewProjection = camera.viewProjection(w / h, 0.01, 100);
        frame.eye = /** @type {Manifold.Vec3} */ (camera.eye.slice());
        frame.bodyDetail = o.bodyDetail;
        self.renderer.draw(self.flatOnTorus(), frame);
      }, force || resized ? null : key);
    }

    // Draws the three panes this view owns (the page draws the top-left one).
    /** @param {boolean} [force] */
    render(force) {
      const o = this.hooks.options();
      const key = [this.camera.version, this.embedded.version, this.flat.version, o.curvature, o.grid, o.antialias,
        this.els.flatCanvas.clientWidth, this.els.flatCanvas.clientHeight].join(":");
      if (!force && key === this.drawnKey) return;
      this.drawnKey = key;
      this.drawTorus(force);
      const K = this.hooks.curvatureOf, C = this.def;
      this.drawSquare("embedded", this.els.squareEmbedded, this.embedded, true,
        /** @param {number} x @param {number} z */ function (x, z) { const p = C.fromSquare(x, 0, z); return K(p); });
      this.drawSquare("flat", this.els.squareFlat, this.flat, false, function () { return 0; });
      this.frames++;
    }

    // ---- input ----
    // the surface point of a pane's world under a client position, or null
    /** @param {string} pane @param {number} clientX @param {number} clientY @returns {Manifold.Vec3 | null} */
    pointIn(pane, clientX, clientY) {
      if (pane === "torus-flat") {
        const px = MW.picking.clientToPixel(this.els.flatCanvas, clientX, clientY);
        if (this.drawnKey === null) this.render(true);
        const q = MW.picking.pick(this.tracer, px[0], px[1]);
        return q ? this.def.toSquare(q[0], q[1], q[2]) : null;
      }
      const canvas = pane === "square-flat" ? this.els.squareFlat : this.els.squareEmbedded;
      const px = MW.picking.clientToPixel(canvas, clientX, clientY);
      const s = this.squareFrame(canvas).fromPixel(px[0], px[1]);
      const half = this.def.half;
      if (Math.abs(s[0]) > half || Math.abs(s[1]) > half) return null;
      return pane === "square-flat" ? [s[0], 0, s[1]] : this.def.fromSquare(s[0], 0, s[1]);
    }

    /** @param {string} pane */
    worldOf(pane) { return pane === "square-embedded" ? this.embedded : this.flat; }

    // where body i's centre is drawn in a pane, in client (CSS) pixels (for tests)
    /** @param {string} pane @param {number} i @returns {[number, number] | null} */
    clientPoint(pane, i) {
      const world = pane === "torus-embedded" || pane === "square-embedded" ? this.embedded : this.flat;
      /** @type {Manifold.Vec3} */
      const p = [world.a.pos[3 * i], world.a.pos[3 * i + 1], world.a.pos[3 * i + 2]];
      let canvas, px;
      if (pane === "torus-embedded" || pane === "torus-flat") {
        canvas = pane === "torus-flat" ? this.els.flatCanvas : this.els.mainCanvas;
        const q = pane === "torus-flat" ? this.def.fromSquare(p[0], p[1], p[2]) : p;
        px = this.camera.project(q, canvas.width, canvas.height);
        if (!px) return null;
      } else {
        canvas = pane === "square-flat" ? this.els.squareFlat : this.els.squareEmbedded;
        const s = pane === "square-flat" ? p : this.def.toSquare(p[0], p[1], p[2]);
        px = this.squareFrame(canvas).toPixel(s[0], s[2]);
      }
      const r = canvas.getBoundingClientRect();
      return [r.left + px[0] * r.width / canvas.width, r.top + px[1] * r.height / canvas.height];
    }

    /**
     * @template {keyof HTMLElementEventMap} K
     * @param {HTMLElement} el @param {K} type @param {(e: HTMLElementEventMap[K]) => void} f
     * @param {AddEventListenerOptions} [opts]
     */
    on(el, type, f, opts) {
      el.addEventListener(type, f, opts);
      this.listeners.push([el, type, /** @type {EventListener} */ (f)]);
    }

    watch() {
      const self = this;
      /** @type {[string, HTMLCanvasElement][]} */
      const panes = [["torus-flat", this.els.flatCanvas], ["square-embedded", this.els.squareEmbedded], ["square-flat", this.els.squareFlat]];
      panes.forEach(function (entry) {
        const pane = entry[0], el = entry[1];
        /** @type {{ id: number, x: number, y: number } | null} */
        let orbit = null;
        self.on(el, "pointerdown", function (e) {
          if (self.held || e.button !== 0) return;
          const q = self.pointIn(pane, e.clientX, e.clientY);
          const world = self.worldOf(pane);
          const hit = q && world.pick(q);
          try { el.setPointerCapture(e.pointerId); } catch (err) { /* synthetic pointers */ }
          e.preventDefault();
          if (hit) {
            world.grab(hit.index, hit.sign, q, self.hooks.grab);
            self.held = { pane: pane, world: world, pointerId: e.pointerId };
            el.classList.add("holding");
          } else if (pane === "torus-flat") {
            orbit = { id: e.pointerId, x: e.clientX, y: e.clientY };
          }
        });
        self.on(el, "pointermove", function (e) {
          if (self.held && self.held.pointerId === e.pointerId && self.held.pane === pane) {
            const q = self.pointIn(pane, e.clientX, e.clientY);
            if (q) self.held.world.drag(q);
            return;
          }
          if (orbit && orbit.id === e.pointerId) {
            self.camera.orbit(e.clientX - orbit.x, e.clientY - orbit.y, Math.max(1, el.getBoundingClientRect().height));
            orbit.x = e.clientX;
            orbit.y = e.clientY;
            self.hooks.interacted();
          }
        });
        /** @param {PointerEvent} e */
        const end = function (e) {
          if (self.held && self.held.pointerId === e.pointerId && self.held.pane === pane) {
            self.held.world.release();
            self.held = null;
            el.classList.remove("holding");
          }
          if (orbit && orbit.id === e.pointerId) orbit = null;
        };
        self.on(el, "pointerup", end);
        self.on(el, "pointercancel", end);
        self.on(el, "contextmenu", function (e) { e.preventDefault(); });
      });
    }

    dispose() {
      if (this.held) this.held.world.release();
      this.listeners.forEach(function (l) { l[0].removeEventListener(l[1], l[2]); });
      this.listeners = [];
      // the canvas keeps its context: the next comparison gets it again
      try {
        this.renderer.dispose();
        this.tracer.dispose();
      } catch (err) {
        // a context already lost has nothing to free
      }
    }
  }

  const exported = { Comparison: Comparison };
  W.ManifoldWeb = W.ManifoldWeb || /** @type {ManifoldWebModules} */ ({});
  W.ManifoldWeb.compare = exported;
  return exported;
})(globalThis);
