// What a press on the surface does, and the curves drawn on it. The tool
// "grab" grabs a body under the press and otherwise throws a new one: drag
// from the press point, and a preview shows the first second of the new
// body's path (a scratch world with the same parameters and the body alone,
// stepped by the generated engine); the release launches it from the press
// point along the drag with a speed from the drag's length (a click puts it
// there at rest). The tool "geodesic" draws the geodesic from the press
// point in the drag's direction for a chosen length (the engine's generated
// walk, Manifold.GeodesicPath). Trails: every body's path over the last
// seconds, fading. Also the new body's template (shape, size, density,
// static) that the Add button and throws use. The tool "joint" joins the
// body pressed on to the body released on with a pin at the release point
// (Ctrl held at the release: a distance joint from the press point to the
// release point), or, released on empty surface, to the world there; a
// line shows the joint being made.
/* exported ManifoldWebTools */
var ManifoldWebTools = (function (W) {
  "use strict";
  const MW = W.ManifoldWeb;
  const P = MW.page, state = P.state;

  /** @typedef {"grab" | "geodesic" | "joint"} Tool */
  /** @type {Tool[]} */
  const TOOLS = ["grab", "geodesic", "joint"];
  // the geodesic tool's curve: its steps, and the length it starts with (a great circle of the unit sphere)
  const GEODESIC_STEPS = 512;
  const GEODESIC_LENGTH = 2 * Math.PI;
  // a throw: launch speed per unit of surface distance dragged (1/s), and the preview's simulated seconds
  const THROW_GAIN = 3;
  const PREVIEW_SECONDS = 1;
  // a press that moves less than this many CSS pixels before its release is a click
  const CLICK_PX = 4;
  // trails: a sample every `every` simulated seconds, kept for `seconds`, of at most `bodies` bodies
  // (a gap of more than `gap` seconds between samples, window.manifold.step's many steps at once, is not drawn across)
  const TRAIL = { every: 0.05, seconds: 3, bodies: 2000, gap: 0.5 };
  const TRAIL_CAPACITY = Math.round(TRAIL.seconds / TRAIL.every) + 1;
  // curve widths in CSS pixels, and colours
  const WIDTH = { geodesic: 3, preview: 3, trail: 2, joint: 2 };
  /** @type {Record<string, Manifold.Rgb>} */
  const COLOUR = { geodesic: [1.0, 0.85, 0.25], preview: [0.55, 0.9, 1.0], joint: [0.95, 0.95, 0.9] };

  /**
   * The body the Add button and throws make: size null is the space's own
   * (its default scene's first body's); friction and restitution null are
   * the scene's (the body has none of its own).
   * @typedef {{ shape: Manifold.Shape, size: number | null, density: number, static: boolean, friction: number | null, restitution: number | null }} NewBody
   */
  /**
   * A curve on the surface: its points (xyz triples) and where it breaks
   * (breaks[k] = 1: no segment from point k - 1 to point k).
   * @typedef {{ points: Float64Array, breaks: Uint8Array, count: number }} Curve
   */

  const tools = {
    /** @type {Tool} */
    tool: "grab",
    /** @type {NewBody} */
    template: { shape: "circle", size: null, density: MW.world.BODY_DEFAULTS.density, static: MW.world.BODY_DEFAULTS.static, friction: null, restitution: null },
    geodesicLength: GEODESIC_LENGTH,
    /** @type {Curve | null} the geodesic tool's curve */
    geodesic: null,
    /** @type {Curve | null} the throw's preview, one point per step */
    preview: null,
    /**
     * the press being dragged on the surface
     * @type {{ tool: Tool, from: Manifold.Vec3, at: [number, number], moved: boolean, to: Manifold.Vec3 | null, body: number } | null}
     */
    gesture: null,
    trailsOn: false,
    trail: {
      world: /** @type {ManifoldWeb.World | null} */ (null),
      bodies: 0,
      stepsPerSample: 1,
      lastStep: -1,
      head: 0,            // the next sample's slot
      filled: 0,          // samples held
      /** @type {Float32Array} per slot, per body: x, y, z, speed */
      data: new Float32Array(0),
      /** @type {Float64Array} per slot: the world's step count when it was taken */
      at: new Float64Array(TRAIL_CAPACITY),
    },
    version: 0,           // bumped whenever something drawn here changes
  };

  function changed() { tools.version++; }

  // ---- the new body's template ------------------------------------------------------
  // The space's own body size: its default scene's first body's.
  function spaceSize() {
    const scene = state.space && state.space.scene;
    return scene && scene.length ? scene[0].size : 0.15;
  }

  // The template as a scene body: its size filled in, its own friction and restitution where it has them.
  /** @returns {{ shape: Manifold.Shape, size: number, density: number, static: boolean, friction?: number, restitution?: number }} */
  function newBody() {
    const t = tools.template;
    /** @type {{ shape: Manifold.Shape, size: number, density: number, static: boolean, friction?: number, restitution?: number }} */
    // (a box's and a capsule's size is how far its numbers reach)
    const b = { shape: MW.world.copyShape(t.shape), size: MW.world.reachOf(t.shape, t.size === null ? spaceSize() : t.size), density: t.density, static: t.static };
    if (t.friction !== null) b.friction = t.friction;
    if (t.restitution !== null) b.restitution = t.restitution;
    return b;
  }
  // The new body as a scene gives it: a box or a capsule without a size
  // (its numbers are its size).
  /** @returns {{ shape: Manifold.Shape, size?: number, density: number, static: boolean, friction?: number, restitution?: number }} */
  function newSceneBody() {
    /** @type {{ shape: Manifold.Shape, size?: number, density: number, static: boolean, friction?: number, restitution?: number }} */
    const b = newBody();
    if (MW.world.sizedByShape(b.shape)) delete b.size;
    return b;
  }

  // Changes the template; throws naming the field of a bad value (and changes nothing then).
  /** @param {Partial<NewBody>} o */
  function setNewBody(o) {
    if (o === null || typeof o !== "object" || Array.isArray(o)) throw new TypeError("setNewBody expects an object {shape, size, density, static, friction, restitution}");
    const next = Object.assign({}, tools.template);
    for (const k of Object.keys(o)) {
      const v = /** @type {Record<string, unknown>} */ (o)[k];
      if (k === "shape") {
        // a scene's shapes, as a scene's reader takes them
        try {
          next.shape = MW.world.shape("newBody.shape", v);
        } catch (e) {
          throw new RangeError(/** @type {Error} */ (e).message, { cause: e });
        }
      } else if (k === "size") {
        if (v !== null && !(typeof v === "number" && isFinite(v) && v > 0)) throw new RangeError("newBody.size must be a positive number (or null: the space's own)");
        next.size = /** @type {number | null} */ (v);
      } else if (k === "density") {
        if (!(typeof v === "number" && isFinite(v) && v > 0)) throw new RangeError("newBody.density must be a positive number");
        next.density = v;
      } else if (k === "static") {
        if (typeof v !== "boolean") throw new TypeError("newBody.static must be true or false");
        next.static = v;
      } else if (k === "friction" || k === "restitution") {
        // null: the scene's; else the scene key's values (generated ranges)
        const key = W.Manifold.sceneKeys.find(function (s) { return s.key === k; });
        const why = v === null || !key ? null : MW.world.keyProblem(key, v);
        if (why !== null) throw new RangeError("newBody." + k + " " + why + " (or null: the scene's)");
        next[k] = /** @type {number | null} */ (v);
      } else {
        throw new RangeError("newBody has no key " + JSON.stringify(k) + " (shape, size, density, static, friction, restitution)");
      }
    }
    tools.template = next;
    if (state.ui) state.ui.setNewBody(next, spaceSize());
    return newBody();
  }

  // The space changed: its own size again, and nothing of the old space drawn.
  function spaceChanged() {
    tools.template = Object.assign({}, tools.template, { size: null });
    tools.geodesic = null;
    tools.preview = null;
    tools.gesture = null;
    resetTrails();
    if (state.ui) state.ui.setNewBody(tools.template, spaceSize());
    changed();
  }

  // ---- the tool ---------------------------------------------------------------------
  /** @param {unknown} name */
  function setTool(name) {
    if (TOOLS.indexOf(/** @type {Tool} */ (name)) < 0) throw new RangeError("tool must be one of " + TOOLS.join(", ") + " (not " + JSON.stringify(name) + ")");
    cancel();
    tools.tool = /** @type {Tool} */ (name);
    if (state.ui) state.ui.setTool(tools.tool);
    changed();
  }

  /** @param {unknown} len */
  function setGeodesicLength(len) {
    if (!(typeof len === "number" && isFinite(len) && len > 0)) throw new RangeError("the geodesic's length must be a positive number");
    tools.geodesicLength = len;
    if (state.ui) state.ui.setGeodesicLength(len);
  }

  // ---- curves -----------------------------------------------------------------------
  // The geodesic from p in the tangent direction of d, `length` long.
  /** @param {Manifold.Vec3} p @param {Manifold.Vec3} d @param {number} length @returns {Curve} */
  function walk(p, d, length) {
    const E = state.space.engine, L = E.path;
    const path = new Float64Array(1 + L.stride * (GEODESIC_STEPS + 1));
    E.geodesic(path, p[0], p[1], p[2], d[0], d[1], d[2], length, GEODESIC_STEPS);
    const count = path[0];
    const points = new Float64Array(3 * count), breaks = new Uint8Array(count);
    for (let k = 0; k < count; k++) {
      const o = 1 + L.stride * k;
      points[3 * k] = path[o + L.slots.pathX];
      points[3 * k + 1] = path[o + L.slots.pathY];
      points[3 * k + 2] = path[o + L.slots.pathZ];
      breaks[k] = path[o + L.slots.pathBreak] ? 1 : 0;
    }
    return { points: points, breaks: breaks, count: count };
  }

  // Shows the geodesic from p along d (the tool's length unless given); returns it.
  /** @param {Manifold.Vec3} p @param {Manifold.Vec3} d @param {number} [length] */
  function showGeodesic(p, d, length) {
    if (!state.space || !state.space.engine) throw new Error("no space with an engine is loaded");
    tools.geodesic = walk(p, d, length === undefined ? tools.geodesicLength : length);
    changed();
    return tools.geodesic;
  }

  function clearGeodesic() {
    tools.geodesic = null;
    changed();
  }

  /** @param {Manifold.Vec3} a @param {Manifold.Vec3} b @returns {Manifold.Vec3} */
  function minus(a, b) { return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]; }

  // A thrown body's velocity: along the drag, THROW_GAIN × its length.
  /** @param {Manifold.Vec3} from @param {Manifold.Vec3} to @returns {Manifold.Vec3} */
  function throwVelocity(from, to) {
    const d = minus(to, from);
    return [THROW_GAIN * d[0], THROW_GAIN * d[1], THROW_GAIN * d[2]];
  }

  // The first PREVIEW_SECONDS of a body thrown from p with velocity v: a
  // scratch world of the current one's parameters holding that body alone,
  // its centre after every step (null if the engine refuses the body).
  /** @param {Manifold.Vec3} p @param {Manifold.Vec3} v @returns {Curve | null} */
  function throwPreview(p, v) {
    const w = state.world;
    if (!w) return null;
    const scratch = new MW.world.World(w.name, w.space);
    scratch.a.params.set(w.a.params);
    try {
      scratch.add(Object.assign(newSceneBody(), { static: false, p: p, v: v }));
    } catch (err) {
      return null;
    }
    const n = Math.max(1, Math.round(PREVIEW_SECONDS / w.param("dt")));
    const points = new Float64Array(3 * (n + 1)), breaks = new Uint8Array(n + 1);
    const pos = scratch.a.pos, vel = scratch.a.vel, jump = MW.curves.wrapJump(w.space);
    points.set(pos.subarray(0, 3), 0);
    let speed = Math.hypot(vel[0], vel[1], vel[2]);
    for (let k = 1; k <= n; k++) {
      scratch.engine.step.apply(null, scratch.arrays);
      points.set(pos.subarray(0, 3), 3 * k);
      const s = Math.hypot(vel[0], vel[1], vel[2]);
      breaks[k] = jumped(points, 3 * (k - 1), 3 * k, speed, s, w.param("dt"), jump) ? 1 : 0;
      speed = s;
    }
    return { points: points, breaks: breaks, count: n + 1 };
  }

  // Whether consecutive samples of a body's centre (at offsets i and j of
  // xyz) lie further apart than its motion explains: it went through a
  // quotient's edge (moved more than half the shortest translation, or more
  // than twice what its speeds s0, s1 cover in dt, as at the projective
  // plane's antipodal gluing).
  /**
   * @param {ArrayLike<number>} xyz @param {number} i @param {number} j
   * @param {number} s0 @param {number} s1 @param {number} dt @param {number} jump
   */
  function jumped(xyz, i, j, s0, s1, dt, jump) {
    const d = Math.hypot(xyz[j] - xyz[i], xyz[j + 1] - xyz[i + 1], xyz[j + 2] - xyz[i + 2]);
    return d > jump || d > 2 * Math.max(s0, s1) * dt + 0.01;
  }

  // ---- gestures on the surface (input.js calls these) -------------------------------
  // A press on empty surface point q at CSS pixel `at`.
  /** @param {Manifold.Vec3} q @param {[number, number]} at */
  function press(q, at) {
    const refused = tools.tool === "joint" && state.world ? MW.world.jointsRefused(state.world.name) : null;
    if (refused !== null) {
      state.ui.showNotice("No joint: " + refused + ".");
      return;
    }
    const picked = tools.tool === "joint" && state.world ? state.world.pick(q) : null;
    if (tools.tool === "joint" && !picked) {
      state.ui.showNotice("Press on a body to join it (to another body, or to the surface).");
      return;
    }
    tools.gesture = { tool: tools.tool, from: q, at: at, moved: false, to: null, body: picked ? picked.index : -1 };
    if (tools.tool === "geodesic") clearGeodesic();
  }

  // The pointer moved to surface point q (null: off the surface) at CSS pixel `at`.
  /** @param {Manifold.Vec3 | null} q @param {[number, number]} at */
  function move(q, at) {
    const g = tools.gesture;
    if (!g) return;
    if (!g.moved && Math.hypot(at[0] - g.at[0], at[1] - g.at[1]) < CLICK_PX) return;
    g.moved = true;
    if (!q) return;
    g.to = q;
    if (g.tool === "geodesic") showGeodesic(g.from, minus(q, g.from));
    else if (g.tool === "joint") {
      tools.preview = { points: Float64Array.from(g.from.concat(q)), breaks: new Uint8Array(2), count: 2 };
      changed();
    } else {
      tools.preview = throwPreview(g.from, throwVelocity(g.from, q));
      changed();
    }
  }

  // The press ends: a throw launches (a click adds the body at rest); the
  // geodesic stays drawn; a joint is made (a distance joint with `distance`).
  // Returns the index of a body (or joint) added, else -1.
  /** @param {boolean} [distance] */
  function release(distance) {
    const g = tools.gesture;
    tools.gesture = null;
    if (!g) return -1;
    tools.preview = null;
    changed();
    if (g.tool === "joint") return join(g.body, g.from, g.moved && g.to ? g.to : g.from, !!distance);
    if (g.tool !== "grab") return -1;
    const v = g.moved && g.to ? throwVelocity(g.from, g.to) : [0, 0, 0];
    return launch(g.from, /** @type {Manifold.Vec3} */ (v));
  }

  // Joins body a (pressed at p) to the body under q, or to the world at q: a
  // pin at q, or a distance joint from p to q; returns the joint's index,
  // or -1 (and a notice).
  /** @param {number} a @param {Manifold.Vec3} p @param {Manifold.Vec3} q @param {boolean} distance */
  function join(a, p, q, distance) {
    const w = P.requireWorld();
    const hit = w.pick(q);
    const b = hit ? hit.index : -1;
    if (b === a) {
      state.ui.showNotice("Release on another body, or on the surface, to join this one to it.");
      return -1;
    }
    /** @type {Manifold.SceneJoint} */
    const spec = distance
      ? { type: "distance", a: a, b: b < 0 ? "world" : b, anchorA: p, anchorB: q }
      : { type: "revolute", a: a, b: b < 0 ? "world" : b, anchor: q };
    try {
      return w.addJoint(spec);
    } catch (e) {
      state.ui.showNotice("No joint: " + e.message);
      return -1;
    }
  }

  // The press is dropped (a second finger came): nothing is added.
  function cancel() {
    if (!tools.gesture) return;
    tools.gesture = null;
    tools.preview = null;
    changed();
  }

  // Adds the template's body at p with velocity v unless it would overlap
  // another; returns its index, or -1 (and a notice).
  /** @param {Manifold.Vec3} p @param {Manifold.Vec3} v */
  function launch(p, v) {
    const w = P.requireWorld();
    const i = w.addFree(Object.assign(newSceneBody(), { p: p, v: v }));
    if (i < 0) state.ui.showNotice("No room there for a body of size " + newBody().size + ".");
    else MW.hash.updateHash();
    return i;
  }

  // ---- trails -----------------------------------------------------------------------
  function resetTrails() {
    const t = tools.trail;
    t.world = null;
    t.filled = 0;
    t.head = 0;
    changed();
  }

  /** @param {boolean} on */
  function setTrails(on) {
    if (typeof on !== "boolean") throw new TypeError("trails are on (true) or off (false)");
    tools.trailsOn = on;
    resetTrails();
    if (state.ui) state.ui.setTrails(on);
  }

  // Takes a sample of every body's centre when the world has stepped on by
  // TRAIL.every seconds since the last (the frame loop calls this). A new
  // world or a body added or removed starts the trails again.
  function sampleTrails() {
    const w = state.world, t = tools.trail;
    if (!tools.trailsOn || !w) return;
    const n = Math.min(w.viewCount(), TRAIL.bodies);
    if (t.world !== w || t.bodies !== n) {
      t.world = w;
      t.bodies = n;
      t.filled = 0;
      t.head = 0;
      t.lastStep = -Infinity;
      t.stepsPerSample = Math.max(1, Math.round(TRAIL.every / w.param("dt")));
      if (t.data.length < 4 * n * TRAIL_CAPACITY) t.data = new Float32Array(4 * n * TRAIL_CAPACITY);
    }
    if (w.steps - t.lastStep < t.stepsPerSample) return;
    t.lastStep = w.steps;
    const view = w.view(), pos = view.pos, vel = view.vel, o = 4 * n * t.head;
    for (let i = 0; i < n; i++) {
      t.data[o + 4 * i] = pos[3 * i];
      t.data[o + 4 * i + 1] = pos[3 * i + 1];
      t.data[o + 4 * i + 2] = pos[3 * i + 2];
      t.data[o + 4 * i + 3] = Math.hypot(vel[3 * i], vel[3 * i + 1], vel[3 * i + 2]);
    }
    t.at[t.head] = w.steps;
    t.head = (t.head + 1) % TRAIL_CAPACITY;
    t.filled = Math.min(TRAIL_CAPACITY, t.filled + 1);
    changed();
  }

  // The trails' segments, oldest first: segment(body, offset of its older
  // end in tools.trail.data, of its newer end, their opacities), none across
  // a quotient's edge.
  /** @param {(i: number, a: number, b: number, alphaA: number, alphaB: number) => void} segment */
  function eachTrailSegment(segment) {
    const w = state.world, t = tools.trail;
    if (!tools.trailsOn || !w || t.world !== w || t.filled < 2) return;
    const dt = w.param("dt"), now = w.steps, jump = MW.curves.wrapJump(w.space);
    const alpha = function (/** @type {number} */ slot) { return Math.max(0, 1 - (now - t.at[slot]) * dt / TRAIL.seconds); };
    const xyz = t.data, n = t.bodies;
    for (let k = t.filled - 1; k >= 1; k--) {
      const a = (t.head - 1 - k + 2 * TRAIL_CAPACITY) % TRAIL_CAPACITY, b = (a + 1) % TRAIL_CAPACITY;
      const fa = alpha(a), fb = alpha(b);
      if (fb <= 0) continue;
      const gap = (t.at[b] - t.at[a]) * dt;
      if (gap > TRAIL.gap) continue;
      for (let i = 0; i < n; i++) {
        const ia = 4 * (n * a + i), ib = 4 * (n * b + i);
        if (!jumped(xyz, ia, ib, xyz[ia + 3], xyz[ib + 3], gap, jump)) segment(i, ia, ib, fa, fb);
      }
    }
  }

  // ---- drawing (frame.js's overlay, after the bodies) -------------------------------
  /** @param {ManifoldWeb.CurveRenderer} r @param {Curve} c @param {Manifold.Rgb} colour */
  function addCurve(r, c, colour) {
    for (let k = 1; k < c.count; k++) {
      if (!c.breaks[k]) r.segment(c.points, 3 * (k - 1), c.points, 3 * k, colour, 1, 1);
    }
  }

  // Every joint as curves on the surface (the engine's jointPaths): a pin
  // by the geodesics from each body's centre to the pin (a chain shows as
  // the line through its links), a distance joint by its chord laid on the
  // surface from anchor to anchor (body b's at its image nearest a's).
  /** @param {ManifoldWeb.CurveRenderer} r @param {ManifoldWeb.World} w */
  function addJoints(r, w) {
    const E = w.engine, J = E.joint, joints = w.a.joints, xyz = w.jointPaths();
    const { walk, chord, points } = E.jointPath;
    /** @param {number} from @param {number} count */
    const polyline = function (from, count) {
      for (let k = from + 1; k < from + count; k++) r.segment(xyz, 3 * (k - 1), xyz, 3 * k, COLOUR.joint, 1, 1);
    };
    for (let j = 0; j < w.jointCount(); j++) {
      const o = E.jointStride * j, first = points * j;
      if (E.jointKinds[joints[o + J.kind]] === "distance") {
        polyline(first + 2 * walk, chord);
      } else {
        polyline(first, walk);
        if (joints[o + J.b] >= 0) polyline(first + walk, walk);
      }
    }
  }

  /** @param {ManifoldWeb.OverlayFrame} frame */
  function draw(frame) {
    const r = state.curveRenderer, w = state.world;
    if (!r || state.compare) return;
    const images = w ? w.images : (state.space && state.space.images) || [];
    r.begin();
    if (w) {
      const xyz = tools.trail.data;
      eachTrailSegment(function (i, a, b, fa, fb) { r.segment(xyz, a, xyz, b, w.info[i].colour, fa, fb); });
      r.draw(frame, images, WIDTH.trail);
    }
    if (w && w.viewJointCount()) {
      r.begin();
      addJoints(r, w);
      r.draw(frame, images, WIDTH.joint);
    }
    r.begin();
    if (tools.geodesic) addCurve(r, tools.geodesic, COLOUR.geodesic);
    if (tools.preview) addCurve(r, tools.preview, COLOUR.preview);
    r.draw(frame, images, WIDTH.geodesic);
  }

  /** @param {Curve | null} c */
  function curveValue(c) {
    if (!c) return null;
    /** @type {Manifold.Vec3[]} */
    const points = [];
    /** @type {number[]} */
    const breaks = [];
    for (let k = 0; k < c.count; k++) {
      points.push([c.points[3 * k], c.points[3 * k + 1], c.points[3 * k + 2]]);
      if (c.breaks[k]) breaks.push(k);
    }
    return { points: points, breaks: breaks };
  }

  // What is drawn, for window.manifold.curves(): the geodesic, the throw's
  // preview (a point per step), and the trails' segments with the opacity
  // of their oldest and newest ends.
  function curves() {
    let segments = 0, oldest = 1, newest = 0;
    eachTrailSegment(function (i, a, b, fa, fb) {
      segments++;
      oldest = Math.min(oldest, fa);
      newest = Math.max(newest, fb);
    });
    return {
      geodesic: curveValue(tools.geodesic),
      preview: curveValue(tools.preview),
      trails: {
        on: tools.trailsOn, samples: tools.trail.world === state.world ? tools.trail.filled : 0, segments: segments,
        oldest: segments ? oldest : null, newest: segments ? newest : null,
      },
    };
  }

  const exported = {
    TOOLS: TOOLS,
    GEODESIC_LENGTH: GEODESIC_LENGTH,
    THROW_GAIN: THROW_GAIN,
    PREVIEW_SECONDS: PREVIEW_SECONDS,
    TRAIL: TRAIL,
    tools: tools,
    spaceSize: spaceSize,
    newBody: newBody,
    newSceneBody: newSceneBody,
    setNewBody: setNewBody,
    spaceChanged: spaceChanged,
    setTool: setTool,
    tool: function () { return tools.tool; },
    setGeodesicLength: setGeodesicLength,
    showGeodesic: showGeodesic,
    clearGeodesic: clearGeodesic,
    press: press,
    move: move,
    release: release,
    cancel: cancel,
    launch: launch,
    setTrails: setTrails,
    sampleTrails: sampleTrails,
    draw: draw,
    curves: curves,
  };
  W.ManifoldWeb = W.ManifoldWeb || /** @type {ManifoldWebModules} */ ({});
  W.ManifoldWeb.tools = exported;
  return exported;
})(globalThis);
