// Draws curves on the surface over the traced picture: the geodesic tool's
// geodesic, a throw's preview and the bodies' trails. A curve is a list of
// segments, each a screen-space ribbon a fixed number of pixels wide (one
// instance of a six-vertex quad, its ends from the segment's points),
// coloured with an opacity at each end (trails fade), hidden behind the
// traced surface as bodies are, and drawn at each of a quotient's images.
/* exported ManifoldWebCurves */
var ManifoldWebCurves = (function (W) {
  "use strict";
  const G = W.ManifoldWeb.gl;
  /** @type {Manifold.Image} */
  // the image p -> L p + t as [L row by row, t] (generated: space.images)
  const IDENTITY = [1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0];
  // numbers per segment: both points, the colour, the opacity at each end
  const SEGMENT = 3 + 3 + 3 + 2;

  const VERTEX = `#version 300 es
precision highp float;
uniform mat4 uViewProjection;
uniform mat3 uImageLinear;
uniform vec3 uImageShift;
uniform vec2 uViewport;
uniform float uWidth;      // pixels
in vec3 aFrom;
in vec3 aTo;
in vec3 aColour;
in vec2 aAlpha;
in vec2 aCorner;           // (end 0 or 1, side -1 or 1)
out vec3 vWorld;
out vec4 vColour;
void main() {
  vec3 a = uImageLinear * aFrom + uImageShift;
  vec3 b = uImageLinear * aTo + uImageShift;
  vec4 ca = projectToClip(a);
  vec4 cb = projectToClip(b);
  vec2 sa = ca.xy / ca.w * uViewport, sb = cb.xy / cb.w * uViewport;
  vec2 along = sb - sa;
  vec2 across = length(along) > 1e-6 ? normalize(vec2(-along.y, along.x)) : vec2(0.0, 1.0);
  vec4 c = aCorner.x < 0.5 ? ca : cb;
  c.xy += across * aCorner.y * 0.5 * uWidth / uViewport * c.w;
  vWorld = aCorner.x < 0.5 ? a : b;
  vColour = vec4(aColour, aCorner.x < 0.5 ? aAlpha.x : aAlpha.y);
  gl_Position = c;
}
`;

  const FRAGMENT = `#version 300 es
precision highp float;
uniform highp sampler2D uPosition;
uniform vec3 uEye;
uniform float uClip;       // > 0: nothing beyond |x| or |z| = uClip (the flat spaces' square)
uniform float uBall;       // > 0: nothing farther from the origin (the ball the surface is traced in: images beyond it float over nothing)
in vec3 vWorld;
in vec4 vColour;
out vec4 outColor;
void main() {
  vec4 P = texelFetch(uPosition, ivec2(gl_FragCoord.xy), 0);
  float d = length(vWorld - uEye);
  if (P.w > 0.0 && d > P.w * 1.01 + 2e-3) discard;
  if (uClip > 0.0 && max(abs(vWorld.x), abs(vWorld.z)) > uClip) discard;
  if (uBall > 0.0 && length(vWorld) > uBall) discard;
  outColor = vec4(vColour.rgb * vColour.a, vColour.a);
}
`;

  // The six corners of a segment's quad: (end, side).
  const CORNERS = new Float32Array([0, -1, 1, -1, 1, 1, 0, -1, 1, 1, 0, 1]);

  class CurveRenderer {
    /** @param {WebGL2RenderingContext} gl */
    constructor(gl) {
      this.gl = gl;
      this.program = G.createProgram(gl, W.ManifoldWeb.disc.withProjection(VERTEX), FRAGMENT, "curves");
      this.vao = /** @type {WebGLVertexArrayObject} */ (gl.createVertexArray());
      this.corners = /** @type {WebGLBuffer} */ (gl.createBuffer());
      this.segments = /** @type {WebGLBuffer} */ (gl.createBuffer());
      this.scratch = new Float32Array(SEGMENT * 1024);
      this.count = 0;           // segments gathered since begin()
      this.held = 0;            // segments the buffer can hold
      const p = this.program.program;
      gl.bindVertexArray(this.vao);
      gl.bindBuffer(gl.ARRAY_BUFFER, this.corners);
      gl.bufferData(gl.ARRAY_BUFFER, CORNERS, gl.STATIC_DRAW);
      const corner = gl.getAttribLocation(p, "aCorner");
      gl.enableVertexAttribArray(corner);
      gl.vertexAttribPointer(corner, 2, gl.FLOAT, false, 0, 0);
      gl.bindBuffer(gl.ARRAY_BUFFER, this.segments);
      let offset = 0;
      for (const [name, size] of /** @type {[string, number][]} */ ([["aFrom", 3], ["aTo", 3], ["aColour", 3], ["aAlpha", 2]])) {
        const loc = gl.getAttribLocation(p, name);
        gl.enableVertexAttribArray(loc);
        gl.vertexAttribPointer(loc, size, gl.FLOAT, false, 4 * SEGMENT, 4 * offset);
        gl.vertexAttribDivisor(loc, 1);
        offset += size;
      }
      gl.bindVertexArray(null);
      gl.bindBuffer(gl.ARRAY_BUFFER, null);
    }

    // Starts gathering this frame's segments.
    begin() { this.count = 0; }

    // A segment from a to b (points of an array of xyz triples, at offsets
    // ia and ib), in colour c with opacity alphaA at a and alphaB at b.
    /**
     * @param {ArrayLike<number>} a @param {number} ia @param {ArrayLike<number>} b @param {number} ib
     * @param {Manifold.Rgb} c @param {number} alphaA @param {number} alphaB
     */
    segment(a, ia, b, ib, c, alphaA, alphaB) {
      if (SEGMENT * (this.count + 1) > this.scratch.length) {
        const bigger = new Float32Array(2 * this.scratch.length);
        bigger.set(this.scratch);
        this.scratch = bigger;
      }
      const s = this.scratch, o = SEGMENT * this.count;
      s[o] = a[ia]; s[o + 1] = a[ia + 1]; s[o + 2] = a[ia + 2];
      s[o + 3] = b[ib]; s[o + 4] = b[ib + 1]; s[o + 5] = b[ib + 2];
      s[o + 6] = c[0]; s[o + 7] = c[1]; s[o + 8] = c[2];
      s[o + 9] = alphaA; s[o + 10] = alphaB;
      this.count++;
    }

    // Draws the gathered segments into the bound colour buffer of `frame`,
    // `width` pixels wide, at each image (the flat spaces' square clipped as
    // bodies are).
    /** @param {ManifoldWeb.OverlayFrame} frame @param {Manifold.Image[]} images @param {number} width */
    draw(frame, images, width) {
      if (this.count === 0) return;
      const gl = this.gl, p = this.program;
      gl.bindBuffer(gl.ARRAY_BUFFER, this.segments);
      if (this.count > this.held) {
        this.held = this.scratch.length / SEGMENT;
        gl.bufferData(gl.ARRAY_BUFFER, this.scratch.byteLength, gl.DYNAMIC_DRAW);
      }
      gl.bufferSubData(gl.ARRAY_BUFFER, 0, this.scratch, 0, SEGMENT * this.count);
      gl.bindBuffer(gl.ARRAY_BUFFER, null);
      gl.viewport(0, 0, frame.width, frame.height);
      gl.disable(gl.DEPTH_TEST);
      gl.enable(gl.BLEND);
      gl.blendFunc(gl.ONE, gl.ONE_MINUS_SRC_ALPHA);
      gl.useProgram(p.program);
      gl.activeTexture(gl.TEXTURE0);
      gl.bindTexture(gl.TEXTURE_2D, frame.positionTexture);
      gl.uniform1i(p.uniform("uPosition"), 0);
      W.ManifoldWeb.disc.setProjection(gl, p, frame);
      gl.uniform3fv(p.uniform("uEye"), frame.eye);
      gl.uniform2f(p.uniform("uViewport"), frame.width / 2, frame.height / 2);
      gl.uniform1f(p.uniform("uWidth"), width * Math.max(1, frame.scale));
      const all = [IDENTITY].concat(images || []);
      let half = 0;
      for (const g of all) half = Math.max(half, Math.abs(g[9]) / 2, Math.abs(g[11]) / 2);
      gl.uniform1f(p.uniform("uClip"), half);
      gl.uniform1f(p.uniform("uBall"), frame.flat ? 0 : frame.bounds || 0);
      gl.bindVertexArray(this.vao);
      for (const g of all) {
        gl.uniformMatrix3fv(p.uniform("uImageLinear"), true, g, 0, 9); // (the linear part: no copy a draw)
        gl.uniform3f(p.uniform("uImageShift"), g[9], g[10], g[11]);
        gl.drawArraysInstanced(gl.TRIANGLES, 0, 6, this.count);
      }
      gl.bindVertexArray(null);
      gl.bindTexture(gl.TEXTURE_2D, null);
      gl.disable(gl.BLEND);
      gl.useProgram(null);
    }

    dispose() {
      const gl = this.gl;
      gl.deleteProgram(this.program.program);
      gl.deleteBuffer(this.corners);
      gl.deleteBuffer(this.segments);
      gl.deleteVertexArray(this.vao);
    }
  }

  // How far apart consecutive points of a curve may be before the curve
  // breaks there (a wrap into the fundamental domain came between them):
  // the space's generated wrapJump, or Infinity where nothing is wrapped.
  /** @param {Manifold.Space} space */
  function wrapJump(space) {
    return space.wrapJump === null ? Infinity : space.wrapJump;
  }

  const exported = { CurveRenderer: CurveRenderer, wrapJump: wrapJump };
  W.ManifoldWeb = W.ManifoldWeb || /** @type {ManifoldWebModules} */ ({});
  W.ManifoldWeb.curves = exported;
  return exported;
})(globalThis);
