// The pinhole camera (eye, target, up, vertical field of view in degrees),
// its orbit/zoom/pan controls, and projection of world points to canvas
// pixels. Pixel coordinates are backing-store pixels with the origin at the
// top-left corner: pixel (i, j) covers [i, i+1) × [j, j+1), so its centre is
// (i + 0.5, j + 0.5). The tracer's fragment shader uses the same convention
// (see rayBasis), so project() inverts the ray of every pixel.
/* exported ManifoldWebCamera */
var ManifoldWebCamera = (function (W) {
  "use strict";

  /** @typedef {Manifold.Vec3} Vec3 */

  // Small vector helpers for the camera (plain arrays of three numbers).
  const v = {
    /** @param {Vec3} a @param {Vec3} b @returns {Vec3} */
    add: function (a, b) { return [a[0] + b[0], a[1] + b[1], a[2] + b[2]]; },
    /** @param {Vec3} a @param {Vec3} b @returns {Vec3} */
    sub: function (a, b) { return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]; },
    /** @param {Vec3} a @param {number} s @returns {Vec3} */
    scale: function (a, s) { return [a[0] * s, a[1] * s, a[2] * s]; },
    /** @param {Vec3} a @param {Vec3} b */
    dot: function (a, b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; },
    /** @param {Vec3} a @param {Vec3} b @returns {Vec3} */
    cross: function (a, b) {
      return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
    },
    /** @param {Vec3} a */
    length: function (a) { return Math.hypot(a[0], a[1], a[2]); },
    /** @param {Vec3} a @returns {Vec3} */
    normalize: function (a) {
      const l = Math.hypot(a[0], a[1], a[2]);
      return l > 0 ? [a[0] / l, a[1] / l, a[2] / l] : [0, 0, 0];
    },
    // Rotates a about the unit axis k by angle (Rodrigues).
    /** @param {Vec3} a @param {Vec3} k @param {number} angle @returns {Vec3} */
    rotate: function (a, k, angle) {
      const c = Math.cos(angle), s = Math.sin(angle);
      const kxa = v.cross(k, a);
      const kda = v.dot(k, a) * (1 - c);
      return [a[0] * c + kxa[0] * s + k[0] * kda,
              a[1] * c + kxa[1] * s + k[1] * kda,
              a[2] * c + kxa[2] * s + k[2] * kda];
    },
  };

  /** @param {Vec3} a @returns {Vec3} */
  function copy(a) { return [a[0], a[1], a[2]]; }

  /** @param {unknown} a @returns {a is Vec3} */
  function isVec3(a) {
    return Array.isArray(a) && a.length === 3 && a.every(function (x) { return typeof x === "number" && isFinite(x); });
  }

  class Camera {
    constructor() {
      /** @type {Vec3} */
      this.eye = [0, 1.5, 3.5];
      /** @type {Vec3} */
      this.target = [0, 0, 0];
      /** @type {Vec3} */
      this.up = [0, 1, 0];
      this.fov = 45;
      this.minDistance = 0.05;
      this.maxDistance = 100;
      this.version = 0; // bumped on every change, so the page knows to redraw
    }

    // Sets any of {eye, target, up, fov}; throws a TypeError on bad input.
    /** @param {Partial<Manifold.CameraSpec>} c */
    set(c) {
      if (!c || typeof c !== "object") throw new TypeError("setCamera expects {eye, target, up, fov}");
      const eye = c.eye !== undefined ? c.eye : this.eye;
      const target = c.target !== undefined ? c.target : this.target;
      const up = c.up !== undefined ? c.up : this.up;
      const fov = c.fov !== undefined ? c.fov : this.fov;
      /** @type {("eye" | "target" | "up")[]} */ (["eye", "target", "up"]).forEach(function (k) {
        if (c[k] !== undefined && !isVec3(c[k])) throw new TypeError("camera." + k + " must be [x, y, z] with finite numbers");
      });
      if (typeof fov !== "number" || !(fov > 0 && fov < 180)) throw new TypeError("camera.fov must be degrees in (0, 180)");
      const f = v.sub(target, eye);
      if (v.length(f) === 0) throw new TypeError("camera.eye and camera.target must differ");
      if (v.length(v.cross(f, up)) === 0) throw new TypeError("camera.up must not be parallel to the view direction");
      this.eye = copy(eye);
      this.target = copy(target);
      this.up = copy(up);
      this.fov = fov;
      this.version++;
    }

    /** @returns {Manifold.CameraSpec} */
    get() {
      return { eye: copy(this.eye), target: copy(this.target), up: copy(this.up), fov: this.fov };
    }

    // The orthonormal frame of the view: forward (into the screen), right, up.
    basis() {
      const forward = v.normalize(v.sub(this.target, this.eye));
      const right = v.normalize(v.cross(forward, this.up));
      const up = v.cross(right, forward);
      return { forward: forward, right: right, up: up, tanHalf: Math.tan(this.fov * Math.PI / 360) };
    }

    // The unit ray direction through backing-store position (px, py) of a
    // width × height canvas (pixel centres at +0.5).
    /** @param {number} px @param {number} py @param {number} width @param {number} height */
    rayDirection(px, py, width, height) {
      const b = this.basis();
      const sx = (2 * px / width - 1) * b.tanHalf * (width / height);
      const sy = (1 - 2 * py / height) * b.tanHalf;
      return v.normalize(v.add(b.forward, v.add(v.scale(b.right, sx), v.scale(b.up, sy))));
    }

    // World point → [px, py] backing-store pixels (continuous), or null
    // when the point is not in front of the camera.
    /** @param {Vec3} p @param {number} width @param {number} height @returns {[number, number] | null} */
    project(p, width, height) {
      const b = this.basis();
      const d = v.sub(p, this.eye);
      const z = v.dot(d, b.forward);
      if (!(z > 1e-9)) return null;
      const sx = v.dot(d, b.right) / z / (b.tanHalf * (width / height));
      const sy = v.dot(d, b.up) / z / b.tanHalf;
      return [(sx + 1) * 0.5 * width, (1 - sy) * 0.5 * height];
    }

    // Orbit about the target: dx, dy in pixels of a canvas `height` tall
    // (dragging across the full height turns by about 180 degrees).
    /** @param {number} dx @param {number} dy @param {number} height */
    orbit(dx, dy, height) {
      const k = Math.PI / Math.max(1, height);
      const pole = v.normalize(this.up);
      let offset = v.sub(this.eye, this.target);
      offset = v.rotate(offset, pole, dx * k);
      const right = v.normalize(v.cross(v.scale(offset, -1), pole));
      // keep the eye off the pole, so the view never flips over
      const dist = v.length(offset);
      const angle = Math.acos(Math.max(-1, Math.min(1, v.dot(offset, pole) / dist)));
      const minA = 0.02, maxA = Math.PI - 0.02;
      // rotating by -turn about `right` lifts the eye by `turn` radians towards the pole
      const turn = Math.max(angle - maxA, Math.min(angle - minA, dy * k));
      offset = v.rotate(offset, right, -turn);
      this.eye = v.add(this.target, offset);
      this.version++;
    }

    // Moves the eye towards (factor < 1) or away from (factor > 1) the target.
    /** @param {number} factor */
    zoom(factor) {
      const offset = v.sub(this.eye, this.target);
      const dist = v.length(offset);
      const d = Math.max(this.minDistance, Math.min(this.maxDistance, dist * factor));
      this.eye = v.add(this.target, v.scale(offset, d / dist));
      this.version++;
    }

    // Slides eye and target in the view plane by dx, dy pixels.
    /** @param {number} dx @param {number} dy @param {number} height */
    pan(dx, dy, height) {
      const b = this.basis();
      const dist = v.length(v.sub(this.eye, this.target));
      const perPixel = 2 * b.tanHalf * dist / Math.max(1, height);
      const move = v.add(v.scale(b.right, -dx * perPixel), v.scale(b.up, dy * perPixel));
      this.eye = v.add(this.eye, move);
      this.target = v.add(this.target, move);
      this.version++;
    }

    // Column-major 4×4 view-projection matrix (WebGL clip space), for
    // rasterising geometry (the engine's body polygons) in the same view as
    // the traced surface.
    /** @param {number} aspect @param {number} near @param {number} far */
    viewProjection(aspect, near, far) {
      const b = this.basis();
      const e = this.eye;
      const f = 1 / b.tanHalf;
      const r = b.right, u = b.up, fw = b.forward;
      // view: rows right, up, -forward
      const view = [
        r[0], u[0], -fw[0], 0,
        r[1], u[1], -fw[1], 0,
        r[2], u[2], -fw[2], 0,
        -v.dot(r, e), -v.dot(u, e), v.dot(fw, e), 1,
      ];
      const nf = 1 / (near - far);
      const proj = [
        f / aspect, 0, 0, 0,
        0, f, 0, 0,
        0, 0, (far + near) * nf, -1,
        0, 0, 2 * far * near * nf, 0,
      ];
      const out = new Float32Array(16);
      for (let c = 0; c < 4; c++) {
        for (let rr = 0; rr < 4; rr++) {
          let s = 0;
          for (let k = 0; k < 4; k++) s += proj[k * 4 + rr] * view[c * 4 + k];
          out[c * 4 + rr] = s;
        }
      }
      return out;
    }
  }

  const exported = { Camera: Camera, vec: v, isVec3: isVec3 };
  W.ManifoldWeb = W.ManifoldWeb || /** @type {ManifoldWebModules} */ ({});
  W.ManifoldWeb.camera = exported;
  return exported;
})(globalThis);
