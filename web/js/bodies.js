// Draws the engine's body polygons (the `verts` array the generated `step` and
// `polygonise` fill) over the traced surface: per body a triangle mesh (a fan
// round the centre, then quads between the rings of geodesic steps), or a
// coarser one (fewer directions, fewer rings, down to a fan from the centre
// to the outline) where that puts the mesh's vertices within half a pixel of
// where they are (buildStatic, chooseForms), filled
// with the body's colour and lit with the traced surface normal, with a dark
// outline and a light axis mark (centre → outline vertex of direction 0) drawn
// in the fragment shader a fixed number of pixels wide. A polygon of corners
// (a box, a square, a polygon of up to eight sides, one's own vertices; not
// rounded) is drawn with its corners: its outline's directions sample its
// edges, so between two of them the form's outer triangle is replaced by a
// fan through the corners the engine walked onto the surface (hullForm). A fragment behind the
// traced surface (further from the eye than the traced distance at its pixel
// plus a small tolerance, the paper's trick) is discarded, so bodies on the far
// side are hidden. On quotient spaces every body is also drawn at each of the
// space's images (space.images, generated: −p on antipodal quotients, the
// neighbouring translates on the flat torus and Klein bottle, so bodies show
// on both sides of a seam).
/* exported ManifoldWebBodies */
var ManifoldWebBodies = (function (W) {
  "use strict";
  const G = W.ManifoldWeb.gl;
  // how far beyond the flat spaces' square bodies are drawn (world units): 0, the
  // fundamental square alone, where a body across an edge shows in two (or four) parts
  const IMAGE_BAND = 0;
  // how far (pixels) a coarser form may put any vertex of a body's mesh from where the mesh has it
  const FORM_TOLERANCE = 0.5;
  // the strides of the directions a coarser form keeps
  const DIRECTION_STRIDES = [4, 3, 2, 1];
  /** @type {Manifold.Image} */
  // the image p -> L p + t as [L row by row, t] (generated: space.images)
  const IDENTITY = [1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0];
  // "auto": each body in the coarsest form that looks the same as its mesh; "mesh": every body as its whole mesh
  const BODY_DETAILS = ["auto", "mesh"];

  const VERTEX = `#version 300 es
precision highp float;
uniform mat4 uViewProjection;
uniform mat3 uImageLinear; // the image p -> linear * p + shift (the identity: I, 0)
uniform vec3 uImageShift;
in vec3 aPosition;
in vec3 aColour;
in vec3 aMark;   // ring (0 at the centre … 1 on the outline), then the vertex's place in a unit disc (x along the axis)
out vec3 vWorld;
out vec3 vColour;
out vec3 vMark;
void main() {
  vec3 p = uImageLinear * aPosition + uImageShift;
  vWorld = p;
  vColour = aColour;
  vMark = aMark;
  gl_Position = projectToClip(p);
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
uniform float uBall;       // > 0: nothing farther from the origin (the ball the surface is traced in: images beyond it float over nothing)
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
  if (uBall > 0.0 && length(vWorld) > uBall) discard;

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
  gl_Position = projectToClip(uPoint);
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

  /**
   * A form a body is drawn in: every `stride`-th direction and `ringStride`-th
   * ring of its mesh; its vertices as offsets into the engine's body, its
   * triangles over those, and their marks.
   * @typedef {{ stride: number, ringStride: number, vertices: Int32Array, indices: Uint32Array, marks: Float32Array }} Form
   */
  /**
   * A polygon's corners in its own frame (the hull array's local corners),
   * and its forms by base form (-1: not made yet).
   * @typedef {{ count: number, local: Float64Array, forms: Int32Array }} CornerSet
   */

  // Whether a corner set holds the `count` corners at hull[local ...] (no closure: it runs a frame per polygon).
  /** @param {CornerSet} set @param {Float64Array} hull @param {number} local @param {number} count */
  function sameCorners(set, hull, local, count) {
    if (set.count !== count) return false;
    for (let q = 0; q < 2 * count; q++) if (set.local[q] !== hull[local + q]) return false;
    return true;
  }

  class BodyRenderer {
    /** @param {WebGL2RenderingContext} gl */
    constructor(gl) {
      this.gl = gl;
      this.program = G.createProgram(gl, W.ManifoldWeb.disc.withProjection(VERTEX), FRAGMENT, "body polygons");
      this.markProgram = G.createProgram(gl, W.ManifoldWeb.disc.withProjection(MARK_VERTEX), MARK_FRAGMENT, "grab mark");
      this.vao = /** @type {WebGLVertexArrayObject} */ (gl.createVertexArray());
      this.markVao = /** @type {WebGLVertexArrayObject} */ (gl.createVertexArray());
      this.positions = /** @type {WebGLBuffer} */ (gl.createBuffer());
      this.colours = /** @type {WebGLBuffer} */ (gl.createBuffer());
      this.marks = /** @type {WebGLBuffer} */ (gl.createBuffer());
      this.indices = /** @type {WebGLBuffer} */ (gl.createBuffer());
      /** @type {{ directions: number, steps: number, verticesPerBody: number } | null} */
      this.layout = null;       // { directions, steps, verticesPerBody } the static buffers were built for
      this.capacity = 0;        // bodies the static buffers hold
      /** @type {Form[] | null} */
      this.forms = null;        // the templates of the coarser forms, coarsest first, then of the whole mesh (buildStatic)
      this.meshForm = 0;        // the whole mesh's index in forms
      this.heldCount = -1;      // bodies the index, mark and colour buffers hold (-1: none yet)
      this.indexCount = 0;      // indices the index buffer holds
      this.scratch = new Float32Array(0);
      this.indexScratch = new Uint32Array(0);
      this.formPoints = new Float64Array(0);
      this.formOf = new Uint16Array(0);
      this.heldForms = new Uint16Array(0);
      this.baseForms = 0;       // forms[0 .. baseForms - 1] are buildStatic's; then the polygons' (hullForm)
      /** @type {CornerSet[]} */
      this.cornerSets = [];     // the polygons' corners seen, each with its forms (hullForm)
      this.cornerSetOf = new Int32Array(0); // per body, its polygon's corner set (-1: none known)
      /** @type {Manifold.Rgb[]} */
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

    // The per-body templates, and buffers for `capacity` bodies in any form.
    // The engine's verts hold a body as vertex 0 the centre and step k
    // along direction d at E.vertexIndex(d, k) (generated). A body is drawn as its
    // whole mesh (a fan round the centre, then quads between the rings of
    // geodesic steps) or, where that looks the same (chooseForms), as a
    // coarser mesh of the same kind: every s-th direction (s = 4, 3, 2, 1,
    // those dividing the directions) and every r-th ring (r dividing the
    // steps; r = steps leaves the fan from the centre to the outline alone).
    // With software rendering the triangles drawn were most of a frame. The
    // marks place the vertices in a unit disc by their indices alone (step
    // k/steps at the d-th of `directions` equal angles, direction 0 the
    // axis): a drawing parametrisation for the outline and the axis mark,
    // linear along a ray and 1 on the outline, so a coarser mesh interpolates
    // the marks the mesh has along its rays and its outline.
    /** @param {Manifold.Engine} E @param {number} capacity */
    buildStatic(E, capacity) {
      const gl = this.gl;
      const nd = E.directions, ns = E.steps, vpb = E.verticesPerBody;
      /** @param {number} d @param {number} k */
      const mesh = function (d, k) { return k === 0 ? 0 : E.vertexIndex(d % nd, k); };
      // the mark of each of the engine's vertices of a body, by its index
      const marks = [[0, 0, 0]];
      for (let d = 0; d < nd; d++) {
        const c = Math.cos(2 * Math.PI * d / nd), sn = Math.sin(2 * Math.PI * d / nd);
        for (let k = 1; k <= ns; k++) marks[E.vertexIndex(d, k)] = [k / ns, d === 0 ? k / ns : c * k / ns, d === 0 ? 0 : sn * k / ns];
      }
      /** @param {number} t */
      const markOf = function (t) { return marks[t]; };
      // the mesh of every s-th direction and every r-th ring: its vertices as
      // offsets into the engine's body, its triangles over those
      /** @param {number} s @param {number} r @returns {Form} */
      const form = function (s, r) {
        const m = nd / s, rings = ns / r, vertices = [0], indices = /** @type {number[]} */ ([]);
        /** @param {number} j @param {number} t */
        const at = function (j, t) { return 1 + (j % m) * rings + t; }; // direction j·s, ring (t + 1)·r
        for (let j = 0; j < m; j++) {
          for (let t = 0; t < rings; t++) vertices.push(mesh(j * s, (t + 1) * r));
          indices.push(0, at(j, 0), at(j + 1, 0));
          for (let t = 0; t + 1 < rings; t++) {
            indices.push(at(j, t), at(j + 1, t), at(j + 1, t + 1), at(j, t), at(j + 1, t + 1), at(j, t + 1));
          }
        }
        return { stride: s, ringStride: r, vertices: Int32Array.from(vertices), indices: Uint32Array.from(indices),
          marks: Float32Array.from(vertices.map(markOf).flat()) };
      };
      this.forms = [];
      for (const s of DIRECTION_STRIDES) {
        if (nd % s !== 0 || nd / s < 3) continue;
        for (let r = ns; r >= 1; r--) if (ns % r === 0 && !(s === 1 && r === 1)) this.forms.push(form(s, r));
      }
      this.forms.sort(function (x, y) { return x.indices.length - y.indices.length; }); // coarsest first
      const whole = form(1, 1); // its vertices are the engine's, in the engine's order
      this.forms.push(whole);
      this.meshForm = this.forms.length - 1;
      this.baseForms = this.forms.length;
      this.cornerSets = [];
      this.cornerSetOf = new Int32Array(capacity).fill(-1);
      // a polygon's form has up to maxCorners vertices more, and a triangle more for each
      const corners = W.Manifold.shapes.maxCorners, vertices = vpb + corners, indices = whole.indices.length + 3 * corners;
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, this.indices);
      gl.bufferData(gl.ELEMENT_ARRAY_BUFFER, 4 * indices * capacity, gl.DYNAMIC_DRAW);
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, null);
      for (const b of [this.positions, this.colours, this.marks]) {
        gl.bindBuffer(gl.ARRAY_BUFFER, b);
        gl.bufferData(gl.ARRAY_BUFFER, 4 * 3 * vertices * capacity, gl.DYNAMIC_DRAW);
      }
      gl.bindBuffer(gl.ARRAY_BUFFER, null);
      this.layout = { directions: nd, steps: ns, verticesPerBody: vpb };
      this.capacity = capacity;
      this.scratch = new Float32Array(3 * vertices * capacity);
      this.indexScratch = new Uint32Array(indices * capacity);
      this.formPoints = new Float64Array(3 * (ns + 1)); // chooseForms' scratch: a form's points along one line
      this.formOf = new Uint16Array(capacity);    // per body, the form chosen this frame (an index into forms)
      this.heldForms = new Uint16Array(capacity); // per body, the form the index, mark and colour buffers hold
      this.heldCount = -1;
      this.indexCount = 0;
      this.colourOf = [];
    }

    // Chooses each body's form for this frame: the coarsest that puts every
    // vertex of the mesh within `FORM_TOLERANCE` pixels of where the mesh has
    // it, at the body's nearest image, else the whole mesh. A form of every
    // s-th direction and r-th ring puts vertex k of direction a + j
    // (0 <= j < s) at the point (k − k0)/r of the way between its rings k0
    // and k0 + r (k0 = 0 the centre) along the line j/s of the way from
    // direction a to direction a + s, which is where it interpolates that
    // vertex's mark. Returns whether any form differs from the one the
    // buffers hold.
    /**
     * @param {ManifoldWeb.DrawnWorld} world @param {number} n @param {ManifoldWeb.OverlayFrame} frame
     * @param {Manifold.Image[]} images
     */
    chooseForms(world, n, frame, images) {
      const E = world.engine, v = world.a.verts;
      const nd = E.directions, ns = E.steps, vpb = E.verticesPerBody;
      const eye = frame.eye, pixel = frame.bodyDetail === "mesh" ? 0 : frame.pixelAngle;
      const forms = this.forms, meshForm = this.meshForm, L = this.formPoints;
      // polygons of corners (the engine's hull array; a comparison's mapped world has none)
      const hull = world.a.hull, scalars = world.a.scalars, S = E.slots, H = E.hull, k = E.sizes.scalars[1];
      let changed = n !== this.heldCount;
      for (let i = 0; i < n; i++) {
        const o = 3 * vpb * i;
        const cx = v[o], cy = v[o + 1], cz = v[o + 2];
        let near = Infinity;
        for (let g = 0; g < images.length; g++) {
          const m = images[g];
          const dx = m[0] * cx + m[1] * cy + m[2] * cz + m[9] - eye[0];
          const dy = m[3] * cx + m[4] * cy + m[5] * cz + m[10] - eye[1];
          const dz = m[6] * cx + m[7] * cy + m[8] * cz + m[11] - eye[2];
          near = Math.min(near, Math.sqrt(dx * dx + dy * dy + dz * dz));
        }
        const allowed = FORM_TOLERANCE * pixel * near;
        const allowed2 = allowed * allowed;
        let chosen = meshForm;
        for (let f = 0; allowed > 0 && f < meshForm && chosen === meshForm; f++) {
          const s = forms[f].stride, r = forms[f].ringStride;
          let fits = true;
          for (let a = 0; fits && a < nd; a += s) {
            const b = (a + s) % nd;
            for (let j = 0; fits && j < s; j++) {
              const t = j / s;
              // the form's points on the line j/s of the way from direction a to b, at its kept rings
              // (L[0] the centre), then direction a + j's vertices against them, the outline first
              for (let m = r, w = 3; m <= ns; m += r, w += 3) {
                const pa = o + 3 * E.vertexIndex(a, m), pb = o + 3 * E.vertexIndex(b, m);
                L[w] = (1 - t) * v[pa] + t * v[pb];
                L[w + 1] = (1 - t) * v[pa + 1] + t * v[pb + 1];
                L[w + 2] = (1 - t) * v[pa + 2] + t * v[pb + 2];
              }
              L[0] = v[o]; L[1] = v[o + 1]; L[2] = v[o + 2];
              for (let k = ns; k >= 1; k--) {
                const m0 = (k - k % r) / r, u = (k % r) / r;
                if (u === 0 && j === 0) continue; // the form has this vertex where the mesh has it
                const w0 = 3 * m0, w1 = u === 0 ? w0 : w0 + 3, q = o + 3 * E.vertexIndex(a + j, k);
                const ex = v[q] - ((1 - u) * L[w0] + u * L[w1]);
                const ey = v[q + 1] - ((1 - u) * L[w0 + 1] + u * L[w1 + 1]);
                const ez = v[q + 2] - ((1 - u) * L[w0 + 2] + u * L[w1 + 2]);
                if (!(ex * ex + ey * ey + ez * ez <= allowed2)) { fits = false; break; }
              }
            }
          }
          if (fits) chosen = f;
        }
        const corners = hull ? scalars[i * k + S.corners] : 0;
        if (corners >= 3 && hull[H.stride * i + H.radius] === 0) chosen = this.hullForm(E, chosen, hull, i, corners);
        this.formOf[i] = chosen;
        if (chosen !== this.heldForms[i]) changed = true;
      }
      return changed;
    }

    // The form of body i, a polygon of `count` corners, drawn in base form f:
    // f's vertices and the corners, f's triangles but for each outer one
    // (the outline between two kept directions) with corners between its
    // directions, which is a fan through them instead. A corner on a kept
    // direction is the outline's vertex there already. A corner's vertex is
    // -1 - its index (drawn from the hull array's walked corners); its mark
    // is 1 (on the outline) at its angle in the unit disc. Bodies with the
    // same corners (in their own frames) share their forms, made once; a
    // frame only compares a body's corners with those of its set.
    /**
     * @param {Manifold.Engine} E @param {number} f @param {Float64Array} hull @param {number} i
     * @param {number} count @returns {number}
     */
    hullForm(E, f, hull, i, count) {
      const H = E.hull, local = H.stride * i + H.local, sets = this.cornerSets;
      let id = this.cornerSetOf[i];
      if (id < 0 || !sameCorners(sets[id], hull, local, count)) {
        id = -1;
        for (let j = 0; j < sets.length && id < 0; j++) if (sameCorners(sets[j], hull, local, count)) id = j;
        if (id < 0) {
          this.cornerSets.push({ count: count, local: hull.slice(local, local + 2 * count), forms: new Int32Array(this.baseForms).fill(-1) });
          id = this.cornerSets.length - 1;
        }
        this.cornerSetOf[i] = id;
      }
      const set = this.cornerSets[id];
      if (set.forms[f] < 0) set.forms[f] = this.makeHullForm(E, this.forms[f], set);
      return set.forms[f];
    }

    // hullForm's form of a corner set in base form `form`; returns its index in forms.
    /** @param {Manifold.Engine} E @param {Form} form @param {CornerSet} set */
    makeHullForm(E, form, set) {
      const nd = E.directions, m = nd / form.stride, rings = E.steps / form.ringStride;
      // each corner's angle in turns from the axis, in [0, 1)
      const angles = /** @type {number[]} */ ([]);
      for (let c = 0; c < set.count; c++) {
        const a = Math.atan2(set.local[2 * c + 1], set.local[2 * c]) / (2 * Math.PI);
        angles.push(a < 0 ? a + 1 : a);
      }
      // the corners in each sector between kept directions j and j + 1, by angle
      /** @type {number[][]} */
      const sectors = [];
      const order = angles.map(function (_, c) { return c; }).sort(function (a, b) { return angles[a] - angles[b]; });
      for (const c of order) {
        const u = angles[c] * m, j = Math.floor(u) % m;
        if (Math.abs(u - Math.round(u)) < 1e-9) continue; // on a kept direction
        (sectors[j] = sectors[j] || []).push(c);
      }
      const vertices = Array.from(form.vertices), marks = Array.from(form.marks), indices = /** @type {number[]} */ ([]);
      /** @param {number} j @param {number} t */
      const at = function (j, t) { return 1 + (j % m) * rings + t; }; // as buildStatic's forms
      /** @param {number[]} t */
      const key = function (t) { return t.slice().sort(function (x, y) { return x - y; }).join(","); };
      /** @type {Record<string, number[]>} */
      const fans = {};
      sectors.forEach(function (cs, j) {
        // the outer triangle's inner vertex: the centre in a fan, else the ring inside at direction j
        const inner = rings === 1 ? 0 : at(j, rings - 2), a = at(j, rings - 1), b = at(j + 1, rings - 1);
        const chain = [a];
        for (const c of cs) {
          chain.push(vertices.length);
          vertices.push(-1 - c);
          const t = 2 * Math.PI * angles[c];
          marks.push(1, Math.cos(t), Math.sin(t));
        }
        chain.push(b);
        const fan = [];
        for (let q = 0; q + 1 < chain.length; q++) fan.push(inner, chain[q], chain[q + 1]);
        fans[key([inner, a, b])] = fan;
      });
      const triangles = form.indices;
      for (let t = 0; t < triangles.length; t += 3) {
        const triangle = [triangles[t], triangles[t + 1], triangles[t + 2]], fan = fans[key(triangle)];
        indices.push.apply(indices, fan || triangle);
      }
      this.forms.push({ stride: form.stride, ringStride: form.ringStride, vertices: Int32Array.from(vertices),
        indices: Uint32Array.from(indices), marks: Float32Array.from(marks) });
      return this.forms.length - 1;
    }

    // Rebuilds the index and mark buffers for the forms chosen (only when
    // they change, so a still pile uploads nothing but its positions).
    /** @param {number} n */
    layOut(n) {
      const gl = this.gl;
      let vertexCount = 0, indexCount = 0;
      for (let i = 0; i < n; i++) {
        const form = this.forms[this.formOf[i]];
        const idx = form.indices, marks = form.marks;
        for (let t = 0; t < idx.length; t++) this.indexScratch[indexCount + t] = vertexCount + idx[t];
        this.scratch.set(marks, 3 * vertexCount);
        indexCount += idx.length;
        vertexCount += form.vertices.length;
        this.heldForms[i] = this.formOf[i];
      }
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, this.indices);
      gl.bufferSubData(gl.ELEMENT_ARRAY_BUFFER, 0, this.indexScratch, 0, indexCount);
      gl.bindBuffer(gl.ELEMENT_ARRAY_BUFFER, null);
      gl.bindBuffer(gl.ARRAY_BUFFER, this.marks);
      gl.bufferSubData(gl.ARRAY_BUFFER, 0, this.scratch, 0, 3 * vertexCount);
      this.heldCount = n;
      this.indexCount = indexCount;
    }

    // Draws the world's bodies into the bound colour buffer of `frame` (see
    // the tracer's overlay hook).
    /** @param {ManifoldWeb.DrawnWorld} world @param {ManifoldWeb.OverlayFrame} frame @param {boolean} [dimSleeping] */
    draw(world, frame, dimSleeping) {
      const gl = this.gl;
      const E = world.engine;
      const n = world.count();
      if (n === 0) this.heldCount = Math.min(this.heldCount, 0);
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
        const images = [IDENTITY].concat(world.images || []);
        const relaid = this.chooseForms(world, n, frame, images);
        if (relaid) this.layOut(n);
        // colours: when a body's colour or form changed (bodies come, go and
        // take each other's indices). The colours are shared constant arrays,
        // so comparing them by reference finds a change without building
        // anything each frame (a key string of all the colours was about 30 KB
        // of garbage a frame with 300 bodies).
        if (this.coloursChanged(world, n, !!dimSleeping) || relaid) {
          let at = 0;
          for (let i = 0; i < n; i++) {
            const c = this.colourOf[i];
            for (let t = this.forms[this.formOf[i]].vertices.length; t > 0; t--, at += 3) {
              this.scratch[at] = c[0];
              this.scratch[at + 1] = c[1];
              this.scratch[at + 2] = c[2];
            }
          }
          gl.bindBuffer(gl.ARRAY_BUFFER, this.colours);
          gl.bufferSubData(gl.ARRAY_BUFFER, 0, this.scratch, 0, at);
        }
        // positions: the vertices of each body's form, the engine's doubles as
        // floats (a polygon's corners from the hull array, as walked)
        const v = world.a.verts, hull = world.a.hull, H = E.hull;
        let at = 0;
        for (let i = 0; i < n; i++) {
          const vertices = this.forms[this.formOf[i]].vertices, o = vpb * i;
          for (let t = 0; t < vertices.length; t++, at += 3) {
            const w = vertices[t];
            const from = w >= 0 ? v : hull, q = w >= 0 ? 3 * (o + w) : H.stride * i + H.world + 3 * (-1 - w);
            this.scratch[at] = from[q];
            this.scratch[at + 1] = from[q + 1];
            this.scratch[at + 2] = from[q + 2];
          }
        }
        gl.bindBuffer(gl.ARRAY_BUFFER, this.positions);
        gl.bufferSubData(gl.ARRAY_BUFFER, 0, this.scratch, 0, at);
        gl.bindBuffer(gl.ARRAY_BUFFER, null);

        const p = this.program;
        gl.useProgram(p.program);
        gl.activeTexture(gl.TEXTURE0);
        gl.bindTexture(gl.TEXTURE_2D, frame.positionTexture);
        gl.activeTexture(gl.TEXTURE1);
        gl.bindTexture(gl.TEXTURE_2D, frame.normalTexture);
        gl.uniform1i(p.uniform("uPosition"), 0);
        gl.uniform1i(p.uniform("uNormal"), 1);
        W.ManifoldWeb.disc.setProjection(gl, p, frame);
        gl.uniform3fv(p.uniform("uEye"), frame.eye);
        gl.uniform1f(p.uniform("uTolerance"), 0.01);
        gl.uniform1f(p.uniform("uLineWidth"), 1.6 * Math.max(1, frame.scale));
        gl.bindVertexArray(this.vao);
        // translation images (the flat spaces): only the fundamental square is drawn,
        // so a body across an edge shows on both sides of it, and nothing is drawn twice
        let half = 0;
        for (const g of images) half = Math.max(half, Math.abs(g[9]) / 2, Math.abs(g[11]) / 2);
        gl.uniform1f(p.uniform("uClip"), half > 0 ? half + IMAGE_BAND : 0);
        gl.uniform1f(p.uniform("uBall"), frame.flat ? 0 : frame.bounds || 0);
        for (const g of images) {
          gl.uniformMatrix3fv(p.uniform("uImageLinear"), true, g, 0, 9); // (the linear part: no copy a draw)
          gl.uniform3f(p.uniform("uImageShift"), g[9], g[10], g[11]);
          gl.drawElements(gl.TRIANGLES, this.indexCount, gl.UNSIGNED_INT, 0);
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
        W.ManifoldWeb.disc.setProjection(gl, m, frame);
        gl.uniform3fv(m.uniform("uPoint"), world.target);
        gl.uniform1f(m.uniform("uSize"), 9 * Math.max(1, frame.scale));
        gl.bindVertexArray(this.markVao);
        gl.drawArrays(gl.POINTS, 0, 1);
        gl.bindVertexArray(null);
      }
      gl.useProgram(null);
    }

    // How many bodies the last frame drew as fans (no inner rings), as
    // coarser meshes, and as whole meshes, and the triangles drawn (at each image).
    formCounts() {
      let fans = 0, meshes = 0;
      for (let i = 0; i < this.heldCount; i++) {
        // (a polygon's form counts as the form it is made from)
        const form = this.forms[this.heldForms[i]];
        if (form.stride === 1 && form.ringStride === 1) meshes++;
        else if (form.ringStride === this.layout.steps) fans++;
      }
      const held = Math.max(0, this.heldCount);
      return { fans: fans, coarser: held - fans - meshes, meshes: meshes, triangles: held > 0 ? this.indexCount / 3 : 0 };
    }

    // Whether the first n bodies' colours differ from those the colour buffer
    // holds; if so, remembers them as held.
    /**
     * Whether the first n bodies' colours (each its own, or, for a sleeping
     * body with dimSleeping, its dimmed one) differ from those the colour
     * buffer holds; if so, remembers them as held.
     * @param {ManifoldWeb.DrawnWorld} world @param {number} n @param {boolean} dimSleeping
     */
    coloursChanged(world, n, dimSleeping) {
      const held = this.colourOf, info = world.info;
      const asleep = world.engine.slots.asleep, k = world.engine.sizes.scalars[1], scalars = world.a.scalars;
      const wanted = function (/** @type {number} */ i) {
        const c = info[i].colour;
        return dimSleeping && scalars[k * i + asleep] > 0 ? dimmed(c) : c;
      };
      let changed = held.length !== n;
      for (let i = 0; !changed && i < n; i++) changed = held[i] !== wanted(i);
      if (changed) {
        held.length = n;
        for (let i = 0; i < n; i++) held[i] = wanted(i);
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

  // A sleeping body's colour: its own, halfway to the dark grey of the
  // background, so that what sleeps reads at a glance. One array per colour
  // (compared by reference, as the colours are).
  const DIMMED = new WeakMap();
  /** @param {Manifold.Rgb} c @returns {Manifold.Rgb} */
  function dimmed(c) {
    let d = DIMMED.get(c);
    if (!d) {
      d = /** @type {Manifold.Rgb} */ (c.map(function (/** @type {number} */ x) { return 0.45 * x + 0.55 * 0.22; }));
      DIMMED.set(c, d);
    }
    return d;
  }

  const exported = { BodyRenderer: BodyRenderer, BODY_DETAILS: BODY_DETAILS };
  W.ManifoldWeb = W.ManifoldWeb || /** @type {ManifoldWebModules} */ ({});
  W.ManifoldWeb.bodies = exported;
  return exported;
})(globalThis);
