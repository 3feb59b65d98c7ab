// The flat views of the hyperbolic spaces: the Poincaré disc (the default)
// and the Klein disc of the hyperboloid, seen by a viewer who walks through
// the plane by Lorentz boosts (as HyperRogue moves), so the disc stays
// centred on where they are. This file holds the viewer's state (a boost and
// the disc's size on the canvas), the pixel frame (points to pixels, pixels
// back to points, for projecting and picking in double precision), and the
// GLSL the overlays' vertex shaders project through. The maps, the boosts
// and the geodesic grid come from web/gen (Manifold.hyperbolic, generated
// from Lib/Manifold/Disc.hs).
//
// The picture: the disc's centre is the canvas's, its radius `zoom` times
// half the canvas's smaller side; canvas right is the disc's u (the view's
// x), canvas down its w (the view's z), as a view from above the plane
// y = 0 with +x to the right shows it.
/* exported ManifoldWebDisc */
var ManifoldWebDisc = (function (W) {
  "use strict";

  /** @type {Manifold.Model[]} */
  const MODELS = ["poincare", "klein", "hyperboloid"];
  const DEFAULT_ZOOM = 0.95;
  const MIN_ZOOM = 0.1, MAX_ZOOM = 50;
  // how far out in the disc a walk takes hold (nearer the rim a pixel spans too much of the plane)
  const WALK_REACH = 0.98;
  // wraps a recentring composes at most (each crosses up to four of the
  // octagon's sides: a boost set from afar may need several)
  const MAX_RECENTRES = 64;
  /** @type {number[]} */
  const IDENTITY = [1, 0, 0, 0, 1, 0, 0, 0, 1];

  function H() { return W.Manifold.hyperbolic; }

  // The overlays' projection (bodies, curves, the grab mark): the perspective
  // camera's matrix, or the flat view's boost and disc. GLSL, after the
  // generated maps.
  const PROJECT_GLSL = `
uniform mat4 uViewProjection;
uniform int uFlat;          // 0: the camera's perspective; 1: the Poincare disc; 2: the Klein disc
uniform mat3 uBoost;        // the flat view's boost (world -> view)
uniform vec2 uDiscScale;    // clip units per disc unit, across and down
vec4 projectToClip(vec3 p) {
  if (uFlat == 0) return uViewProjection * vec4(p, 1.0);
  vec3 q = uBoost * p;
  vec2 d = uFlat == 2 ? toKlein(q) : toPoincare(q);
  return vec4(d.x * uDiscScale.x, -d.y * uDiscScale.y, 0.0, 1.0);
}
`;

  // The generated maps and projectToClip.
  function projectionGlsl() {
    return H().glsl + PROJECT_GLSL;
  }

  // An overlay's vertex shader with its `uniform mat4 uViewProjection;` line
  // made the projection (it then calls projectToClip(p)).
  /** @param {string} source */
  function withProjection(source) {
    return source.replace("uniform mat4 uViewProjection;\n", projectionGlsl());
  }

  /** @param {unknown} m @returns {m is number[]} */
  function isBoost(m) {
    return Array.isArray(m) && m.length === 9 && m.every(function (x) { return typeof x === "number" && isFinite(x); });
  }

  class DiscView {
    constructor() {
      /** @type {number[]} world → view, nine numbers row by row */
      this.boost = IDENTITY.slice();
      this.zoom = DEFAULT_ZOOM;
      this.version = 0; // bumped on every change, so the page knows to redraw
      /** @type {Manifold.Wrap | null} the space's quotient's wrap (generated), or null */
      this.wrap = null;
    }

    // The space whose quotient the view's centre is kept in (its generated
    // wrapIntoDomain; null: none).
    /** @param {Manifold.Wrap | null} wrap */
    setWrap(wrap) {
      this.wrap = wrap;
      this.recentre();
    }

    // On a quotient (the Bolza surface) the view's centre is kept in the
    // fundamental domain, as HyperRogue keeps its viewer in the current
    // cell: where a walk takes it out, the boost is composed with the group
    // element that brings it back. The picture is the same (the world
    // repeats by the group), and the images drawn about the domain are then
    // the tiles about the view however far it walks.
    recentre() {
      if (!this.wrap) return;
      for (let k = 0; k < MAX_RECENTRES; k++) {
        const c = H().apply(...H().inverse(...this.boost), 0, 1, 0);
        const w = this.wrap(c[0], c[1], c[2]);
        if (IDENTITY.every(function (x, i) { return Math.abs(w[i] - x) < 1e-12; })) return;
        // B L⁻¹ puts the view's centre at L c, in the domain (not
        // renormalised: a walk there and back comes back to 3e-8 as it is,
        // to 1e-6 renormalised after each recentring, the drift carried
        // through the pairings' large entries)
        this.boost = H().compose(...this.boost, ...H().inverse(...w.slice(0, 9)));
      }
    }

    reset() {
      this.boost = IDENTITY.slice();
      this.zoom = DEFAULT_ZOOM;
      this.version++;
    }

    /** @returns {Manifold.DiscViewSpec} */
    get() { return { boost: this.boost.slice(), zoom: this.zoom }; }

    // Sets any of {boost, zoom}; throws a TypeError on bad input (a boost must
    // keep the metric: its inverse times it the identity, to 1e-6).
    /** @param {Partial<Manifold.DiscViewSpec>} s */
    set(s) {
      if (!s || typeof s !== "object") throw new TypeError("setDiscView expects {boost, zoom}");
      if (s.zoom !== undefined && !(typeof s.zoom === "number" && s.zoom >= MIN_ZOOM && s.zoom <= MAX_ZOOM)) {
        throw new TypeError("discView.zoom must be a number from " + MIN_ZOOM + " to " + MAX_ZOOM);
      }
      if (s.boost !== undefined) {
        if (!isBoost(s.boost)) throw new TypeError("discView.boost must be nine finite numbers, row by row");
        const m = s.boost;
        const check = H().compose(...H().inverse(...m), ...m);
        if (check.some(function (x, k) { return Math.abs(x - IDENTITY[k]) > 1e-6; }) || !(m[4] > 0)) {
          throw new TypeError("discView.boost must be a Lorentz matrix keeping x^2 - y^2 + z^2 and the upper sheet");
        }
        this.boost = m.slice();
        this.recentre();
      }
      if (s.zoom !== undefined) this.zoom = s.zoom;
      this.version++;
    }

    // The disc's radius in pixels of a width × height canvas.
    /** @param {number} width @param {number} height */
    radius(width, height) { return this.zoom * 0.5 * Math.min(width, height); }

    // World point → [px, py] continuous backing-store pixels in a model's disc
    // (null: not on the upper sheet).
    /** @param {Manifold.Model} model @param {Manifold.Vec3} p @param {number} width @param {number} height @returns {[number, number] | null} */
    project(model, p, width, height) {
      const q = H().apply(...this.boost, p[0], p[1], p[2]);
      if (!(q[1] > 0)) return null;
      const d = model === "klein" ? H().toKlein(q[0], q[1], q[2]) : H().toPoincare(q[0], q[1], q[2]);
      const r = this.radius(width, height);
      return [0.5 * width + r * d[0], 0.5 * height + r * d[1]];
    }

    // The world point under backing-store pixel (px, py), or null off the disc.
    /** @param {Manifold.Model} model @param {number} px @param {number} py @param {number} width @param {number} height @returns {Manifold.Vec3 | null} */
    unproject(model, px, py, width, height) {
      const r = this.radius(width, height);
      const u = (px - 0.5 * width) / r, w = (py - 0.5 * height) / r;
      if (!(u * u + w * w < 1)) return null;
      const q = model === "klein" ? H().fromKlein(u, w) : H().fromPoincare(u, w);
      const p = H().apply(...H().inverse(...this.boost), q[0], q[1], q[2]);
      return [p[0], p[1], p[2]];
    }

    // Walks: the plane is dragged from backing-store pixel `from` to pixel
    // `to` of a width × height canvas, so the point under `from` comes under
    // `to` (each held within 0.98 of the disc's radius). A drag there and
    // back along any path returns the view to where it was.
    /**
     * @param {Manifold.Model} model @param {[number, number]} from @param {[number, number]} to
     * @param {number} width @param {number} height
     */
    walk(model, from, to, width, height) {
      const a = this.viewPoint(model, from, width, height), b = this.viewPoint(model, to, width, height);
      const step = H().compose(...H().translationTo(b[0], b[1], b[2]), ...H().inverse(...H().translationTo(a[0], a[1], a[2])));
      this.boost = H().renormalise(...H().compose(...step, ...this.boost));
      this.recentre();
      this.version++;
    }

    // The point of the view (before the boost's inverse) under a pixel, held
    // within WALK_REACH of the disc's radius.
    /** @param {Manifold.Model} model @param {[number, number]} px @param {number} width @param {number} height */
    viewPoint(model, px, width, height) {
      const r = this.radius(width, height);
      let u = (px[0] - 0.5 * width) / r, w = (px[1] - 0.5 * height) / r;
      const l = Math.hypot(u, w);
      if (l > WALK_REACH) { u *= WALK_REACH / l; w *= WALK_REACH / l; }
      return model === "klein" ? H().fromKlein(u, w) : H().fromPoincare(u, w);
    }

    // Makes the disc larger (factor < 1, as the camera's zoom comes nearer) or smaller.
    /** @param {number} factor */
    zoomBy(factor) {
      this.zoom = Math.max(MIN_ZOOM, Math.min(MAX_ZOOM, this.zoom / factor));
      this.version++;
    }
  }

  // Sets an overlay program's projection uniforms for its frame: the
  // camera's perspective, or a flat view's boost and disc (frame.flat).
  /** @param {WebGL2RenderingContext} gl @param {ManifoldWeb.Program} program @param {ManifoldWeb.OverlayFrame} frame */
  function setProjection(gl, program, frame) {
    const flat = frame.flat || null;
    gl.uniformMatrix4fv(program.uniform("uViewProjection"), false, frame.viewProjection || new Float32Array(16));
    gl.uniform1i(program.uniform("uFlat"), flat === null ? 0 : flat.model === "klein" ? 2 : 1);
    if (flat !== null) {
      gl.uniformMatrix3fv(program.uniform("uBoost"), true, flat.boost);
      gl.uniform2f(program.uniform("uDiscScale"), 2 * flat.radius / frame.width, 2 * flat.radius / frame.height);
    }
  }

  const exported = { DiscView: DiscView, MODELS: MODELS, withProjection: withProjection, setProjection: setProjection };
  W.ManifoldWeb = W.ManifoldWeb || /** @type {ManifoldWebModules} */ ({});
  W.ManifoldWeb.disc = exported;
  return exported;
})(globalThis);
