// The world of bodies: the generated engine's arrays (Manifold.spaces[NAME].engine),
// scenes as JSON (the format `manifold sim` reads), and the stepping loop at a
// fixed dt. Every body is added, stepped, picked, grabbed, dragged and removed
// through the generated procedures; this file only allocates, copies, counts,
// validates and converts.
/* exported ManifoldWebWorld */
var ManifoldWebWorld = (function (W) {
  "use strict";

  // a new world's arrays hold this many bodies; they double as bodies are
  // added, up to the engine's maxBodies (generated, Manifold.Stage.EngineScript)
  const FIRST_CAPACITY = 64;
  // World.fill gives up after this many placements in a row found no room
  // (a body off the surface, outside the boundary or on another body):
  // past that the space is about as full of bodies of that size as random
  // placement gets it, and more tries only cost time
  const FILL_GIVE_UP = 500;
  // |field| at a new body's centre above this: the engine's projection failed
  const ON_SURFACE = 1e-6;
  // colours by the order bodies are added (display RGB 0..1): saturated, far from the surface's beige
  /** @type {Manifold.Rgb[]} */
  const PALETTE = [
    [0.90, 0.22, 0.20], [0.16, 0.47, 0.90], [0.18, 0.70, 0.32], [0.95, 0.62, 0.08],
    [0.60, 0.28, 0.85], [0.05, 0.68, 0.72], [0.88, 0.25, 0.62], [0.50, 0.75, 0.10],
  ];
  /** @type {Manifold.Rgb} */
  const STATIC_COLOUR = [0.42, 0.45, 0.50];

  // ---- a world shared with the physics worker (web/js/physics-worker.js) ----
  // When the page is cross-origin isolated, a world's arrays may live in
  // SharedArrayBuffers stepped by a worker. Whoever touches them holds
  // SHARED.LOCK: the worker for a batch of steps, the main thread for the
  // rest of the task that touched them (World.hold). The main thread sets
  // WANT before it waits, and the worker gives way at the next step. What the
  // page draws is a snapshot of the VIEW arrays in one of three buffers
  // (triple buffering: the worker writes its own, publishes it as the middle
  // one by an atomic exchange, and the main thread takes the middle one when
  // it is FRESH), so a frame never waits for a step nor draws half of one.
  const SHARED = {
    LOCK: 0, WANT: 1, GENERATION: 2, MIDDLE: 3, RUNNING: 4, SLOTS: 8,
    MAIN: 1, WORKER: 2, FRESH: 4,
  };
  // the shared clock's numbers (a Float64Array): steps taken, ms a step (NaN: not known), the clock's speed
  const CLOCK = { STEPS: 0, STEP_MS: 1, TIME_SCALE: 2, SLOTS: 4 };
  // how long the main thread waits for the worker to end a step (ms): a step
  // of the most bodies takes a fraction of a second; beyond this the worker
  // is taken for dead (Sharing.unanswered) and the main thread takes the world
  const HOLD_PATIENCE_MS = 5000;
  // the arrays a frame reads (the bodies' outlines and corners, poses, speeds and states, and the counters)
  /** @type {(keyof ManifoldWeb.View & Manifold.ArrayName)[]} */
  const VIEW = ["meta", "pos", "vel", "scalars", "verts", "hull"];

  /** @param {number} length @param {boolean} shared */
  function doubles(length, shared) {
    return new Float64Array(shared ? new SharedArrayBuffer(8 * length) : new ArrayBuffer(8 * length));
  }

  // The VIEW arrays of an engine for `capacity` bodies, in shared memory.
  /** @param {Manifold.Engine} E @param {number} capacity @returns {ManifoldWeb.View} */
  function viewBuffers(E, capacity) {
    /** @type {Record<string, Float64Array>} */
    const out = {};
    VIEW.forEach(function (n) { out[n] = doubles(E.sizes[n][0] + E.sizes[n][1] * capacity, true); });
    return /** @type {ManifoldWeb.View} */ (/** @type {unknown} */ (out));
  }

  // Copies the VIEW arrays' rows of the world's bodies from `from` into `to`.
  /** @param {Manifold.Engine} E @param {ManifoldWeb.View} from @param {ManifoldWeb.View} to */
  function copyView(E, from, to) {
    const count = from.meta[E.meta.bodyCount];
    VIEW.forEach(function (n) {
      const s = E.sizes[n];
      to[n].set(from[n].subarray(0, s[0] + s[1] * count));
    });
  }

  // ---- scenes: read by the generated scene format (Manifold.SceneFormat), naming the JSON path of the first problem ----
  // The keys that set engine parameters, their parameters and kinds, are
  // generated (Manifold.sceneKeys, from Lib/Manifold/Params.hs).
  function sceneKeys() { return W.Manifold.sceneKeys; }
  /** @typedef {Required<Omit<Manifold.SceneBody, "axis" | "normal" | "awake" | "island" | "friction" | "restitution">> & Pick<Manifold.SceneBody, "axis" | "normal" | "awake" | "island" | "friction" | "restitution">} ParsedBody */
  function shapes() { return W.Manifold.shapes; }
  // what a contact row to be kept lists after [key, normal, friction] (generated: Manifold.World.keptFields)
  function keptFields() { return W.Manifold.keptFields; }

  class SceneError extends Error {
    /** @param {string} message */
    constructor(message) {
      super(message);
      this.name = "SceneError";
    }
  }

  /** @param {string} path @param {string} msg @returns {never} */
  function problem(path, msg) { throw new SceneError(path + ": " + msg); }

  /** @param {unknown} v @returns {v is Record<string, unknown>} */
  function isObject(v) { return v !== null && typeof v === "object" && !Array.isArray(v); }

  /** @param {unknown} o @param {string} k */
  function hasOwn(o, k) { return isObject(o) && Object.prototype.hasOwnProperty.call(o, k); }

  // ---- the scene file's format, read ----
  // The format is data (generated: Manifold.sceneFormat, bodyFormat and
  // jointFormat, from Lib/Manifold/SceneFormat.hs): every key, what its
  // value must be, its default, the words of each problem and the order they
  // are found in. `check` is its one reader here, step for step
  // Manifold.SceneFormat.check: a value completed with its defaults, or a
  // SceneError naming the first problem's JSON path in the same words.

  /**
   * What a check knows besides the value: the lengths of the lists and the
   * names read so far, by key.
   * @typedef {{ counts: Record<string, number>, facts: Record<string, string>, names: (kind: string) => string[] }} Context
   */

  // A message with its holes {0}, {1}, ... filled.
  /** @param {string} msg @param {unknown[]} args */
  function fill(msg, args) {
    return msg.replace(/\{(\d)\}/g, function (m, d) { return Number(d) < args.length ? String(args[Number(d)]) : m; });
  }

  // Why a finite number is out of bounds, or null.
  /** @param {Manifold.Bounds} b @param {number} x @returns {string | null} */
  function boundsProblem(b, x) {
    const lo = b.lowest, hi = b.highest;
    if (lo && (x < lo.at || (lo.strict && x === lo.at))) return lo.message;
    if (hi && (x > hi.at || (hi.strict && x === hi.at))) return hi.message;
    if (b.whole !== null && x !== Math.round(x)) return b.whole;
    return null;
  }

  /** @param {string} path @param {string[]} allowed @param {Record<string, unknown>} v */
  function known(path, allowed, v) {
    const unknown = Object.keys(v).filter(function (k) { return allowed.indexOf(k) < 0; });
    if (unknown.length) problem(path + "." + unknown[0], "unknown key; the keys are " + allowed.join(", "));
  }

  // The value read against the format: completed, or a SceneError.
  /** @param {Manifold.Format} f @param {string} path @param {unknown} v @param {Context} ctx @returns {any} */
  function check(f, path, v, ctx) {
    if ("number" in f) {
      if (typeof v !== "number") problem(path, "must be a number");
      if (!isFinite(v)) problem(path, "must be a finite number");
      const why = boundsProblem(f.number, v);
      return why === null ? v : problem(path, why);
    }
    if ("flag" in f) return typeof v === "boolean" ? v : problem(path, "must be true or false");
    if ("row" in f) {
      const r = f.row;
      if (!Array.isArray(v) || r.lengths.indexOf(v.length) < 0) problem(path, r.message);
      return v.map(function (x, k) { return check(k < r.items.length ? r.items[k] : r.rest, path + "[" + k + "]", x, ctx); });
    }
    if ("list" in f) {
      const l = f.list;
      if (!Array.isArray(v) || v.length < l.least || (l.most !== null && v.length > l.most)) problem(path, l.message);
      return v.map(function (x, k) { return check(l.item, path + "[" + k + "]", x, ctx); });
    }
    if ("convex" in f) {
      /** @type {[number, number][]} */
      const cs = check(f.convex.corners, path, v, ctx), most = shapes().maxCorners;
      // (Manifold.Hull.convexRound, generated: the count, then the corners padded to maxCorners)
      const flat = new Array(2 * most).fill(0);
      cs.forEach(function (c, k) { flat[2 * k] = c[0]; flat[2 * k + 1] = c[1]; });
      if (!(shapes().convexRound.apply(null, /** @type {[number, ...number[]]} */ ([cs.length].concat(flat))) > 0.5)) problem(path, f.convex.message);
      return cs;
    }
    if ("record" in f) return record(f.record, path, v, ctx).out;
    if ("oneOf" in f) {
      const c = f.oneOf;
      if (typeof v === "string") return c.names.indexOf(v) >= 0 ? v : problem(path, fill(c.unknown, [JSON.stringify(v)]));
      if (!isObject(v)) problem(path, c.notOne);
      known(path, c.keyed.map(function (k) { return k[0]; }).concat(c.companions.map(function (k) { return k[0]; })), v);
      const given = c.keyed.filter(function (k) { return hasOwn(v, k[0]); });
      c.companions.forEach(function (m) {
        if (hasOwn(v, m[0]) && !(given.length === 1 && given[0][0] === m[1])) problem(path + "." + m[0], fill(c.companion, [m[1]]));
      });
      if (given.length !== 1) problem(path, c.oneKey);
      const k = given[0][0];
      /** @type {Record<string, unknown>} */
      const out = {};
      out[k] = check(given[0][1], path + "." + k, v[k], ctx);
      c.companions.forEach(function (m) { if (m[1] === k && hasOwn(v, m[0])) out[m[0]] = check(m[2], path + "." + m[0], v[m[0]], ctx); });
      return out;
    }
    if ("tagged" in f) {
      const t = f.tagged;
      if (!isObject(v)) problem(path, "must be an object");
      if (!hasOwn(v, t.key)) problem(path + "." + t.key, "is missing");
      const kind = v[t.key];
      if (typeof kind !== "string") problem(path + "." + t.key, t.notOne);
      if (!hasOwn(t.kinds, kind)) problem(path + "." + t.key, fill(t.unknown, [JSON.stringify(kind)]));
      const out = check(t.kinds[kind], path, v, ctx);
      out[t.key] = kind;
      return out;
    }
    if ("name" in f) {
      const n = f.name, names = ctx.names(n.kind);
      if (typeof v !== "string") problem(path, n.notString);
      return names.indexOf(v) >= 0 ? v : problem(path, fill(n.unknown, [JSON.stringify(v), names.join(", ")]));
    }
    const ix = f.index, count = ctx.counts[ix.list] || 0;
    if (v === ix.or && ix.or !== null) return v;
    if (typeof v === "number" && Number.isInteger(v) && v >= 0 && v < count) return v;
    return problem(path, fill(ix.message, [count - 1]));
  }

  // A record read entry by entry: the completed object, and the context with
  // the lengths of its lists and its names.
  /**
   * @param {{ keys: string[], entries: Manifold.FormatEntry[] }} r @param {string} path @param {unknown} v @param {Context} ctx
   * @returns {{ out: Record<string, any>, ctx: Context }}
   */
  function record(r, path, v, ctx) {
    if (!isObject(v)) problem(path, "must be an object");
    known(path, r.keys, v);
    /** @type {Record<string, any>} */
    const out = {};
    let c = ctx;
    /** @param {string} k @param {Manifold.Format} f @param {unknown} y */
    const learn = function (k, f, y) {
      if ("list" in f && Array.isArray(y)) c = { counts: Object.assign({}, c.counts, { [k]: y.length }), facts: c.facts, names: c.names };
      if ("name" in f && typeof y === "string") c = { counts: c.counts, facts: Object.assign({}, c.facts, { [k]: y }), names: c.names };
    };
    /** @param {Manifold.FormatEntry[]} entries */
    const run = function (entries) {
      entries.forEach(function (e) {
        if ("field" in e) {
          const k = e.field, p = e.presence;
          if (hasOwn(v, k)) {
            out[k] = check(e.format, path + "." + k, v[k], c);
            learn(k, e.format, out[k]);
          } else if ("required" in p) {
            problem(path + "." + k, "is missing");
          } else if ("default" in p) {
            out[k] = JSON.parse(JSON.stringify(p.default));
            learn(k, e.format, out[k]);
          } else if ("perStep" in p) {
            out[k] = p.perStep / out[p.of];
          }
        } else if ("when" in e) {
          const s = out[e.when];
          run(isObject(s) && e.has.some(function (h) { return hasOwn(s, h); }) ? e.then : e.else);
        } else {
          rule(e.rule, path, v, out, c);
        }
      });
    };
    run(r.entries);
    return { out: out, ctx: c };
  }

  // A rule of a record whose entries so far gave `out` (from the object
  // `given`): completes `out` (a sleeping body's island), or throws.
  /** @param {Manifold.FormatRule} r @param {string} path @param {Record<string, unknown>} given @param {Record<string, any>} out @param {Context} ctx */
  function rule(r, path, given, out, ctx) {
    /** @param {string} k */
    const has = function (k) { return hasOwn(out, k); };
    if ("together" in r) {
      const a = r.together[0], b = r.together[1], note = r.together[2];
      if (has(a) && !has(b)) problem(path + "." + b, "must be given with " + a + note);
      if (!has(a) && has(b)) problem(path + "." + a, "must be given with " + b + note);
    } else if ("ordered" in r) {
      const a = r.ordered[0], b = r.ordered[1];
      if (has(a) && has(b) && out[a] > out[b]) {
        if (r.atSecond) problem(path + "." + b, "must not be less than " + a);
        problem(path + "." + a, "must not be more than " + b);
      }
    } else if ("differ" in r) {
      const a = r.differ[0], b = r.differ[1];
      if (typeof out[a] === "number" && out[a] === out[b]) problem(path + "." + b, fill(r.differ[2], [out[a]]));
    } else if ("notGiven" in r) {
      if (hasOwn(given, r.notGiven[0])) problem(path + "." + r.notGiven[0], r.notGiven[1]);
    } else if ("islands" in r) {
      const raw = /** @type {unknown[]} */ (hasOwn(given, "bodies") ? given.bodies : []), bodies = /** @type {Record<string, unknown>[]} */ (out.bodies);
      /** @param {number} i */
      const asleepAt = function (i) { return i >= 0 && i < raw.length && hasOwn(raw[i], "awake") && /** @type {Record<string, unknown>} */ (raw[i]).awake === false && bodies[i].static !== true; };
      bodies.forEach(function (b, k) {
        const at = path + ".bodies[" + k + "]", g = /** @type {Record<string, unknown>} */ (raw[k]);
        const awake = hasOwn(g, "awake") ? check({ flag: null }, at + ".awake", g.awake, ctx) : true;
        let label = null;
        if (hasOwn(g, "island")) {
          const x = g.island;
          if (!(typeof x === "number" && Number.isInteger(x) && asleepAt(x))) problem(at + ".island", r.islands[0]);
          label = x;
        }
        if (awake && label !== null) problem(at + ".island", r.islands[1]);
        if (!awake && b.static === true) problem(at + ".awake", r.islands[2]);
        if (!awake) {
          b.awake = false;
          b.island = label === null ? k : label;
        }
      });
    } else if ("remembered" in r) {
      const bodies = /** @type {{ impulses: unknown[] }[]} */ (out.bodies);
      const total = bodies.reduce(function (t, b) { return t + b.impulses.length; }, 0);
      if (total > r.perBody * bodies.length) problem(path + ".bodies", fill(r.remembered, [total, bodies.length, r.perBody]));
    } else if ("refusedBy" in r) {
      const space = ctx.facts[r.refusedBy[1]], why = space === undefined ? null : jointsRefused(space);
      if (why !== null && out[r.refusedBy[0]].length > 0) problem(path + "." + r.refusedBy[0], why);
    } else if ("atMostTwice" in r) {
      const n = out[r.atMostTwice[0]].length, m = out[r.atMostTwice[1]].length;
      if (n > 2 * Math.max(1, m)) problem(path + "." + r.atMostTwice[0], fill(r.atMostTwice[2], [n, m]));
    } else {
      const names = r.view, eye = out[names[0]], target = out[names[1]];
      const f = [target[0] - eye[0], target[1] - eye[1], target[2] - eye[2]];
      const own = W.Manifold.spaceIndex.find(function (e) { return e.name === ctx.facts.space; });
      const up = has(names[2]) ? out[names[2]] : own ? own.up : null;
      if (f[0] === 0 && f[1] === 0 && f[2] === 0) problem(path + "." + names[1], names[3]);
      if (up && up[1] * f[2] - up[2] * f[1] === 0 && up[2] * f[0] - up[0] * f[2] === 0 && up[0] * f[1] - up[1] * f[0] === 0) {
        problem(path + "." + names[2], names[4]);
      }
    }
  }

  // The generated formats' parts the page reads on its own: a body's shape,
  // and the defaults of a body's keys.
  /** @param {Manifold.Format} format a record's @param {string} key */
  function formatField(format, key) {
    const entries = "record" in format ? format.record.entries : [];
    const e = entries.find(function (x) { return "field" in x && x.field === key; });
    if (!e || !("field" in e)) throw new Error("the format has no key " + key);
    return e;
  }
  /** @param {string} key */
  function bodyEntry(key) { return formatField(W.Manifold.bodyFormat, key); }
  // (none where the generated index is missing: the page then says to build it)
  /** @param {string} key */
  function bodyDefault(key) {
    return W.Manifold && W.Manifold.bodyFormat ? /** @type {{ default: unknown }} */ (bodyEntry(key).presence).default : undefined;
  }
  // what a scene body without these keys has (Manifold.SceneFormat's
  // defaults; read when asked, as the generated index may load after this script)
  const BODY_DEFAULTS = {
    get density() { return /** @type {number} */ (bodyDefault("density")); },
    get static() { return /** @type {boolean} */ (bodyDefault("static")); },
  };

  /** @returns {Context} */
  function noContext() { return { counts: {}, facts: {}, names: function () { return []; } }; }

  // A shape (JSON value) → the shape; throws a SceneError naming `path`.
  /** @param {string} path @param {unknown} v @returns {Manifold.Shape} */
  function shape(path, v) { return check(bodyEntry("shape").format, path, v, noContext()); }

  // Why space `name`'s scenes can have no joints (generated:
  // Manifold.jointsRefused), or null.
  /** @param {string} name @returns {string | null} */
  function jointsRefused(name) {
    const why = W.Manifold.jointsRefused;
    return why && Object.prototype.hasOwnProperty.call(why, name) ? why[name] : null;
  }

  // A checked body completed for the engine: a box's, a capsule's or
  // vertices' size is their numbers' reach.
  /** @param {Record<string, any>} b @returns {ParsedBody} */
  function completeBody(b) {
    if (!hasOwn(b, "size")) b.size = reachOf(b.shape, 0);
    return /** @type {ParsedBody} */ (b);
  }

  // A scene body (JSON value) → a complete body spec (its awake and island
  // keys are the scene's to read); throws a SceneError naming `path`.
  /** @param {unknown} v @param {string} [path] @returns {ParsedBody} */
  function parseBody(v, path) { return completeBody(check(W.Manifold.bodyFormat, path || "body", v, noContext())); }

  // A checked joint in the engine's terms (b -1: the world; null where the
  // scene left a key out).
  /** @param {Record<string, any>} j @returns {ManifoldWeb.ParsedJoint} */
  function jointOf(j) {
    const distance = j.type === "distance";
    /** @param {string} k */
    const opt = function (k) { return hasOwn(j, k) ? j[k] : null; };
    return { type: j.type, a: j.a, b: j.b === "world" ? -1 : j.b,
      anchorA: distance ? j.anchorA : j.anchor, anchorB: distance ? j.anchorB : j.anchor,
      length: opt("length"), minLength: opt("minLength"), maxLength: opt("maxLength"),
      hertz: opt("hertz") || 0, dampingRatio: opt("dampingRatio") || 0, referenceAngle: opt("referenceAngle"),
      limit: hasOwn(j, "lowerAngle") ? [j.lowerAngle, j.upperAngle] : null,
      motor: hasOwn(j, "motorSpeed") ? [j.motorSpeed, j.maxMotorTorque] : null,
      local: opt("local"), impulses: j.impulses, collide: j.collide };
  }

  // a saved joint's anchors in its bodies' coordinates (Manifold.Scene's "local"), and its impulses
  /** @type {Manifold.JointField[]} */
  const JOINT_LOCAL = ["radiusA", "thetaA", "radiusB", "thetaB", "worldX", "worldY", "worldZ"];
  /** @type {Manifold.JointField[]} */
  const JOINT_IMPULSES = ["impulse1", "impulse2", "impulseAxial", "impulseLower", "impulseUpper", "impulseMotor", "impulseAngle"];

  // A scene joint (JSON value) of a world of n bodies → a complete joint
  // spec; throws a SceneError naming `path`.
  /** @param {unknown} v @param {string} path @param {number} n @returns {ManifoldWeb.ParsedJoint} */
  function parseJoint(v, path, n) {
    const ctx = noContext();
    ctx.counts.bodies = n;
    return jointOf(check(W.Manifold.jointFormat, path, v, ctx));
  }

  // A scene (JSON text or value) → a complete scene; spaceNames: the known spaces.
  /** @param {unknown} json @param {string[]} spaceNames @returns {ManifoldWeb.ParsedScene} */
  function parseScene(json, spaceNames) {
    let v = json;
    if (typeof json === "string") {
      try {
        v = JSON.parse(json);
      } catch (e) {
        throw new SceneError("not JSON: " + e.message);
      }
    }
    const scene = check(W.Manifold.sceneFormat, "$", v, { counts: {}, facts: {}, names: function () { return spaceNames; } });
    scene.bodies.forEach(completeBody);
    scene.joints = scene.joints.map(jointOf);
    if (!hasOwn(scene, "camera")) scene.camera = null;
    return /** @type {ManifoldWeb.ParsedScene} */ (scene);
  }
  // Why v is not a value of scene key k: the problem the scene format's
  // reader finds in it (its words, without a path), or null.
  /** @param {Manifold.SceneKey} k @param {unknown} v @returns {string | null} */
  function keyProblem(k, v) {
    try {
      check(formatField(W.Manifold.sceneFormat, k.key).format, "", v, noContext());
      return null;
    } catch (e) {
      if (e instanceof SceneError) return e.message.slice(2);
      throw e;
    }
  }

  // A parsed scene's parameters as the engine's (by parameter name).
  /** @param {ManifoldWeb.ParsedScene} scene */
  function sceneParams(scene) {
    /** @type {ManifoldWeb.Params} */
    const p = {};
    sceneKeys().forEach(function (k) { p[k.param] = k.kind === "switch" ? (scene[k.key] ? 1 : 0) : /** @type {number} */ (scene[k.key]); });
    return p;
  }

  // The scene keys' values for the engine's parameters (param: name → value),
  // added to a scene: the inverse of sceneParams.
  /** @param {Record<string, unknown>} scene @param {(name: Manifold.ParamName) => number} param */
  function withParams(scene, param) {
    sceneKeys().forEach(function (k) { scene[k.key] = k.kind === "switch" ? param(k.param) > 0 : param(k.param); });
    return scene;
  }

  // A shape as addBody takes it: its code and its two numbers (generated:
  // Manifold.shapes, from Lib/Manifold/Hull.hs).
  /** @param {Manifold.Shape} s @returns {[number, number, number]} */
  function shapeArgs(s) {
    const c = shapes().codes;
    if (s === "circle") return [c.circle, 0, 0];
    if (s === "square") return [4, 0, 0];
    if ("polygon" in s) return [s.polygon, 0, 0];
    if ("box" in s) return [c.box, s.box[0], s.box[1]];
    if ("vertices" in s) return [c.vertices, s.vertices.length, s.radius || 0];
    return [c.capsule, s.capsule[0], s.capsule[1]];
  }
  // A shape's corners as addBody takes them: a convex polygon's a0, b0, ...
  // (Manifold.shapes.maxCorners of them, the unused ones 0), else all 0.
  /** @param {Manifold.Shape} s @param {Float64Array} out */
  function cornersInto(s, out) {
    out.fill(0);
    if (typeof s === "object" && "vertices" in s) s.vertices.forEach(function (c, k) { out[2 * k] = c[0]; out[2 * k + 1] = c[1]; });
    return out;
  }
  /** @param {Manifold.Shape} s @returns {Manifold.Shape} */
  function copyShape(s) {
    if (typeof s === "string") return s;
    if ("polygon" in s) return { polygon: s.polygon };
    if ("box" in s) return { box: [s.box[0], s.box[1]] };
    if ("vertices" in s) {
      /** @type {[number, number][]} */
      const vs = s.vertices.map(function (c) { return /** @type {[number, number]} */ ([c[0], c[1]]); });
      return s.radius ? { vertices: vs, radius: s.radius } : { vertices: vs };
    }
    return { capsule: [s.capsule[0], s.capsule[1]] };
  }
  // Whether a shape's numbers are its size (a box, a capsule, vertices: a
  // scene gives no size with them), as the body format says.
  /** @param {Manifold.Shape} s */
  function sizedByShape(s) {
    const entries = /** @type {{ record: { entries: Manifold.FormatEntry[] } }} */ (W.Manifold.bodyFormat).record.entries;
    const e = entries.find(function (x) { return "when" in x && x.when === "shape"; });
    if (!e || !("when" in e)) throw new Error("the body format says nothing of sized shapes");
    return typeof s === "object" && s !== null && e.has.some(function (k) { return k in s; });
  }
  // A scene body of a shape and size (a box's or a capsule's without the
  // size: its numbers are its size).
  /** @param {Manifold.Shape} shape @param {number} size @returns {{ shape: Manifold.Shape, size?: number }} */
  function bodyOfShape(shape, size) { return sizedByShape(shape) ? { shape: copyShape(shape) } : { shape: copyShape(shape), size: size }; }
  // How far a body of a shape reaches from its centre: its size, or a box's
  // or a capsule's numbers'.
  /** @param {Manifold.Shape} shape @param {number} size */
  function reachOf(shape, size) {
    const a = shapeArgs(shape);
    if (typeof shape === "object" && "vertices" in shape) {
      const args = /** @type {[number, number, ...number[]]} */ ([a[1], a[2]].concat(Array.from(cornersInto(shape, new Float64Array(2 * shapes().maxCorners)))));
      return shapes().polygonSize.apply(null, args);
    }
    return shapes().size(a[0], a[1], a[2], size);
  }

  // Deterministic pseudo-random numbers in [0, 1) (for scene filling).
  /** @param {number} seed */
  function random(seed) {
    let s = seed >>> 0;
    return function () {
      s = (Math.imul(s, 1664525) + 1013904223) >>> 0;
      return s / 4294967296;
    };
  }

  // ---- the world ----------------------------------------------------------------
  class World {
    // space: Manifold.spaces[NAME] (with .engine)
    /** @param {string} name @param {Manifold.Space} space */
    constructor(name, space) {
      if (!space || !space.engine) throw new Error("the space " + JSON.stringify(name) + " has no engine; rebuild web/gen with `manifold build`");
      if (!(space.engine.maxBodies >= 1)) throw new Error("the engine of " + JSON.stringify(name) + " does not say how many bodies it holds (maxBodies); rebuild web/gen with `manifold build`");
      this.name = name;
      this.space = space;
      this.engine = space.engine;
      this.images = space.images || [];
      /** @type {ManifoldWeb.BodyInfo[]} */
      this.info = [];          // per body: { shape, density, static, colour }
      this.added = 0;          // bodies ever added (picks the next colour)
      this.version = 0;        // bumped whenever bodies move, appear or go
      this.grabbed = -1;       // the body held by the mouse joint, or -1
      /** @type {Manifold.Vec3 | null} */
      this.target = null;      // the joint's target surface point (as picked)
      /** @type {Float64Array | null} */
      this.measured = null;    // the engine's measures write here (measureOut)
      /** @type {Float64Array | null} */
      this.anchorsOut = null;  // jointAnchors writes here
      this.cornersIn = new Float64Array(2 * shapes().maxCorners);  // addBody reads a convex polygon's corners here
      /** @type {Float64Array | null} */
      this.pathsOut = null;    // jointPaths writes here
      this.capacity = 0;
      /** @type {Float64Array[]} */
      this.list = [];          // the engine's arrays, in the order its procedures take them …
      /** @type {Record<Manifold.ArrayName, Float64Array>} */
      this.live = null;        // … and by name (read them through `arrays` and `a`, which hold the lock)
      /** @type {ManifoldWeb.Sharing | null} */
      this.shared = null;      // the shared memory and snapshots when a worker steps this world
      this.holding = false;    // the main thread holds the shared lock until its task ends
      this.heldAt = 0;         // this.version when it took the lock
      this.counts = doubles(CLOCK.SLOTS, false);  // steps taken and ms a step (shared with the worker)
      this.counts[CLOCK.STEP_MS] = NaN;
      this.allocate(FIRST_CAPACITY);
      this.setParams(this.engine.defaults);
    }

    // The engine's arrays in its procedures' order, and by name: reading them
    // holds the lock of a world shared with the worker until the task ends.
    get arrays() { this.hold(); return this.list; }
    get a() { this.hold(); return this.live; }

    get steps() { return this.counts[CLOCK.STEPS]; }
    set steps(n) { this.counts[CLOCK.STEPS] = n; }
    // moving average of the physics time per step (ms), or null
    /** @returns {number | null} */
    get stepMs() { const x = this.counts[CLOCK.STEP_MS]; return isNaN(x) ? null : x; }
    set stepMs(ms) { this.counts[CLOCK.STEP_MS] = ms === null ? NaN : ms; }

    // Takes the shared lock for the rest of this task (no-op unless a worker
    // steps this world): the worker ends its step, and waits until then.
    hold() {
      const s = this.shared;
      if (s === null || this.holding) return;
      const c = s.control, t0 = performance.now();
      Atomics.store(c, SHARED.WANT, 1);
      while (Atomics.compareExchange(c, SHARED.LOCK, 0, SHARED.MAIN) !== 0) {
        // (the worker ends its step)
        if (performance.now() - t0 > HOLD_PATIENCE_MS) {
          Atomics.store(c, SHARED.LOCK, SHARED.MAIN);
          s.unanswered = true;
          break;
        }
      }
      this.holding = true;
      this.heldAt = this.version;
      queueMicrotask(this.letGo.bind(this, s));
    }

    // Gives the lock back; a change made under it is drawn from now on (the
    // main thread's snapshot, not a worker's older one).
    /** @param {ManifoldWeb.Sharing} s */
    letGo(s) {
      if (this.version !== this.heldAt && this.shared === s) {
        copyView(this.engine, /** @type {ManifoldWeb.View} */ (/** @type {unknown} */ (this.live)), s.snapshots[s.front]);
        Atomics.and(s.control, SHARED.MIDDLE, 3);
      }
      this.holding = false;
      Atomics.store(s.control, SHARED.LOCK, 0);
      Atomics.store(s.control, SHARED.WANT, 0);
      Atomics.notify(s.control, SHARED.WANT);
    }

    // What a frame draws: the world's own arrays, or when a worker steps it,
    // the newest snapshot taken (takeSnapshot). Never waits.
    /** @returns {ManifoldWeb.View} */
    view() {
      const s = this.shared;
      return s ? s.snapshots[s.front] : /** @type {ManifoldWeb.View} */ (/** @type {unknown} */ (this.live));
    }
    // the bodies a frame draws
    viewCount() { return this.view().meta[this.engine.meta.bodyCount]; }
    // the joints a frame draws (their paths are the world's own: drawing them takes the lock)
    viewJointCount() { return this.engine.addJoint ? this.view().meta[this.engine.meta.jointCount] : 0; }

    // The world as BodyRenderer.draws it: itself, or when a worker steps it,
    // its snapshot (itself again within a task that holds the lock, whose
    // changes the snapshot has not yet).
    /** @returns {ManifoldWeb.DrawnWorld} */
    drawn() {
      if (!this.shared || this.holding) return this;
      const v = this.view(), n = Math.min(this.viewCount(), this.info.length);
      return {
        engine: this.engine, info: this.info, capacity: this.capacity, images: this.images,
        count: function () { return n; }, a: v, target: this.target,
      };
    }

    // Takes the worker's newest snapshot if there is one; true if it did.
    takeSnapshot() {
      const s = this.shared;
      if (!s || !(Atomics.load(s.control, SHARED.MIDDLE) & SHARED.FRESH)) return false;
      s.front = Atomics.exchange(s.control, SHARED.MIDDLE, s.front) & 3;
      this.version++;
      return true;
    }

    // Moves the arrays into shared memory (a worker may then step them), or
    // back (shared false). `notify` hears of every new set of shared arrays.
    /** @param {boolean} shared @param {(w: World) => void} [notify] */
    share(shared, notify) {
      if (shared === (this.shared !== null)) return;
      this.hold();
      const old = this.shared;
      if (shared) {
        const control = new Int32Array(new SharedArrayBuffer(4 * SHARED.SLOTS));
        const counts = doubles(CLOCK.SLOTS, true);
        counts.set(this.counts);
        counts[CLOCK.TIME_SCALE] = 1;
        this.counts = counts;
        this.shared = { control: control, snapshots: [], front: 1, unanswered: false, notify: notify || function () { return undefined; } };
      } else {
        this.counts = Float64Array.from(this.counts);
        this.shared = null;
      }
      this.allocate(this.capacity, true);
      // the old lock is let go by the hold's microtask; a worker still holding the old arrays finds GENERATION changed
      if (old) Atomics.add(old.control, SHARED.GENERATION, 1);
      this.version++;
    }

    /** @param {number} capacity @param {boolean} [keep] */
    allocate(capacity, keep) {
      const E = this.engine, shared = this.shared !== null;
      const old = this.a;
      this.adopt(E.arrays.map(function (n) {
        const s = E.sizes[n];
        const arr = doubles(s[0] + s[1] * capacity, shared);
        // the arrays are indexed from 0 with per-body strides: the old contents keep their places
        if (keep && old) arr.set(old[n]);
        return arr;
      }), capacity);
      this.live.meta[E.meta.capacity] = capacity;
    }

    // Makes `list` (the engine's arrays, in its order) the world's arrays;
    // a worker stepping the world is given them (and new snapshots).
    /** @param {Float64Array[]} list @param {number} capacity */
    adopt(list, capacity) {
      const E = this.engine, s = this.shared;
      this.capacity = capacity;
      this.list = list;
      this.live = /** @type {Record<Manifold.ArrayName, Float64Array>} */ ({});
      E.arrays.forEach(/** @this {World} */ function (n, i) { this.live[n] = list[i]; }, this);
      if (s) {
        s.snapshots = [viewBuffers(E, capacity), viewBuffers(E, capacity), viewBuffers(E, capacity)];
        s.front = 1;
        copyView(E, /** @type {ManifoldWeb.View} */ (/** @type {unknown} */ (this.live)), s.snapshots[s.front]);
        Atomics.store(s.control, SHARED.MIDDLE, 2);
        Atomics.add(s.control, SHARED.GENERATION, 1);
        this.version++;
        s.notify(this);
      }
    }

    // the most bodies the world holds (the generated engine's maxBodies)
    maxBodies() { return this.engine.maxBodies; }

    /** @param {Manifold.MetaName} k */
    meta(k) { return this.a.meta[this.engine.meta[k]]; }
    count() { return this.a.meta[this.engine.meta.bodyCount]; }
    /** @param {Manifold.ParamName} k */
    param(k) { return this.a.params[this.engine.params[k]]; }

    // The engine's arrays, then a procedure's own arguments (for proc.apply).
    /** @param {number[]} own @returns {(Float64Array | number)[]} */
    args(own) { return /** @type {(Float64Array | number)[]} */ (this.arrays).concat(own); }

    // Sets engine parameters by name ({dt, gravityOn, iterations, friction, restitution, ...}).
    /** @param {ManifoldWeb.Params} p */
    setParams(p) {
      const E = this.engine;
      /** @type {Manifold.ParamName[]} */ (Object.keys(p)).forEach(/** @this {World} */ function (k) {
        if (!(k in E.params)) throw new Error("unknown engine parameter " + JSON.stringify(k));
        const x = Number(p[k]);
        if (!isFinite(x)) throw new Error("engine parameter " + k + " must be a finite number");
        this.a.params[E.params[k]] = x;
      }, this);
    }

    // Adds a body from a scene body (JSON value); returns its index or throws.
    /** @param {unknown} v */
    add(v) {
      const b = parseBody(v, "body");
      // a contact key names the other body by its index in a whole scene
      if (b.impulses.length) problem("body.impulses", "only a scene's bodies carry contact impulses (load the scene)");
      if (hasOwn(v, "island")) problem("body.island", "only a scene's bodies name an island (load the scene)");
      if (hasOwn(v, "awake") && check({ flag: null }, "body.awake", /** @type {Record<string, unknown>} */ (v).awake, noContext()) === false) b.awake = false;
      if (b.awake === false && b.static) problem("body.awake", "a static body does not sleep");
      const i = this.place(b);
      // a lone sleeping body is an island of its own
      if (b.awake === false || b.sleepTime) this.engine.setSleeping.apply(null, this.args([i, b.awake === false ? i : -1, b.sleepTime]));
      return i;
    }

    // Adds a parsed body (its impulses aside); returns its index or throws.
    /** @param {ParsedBody} b */
    place(b) {
      const E = this.engine;
      if (this.count() >= this.capacity) {
        const most = this.maxBodies();
        if (this.capacity >= most) throw new Error("the world is full (" + most + " bodies)");
        this.allocate(Math.min(most, this.capacity * 2), true);
      }
      // a saved body (axis and normal given) is restored as saved
      const axis = b.axis || [0, 0, 0], normal = b.normal || [0, 0, 0];
      const corners = cornersInto(b.shape, this.cornersIn);
      E.addBody.apply(null, /** @type {(Float64Array | number)[]} */ (this.arrays).concat([corners], shapeArgs(b.shape), [b.size, b.density, b.static ? 1 : 0,
        b.p[0], b.p[1], b.p[2], b.v[0], b.v[1], b.v[2], b.angle, b.omega, b.axis ? 1 : 0,
        axis[0], axis[1], axis[2], normal[0], normal[1], normal[2],
        b.friction === undefined ? -1 : b.friction, b.restitution === undefined ? -1 : b.restitution]));
      const i = this.meta("lastAdded");
      if (i === -2) throw new Error(E.frameMisfit);
      const a = this.a;
      // the engine refuses a point it cannot project; it lets through a few
      // where the gradient is NaN (on an axis, at a centre): a body whose
      // normal is not finite, or whose centre is not on the surface, is taken back
      const onSurface = i >= 0 && [0, 1, 2].every(function (k) { return isFinite(a.normal[3 * i + k]); }) &&
        Math.abs(this.space.field(a.pos[3 * i], a.pos[3 * i + 1], a.pos[3 * i + 2])) <= ON_SURFACE;
      if (i >= 0 && !onSurface) E.removeBody.apply(null, this.args([i]));
      if (!onSurface) {
        throw new Error("the body at p = " + JSON.stringify(b.p) + " does not project onto the surface of " + this.name +
          " (the field's gradient vanishes or is undefined there)");
      }
      const colour = b.static ? STATIC_COLOUR : PALETTE[this.added % PALETTE.length];
      this.added++;
      this.info[i] = { shape: copyShape(b.shape), size: b.size, density: b.density, static: b.static, colour: colour };
      this.version++;
      return i;
    }

    // Removes body i (the last body takes its index, as the engine does).
    /** @param {number} i */
    remove(i) {
      const n = this.count();
      if (!(Number.isInteger(i) && i >= 0 && i < n)) throw new RangeError("no body " + i + " (there are " + n + ")");
      this.engine.removeBody.apply(null, this.args([i]));
      this.info[i] = this.info[n - 1];
      this.info.length = n - 1;
      if (this.grabbed === i) this.release();
      else if (this.grabbed === n - 1) this.grabbed = i;
      this.version++;
    }

    // Removes every body (a fresh world with the same parameters), with room
    // for `capacity` bodies (default: as many as now).
    /** @param {number} [capacity] */
    clear(capacity) {
      const params = Float64Array.from(this.a.params);
      this.allocate(capacity || this.capacity, false);
      this.a.params.set(params);
      this.info = [];
      this.added = 0;
      this.grabbed = -1;
      this.target = null;
      this.version++;
    }

    // n physics steps; returns the time they took in ms.
    /** @param {number} n */
    step(n) {
      if (n <= 0) return 0;
      const E = this.engine, args = this.arrays;
      const t0 = performance.now();
      for (let k = 0; k < n; k++) E.step.apply(null, args);
      const ms = performance.now() - t0;
      const per = ms / n;
      this.stepMs = this.stepMs === null ? per : this.stepMs + (per - this.stepMs) * Math.min(1, n / 20);
      this.steps += n;
      this.version++;
      return ms;
    }

    // The body whose polygon holds surface point q: { index, sign } or null.
    /** @param {Manifold.Vec3} q @returns {{ index: number, sign: number } | null} */
    pick(q) {
      this.engine.pickBody.apply(null, this.args([q[0], q[1], q[2]]));
      const i = this.meta("picked");
      return i >= 0 ? { index: i, sign: this.meta("pickedSign") } : null;
    }

    // Holds body i at surface point q (picked through its image when sign = -1).
    /**
     * @param {number} i @param {number} sign @param {Manifold.Vec3} q
     * @param {{ frequency?: number, damping?: number, maxForce?: number }} [options]
     */
    grab(i, sign, q, options) {
      const o = options || {};
      const invMass = this.a.scalars[i * this.stride() + this.engine.slots.invMass];
      const maxForce = o.maxForce !== undefined ? o.maxForce : invMass > 0 ? 1000 / invMass : 1000;
      this.engine.grab.apply(null, this.args([i, sign, q[0], q[1], q[2],
        o.frequency || 5, o.damping !== undefined ? o.damping : 0.7, maxForce]));
      this.grabbed = i;
      this.target = /** @type {Manifold.Vec3} */ (q.slice());
      this.version++;
    }

    /** @param {Manifold.Vec3} q */
    drag(q) {
      if (this.grabbed < 0) return;
      this.engine.drag.apply(null, this.args([q[0], q[1], q[2]]));
      this.target = /** @type {Manifold.Vec3} */ (q.slice());
      this.version++;
    }

    release() {
      this.engine.release.apply(null, this.arrays);
      this.grabbed = -1;
      this.target = null;
      this.version++;
    }

    stride() { return Object.keys(this.engine.slots).length; }

    // The bodies in the scene format: each with the axis it has carried along
    // and its normal (its angle measured from that axis), which loading
    // restores bit for bit (Manifold.Scene), and what each remembers of the
    // last step's contacts.
    /** @returns {Manifold.Body[]} */
    bodies() {
      const a = this.a, E = this.engine, S = E.slots, k = this.stride(), out = [];
      /** @param {Float64Array} arr @param {number} i @returns {Manifold.Vec3} */
      const v3 = function (arr, i) { return [arr[3 * i], arr[3 * i + 1], arr[3 * i + 2]]; };
      for (let i = 0; i < this.count(); i++) {
        const info = this.info[i];
        // (in the scene's key order: the body's own material, where it has one, after its density)
        /** @type {Manifold.Body} */
        const b = Object.assign({
          shape: copyShape(info.shape),
          size: info.size,
          density: info.density,
        }, this.material(i), {
          static: info.static,
          p: v3(a.pos, i),
          v: v3(a.vel, i),
          angle: a.scalars[i * k + S.angle],
          omega: a.scalars[i * k + S.omega],
          axis: v3(a.axis, i),
          normal: v3(a.normal, i),
        });
        // (a box's or a capsule's size is its numbers': a scene does not give it)
        if (sizedByShape(info.shape)) delete b.size;
        const remembered = this.impulses(i);
        if (remembered.length) b.impulses = remembered;
        if (a.scalars[i * k + S.asleep] > 0) {
          b.awake = false;
          b.island = a.scalars[i * k + S.island];
        }
        const timer = a.scalars[i * k + S.sleepTimer];
        if (timer !== 0) b.sleepTime = timer;
        out.push(b);
      }
      return out;
    }

    // Body i's own friction and restitution, those it has ({} when it takes the scene's).
    /** @param {number} i @returns {{ friction?: number, restitution?: number }} */
    material(i) {
      const a = this.a, S = this.engine.slots, k = this.stride();
      /** @type {{ friction?: number, restitution?: number }} */
      const m = {};
      const mu = a.scalars[i * k + S.bodyFriction], e = a.scalars[i * k + S.bodyRestitution];
      if (mu >= 0) m.friction = mu;
      if (e >= 0) m.restitution = e;
      return m;
    }

    // What body i remembers of the last step's contact rows it owns, for
    // warm starting: [key, normal, friction], and for a row the next step
    // may keep its kept numbers after them (rows with no impulse that are
    // not kept left out).
    /** @param {number} i @returns {Manifold.Impulse[]} */
    impulses(i) {
      const E = this.engine, P = E.prev, prev = this.a.prev, out = /** @type {Manifold.Impulse[]} */ ([]);
      const start = this.a.bodyPrev[2 * i], count = this.a.bodyPrev[2 * i + 1];
      for (let r = start; r < start + count; r++) {
        const o = E.prevStride * r, kept = prev[o + P.prevKept] > 0;
        if (prev[o + P.prevNormal] !== 0 || prev[o + P.prevFriction] !== 0 || kept) {
          /** @type {Manifold.Impulse} */
          const row = [prev[o + P.prevKey], prev[o + P.prevNormal], prev[o + P.prevFriction]];
          if (kept) keptFields().forEach(function (f) { row.push(prev[o + P[f]]); });
          out.push(row);
        }
      }
      return out;
    }

    // Replaces what the bodies remember of the last step's contacts (one
    // list of impulses per body, in order; see impulses).
    /** @param {Manifold.Impulse[][]} perBody */
    restoreImpulses(perBody) {
      const E = this.engine, P = E.prev, a = this.a;
      const total = perBody.reduce(function (t, rows) { return t + rows.length; }, 0);
      if (total * E.prevStride > a.prev.length) throw new Error(total + " remembered contact rows, more than the world's " + a.prev.length / E.prevStride);
      let slot = 0;
      for (let i = 0; i < this.count(); i++) {
        const rows = perBody[i] || [];
        a.bodyPrev[2 * i] = slot;
        a.bodyPrev[2 * i + 1] = rows.length;
        rows.forEach(function (r) {
          const o = E.prevStride * slot++;
          a.prev[o + P.prevOwner] = i;
          a.prev[o + P.prevKey] = r[0];
          a.prev[o + P.prevNormal] = r[1];
          a.prev[o + P.prevFriction] = r[2];
          a.prev[o + P.prevKept] = r.length > 3 ? 1 : 0;
          keptFields().forEach(function (f, m) { if (r.length > 3) a.prev[o + P[f]] = r[3 + m]; });
        });
      }
    }

    // Adds a parsed joint (see parseJoint); returns its index, or throws
    // naming `path` (the joint is then not added).
    /** @param {ManifoldWeb.ParsedJoint} j @param {string} [path] */
    placeJoint(j, path) {
      const E = this.engine, a = this.a;
      path = path || "joint";
      if (!E.addJoint) throw new Error("this engine has no joints: rebuild web/gen with `manifold build`");
      const refused = jointsRefused(this.name);
      if (refused !== null) throw new SceneError(path + ": " + refused);
      if (this.jointCount() >= 2 * this.capacity) {
        const most = this.maxBodies();
        if (this.capacity >= most) throw new SceneError(path + ": " + E.jointProblems["-1"]);
        this.allocate(Math.min(most, this.capacity * 2), true);
      }
      E.addJoint.apply(null, this.args([E.jointKinds.indexOf(j.type), j.a, j.b,
        j.anchorA[0], j.anchorA[1], j.anchorA[2], j.anchorB[0], j.anchorB[1], j.anchorB[2]]));
      const i = this.meta("lastJoint");
      const anchorKey = j.type === "distance" ? ".anchorA" : ".anchor";
      if (i < 0) throw new SceneError(path + anchorKey + ": " + E.jointProblems[String(i)]);
      const J = E.joint, o = E.jointStride * i;
      /** @param {Manifold.JointField} k @param {number} x */
      const set = function (k, x) { a.joints[o + J[k]] = x; };
      if (j.local) JOINT_LOCAL.forEach(function (k, m) { set(k, /** @type {number[]} */ (j.local)[m]); });
      if (j.type === "distance") {
        const len = j.length === null ? a.joints[o + J.length] : j.length;
        const lo = j.minLength === null ? len : j.minLength, hi = j.maxLength === null ? len : j.maxLength;
        if (lo > len || len > hi) {
          E.removeJoint.apply(null, this.args([i]));
          throw new SceneError(path + (lo > len ? ".minLength: must not be more than" : ".maxLength: must not be less than") + " the length (the anchors' distance)");
        }
        set("length", len);
        set("minLength", lo);
        set("maxLength", hi);
      }
      set("hertz", j.hertz);
      set("collide", j.collide ? 1 : 0);
      set("damping", j.dampingRatio);
      if (j.referenceAngle !== null) set("reference", j.referenceAngle);
      if (j.limit) { set("limitOn", 1); set("lower", j.limit[0]); set("upper", j.limit[1]); }
      if (j.motor) { set("motorOn", 1); set("motorSpeed", j.motor[0]); set("maxTorque", j.motor[1]); }
      j.impulses.forEach(function (x, m) { set(JOINT_IMPULSES[m], x); });
      this.version++;
      return i;
    }

    // Adds a joint from a scene joint (JSON value) between the world's
    // bodies; returns its index or throws.
    /** @param {unknown} v */
    addJoint(v) { return this.placeJoint(parseJoint(v, "joint", this.count()), "joint"); }

    // Removes joint i (the last joint takes its index).
    /** @param {number} i */
    removeJoint(i) {
      const n = this.jointCount();
      if (!(Number.isInteger(i) && i >= 0 && i < n)) throw new RangeError("no joint " + i + " (there are " + n + ")");
      this.engine.removeJoint.apply(null, this.args([i]));
      this.version++;
    }

    jointCount() { return this.engine.addJoint ? this.meta("jointCount") : 0; }

    // Every joint as a scene holds it, its anchors in its bodies'
    // coordinates and its impulses (restored exactly by load).
    /** @returns {Manifold.SceneJoint[]} */
    jointsSaved() {
      const E = this.engine, a = this.a, J = E.joint, out = [];
      for (let i = 0; i < this.jointCount(); i++) {
        const o = E.jointStride * i;
        /** @param {Manifold.JointField} k */
        const get = function (k) { return a.joints[o + J[k]]; };
        /** @param {Manifold.JointField} k @returns {Manifold.Vec3} */
        const v3 = function (k) { return [a.joints[o + J[k]], a.joints[o + J[k] + 1], a.joints[o + J[k] + 2]]; };
        const type = E.jointKinds[get("kind")], b = get("b");
        /** @type {Record<string, unknown>} */
        const j = { type: type, a: get("a"), b: b < 0 ? "world" : b };
        if (type === "distance") {
          j.anchorA = v3("anchorAX");
          j.anchorB = b < 0 ? v3("worldX") : v3("anchorBX");
          j.length = get("length");
          j.minLength = get("minLength");
          j.maxLength = get("maxLength");
        } else {
          j.anchor = v3("anchorAX");
          j.referenceAngle = get("reference");
        }
        if (type !== "revolute" && get("hertz") !== 0) j.hertz = get("hertz");
        if (type !== "revolute" && get("damping") !== 0) j.dampingRatio = get("damping");
        if (get("limitOn") > 0) { j.lowerAngle = get("lower"); j.upperAngle = get("upper"); }
        if (get("motorOn") > 0) { j.motorSpeed = get("motorSpeed"); j.maxMotorTorque = get("maxTorque"); }
        if (get("collide") > 0) j.collide = true;
        j.local = JOINT_LOCAL.map(get);
        j.impulses = JOINT_IMPULSES.map(get);
        out.push(/** @type {Manifold.SceneJoint} */ (/** @type {unknown} */ (j)));
      }
      return out;
    }

    // Where every joint's two anchors are now: [ax, ay, az, bx, by, bz] a
    // joint (body b's at the image nearest body a's), for drawing.
    /** @returns {Float64Array} */
    jointAnchors() {
      const n = this.jointCount();
      if (!this.anchorsOut || this.anchorsOut.length < 6 * n) this.anchorsOut = new Float64Array(6 * Math.max(16, n));
      if (n) this.engine.jointAnchors.apply(null, /** @type {(Float64Array | number)[]} */ (this.arrays).concat([this.anchorsOut]));
      return this.anchorsOut;
    }

    // Every joint as curves on the surface, for drawing (the engine's
    // jointPaths): per joint, engine.jointPath.points points of three
    // numbers: body a's walk from its centre to its anchor, body b's, and
    // the chord between the anchors laid on the surface.
    /** @returns {Float64Array} */
    jointPaths() {
      const n = this.jointCount(), per = 3 * this.engine.jointPath.points;
      if (!this.pathsOut || this.pathsOut.length < per * n) this.pathsOut = new Float64Array(per * Math.max(16, n));
      if (n) this.engine.jointPaths.apply(null, /** @type {(Float64Array | number)[]} */ (this.arrays).concat([this.pathsOut]));
      return this.pathsOut;
    }

    // The world as a scene (JSON value).
    /** @returns {Manifold.SavedScene} */
    scene() {
      const scene = withParams({ space: this.name }, this.param.bind(this));
      scene.bodies = this.bodies();
      const joints = this.jointsSaved();
      if (joints.length) scene.joints = joints;
      // (the scene keys are the generated ones, Manifold.sceneKeys)
      return /** @type {Manifold.SavedScene} */ (/** @type {unknown} */ (scene));
    }

    // Replaces the world's bodies and parameters by a parsed scene (see parseScene),
    // the bodies remembering the contact impulses the scene gives them.
    // All or nothing: a body that cannot be added leaves the world as it was and throws.
    /** @param {ManifoldWeb.ParsedScene} scene */
    load(scene) {
      const n = scene.bodies.length, most = this.maxBodies();
      if (n > most) problem("$.bodies", n + " bodies, more than a world of " + this.name + " holds (" + most + ")");
      const saved = { arrays: this.arrays.map(function (x) { return x; }), capacity: this.capacity,
        info: this.info, added: this.added };
      // room for every body at once: no growing (and copying) on the way
      let capacity = FIRST_CAPACITY;
      while (capacity < n) capacity *= 2;
      this.clear(Math.min(most, capacity));
      this.setParams(sceneParams(scene));
      try {
        scene.bodies.forEach(/** @this {World} */ function (b, k) {
          try {
            // (a parsed box or capsule carries the size its numbers give it)
            const given = sizedByShape(b.shape) ? Object.assign({}, b) : b;
            if (given !== b) Reflect.deleteProperty(given, "size");
            this.place(parseBody(given, "body"));
          } catch (e) {
            throw new SceneError("$.bodies[" + k + "]" + ("axis" in b ? ".axis: " : ".p: ") + e.message);
          }
        }, this);
        const remembered = scene.bodies.map(function (b) { return b.impulses || []; });
        const total = remembered.reduce(function (t, rows) { return t + rows.length; }, 0);
        const room = this.engine.contactsPerBody * scene.bodies.length;
        if (total > room) {
          problem("$.bodies", total + " remembered contact impulses, more than " + scene.bodies.length +
            " bodies remember (" + this.engine.contactsPerBody + " a body)");
        }
        this.restoreImpulses(remembered);
        (scene.joints || []).forEach(/** @this {World} */ function (j, k) { this.placeJoint(j, "$.joints[" + k + "]"); }, this);
        // asleep after the joints are made: a joint made wakes its bodies
        const E = this.engine;
        scene.bodies.forEach(/** @this {World} */ function (b, k) {
          const label = b.awake === false ? /** @type {number} */ (b.island) : -1;
          E.setSleeping.apply(null, this.args([k, label, b.sleepTime || 0]));
        }, this);
      } catch (e) {
        this.adopt(saved.arrays, saved.capacity);
        this.info = saved.info;
        this.added = saved.added;
        this.version++;
        throw e;
      }
    }

    // The space's default scene (Manifold.spaces[NAME].scene) with the engine's
    // default parameters, cut or filled up to n bodies (seeded random points,
    // projected onto the surface by the engine, inside the boundary).
    /** @param {number} [n] */
    loadDefault(n) {
      const E = this.engine;
      const base = (this.space.scene || []).map(function (b) {
        return { shape: copyShape(b.shape), size: b.size, p: /** @type {Manifold.Vec3} */ (b.p.slice()) };
      });
      const want = n === undefined || n === null ? base.length : n;
      const bodies = base.slice(0, want);
      this.load(/** @type {ManifoldWeb.ParsedScene} */ (withParams({ space: this.name, bodies: bodies }, function (name) { return E.defaults[name]; })));
      if (bodies.length < want) this.fill(want, base);
    }

    // Adds bodies until there are n: shapes and sizes cycle through `base`
    // (the default scene), positions are seeded random points of the bounding
    // ball, projected by the engine; a body outside the boundary or on
    // another body is taken back. Gives up when FILL_GIVE_UP placements in a
    // row found no room, or when the world is full. Returns the count.
    /** @param {number} n @param {{ shape: Manifold.Shape, size: number }[]} base */
    fill(n, base) {
      const rnd = random(20170 + this.count());
      const bounds = this.space.bounds || 1;
      const boundary = this.space.boundary;
      /** @type {{ shape: Manifold.Shape, size: number }[]} */
      const defaults = [{ shape: "circle", size: 0.15 }, { shape: "square", size: 0.15 }];
      const templates = base.length ? base : defaults;
      const most = Math.min(n, this.maxBodies());
      let failed = 0;
      while (this.count() < most && failed < FILL_GIVE_UP) {
        failed++;
        const tmpl = templates[this.count() % templates.length];
        const p = /** @type {Manifold.Vec3} */ ([0, 1, 2].map(function () { return (2 * rnd() - 1) * bounds * 0.9; }));
        let i;
        try {
          i = this.add(Object.assign(bodyOfShape(tmpl.shape, tmpl.size), { p: p, angle: 2 * Math.PI * rnd() }));
        } catch (e) {
          continue;
        }
        /** @type {Manifold.Vec3} */
        const q = [this.a.pos[3 * i], this.a.pos[3 * i + 1], this.a.pos[3 * i + 2]];
        const free = (!boundary || boundary(q[0], q[1], q[2]) > reachOf(tmpl.shape, tmpl.size)) && !this.overlaps(i);
        if (free) {
          failed = 0;
        } else {
          this.added--;
          this.remove(i);
        }
      }
      return this.count();
    }

    // Whether body i's centre or an outline vertex lies in another body (by
    // the engine's pickBody).
    /** @param {number} i */
    overlaps(i) {
      const E = this.engine, vpb = E.verticesPerBody;
      for (let d = -1; d < E.directions; d++) {
        const o = 3 * (vpb * i + (d < 0 ? 0 : E.vertexIndex(d, E.steps)));
        const hit = this.pick([this.a.verts[o], this.a.verts[o + 1], this.a.verts[o + 2]]);
        if (hit && hit.index !== i) return true;
      }
      return false;
    }

    // Adds a body unless it would overlap another one; returns its index or -1.
    /** @param {Manifold.SceneBody} v */
    addFree(v) {
      const i = this.add(v);
      if (!this.overlaps(i)) return i;
      this.added--;
      this.remove(i);
      return -1;
    }

    // The hash of the world's state, 16 hex digits: FNV-1a (64 bits) over the
    // bit patterns, least significant byte first, of the rows the engine
    // lists in `hashed` (Manifold.StateHash; `manifold sim --hash` computes
    // the same; -0 counts as 0). The 64-bit product is taken in 32-bit
    // halves: the prime is 2^40 + 435.
    /** @returns {string} */
    hash() {
      const E = this.engine, bytes = new DataView(new ArrayBuffer(8)), TWO32 = 4294967296;
      let hi = 0xcbf29ce4, lo = 0x84222325;
      for (const [name, rows, stride] of E.hashed) {
        const arr = this.a[name], n = this.meta(rows) * stride;
        for (let i = 0; i < n; i++) {
          bytes.setFloat64(0, arr[i] === 0 ? 0 : arr[i], true);
          for (let b = 0; b < 8; b++) {
            lo = (lo ^ bytes.getUint8(b)) >>> 0;
            const low = lo * 435;
            hi = (hi * 435 + Math.floor(low / TWO32) + ((lo << 8) >>> 0)) % TWO32;
            lo = low % TWO32;
          }
        }
      }
      return (hi.toString(16).padStart(8, "0") + lo.toString(16).padStart(8, "0"));
    }

    // The bodies' kinetic energy and their centres' angular momentum about
    // the space's axis (0 without one), by the engine's measure.
    /** @returns {{ kineticEnergy: number, axialMomentum: number }} */
    measures() {
      const E = this.engine, out = this.measureOut();
      E.measure.apply(null, /** @type {Float64Array[]} */ (this.arrays).concat([out]));
      return { kineticEnergy: out[E.measures.slots.kineticEnergy], axialMomentum: out[E.measures.slots.axialMomentum] };
    }

    // Body i's speed, kinetic energy and the last step's contact rows it is in, by the engine's measureBody.
    /** @param {number} i @returns {{ speed: number, energy: number, contacts: number }} */
    measureBody(i) {
      const E = this.engine, out = this.measureOut(), S = E.measures.slots;
      E.measureBody.apply(null, /** @type {(Float64Array | number)[]} */ (this.arrays).concat([out, i]));
      return { speed: out[S.bodySpeed], energy: out[S.bodyEnergy], contacts: out[S.bodyContacts] };
    }

    // the measures' out array (made once)
    measureOut() {
      if (!this.measured) this.measured = new Float64Array(this.engine.measures.size);
      return this.measured;
    }

    // Contacts, warnings, dropped contacts: the engine's counters (of the
    // snapshot drawn when a worker steps the world: they never wait for it).
    counters() {
      const E = this.engine;
      // (within a task that holds the lock, the world's own: the snapshot has not its changes yet)
      const live = !this.shared || this.holding;
      if (live) E.countIslands.apply(null, this.args([]));
      const m = live ? this.live.meta : this.view().meta;
      /** @param {Manifold.MetaName} k */
      const meta = function (k) { return m[E.meta[k]]; };
      return {
        bodies: meta("bodyCount"),
        awake: meta("awakeCount"),
        islands: meta("islandCount"),
        joints: E.addJoint ? meta("jointCount") : 0,
        contacts: meta("contactCount"),
        warnings: meta("warnings"),
        droppedContacts: meta("droppedContacts"),
      };
    }
  }

  // ---- the stepping loop: fixed dt, scaled real time, a bounded amount of physics per frame ----
  class Clock {
    constructor() {
      this.paused = false;
      this.timeScale = 1;
      this.maxStepsPerFrame = 10;  // at most this many steps per frame …
      this.maxMsPerFrame = 30;     // … and about this much physics time; beyond, the simulation runs slower than real time
      this.accumulator = 0;
      /** @type {number | null} */
      this.last = null;
    }

    // The steps due at time `now` (ms) for a world with step dt (s) whose
    // steps take about stepMs (ms; null: not known yet).
    /** @param {number} now @param {number} dt @param {number | null} stepMs */
    due(now, dt, stepMs) {
      const last = this.last;
      this.last = now;
      if (this.paused || last === null || !(dt > 0)) return 0;
      this.accumulator += Math.min(0.25, (now - last) / 1000) * this.timeScale;
      const cap = Math.max(1, Math.min(this.maxStepsPerFrame,
        stepMs > 0 ? Math.floor(this.maxMsPerFrame / stepMs) : this.maxStepsPerFrame));
      let n = Math.floor(this.accumulator / dt + 1e-9);
      if (n > cap) {
        n = cap;
        this.accumulator = 0;
      } else {
        this.accumulator -= n * dt;
      }
      return n;
    }

    reset() {
      this.accumulator = 0;
      this.last = null;
    }
  }

  const exported = {
    BODY_DEFAULTS: BODY_DEFAULTS,
    SHARED: SHARED,
    CLOCK: CLOCK,
    copyView: copyView,
    World: World,
    Clock: Clock,
    SceneError: SceneError,
    parseScene: parseScene,
    jointsRefused: jointsRefused,
    parseBody: parseBody,
    parseJoint: parseJoint,
    keyProblem: keyProblem,
    shape: shape,
    copyShape: copyShape,
    sizedByShape: sizedByShape,
    bodyOfShape: bodyOfShape,
    reachOf: reachOf,
    PALETTE: PALETTE,
    STATIC_COLOUR: STATIC_COLOUR,
  };
  W.ManifoldWeb = W.ManifoldWeb || /** @type {ManifoldWebModules} */ ({});
  W.ManifoldWeb.world = exported;
  return exported;
})(globalThis);
