// Draws the engine's body polygons (the `verts` array the generated `step` and
// `polygonise` fill) over the traced surface: per body a triangle mesh (a fan
// round the centre, then quads between the rings of geodesic steps), filled
// with the body's colour and lit with the traced surface normal, with a dark
// outline and a light axis mark (centre → outline vertex of direction 0) drawn
// in the fragment shader a fixed number of pixels wide. A fragment behind the
// traced surface (further from the eye than the traced distance at its pixel
// plus a small tolerance, the paper's trick) is discarded, so bodies on the far
// side are hidden. On quotient spaces every body is also drawn at each of the
// space's images (space.images, generated: −p on antipodal quotients, the
// neighbouring translates on the flat torus and Klein bottle, so bodies show
// on both sides of a seam).
(function (W) {
  "use strict";
  const G = W.ManifoldWeb.gl;
  // how far beyond the flat spaces' square bodies are drawn (world units): 0, the
  // fundamental square alone, where a body across an edge shows in two (or four) parts
  const IMAGE_BAND = 0;

  const VERTEX = `#version 300 es
precision highp float;
uniform mat4 uViewProjection;
uniform vec3 uImageScale;  // the image p -> scale * p + shift (the identity: 1, 0)
uniform vec3 uImageShift;
in vec3 aPosition;
in vec3 aColour;
in vec3 aMark;   // ring (0 at the centre … 1 on the outline), then the vertex's place in a unit disc (x along the axis)
out vec3 vWorld;
out vec3 vColour;
out vec3 vMark;
void main() {
  vec3 p = uImageScale * aPosition + uImageShift;
  vWorld = p;
  vColour = aColour;
  vMark = aMark;
  gl_Position = uViewProjection * vec4(p, 1.0);
}
`;

  const FRAGMENT = `#version 300 es
precision highp float;
uniform highp sampler2D uPosition;
uniform highp sampler2D uNormal;
uniform vec3 uEye;
uniform float uTolerance;   // relative depth tolerance
uniform float uLineWidth;   // outline width in pixels of this buffer
uniform float uClip;        // > 0: nothing beyond |x| or |z| = uClip (the flat spaces' square)
in vec3 vWorld;
in vec3 vColour;
in vec3 vMark;
out vec4 outColor;

vec3 toLinear(vec3 c) { return pow(c, vec3(2.2)); }
vec3 toDisplay(vec3 c) { return pow(clamp(c, 0.0, 1.0), vec3(1.0 / 2.2)); }

void main() {
  // pixel distances to the outline and to the axis (derivatives before any branch)
  vec3 w = fwidth(vMark);
  float toOutline = (1.0 - vMark.x) / max(w.x, 1e-6);
  float toAxis = vMark.y > 0.0 ? abs(vMark.z) / max(w.z, 1e-6) : 1e6;

  ivec2 ij = ivec2(gl_FragCoord.xy);
  vec4 P = texelFetch(uPosition, ij, 0);
  float d = length(vWorld - uEye);
  // hidden behind the traced surface (background pixels hide nothing)
  if (P.w > 0.0 && d > P.w * (1.0 + uTolerance) + 1e-3) discard;
  if (uClip > 0.0 && max(abs(vWorld.x), abs(vWorld.z)) > uClip) discard;

  vec3 view = normalize(uEye - vWorld);
  vec3 n = texelFetch(uNormal, ij, 0).xyz;
  float facing = P.w > 0.0 && dot(n, n) > 0.5 ? abs(dot(normalize(n), view)) : 1.0;
  vec3 base = toLinear(vColour);
  vec3 c = base * (0.35 + 0.75 * facing);

  float outline = 1.0 - smoothstep(uLineWidth - 0.5, uLineWidth + 0.5, toOutline);
  float axis = 1.0 - smoothstep(0.8 * uLineWidth - 0.5, 0.8 * uLineWidth + 0.5, toAxis);
  c = mix(c, mix(c, vec3(1.0), 0.75), axis);
  c = mix(c, base * 0.12, outline);
  outColor = vec4(toDisplay(c), 1.0);
}
`;

  // The grabbed body's target: a round dot at the picked surface point.
  const MARK_VERTEX = `#version 300 es
precision highp float;
uniform mat4 uViewProjection;
uniform vec3 uPoint;
uniform float uSize;
void main() {
  gl_Position = uViewProjection * vec4(uPoint, 1.0);
  gl_PointSize = uSize;
}
`;
  const MARK_FRAGMENT = `#version 300 es
precision highp float;
out vec4 outColor;
void main() {
  float r = length(gl_PointCoord - 0.5) * 2.0;
  if (r > 1.0) discard;
  outColor = vec4(r > 0.6 ? vec3(0.05) : vec3(1.0), 1.0);
}
`;

  class BodyRenderer {
    constructor(gl) {
      this.gl = gl;
      this.program = G.createProgram(gl, VERTEX, FRAGMENT, "body polygons");
      this.markProgram = G.createProgram(gl, MARK_VERTEX, MARK_FRAGMENT, "grab mark");
      this.vao = gl.createVertexArray();
      this.markVao = gl.createVertexArray();
      this.positions = gl.createBuffer();
      this.colours = gl.createBuffer();
      this.marks = gl.createBuffer();
      this.indices = gl.createBuffer();
      this.layout = null;       // { directions, steps, verticesPerBody } the static buffers were built for
      this.capacity = 0;        // bodies the static buffers hold
      this.indicesPerBody = 0;
      this.scratch = new Float32Array(0);
      this.colourOf = [];       // per body, the colour its vertices in the colour buffer have
      const p = this.program.program;
      gl.bindVertexArray(this.vao);
      gl.bindBuffer(gl.ARRAY_BUFFER, this.positions);
      const locPos = gl.getAttribLocation(p, "aPosition");
      gl.enableVertexAttribArray(locPos);
      gl.vertexAttribPointer(locPos, 3, gl.FLOAT, false, 0, 0);
      gl.bindBuffer(gl.ARRAY_BUFFER, this.colours);
      const locCol = gl.getAttribLocation(p, "aColour");
      gl.enableVertexAttribArray(locCol);
      gl.vertexAttribPointer(locCol, 3, gl.FLOAT, false, 0, 0);
      gl.bindBuffer(gl.ARRAY_BUFFER, this.marks);
      const locMark = gl.getAttribLocation(p, "aMark");
      gl.enableVertexAttribArray(locMark);
      gl.vertexAttribPointer(locMark, 3, gl.FLOAT, false, 0, 0);
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, this.indices);
      gl.bindVertexArray(null);
      gl.bindBuffer(gl.ARRAY_BUFFER, null);
    }

    // The triangles and per-vertex marks of `capacity` bodies laid out as the
    // engine's verts: vertex 0 the centre, vertex 1 + d·steps + (k − 1) step k along direction d.
    // The marks place the vertices in a unit disc by their indices alone (step
    // k/steps at the d-th of `directions` equal angles, direction 0 the axis): a
    // drawing parametrisation for the outline and the axis mark, not the body's geometry.
    buildStatic(E, capacity) {
      const gl = this.gl;
      const nd = E.directions, ns = E.steps, vpb = E.verticesPerBody;
      const v = function (d, k) { return k === 0 ? 0 : 1 + (d % nd) * ns + (k - 1); };
      const local = [];
      for (let d = 0; d < nd; d++) {
        local.push(0, v(d, 1), v(d + 1, 1));
        for (let k = 1; k < ns; k++) {
          const a = v(d, k), b = v(d + 1, k), c = v(d, k + 1), e = v(d + 1, k + 1);
          local.push(a, b, e, a, e, c);
        }
      }
      const idx = new Uint32Array(local.length * capacity);
      const marks = new Float32Array(3 * vpb * capacity);
      for (let i = 0; i < capacity; i++) {
        for (let t = 0; t < local.length; t++) idx[i * local.length + t] = i * vpb + local[t];
        const m = 3 * vpb * i;
        for (let d = 0; d < nd; d++) {
          const c = Math.cos(2 * Math.PI * d / nd), s = Math.sin(2 * Math.PI * d / nd);
          for (let k = 1; k <= ns; k++) {
            const o = m + 3 * v(d, k);
            marks[o] = k / ns;
            marks[o + 1] = d === 0 ? k / ns : c * k / ns;
            marks[o + 2] = d === 0 ? 0 : s * k / ns;
          }
        }
      }
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, this.indices);
      gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, idx, gl.STATIC_DRAW);
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, null);
      gl.bindBuffer(gl.ARRAY_BUFFER, this.marks);
      gl.bufferData(gl.ARRAY_BUFFER, marks, gl.STATIC_DRAW);
      gl.bindBuffer(gl.ARRAY_BUFFER, this.positions);
      gl.bufferData(gl.ARRAY_BUFFER, 4 * 3 * vpb * capacity, gl.DYNAMIC_DRAW);
      gl.bindBuffer(gl.ARRAY_BUFFER, this.colours);
      gl.bufferData(gl.ARRAY_BUFFER, 4 * 3 * vpb * capacity, gl.DYNAMIC_DRAW);
      gl.bindBuffer(gl.ARRAY_BUFFER, null);
      this.layout = { directions: nd, steps: ns, verticesPerBody: vpb };
      this.capacity = capacity;
      this.indicesPerBody = local.length;
      this.scratch = new Float32Array(3 * vpb * capacity);
      this.colourOf = [];
    }

    // Draws the world's bodies into the bound colour buffer of `frame` (see
    // the tracer's overlay hook).
    draw(world, frame) {
      const gl = this.gl;
      const E = world.engine;
      const n = world.count();
      if (n === 0 && !world.target) return;
      const L = this.layout;
      if (!L || L.directions !== E.directions || L.steps !== E.steps || L.verticesPerBody !== E.verticesPerBody ||
          this.capacity < n) {
        this.buildStatic(E, Math.max(64, world.capacity, n));
      }
      const vpb = E.verticesPerBody;
      gl.viewport(0, 0, frame.width, frame.height);
      gl.disable(gl.DEPTH_TEST);
      gl.disable(gl.BLEND);
      if (n > 0) {
        // positions: the engine's doubles as floats
        const count = 3 * vpb * n;
        this.scratch.set(world.a.verts.subarray(0, count));
        gl.bindBuffer(gl.ARRAY_BUFFER, this.positions);
        gl.bufferSubData(gl.ARRAY_BUFFER, 0, this.scratch, 0, count);
        // colours: only when a body's colour changed (bodies come, go and take
        // each other's indices). The colours are shared constant arrays, so
        // comparing them by reference finds a change without building anything
        // each frame (a key string of all the colours was about 30 KB of
        // garbage a frame with 300 bodies).
        if (this.coloursChanged(world.info, n)) {
          for (let i = 0; i < n; i++) {
            const c = world.info[i].colour;
            for (let v = 0; v < vpb; v++) {
              const o = 3 * (vpb * i + v);
              this.scratch[o] = c[0];
              this.scratch[o + 1] = c[1];
              this.scratch[o + 2] = c[2];
            }
          }
          gl.bindBuffer(gl.ARRAY_BUFFER, this.colours);
          gl.bufferSubData(gl.ARRAY_BUFFER, 0, this.scratch, 0, count);
        }
        gl.bindBuffer(gl.ARRAY_BUFFER, null);

        const p = this.program;
        gl.useProgram(p.program);
        gl.activeTexture(gl.TEXTURE0);
        gl.bindTexture(gl.TEXTURE_2D, frame.positionTexture);
        gl.activeTexture(gl.TEXTURE1);
        gl.bindTexture(gl.TEXTURE_2D, frame.normalTexture);
        gl.uniform1i(p.uniform("uPosition"), 0);
        gl.uniform1i(p.uniform("uNormal"), 1);
        gl.uniformMatrix4fv(p.uniform("uViewProjection"), false, frame.viewProjection);
        gl.uniform3fv(p.uniform("uEye"), frame.eye);
        gl.uniform1f(p.uniform("uTolerance"), 0.01);
        gl.uniform1f(p.uniform("uLineWidth"), 1.6 * Math.max(1, frame.scale));
        gl.bindVertexArray(this.vao);
        const images = [[1, 1, 1, 0, 0, 0]].concat(world.images || []);
        // translation images (the flat spaces): only the fundamental square is drawn,
        // so a body across an edge shows on both sides of it, and nothing is drawn twice
        let half = 0;
        for (const g of images) half = Math.max(half, Math.abs(g[3]) / 2, Math.abs(g[5]) / 2);
        gl.uniform1f(p.uniform("uClip"), half > 0 ? half + IMAGE_BAND : 0);
        for (const g of images) {
          gl.uniform3f(p.uniform("uImageScale"), g[0], g[1], g[2]);
          gl.uniform3f(p.uniform("uImageShift"), g[3], g[4], g[5]);
          gl.drawElements(gl.TRIANGLES, this.indicesPerBody * n, gl.UNSIGNED_INT, 0);
        }
        gl.bindVertexArray(null);
        gl.activeTexture(gl.TEXTURE1);
        gl.bindTexture(gl.TEXTURE_2D, null);
        gl.activeTexture(gl.TEXTURE0);
        gl.bindTexture(gl.TEXTURE_2D, null);
      }
      if (world.target) {
        const m = this.markProgram;
        gl.useProgram(m.program);
        gl.uniformMatrix4fv(m.uniform("uViewProjection"), false, frame.viewProjection);
        gl.uniform3fv(m.uniform("uPoint"), world.target);
        gl.uniform1f(m.uniform("uSize"), 9 * Math.max(1, frame.scale));
        gl.bindVertexArray(this.markVao);
        gl.drawArrays(gl.POINTS, 0, 1);
        gl.bindVertexArray(null);
      }
      gl.useProgram(null);
    }

    // Whether the first n bodies' colours differ from those the colour buffer
    // holds; if so, remembers them as held.
    coloursChanged(info, n) {
      const held = this.colourOf;
      let changed = held.length !== n;
      for (let i = 0; !changed && i < n; i++) changed = held[i] !== info[i].colour;
      if (changed) {
        held.length = n;
        for (let i = 0; i < n; i++) held[i] = info[i].colour;
      }
      return changed;
    }

    dispose() {
      const gl = this.gl;
      gl.deleteProgram(this.program.program);
      gl.deleteProgram(this.markProgram.program);
      [this.positions, this.colours, this.marks, this.indices].forEach(function (b) { gl.deleteBuffer(b); });
      gl.deleteVertexArray(this.vao);
      gl.deleteVertexArray(this.markVao);
    }
  }

  W.ManifoldWeb = W.ManifoldWeb || {};
  W.ManifoldWeb.bodies = { BodyRenderer: BodyRenderer };
})(globalThis);
