// Picking: the surface point under a canvas pixel, read back from the
// tracer's float framebuffer (attachment 0 holds the traced world position).
/* exported ManifoldWebPicking */
var ManifoldWebPicking = (function (W) {
  "use strict";

  // [x, y, z] of the surface under backing-store pixel (x, y) (origin
  // top-left), or null on background or outside the canvas.
  /** @param {ManifoldWeb.Tracer | null} tracer @param {number} x @param {number} y @returns {Manifold.Vec3 | null} */
  function pick(tracer, x, y) {
    checkPixel(x, y);
    if (!tracer || !tracer.hasFrame) return null;
    const xi = Math.floor(x), yi = Math.floor(y);
    if (xi < 0 || yi < 0 || xi >= tracer.width || yi >= tracer.height) return null;
    const texel = tracer.readTexel(xi, yi);
    if (!(texel[3] > 0)) return null;
    return [texel[0], texel[1], texel[2]];
  }

  // Throws unless (x, y) are finite numbers.
  /** @param {unknown} x @param {unknown} y */
  function checkPixel(x, y) {
    if (typeof x !== "number" || typeof y !== "number" || !isFinite(x) || !isFinite(y)) {
      throw new TypeError("pick(x, y) expects canvas backing-store pixel coordinates");
    }
  }

  // Client (CSS) coordinates of a pointer event → backing-store pixels.
  /** @param {HTMLCanvasElement} canvas @param {number} clientX @param {number} clientY @returns {[number, number]} */
  function clientToPixel(canvas, clientX, clientY) {
    const r = canvas.getBoundingClientRect();
    return [(clientX - r.left) * (canvas.width / Math.max(1, r.width)),
            (clientY - r.top) * (canvas.height / Math.max(1, r.height))];
  }

  const exported = { pick: pick, checkPixel: checkPixel, clientToPixel: clientToPixel };
  W.ManifoldWeb = W.ManifoldWeb || /** @type {ManifoldWebModules} */ ({});
  W.ManifoldWeb.picking = exported;
  return exported;
})(globalThis);
