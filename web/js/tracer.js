// The sphere tracer's host code and shaders. The space-specific GLSL
// (field, gradient, boundary, curvature) comes only from web/gen; this file
// supplies the marching loop that uses it, the shading, and the
// antialiasing passes.
//
// Passes per frame:
//   1. trace  → float framebuffer (RGBA32F × 2) at scale s (s = 2 for 2× supersampling,
//               0.5 for a preview frame while the view moves on a slow GPU, else 1):
//        attachment 0 = (x, y, z, distance from the eye) of the surface point; w = -1 on background
//        attachment 1 = (unit normal from the generated gradient, Gaussian curvature, or 0
//                        when curvature colouring is off)
//   2. shade  → the surface buffer (RGBA8): lighting, background gradient, optional
//               curvature colouring
//   (copy)      surface buffer → colour buffer (RGBA8), then the page's overlay (the
//               engine's body polygons) draws into the colour buffer
//   3. post   → canvas: FXAA, or resampling (the 2×2 box filter of the supersampled buffer,
//               the bilinear upscaling of a preview, a plain copy without antialiasing)
// Passes 1 and 2 depend only on the camera, the space and the options: render()
// skips them when the caller's surface key matches the one the buffers were
// shaded with, so moving bodies cost only the copy, the overlay and the post pass.
/* exported ManifoldWebTracer */
var ManifoldWebTracer = (function (W) {
  "use strict";
  const G = W.ManifoldWeb.gl;

  const MAX_STEPS = 192;

  // Appended to the generated GLSL. Uses only field, gradient, boundary and curvature.
  const TRACE_MAIN = `
uniform vec3 uEye;
uniform vec3 uForward;
uniform vec3 uRight;
uniform vec3 uUp;
uniform float uTanHalf;
uniform float uAspect;
uniform vec2 uResolution;
uniform float uBounds;
uniform float uPixelAngle;
uniform bool uCurvature;

layout(location = 0) out vec4 outPosition;
layout(location = 1) out vec4 outNormal;

const int MAX_STEPS = ${MAX_STEPS};
const float RELAX = 0.9;

// distanceEstimate(p) (|f|/|grad f|, or |f| where the gradient is unusable)
// and projectToSurface(p) (Newton along the gradient) come with the space's
// generated GLSL, from Manifold.Surface.

// Newton's method on f along the ray, staying within maxDelta of t; returns
// the sample with the smallest |f| (t itself when the ray only grazes the surface).
float refineAlongRay(vec3 ro, vec3 rd, float t, float maxDelta) {
  float t0 = t;
  float best = t;
  float bestF = 1e30;
  for (int k = 0; k < 4; k++) {
    vec3 p = ro + rd * t;
    float f = field(p);
    if (abs(f) < bestF) { bestF = abs(f); best = t; }
    vec3 g = gradient(p);
    float den = dot(g, rd);
    if (!(abs(den) > 1e-4 * length(g))) break;
    float tn = clamp(t - f / den, t0 - maxDelta, t0 + maxDelta);
    if (abs(tn - t) < 1e-6 * t) break; // converged to float precision
    t = tn;
  }
  return best;
}

// The sign change of f along the ray in [a, b] (fa = f(a), fb = f(b) of
// opposite signs): regula falsi with the Illinois rule, then bisection's guarantee.
float bracketRoot(vec3 ro, vec3 rd, float a, float b, float fa, float fb) {
  int side = 0;
  for (int k = 0; k < 12; k++) {
    float m = (a * fb - b * fa) / (fb - fa);
    if (!(m > a && m < b)) m = 0.5 * (a + b);
    float fm = field(ro + rd * m);
    if ((fm < 0.0) == (fa < 0.0)) {
      a = m; fa = fm;
      if (side == -1) fb *= 0.5;
      side = -1;
    } else {
      b = m; fb = fm;
      if (side == 1) fa *= 0.5;
      side = 1;
    }
    if (b - a < 1e-6 * b) break;
  }
  return abs(fa) < abs(fb) ? a : b;
}

void main() {
  vec2 s = gl_FragCoord.xy / uResolution * 2.0 - 1.0;
  vec3 rd = normalize(uForward + (s.x * uTanHalf * uAspect) * uRight + (s.y * uTanHalf) * uUp);
  vec3 ro = uEye;
  outPosition = vec4(0.0, 0.0, 0.0, -1.0);
  outNormal = vec4(0.0);

  // march only inside the ball of radius uBounds about the origin
  float b = dot(ro, rd);
  float disc = b * b - (dot(ro, ro) - uBounds * uBounds);
  if (disc <= 0.0) return;
  float sq = sqrt(disc);
  float tFar = -b + sq;
  if (tFar <= 0.0) return;
  float t = max(-b - sq, 0.0);

  float tPrev = t;
  float fPrev = 0.0;
  bool checkSign = false;
  bool found = false;
  vec3 hit = vec3(0.0);
  float lastD = 1e30;
  float lastEps = 0.0;

  for (int i = 0; i < MAX_STEPS; i++) {
    vec3 p = ro + rd * t;
    float f = field(p);
    float eps = 0.5 * uPixelAngle * t + 1e-5; // half a pixel's footprint at t
    if (checkSign && ((f < 0.0) != (fPrev < 0.0))) {
      // the step from tPrev crossed the surface
      vec3 q = projectToSurface(ro + rd * bracketRoot(ro, rd, tPrev, t, fPrev, f));
      if (boundary(q) >= 0.0) { found = true; hit = q; break; }
      // outside the allowed region: go on from t, already past it
    }
    float d = distanceEstimate(p);
    lastD = d;
    lastEps = eps;
    if (d < eps) {
      float tr = refineAlongRay(ro, rd, t, 4.0 * eps);
      vec3 q = projectToSurface(ro + rd * tr);
      if (boundary(q) >= 0.0) { found = true; hit = q; break; }
      // outside the allowed region: step through the surface and march on
      tPrev = t;
      t = max(t, tr) + 2.0 * eps;
      checkSign = false;
      if (t >= tFar) break;
      continue;
    }
    if (t >= tFar) break;
    tPrev = t;
    fPrev = f;
    checkSign = true;
    t = min(t + d * RELAX, tFar);
  }
  if (!found && lastD < 2.0 * lastEps) {
    // out of steps right next to the surface (grazing rays): take it
    vec3 q = projectToSurface(ro + rd * t);
    if (boundary(q) >= 0.0) { found = true; hit = q; }
  }
  if (!found) return;

  vec3 g = gradient(hit);
  float gLen = length(g);
  vec3 n = (gLen > 1e-20 && gLen < 1e30) ? g / gLen : -rd;
  float k = uCurvature ? curvature(hit) : 0.0;
  outPosition = vec4(hit, length(hit - ro));
  outNormal = vec4(n, (abs(k) < 1e20) ? k : 0.0);
}
`;

  // The trace pass of a flat view (the Poincaré or Klein disc of a hyperbolic
  // space), appended to the space's GLSL and the generated maps: each pixel's
  // point of the plane, from the disc's map and the view's inverse boost. Its
  // distance is huge (nothing hides behind a flat picture); its normal is 0
  // (the shading draws it unlit).
  const FLAT_MAIN = `
uniform vec2 uCentre;      // the disc's centre, pixels of this buffer
uniform float uRadius;     // the disc's radius, pixels of this buffer
uniform int uModel;        // 1: the Poincare disc; 2: the Klein disc
uniform mat3 uToWorld;     // the view's inverse boost
uniform bool uCurvature;

layout(location = 0) out vec4 outPosition;
layout(location = 1) out vec4 outNormal;

void main() {
  outPosition = vec4(0.0, 0.0, 0.0, -1.0);
  outNormal = vec4(0.0);
  vec2 d = (gl_FragCoord.xy - uCentre) / uRadius;
  float u = d.x, w = -d.y; // the buffer's rows go up, the disc's w down the canvas
  if (u * u + w * w >= 1.0) return;
  vec3 p = uToWorld * (uModel == 2 ? fromKlein(u, w) : fromPoincare(u, w));
  if (boundary(p) < 0.0) return;
  // the point folded into the quotient's fundamental domain (generated:
  // the Bolza surface's octagon, four side pairings a call; elsewhere the
  // point itself), so the grid and the colouring repeat in every tile; the
  // normal's y says the point was folded (a quarter: the bodies' shading
  // takes a normal shorter than a half for none)
  vec3 f = foldIntoDomain(foldIntoDomain(foldIntoDomain(p)));
  float folded = distance(f, p) > 1e-4 * p.y ? 0.25 : 0.0;
  float k = uCurvature ? curvature(f) : 0.0;
  outPosition = vec4(f, 1.0e30);
  outNormal = vec4(0.0, folded, 0.0, (abs(k) < 1e20) ? k : 0.0);
}
`;

  const SHADE_FRAGMENT = `#version 300 es
precision highp float;
precision highp int;
uniform highp sampler2D uPosition;
uniform highp sampler2D uNormal;
uniform vec3 uEye;
uniform vec3 uForward;
uniform vec3 uRight;
uniform vec3 uUp;
uniform vec2 uResolution;
uniform vec3 uBackgroundTop;
uniform vec3 uBackgroundBottom;
uniform bool uCurvature;
uniform float uCurvatureScale;
uniform bool uGrid;
uniform float uGridSpacing;
uniform float uLineWidth; // grid line width in pixels of this buffer
uniform bool uFlat;       // a flat view (a hyperbolic disc): unlit, its grid of geodesics
uniform bool uTiled;      // a flat view of a quotient: its fundamental domain's tiles marked
out vec4 outColor;

vec3 toLinear(vec3 c) { return pow(c, vec3(2.2)); }
vec3 toDisplay(vec3 c) { return pow(clamp(c, 0.0, 1.0), vec3(1.0 / 2.2)); }

void main() {
  ivec2 ij = ivec2(gl_FragCoord.xy);
  vec4 P = texelFetch(uPosition, ij, 0);
  // grid coordinates and their change per pixel (derivatives before any branch)
  vec3 q = P.xyz / uGridSpacing;
  vec3 qw = fwidth(q);
  // a flat view's grid: the geodesics of the generated grid (the vertex where there is no point)
  vec2 g2 = geodesicGrid(P.w > 0.0 ? P.xyz : vec3(0.0, 1.0, 0.0)) / uGridSpacing;
  vec2 g2w = fwidth(g2);
  // a tiled flat view's tile edges: where neighbouring pixels were folded
  // into the domain differently, their points jump
  float jump = length(fwidth(P.xyz)) / max(abs(P.y), 1.0);
  vec3 background = mix(uBackgroundBottom, uBackgroundTop, gl_FragCoord.y / uResolution.y);
  if (!(P.w > 0.0)) { outColor = vec4(background, 1.0); return; }

  vec4 N = texelFetch(uNormal, ij, 0);
  vec3 n = normalize(N.xyz);
  vec3 view = normalize(uEye - P.xyz);
  float facing = dot(n, view);
  if (facing < 0.0) { n = -n; facing = -facing; } // two-sided: light the side we see

  vec3 albedo = vec3(0.86, 0.80, 0.70);
  if (uCurvature) {
    // white at K = 0, red for K > 0, blue for K < 0
    float c = tanh(N.w * uCurvatureScale);
    albedo = c >= 0.0 ? mix(vec3(0.93), vec3(0.86, 0.12, 0.10), c)
                      : mix(vec3(0.93), vec3(0.12, 0.30, 0.90), -c);
  }
  if (uGrid && !uFlat) {
    // contour lines of x, y and z on the surface, one pixel wide; each family fades
    // where the surface is nearly parallel to its planes or the lines get too dense
    vec3 lineDist = abs(fract(q - 0.5) - 0.5) / max(qw, vec3(1e-6));
    vec3 line = 1.0 - clamp(lineDist - 0.5 * uLineWidth, 0.0, 1.0);
    vec3 across = sqrt(max(1.0 - n * n, 0.0));
    vec3 sparse = 1.0 - smoothstep(vec3(0.12), vec3(0.35), qw * uLineWidth);
    vec3 g = line * smoothstep(vec3(0.15), vec3(0.5), across) * sparse;
    albedo *= 1.0 - 0.2 * max(g.x, max(g.y, g.z));
  }
  if (uFlat) {
    if (uGrid) {
      vec2 lineDist = abs(fract(g2 - 0.5) - 0.5) / max(g2w, vec2(1e-6));
      vec2 line = (1.0 - clamp(lineDist - 0.5 * uLineWidth, 0.0, 1.0)) * (1.0 - smoothstep(vec2(0.12), vec2(0.35), g2w * uLineWidth));
      albedo = (uCurvature ? albedo : vec3(0.86, 0.80, 0.70)) * (1.0 - 0.25 * max(line.x, line.y));
    }
    if (uTiled) {
      // the domain's images a shade darker than the domain, their edges dark
      if (N.y > 0.1) albedo *= 0.78;
      if (jump > 0.2) albedo *= 0.35;
    }
    outColor = vec4(toDisplay(toLinear(albedo) * 0.92), 1.0);
    return;
  }
  vec3 base = toLinear(albedo);

  // lights fixed to the camera: a warm key from the upper left, a cool fill from the right
  vec3 key = normalize(-0.45 * uRight + 0.75 * uUp - 0.5 * uForward);
  vec3 fill = normalize(0.8 * uRight - 0.1 * uUp - 0.6 * uForward);
  float dKey = max(dot(n, key), 0.0);
  float dFill = max(dot(n, fill), 0.0);
  vec3 h = normalize(key + view);
  float spec = dKey > 0.0 ? pow(max(dot(n, h), 0.0), 60.0) : 0.0;
  float sky = 0.5 + 0.5 * dot(n, uUp);
  vec3 ambient = mix(vec3(0.05, 0.045, 0.04), vec3(0.14, 0.15, 0.18), sky);
  float rim = pow(1.0 - facing, 4.0);

  vec3 c = base * (ambient + 1.0 * dKey * vec3(1.0, 0.96, 0.9) + 0.3 * dFill * vec3(0.75, 0.85, 1.0))
         + 0.28 * spec * vec3(1.0, 0.98, 0.95)
         + 0.06 * rim * vec3(0.7, 0.8, 1.0);
  outColor = vec4(toDisplay(c), 1.0);
}
`;

  // FXAA (after Timothy Lottes' FXAA, the compact PC variant).
  const FXAA_FRAGMENT = `#version 300 es
precision highp float;
uniform sampler2D uColor;
uniform vec2 uInvResolution;
out vec4 outColor;
float luma(vec3 c) { return dot(c, vec3(0.299, 0.587, 0.114)); }
void main() {
  vec2 uv = gl_FragCoord.xy * uInvResolution;
  vec3 cNW = texture(uColor, uv + vec2(-1.0, -1.0) * uInvResolution).rgb;
  vec3 cNE = texture(uColor, uv + vec2( 1.0, -1.0) * uInvResolution).rgb;
  vec3 cSW = texture(uColor, uv + vec2(-1.0,  1.0) * uInvResolution).rgb;
  vec3 cSE = texture(uColor, uv + vec2( 1.0,  1.0) * uInvResolution).rgb;
  vec3 cM = texture(uColor, uv).rgb;
  float lNW = luma(cNW), lNE = luma(cNE), lSW = luma(cSW), lSE = luma(cSE), lM = luma(cM);
  float lMin = min(lM, min(min(lNW, lNE), min(lSW, lSE)));
  float lMax = max(lM, max(max(lNW, lNE), max(lSW, lSE)));
  if (lMax - lMin < max(0.0312, lMax * 0.125)) { outColor = vec4(cM, 1.0); return; }
  vec2 dir = vec2(-((lNW + lNE) - (lSW + lSE)), (lNW + lSW) - (lNE + lSE));
  float reduce = max((lNW + lNE + lSW + lSE) * (0.25 / 8.0), 1.0 / 128.0);
  float rcpMin = 1.0 / (min(abs(dir.x), abs(dir.y)) + reduce);
  dir = clamp(dir * rcpMin, vec2(-8.0), vec2(8.0)) * uInvResolution;
  vec3 a = 0.5 * (texture(uColor, uv + dir * (1.0 / 3.0 - 0.5)).rgb +
                  texture(uColor, uv + dir * (2.0 / 3.0 - 0.5)).rgb);
  vec3 b = a * 0.5 + 0.25 * (texture(uColor, uv - dir * 0.5).rgb +
                             texture(uColor, uv + dir * 0.5).rgb);
  float lB = luma(b);
  outColor = vec4((lB < lMin || lB > lMax) ? a : b, 1.0);
}
`;

  // Resampling to the canvas with one bilinear tap: the 2×2 box filter of a
  // supersampled buffer, or the upscaling of a half-resolution preview.
  const RESAMPLE_FRAGMENT = `#version 300 es
precision highp float;
uniform sampler2D uColor;
uniform vec2 uInvResolution;
out vec4 outColor;
void main() {
  outColor = vec4(texture(uColor, gl_FragCoord.xy * uInvResolution).rgb, 1.0);
}
`;

  const ANTIALIAS_MODES = ["fxaa", "ssaa", "off"];

  // The shading pass, with the generated geodesic grid of the flat views.
  function shadeSource() {
    return SHADE_FRAGMENT.replace("out vec4 outColor;\n", "out vec4 outColor;\n" + W.Manifold.hyperbolic.glsl);
  }

  // The flat views' trace pass for a space's GLSL (numbered as traceSource's).
  /** @param {string} spaceGlsl */
  function flatSource(spaceGlsl) {
    return "#version 300 es\nprecision highp float;\nprecision highp int;\n" +
      "#line 1 1\n" + spaceGlsl + "\n#line 1 2\n" + W.Manifold.hyperbolic.glsl + FLAT_MAIN;
  }

  // The full fragment shader of the trace pass for a space's GLSL. `#line`
  // numbers the generated part as source 1 and the tracer as source 2, so a
  // compiler log line "ERROR: 1:12" points at line 12 of the space's glsl.
  /** @param {string} spaceGlsl */
  function traceSource(spaceGlsl) {
    return "#version 300 es\nprecision highp float;\nprecision highp int;\n" +
      "#line 1 1\n" + spaceGlsl + "\n#line 1 2\n" + TRACE_MAIN;
  }

  /**
   * The buffers of one trace size: the float target (positions, normals), the
   * shaded surface, and the colour buffer the overlay draws into.
   * @typedef {{ float: ManifoldWeb.Target, surface: ManifoldWeb.Target, color: ManifoldWeb.Target,
   *   surfaceKey: string | null, traced: boolean }} Buffers
   */

  class Tracer {
    /** @param {WebGL2RenderingContext} gl */
    constructor(gl) {
      this.gl = gl;
      this.vao = /** @type {WebGLVertexArrayObject} */ (gl.createVertexArray());
      /** @type {ManifoldWeb.Program | null} */
      this.traceProgram = null;
      /** @type {ManifoldWeb.Program | null} the flat views' trace pass (hyperbolic spaces) */
      this.flatProgram = null;
      this.tiled = false; // the flat views mark the fundamental domain's tiles
      this.shadeProgram = G.createProgram(gl, G.FULLSCREEN_VERTEX, shadeSource(), "shading pass");
      this.fxaaProgram = G.createProgram(gl, G.FULLSCREEN_VERTEX, FXAA_FRAGMENT, "FXAA pass");
      this.resampleProgram = G.createProgram(gl, G.FULLSCREEN_VERTEX, RESAMPLE_FRAGMENT, "resampling pass");
      /** @type {Map<string, Buffers>} */
      this.buffers = new Map(); // "W×H" → { float (RGBA32F × 2), surface, color (RGBA8), surfaceKey }
      /** @type {Buffers | null} */
      this.current = null;      // the buffers of the configured frame
      this.width = 0;           // canvas backing store
      this.height = 0;
      this.scale = 1;           // trace buffer pixels per canvas pixel (2: supersampling, 0.5: preview)
      /** @type {Manifold.Antialias} */
      this.antialias = "fxaa";
      this.hasFrame = false;    // the current float buffer holds a traced frame
      this.preview = false;     // the configured frame is a half-resolution preview
    }

    // Compiles the trace pass for a space's GLSL; throws a PageError with the
    // compiler log when it fails (the previous program is dropped either way).
    // flat: the space is hyperbolic, so its flat views' pass is made too;
    // tiled: it is a quotient, whose flat views mark the fundamental
    // domain's tiles.
    /** @param {string} glsl @param {string} label @param {boolean} [flat] @param {boolean} [tiled] */
    setSpaceGlsl(glsl, label, flat, tiled) {
      this.dropSpace();
      this.tiled = !!tiled;
      this.traceProgram = G.createProgram(this.gl, G.FULLSCREEN_VERTEX, traceSource(glsl), label);
      if (flat) this.flatProgram = G.createProgram(this.gl, G.FULLSCREEN_VERTEX, flatSource(glsl), label + " (flat view)");
    }

    dropSpace() {
      if (this.traceProgram) this.gl.deleteProgram(this.traceProgram.program);
      if (this.flatProgram) this.gl.deleteProgram(this.flatProgram.program);
      this.traceProgram = null;
      this.flatProgram = null;
      this.hasFrame = false;
      this.buffers.forEach(function (b) { b.traced = false; b.surfaceKey = null; });
    }

    // Sizes the buffers for a width × height canvas and an antialiasing mode.
    // preview: trace at half resolution, no antialiasing (for slow GPUs while the view moves).
    /** @param {number} width @param {number} height @param {Manifold.Antialias} antialias @param {boolean} [preview] */
    configure(width, height, antialias, preview) {
      const gl = this.gl;
      if (ANTIALIAS_MODES.indexOf(antialias) < 0) throw new TypeError("antialias must be one of " + ANTIALIAS_MODES.join(", "));
      const scale = preview ? 0.5 : antialias === "ssaa" ? 2 : 1;
      const tw = Math.max(1, Math.round(width * scale)), th = Math.max(1, Math.round(height * scale));
      const key = tw + "x" + th;
      if (width !== this.width || height !== this.height) {
        // a new canvas size: the buffers of the old one go
        const self = this;
        this.buffers.forEach(function (b) { G.deleteTarget(gl, b.float); G.deleteTarget(gl, b.surface); G.deleteTarget(gl, b.color); });
        this.buffers.clear();
        self.current = null;
      }
      let b = this.buffers.get(key);
      if (!b) {
        b = { float: G.createFloatTarget(gl, tw, th, 2), surface: G.createColorTarget(gl, tw, th),
          color: G.createColorTarget(gl, tw, th), surfaceKey: null, traced: false };
        this.buffers.set(key, b);
      }
      this.current = b;
      this.hasFrame = b.traced;
      this.width = width;
      this.height = height;
      this.scale = tw / width;
      this.antialias = antialias;
      this.preview = !!preview;
    }

    // Draws one frame. view = { camera (a Camera), bounds, curvature (bool),
    // curvatureScale, grid (bool), gridSpacing, background: {top, bottom} (0..1 RGB) }.
    // overlay(frame) is called after shading with the colour buffer bound.
    // surfaceKey: anything that changes whenever the traced picture would
    // (camera, space, options); when it equals the key of the buffers' last
    // shading, the trace and shading are reused. null: always trace.
    /**
     * @param {ManifoldWeb.TraceView} view
     * @param {((frame: ManifoldWeb.OverlayFrame) => void) | null} overlay
     * @param {string | null} [surfaceKey]
     */
    render(view, overlay, surfaceKey) {
      const gl = this.gl;
      if (!this.current) throw new Error("Tracer.render before configure");
      const buffers = this.current;
      const floatTarget = buffers.float;
      const reuse = surfaceKey !== undefined && surfaceKey !== null && buffers.traced && buffers.surfaceKey === surfaceKey;
      const tw = floatTarget.width, th = floatTarget.height;
      const basis = view.camera.basis();
      gl.disable(gl.BLEND);
      gl.disable(gl.DEPTH_TEST);
      gl.disable(gl.CULL_FACE);

      if (!reuse) {
        // 1. trace
        gl.bindFramebuffer(gl.FRAMEBUFFER, floatTarget.fb);
        gl.viewport(0, 0, tw, th);
        gl.clearBufferfv(gl.COLOR, 0, [0, 0, 0, -1]);
        gl.clearBufferfv(gl.COLOR, 1, [0, 0, 0, 0]);
        const flat = view.flat || null;
        if (flat && this.flatProgram) {
          const p = this.flatProgram;
          gl.useProgram(p.program);
          gl.uniform2f(p.uniform("uCentre"), 0.5 * tw, 0.5 * th);
          gl.uniform1f(p.uniform("uRadius"), flat.radius * this.scale);
          gl.uniform1i(p.uniform("uModel"), flat.model === "klein" ? 2 : 1);
          gl.uniformMatrix3fv(p.uniform("uToWorld"), true, flat.toWorld);
          gl.uniform1i(p.uniform("uCurvature"), view.curvature ? 1 : 0);
          G.drawFullscreen(gl, this.vao);
          this.hasFrame = true;
        } else if (this.traceProgram) {
          const p = this.traceProgram;
          gl.useProgram(p.program);
          gl.uniform3fv(p.uniform("uEye"), view.camera.eye);
          gl.uniform3fv(p.uniform("uForward"), basis.forward);
          gl.uniform3fv(p.uniform("uRight"), basis.right);
          gl.uniform3fv(p.uniform("uUp"), basis.up);
          gl.uniform1f(p.uniform("uTanHalf"), basis.tanHalf);
          gl.uniform1f(p.uniform("uAspect"), tw / th);
          gl.uniform2f(p.uniform("uResolution"), tw, th);
          gl.uniform1f(p.uniform("uBounds"), view.bounds);
          gl.uniform1f(p.uniform("uPixelAngle"), 2 * basis.tanHalf / th);
          gl.uniform1i(p.uniform("uCurvature"), view.curvature ? 1 : 0);
          G.drawFullscreen(gl, this.vao);
          this.hasFrame = true;
        }
        buffers.traced = this.hasFrame;
        buffers.surfaceKey = this.hasFrame ? surfaceKey : null;

        // 2. shade
        gl.bindFramebuffer(gl.FRAMEBUFFER, buffers.surface.fb);
        gl.viewport(0, 0, tw, th);
        const s = this.shadeProgram;
        gl.useProgram(s.program);
        gl.activeTexture(gl.TEXTURE0);
        gl.bindTexture(gl.TEXTURE_2D, floatTarget.textures[0]);
        gl.activeTexture(gl.TEXTURE1);
        gl.bindTexture(gl.TEXTURE_2D, floatTarget.textures[1]);
        gl.uniform1i(s.uniform("uPosition"), 0);
        gl.uniform1i(s.uniform("uNormal"), 1);
        gl.uniform3fv(s.uniform("uEye"), view.camera.eye);
        gl.uniform3fv(s.uniform("uForward"), basis.forward);
        gl.uniform3fv(s.uniform("uRight"), basis.right);
        gl.uniform3fv(s.uniform("uUp"), basis.up);
        gl.uniform2f(s.uniform("uResolution"), tw, th);
        gl.uniform3fv(s.uniform("uBackgroundTop"), view.background.top);
        gl.uniform3fv(s.uniform("uBackgroundBottom"), view.background.bottom);
        gl.uniform1i(s.uniform("uCurvature"), view.curvature ? 1 : 0);
        gl.uniform1f(s.uniform("uCurvatureScale"), view.curvatureScale);
        gl.uniform1i(s.uniform("uGrid"), view.grid ? 1 : 0);
        gl.uniform1f(s.uniform("uGridSpacing"), view.gridSpacing);
        gl.uniform1f(s.uniform("uLineWidth"), Math.max(1, this.scale));
        gl.uniform1i(s.uniform("uFlat"), flat && this.flatProgram ? 1 : 0);
        gl.uniform1i(s.uniform("uTiled"), flat && this.flatProgram && this.tiled ? 1 : 0);
        G.drawFullscreen(gl, this.vao);
        gl.activeTexture(gl.TEXTURE1);
        gl.bindTexture(gl.TEXTURE_2D, null);
        gl.activeTexture(gl.TEXTURE0);
        gl.bindTexture(gl.TEXTURE_2D, null);
      }

      // the shaded surface → the colour buffer, where the overlay draws
      const target = buffers.color;
      gl.bindFramebuffer(gl.READ_FRAMEBUFFER, buffers.surface.fb);
      gl.bindFramebuffer(gl.DRAW_FRAMEBUFFER, target.fb);
      gl.blitFramebuffer(0, 0, tw, th, 0, 0, tw, th, gl.COLOR_BUFFER_BIT, gl.NEAREST);
      gl.bindFramebuffer(gl.READ_FRAMEBUFFER, null);
      gl.bindFramebuffer(gl.FRAMEBUFFER, target.fb);
      gl.viewport(0, 0, tw, th);

      if (overlay) {
        overlay({
          gl: gl,
          framebuffer: target.fb,
          width: tw,
          height: th,
          scale: this.scale,
          pixelAngle: 2 * basis.tanHalf / th, // the angle a pixel of this buffer spans at the eye
          positionTexture: floatTarget.textures[0],
          normalTexture: floatTarget.textures[1],
        });
      }

      // 3. post: FXAA at full resolution, else resample (2×2 box filter for
      // supersampling, bilinear upscaling for a preview, a copy without antialiasing)
      {
        const post = this.scale === 1 && this.antialias === "fxaa" ? this.fxaaProgram : this.resampleProgram;
        gl.bindFramebuffer(gl.FRAMEBUFFER, null);
        gl.viewport(0, 0, this.width, this.height);
        gl.useProgram(post.program);
        gl.activeTexture(gl.TEXTURE0);
        gl.bindTexture(gl.TEXTURE_2D, target.textures[0]);
        gl.uniform1i(post.uniform("uColor"), 0);
        gl.uniform2f(post.uniform("uInvResolution"), 1 / this.width, 1 / this.height);
        G.drawFullscreen(gl, this.vao);
        gl.bindTexture(gl.TEXTURE_2D, null);
      }
      gl.useProgram(null);
    }

    // The traced texel under canvas backing-store pixel (x, y), origin
    // top-left: Float32Array [x, y, z, distance] (distance -1 on background).
    /** @param {number} x @param {number} y */
    readTexel(x, y) {
      const t = this.current.float;
      const bx = Math.min(t.width - 1, Math.floor(x * this.scale));
      const by = Math.min(t.height - 1, Math.floor(y * this.scale));
      return G.readFloatPixel(this.gl, t, 0, bx, t.height - 1 - by);
    }

    dispose() {
      const gl = this.gl;
      this.dropSpace();
      [this.shadeProgram, this.fxaaProgram, this.resampleProgram].forEach(function (p) { gl.deleteProgram(p.program); });
      this.buffers.forEach(function (b) { G.deleteTarget(gl, b.float); G.deleteTarget(gl, b.surface); G.deleteTarget(gl, b.color); });
      this.buffers.clear();
      this.current = null;
      gl.deleteVertexArray(this.vao);
    }
  }

  const exported = { Tracer: Tracer, traceSource: traceSource, ANTIALIAS_MODES: ANTIALIAS_MODES, MAX_STEPS: MAX_STEPS };
  W.ManifoldWeb = W.ManifoldWeb || /** @type {ManifoldWebModules} */ ({});
  W.ManifoldWeb.tracer = exported;
  return exported;
})(globalThis);
