// Types of what the page offers to scripts: the scripting API (window.manifold,
// web/README.md lists its calls) and what the generated scripts define
// (window.Manifold: web/gen/spaces.js, the catalogue and the scene keys; each
// web/gen/space-NAME.js, a space with its GLSL and its physics engine;
// web/gen/compare-torus.js, the comparison's chart and scenes), all written by
// `manifold build` from the Haskell library. A script that drives the page
// (a test, a notebook, the browser's console with a checker) can use it with
// `/// <reference path="web/manifold.d.ts" />`. The page's own scripts
// (web/js) are type-checked against it (tsconfig.json): what they read of
// the generated objects and what window.manifold returns.

declare namespace Manifold {
  /** A point or vector of R³: [x, y, z]. */
  type Vec3 = [number, number, number];
  /** Display-space RGB, each 0..1. */
  type Rgb = [number, number, number];

  // ---- scenes (the JSON of `manifold sim`, docs/scenes.md) ----

  /** A body's shape: a circle, a square, a regular polygon of 3 to 64 sides, a box of two half-extents (along the body's direction, across it), or a capsule (half its segment's length, its radius). */
  /** A convex polygon: 3 to 8 corners [a, b] in the body's frame going round it (either way; the body's centre is its centre of mass), rounded by radius (default 0). */
  type Vertices = { vertices: [number, number][]; radius?: number };
  type Shape = "circle" | "square" | { polygon: number } | { box: [number, number] } | { capsule: [number, number] } | Vertices;
  /** A contact row a body remembers: [contact key, normal, friction] for warm starting, followed for a row the next step may keep by its kept numbers (Manifold.keptFields). */
  type Impulse = [number, number, number, ...number[]];
  /** A body as a scene gives it: shape, size and p are required, the rest has defaults. */
  interface SceneBody {
    shape: Shape;
    /** > 0; not given with a box, a capsule or vertices (their numbers are their size) */
    size?: number;
    /** projected onto the surface by the engine */
    p: Vec3;
    density?: number;
    /** the body's own friction coefficient and restitution (the scene key's values); without them, the scene's */
    friction?: number;
    restitution?: number;
    static?: boolean;
    v?: Vec3;
    angle?: number;
    omega?: number;
    /** a saved body's frame, both or neither: the body is restored exactly as saved (see docs/scenes.md) */
    axis?: Vec3;
    normal?: Vec3;
    impulses?: Impulse[];
    /** false: the body sleeps (docs/scenes.md#sleeping), in the island named by a sleeping body's index (default its own) */
    awake?: boolean;
    island?: number;
    /** how long the body has moved slower than the sleep threshold (s) */
    sleepTime?: number;
  }
  /** A joint's type (docs/scenes.md#joints). */
  type JointType = "revolute" | "distance" | "weld";
  /**
   * A joint as a scene gives it: between bodies a and b (by index) or a body
   * and "world"; a revolute or weld joint has one anchor, a distance joint
   * two; the other keys are its type's (docs/scenes.md#joints).
   */
  interface SceneJoint {
    type: JointType;
    a: number;
    b: number | "world";
    anchor?: Vec3;
    anchorA?: Vec3;
    anchorB?: Vec3;
    length?: number;
    minLength?: number;
    maxLength?: number;
    hertz?: number;
    dampingRatio?: number;
    referenceAngle?: number;
    lowerAngle?: number;
    upperAngle?: number;
    motorSpeed?: number;
    maxMotorTorque?: number;
    /** whether the joined bodies collide (default false) */
    collide?: boolean;
    /** a saved joint's anchors in its bodies' coordinates: [rA, thetaA, rB, thetaB, worldX, worldY, worldZ] */
    local?: number[];
    /** a saved joint's seven impulses */
    impulses?: number[];
  }
  /** A body as the page gives it back (bodies(), scene()): every key. */
  interface Body {
    shape: Shape;
    /** absent for a box or a capsule (their numbers are their size) */
    size?: number;
    density: number;
    /** present when the body has its own friction or restitution */
    friction?: number;
    restitution?: number;
    static: boolean;
    p: Vec3;
    v: Vec3;
    /** from the axis the body has carried along */
    angle: number;
    omega: number;
    /** the axis the body has carried along (a unit tangent) and the surface's normal at p */
    axis: Vec3;
    normal: Vec3;
    /** present when the body remembers contact impulses */
    impulses?: Impulse[];
    /** present (false) when the body sleeps, with its island (a sleeping body's index) */
    awake?: boolean;
    island?: number;
    /** present when the body's sleep timer runs (s) */
    sleepTime?: number;
  }
  /**
   * A scene as loadScene reads it. The keys between space and bodies are the
   * scene keys of the engine's parameters (Manifold.sceneKeys, from
   * Lib/Manifold/Params.hs); left out, they take the engine's defaults.
   */
  interface Scene {
    space: string;
    dt?: number;
    gravity?: boolean;
    substeps?: number;
    iterations?: number;
    friction?: number;
    restitution?: number;
    contactHertz?: number;
    dampingRatio?: number;
    pushout?: number;
    slop?: number;
    jointHertz?: number;
    jointDampingRatio?: number;
    sleep?: boolean;
    sleepSpeed?: number;
    sleepTime?: number;
    keepContacts?: boolean;
    bodies?: SceneBody[];
    joints?: SceneJoint[];
    /** the view the scene opens with (up and fov default to the space's camera's); the page's Save scene writes the view it shows */
    camera?: SceneCamera;
  }
  /** A scene's camera: eye and target in world coordinates; up and fov (degrees) as the space's camera's where left out. */
  interface SceneCamera {
    eye: Vec3;
    target: Vec3;
    up?: Vec3;
    fov?: number;
  }
  /** A scene as the page saves it (scene(), Save scene): every key. */
  interface SavedScene {
    space: string;
    dt: number;
    gravity: boolean;
    substeps: number;
    iterations: number;
    friction: number;
    restitution: number;
    contactHertz: number;
    dampingRatio: number;
    pushout: number;
    slop: number;
    jointHertz: number;
    jointDampingRatio: number;
    sleep: boolean;
    sleepSpeed: number;
    sleepTime: number;
    keepContacts: boolean;
    bodies: Body[];
    joints?: SceneJoint[];
  }

  // ---- the generated catalogue (web/gen/spaces.js) ----

  /** A scene key that sets an engine parameter, with the values it takes (Lib/Manifold/Params.hs). */
  interface SceneKey {
    /** the key in a scene */
    key: string;
    /** the engine parameter it sets (a name of Engine.params) */
    param: ParamName;
    default: number | boolean;
    /** a key whose default follows the scene's step: the default is this over the scene's dt */
    perStep?: number;
    /** "switch": true or false (the parameter is 1 or 0); the values a number takes are the scene format's (sceneFormat) */
    kind: "number" | "switch";
    /** the page's control for the key, when it offers one (in sceneKeys' order) */
    control?: SceneControl;
  }
  /**
   * How the page offers a scene key (Lib/Manifold/Params.hs, Control): a
   * checkbox for a switch, a slider from lo to hi by step for a number. The
   * slider's extent is only the slider's: setSimulation and a scene take
   * what the key's range takes.
   */
  interface SceneControl {
    label: string;
    /** the control's tooltip */
    help: string;
    lo?: number;
    hi?: number;
    step?: number;
  }
  /** How a space is a quotient of its surface: its images are Space.images. */
  type Quotient = "none" | "antipodal" | "translations" | "glide" | "octagon";
  /** The ambient metric a space's surface sits in: R³'s, or Minkowski space's x² − y² + z² (the hyperbolic plane's hyperboloid). */
  type Metric = "euclidean" | "minkowski";
  /** A space as the catalogue lists it (the page loads its script when it is chosen). */
  interface SpaceEntry {
    name: string;
    description: string;
    quotient: Quotient;
    metric: Metric;
    hasBoundary: boolean;
    /** the space's camera's up: a scene's camera that gives no up has it */
    up: Vec3;
    /** the space's script in web/gen */
    script: string;
  }
  /** A bound of a number in the scene format: the limit, whether the limit itself is out, the message past it. */
  interface Bound {
    at: number;
    strict: boolean;
    message: string;
  }
  /** What a number of the scene format must be besides finite (Manifold.SceneFormat.Bounds). */
  interface Bounds {
    lowest: Bound | null;
    highest: Bound | null;
    /** a whole number, or this message */
    whole: string | null;
  }
  /** What a JSON value of a scene must be (Manifold.SceneFormat.Format): one key, the kind of value. */
  type Format =
    | { number: Bounds }
    | { flag: null }
    | { row: { items: Format[]; rest: Format; lengths: number[]; message: string } }
    | { list: { item: Format; least: number; most: number | null; message: string } }
    | { record: { keys: string[]; entries: FormatEntry[] } }
    | { oneOf: { names: string[]; keyed: [string, Format][]; companions: [string, string, Format][]; notOne: string; unknown: string; oneKey: string; companion: string } }
    | { tagged: { key: string; kinds: Record<string, Format>; notOne: string; unknown: string } }
    | { name: { kind: string; notString: string; unknown: string } }
    | { index: { list: string; message: string; or: string | null } }
    | { convex: { corners: Format; message: string } };
  /** How a record's key may be left out. */
  type Presence = { required: true } | { optional: true } | { default: unknown } | { perStep: number; of: string };
  /** A step of reading a record of the scene format. */
  type FormatEntry =
    | { field: string; presence: Presence; format: Format }
    | { when: string; has: string[]; then: FormatEntry[]; else: FormatEntry[] }
    | { rule: FormatRule };
  /** What a record's keys must satisfy together (Manifold.SceneFormat.Rule). */
  type FormatRule =
    | { together: [string, string, string] }
    | { ordered: [string, string]; atSecond: boolean }
    | { differ: [string, string, string] }
    | { notGiven: [string, string] }
    | { islands: [string, string, string] }
    | { remembered: string; perBody: number }
    | { refusedBy: [string, string] }
    | { atMostTwice: [string, string, string] }
    | { view: [string, string, string, string, string] };
  /** A camera: eye, target and up in world coordinates, fov the vertical field of view in degrees. */
  interface CameraSpec {
    eye: Vec3;
    target: Vec3;
    up: Vec3;
    fov: number;
  }

  // ---- a space (web/gen/space-NAME.js) ----

  /** A function of a point of R³ (the arguments are x, y, z). */
  type ScalarField = (x: number, y: number, z: number) => number;
  type VectorField = (x: number, y: number, z: number) => Vec3;
  /** One of a quotient's images of a point: p ↦ L p + t, as L row by row then t (twelve numbers). */
  type Image = number[];
  /** A point brought into a quotient's fundamental domain: the map that does it (nine numbers, row by row), then the point. */
  type Wrap = (x: number, y: number, z: number) => number[];
  interface Space {
    name: string;
    description: string;
    /** the surface is field = 0 */
    field: ScalarField;
    gradient: VectorField;
    /** the part of the surface that is the space is boundary ≥ 0; null: all of it */
    boundary: ScalarField | null;
    gravity: VectorField;
    /** Gaussian curvature at a surface point */
    curvature: ScalarField;
    quotient: Quotient;
    metric: Metric;
    /** the images a body is also drawn at (none for quotient "none") */
    images: Image[];
    /** a contact row's key: (other body + 1) · keysPerBody + group · perGroup + point */
    keysPerBody: number;
    /** consecutive points of a curve further apart than this were wrapped into the fundamental domain between them (null: nothing is wrapped) */
    wrapJump: number | null;
    /** a point brought into the fundamental domain (null: the quotient has no wrap) */
    wrapIntoDomain: Wrap | null;
    /** the radius of the ball about the origin that holds the surface's view */
    bounds: number;
    /** the axis the space is symmetric about (the measures' axial momentum is about it), or null */
    axis: Vec3 | null;
    camera: CameraSpec;
    /** the default scene's bodies */
    scene: { shape: Shape; size: number; p: Vec3 }[];
    engine: Engine;
    /** field, gradient, boundary, curvature (and helpers) as GLSL, for the sphere tracer */
    glsl: string;
  }

  // ---- a space's physics engine (Lib/Manifold/Stage/EngineScript.hs) ----

  /** The engine's arrays, in the order every procedure takes them. */
  type ArrayName =
    | "meta" | "params" | "pos" | "vel" | "axis" | "normal" | "scalars" | "radii" | "verts" | "outline"
    | "grid" | "cellOf" | "items" | "contacts" | "prev" | "bodyPrev" | "mouse" | "probe" | "near" | "walk"
    | "joints" | "flip" | "partners" | "islands" | "seenParams" | "hull";
  /** The world's counters and results, slots of the array meta. */
  type MetaName =
    | "bodyCount" | "warnings" | "contactCount" | "capacity" | "gridBuckets" | "cellSize" | "droppedContacts"
    | "lastAdded" | "picked" | "pickedSign" | "jointCount" | "lastJoint" | "awakeCount" | "islandCount" | "wakeRequest" | "largeCount" | "keptRows";
  /** The engine's parameters, slots of the array params (Lib/Manifold/Params.hs). */
  type ParamName =
    | "dt" | "gravityOn" | "substeps" | "iterations" | "friction" | "restitution" | "contactHertz" | "dampingRatio"
    | "pushout" | "slop" | "speculative" | "bounceThreshold" | "warmStart" | "polygonStep" | "jointHertz" | "jointDampingRatio"
    | "sleep" | "sleepSpeed" | "sleepTime" | "keepContacts";
  /** A body's scalars, each body's `slots` consecutive entries of the array scalars. */
  type SlotName =
    | "angle" | "omega" | "invMass" | "invInertia" | "size" | "boundRadius" | "turnCos" | "turnSin"
    | "movedX" | "movedY" | "movedZ" | "turned" | "asleep" | "sleepTimer" | "island" | "bodyFriction" | "bodyRestitution" | "corners";
  type ContactField =
    | "cA" | "cB" | "cOwner" | "cKey" | "jaX" | "jaY" | "jaZ" | "jaW" | "jbX" | "jbY" | "jbZ" | "jbW"
    | "taX" | "taY" | "taZ" | "taW" | "tbX" | "tbY" | "tbZ" | "tbW" | "cDepth" | "normalMass" | "tangentMass"
    | "impulseN" | "impulseT" | "cSelfScale" | "pointX" | "pointY" | "pointZ"
    | "cPenetration" | "cBiasRate" | "cMassScale" | "cImpulseScale" | "cApproach" | "cTotalImpulse"
    | "cFriction" | "cRestitution" | "cKept" | "cDriftX" | "cDriftY" | "cDriftZ" | "cTurnA" | "cTurnB";
  type PrevField =
    | "prevOwner" | "prevKey" | "prevNormal" | "prevFriction" | "prevKept" | "prevA" | "prevB" | "prevDepth"
    | "prevDriftX" | "prevDriftY" | "prevDriftZ" | "prevTurnA" | "prevTurnB"
    | "prevPointX" | "prevPointY" | "prevPointZ"
    | "prevJaX" | "prevJaY" | "prevJaZ" | "prevJaW" | "prevJbX" | "prevJbY" | "prevJbZ" | "prevJbW"
    | "prevTaX" | "prevTaY" | "prevTaZ" | "prevTaW" | "prevTbX" | "prevTbY" | "prevTbZ" | "prevTbW";
  type MouseField =
    | "mActive" | "mBody" | "mLocalR" | "mLocalTheta" | "mTargetX" | "mTargetY" | "mTargetZ"
    | "mFrequency" | "mDamping" | "mMaxForce" | "mImpulseU" | "mImpulseW" | "mSign";
  /** A joint's fields, `jointStride` consecutive entries of the array joints (Lib/Manifold/World.hs, JointField). */
  type JointField =
    | "kind" | "a" | "b" | "radiusA" | "thetaA" | "radiusB" | "thetaB" | "worldX" | "worldY" | "worldZ"
    | "length" | "minLength" | "maxLength" | "hertz" | "damping" | "reference" | "limitOn" | "lower" | "upper"
    | "motorOn" | "motorSpeed" | "maxTorque" | "impulse1" | "impulse2" | "impulseAxial" | "impulseLower"
    | "impulseUpper" | "impulseMotor" | "impulseAngle" | "anchorAX" | "anchorAY" | "anchorAZ" | "anchorBX"
    | "anchorBY" | "anchorBZ"
    | "slideUAX" | "slideUAY" | "slideUAZ" | "slideWAX" | "slideWAY" | "slideWAZ" | "turnAX" | "turnAY" | "turnAZ"
    | "slideUBX" | "slideUBY" | "slideUBZ" | "slideWBX" | "slideWBY" | "slideWBZ" | "turnBX" | "turnBY" | "turnBZ"
    | "uBX" | "uBY" | "uBZ" | "wBX" | "wBY" | "wBZ"
    | "signX" | "signY" | "signZ" | "e1X" | "e1Y" | "e1Z" | "e2X" | "e2Y" | "e2Z" | "chord" | "sigma"
    | "angleError" | "angularMass" | "collide";
  /** What the engine's measure (the world) and measureBody (one body) write, slots of their out array. */
  type MeasureField = "kineticEnergy" | "axialMomentum" | "bodySpeed" | "bodyEnergy" | "bodyContacts";
  /** A point of a walked geodesic, `path.stride` consecutive entries after the count in path[0]. */
  type PathField = "pathX" | "pathY" | "pathZ" | "pathBreak";
  type ContactGroup = "pairKey" | "unused" | "boundaryKey" | "selfKey" | "firstImageKey";
  /**
   * A generated procedure: it takes the engine's arrays (Engine.arrays, in
   * that order), then its own numbers, and works in the arrays.
   */
  type Procedure = (...arraysThenArguments: (Float64Array | number)[]) => void;
  interface Engine {
    arrays: ArrayName[];
    /** an array's length for a capacity of n bodies: fixed + perBody · n, as [fixed, perBody] */
    sizes: Record<ArrayName, [number, number]>;
    /** a body's polygon: the centre, then `steps` geodesic steps along each of `directions` directions */
    directions: number;
    steps: number;
    /** the most bodies a world holds (its arrays grow to this by doubling) */
    maxBodies: number;
    verticesPerBody: number;
    contactStride: number;
    contactsPerBody: number;
    meta: Record<MetaName, number>;
    params: Record<ParamName, number>;
    slots: Record<SlotName, number>;
    contact: Record<ContactField, number>;
    prev: Record<PrevField, number>;
    prevStride: number;
    /** a contact row's key: (other body + 1) · the space's keysPerBody + group · perGroup + point */
    keys: { perGroup: number; groups: Record<ContactGroup, number> };
    /** where step k (1 … steps) along direction d sits among a body's vertices (0 is the centre) */
    vertexIndex: (d: number, k: number) => number;
    mouse: Record<MouseField, number>;
    /**
     * a body's hull among its `stride` numbers of the hull array: the radius
     * rounding it, corner k's (a, b) in the body's frame at local + 2k, and
     * walked onto the surface, (x, y, z) at world + 3k (slots.corners counts them)
     */
    hull: { stride: number; radius: number; local: number; world: number };
    /** a joint's fields and their number */
    joint: Record<JointField, number>;
    jointStride: number;
    /** the joint types by their kind code (the field kind) */
    jointKinds: JointType[];
    /** why addJoint refused a joint, by meta lastJoint ("-1", "-2", "-3") */
    jointProblems: Record<string, string>;
    /** (arrays, kind, a, b (-1: the world), ax, ay, az, bx, by, bz): meta lastJoint, or -1, -2, -3 (jointProblems) */
    addJoint: Procedure;
    /** (arrays, index): the last joint takes the index */
    removeJoint: Procedure;
    /** (arrays, out): every joint's two anchors now, six numbers a joint */
    jointAnchors: Procedure;
    /** (arrays, out): every joint as curves on the surface, jointPath.points points of three numbers a joint: body a's walk to its anchor, body b's, the chord between the anchors */
    jointPaths: Procedure;
    /** how many points jointPaths gives each part of a joint, and all of it */
    jointPath: { walk: number; chord: number; points: number };
    /** (arrays): meta awakeCount and islandCount, counted now */
    countIslands: Procedure;
    /** (arrays, index, island (-1: awake), timer): a body's sleep state as a scene restores it */
    setSleeping: Procedure;
    /** the state's hash: FNV-1a over these arrays' first (meta counter × numbers a row) numbers, in order */
    hashed: [ArrayName, MetaName, number][];
    /** why a restored body was refused (addBody's -2) */
    frameMisfit: string;
    defaults: Record<ParamName, number>;
    /** the step's phases in order, for the benchmarks and profiles */
    phases: [string, Procedure][];
    /** what the phases call, each printed once */
    subroutines: [string, Procedure][];
    /** one step of the world */
    step: Procedure;
    /** the bodies' polygons again, from their positions and axes */
    polygonise: Procedure;
    /** (arrays, shape code (shapeCodes, or a regular polygon's sides), the shape's two numbers (a box's half-extents, a capsule's half length and radius; 0 for the others), size (a box's and a capsule's come from their numbers), density, static 0/1, px, py, pz, vx, vy, vz, angle, omega, restore 0/1, ax, ay, az, nx, ny, nz, friction, restitution (each -1: the scene's)): meta lastAdded, -1 if refused, -2 if a restored body's axis and normal do not fit (frameMisfit says why) */
    addBody: Procedure;
    /** (arrays, index): the last body takes the index */
    removeBody: Procedure;
    /** (arrays, qx, qy, qz): meta picked (-1: none) and pickedSign */
    pickBody: Procedure;
    /** (arrays, index, sign, qx, qy, qz, frequency, damping, maxForce): the mouse joint holds the body at q */
    grab: Procedure;
    /** (arrays, qx, qy, qz): the mouse joint's target */
    drag: Procedure;
    release: Procedure;
    /** the measures' out array (Lib/Manifold/Measures.hs): its length and slots */
    measures: { size: number; slots: Record<MeasureField, number> };
    /** (arrays, out): the bodies' kinetic energy and their centres' angular momentum about the space's axis (0 without one) into out */
    measure: Procedure;
    /** (arrays, out, index): the body's speed, kinetic energy and contact rows into out */
    measureBody: Procedure;
    /** a walked geodesic's layout (Lib/Manifold/GeodesicPath.hs): path[0] the points walked, then each point's slots */
    path: { stride: number; slots: Record<PathField, number> };
    /** (path, px, py, pz, dx, dy, dz, length, steps): the geodesic from p in the tangent direction of d, walked into path (length 1 + stride · (steps + 1)); it takes the one array, not the engine's */
    geodesic: (path: Float64Array, px: number, py: number, pz: number, dx: number, dy: number, dz: number, length: number, steps: number) => void;
  }

  // ---- the comparison (web/gen/compare-torus.js, Lib/Manifold/Chart.hs) ----

  interface ComparisonDef {
    /** the view's name in the space list and the URL */
    name: string;
    title: string;
    /** the two spaces: the embedded torus and the flat one */
    embedded: string;
    flat: string;
    /** a point of the embedded torus → (x, 0, z) of the flat torus's square */
    toSquare: VectorField;
    /** (x, _, z) of the square → the point of the embedded torus at those angles */
    fromSquare: VectorField;
    /** the square is [-half, half]² */
    half: number;
    /** the torus traced with the flat torus's curvature (0), through the chart */
    flatGlsl: string;
    scenes: { embedded: Scene; flat: Scene };
  }

  /** window.Manifold: what the generated scripts define. */
  interface Generated {
    /** the spaces whose scripts have loaded, by name */
    spaces: Record<string, Space>;
    /** web/gen/spaces.js: the scene keys that set the engine's parameters */
    sceneKeys: SceneKey[];
    /** what a saved contact row to be kept lists after [key, normal, friction]: remembered rows' fields (Manifold.World.keptFields) */
    keptFields: PrevField[];
    /** the scene file's format, a scene's body's and a joint's (Manifold.SceneFormat), read by world.js's interpreter of it */
    sceneFormat: Format;
    bodyFormat: Format;
    jointFormat: Format;
    /** why a space's scenes can have no joints, by space name (a space not named takes joints; Manifold.Space.jointsRefused) */
    jointsRefused: { [space: string]: string };
    /** addBody's shape codes (a regular polygon's is its number of sides), and a body's size from its shape's code, its two numbers and its given size (Manifold.Hull) */
    shapes: {
      codes: { circle: number; box: number; capsule: number; vertices: number };
      /** how many corners a convex polygon may have */
      maxCorners: number;
      size: (code: number, p: number, q: number, size: number) => number;
      /** a convex polygon's size from its count, its radius and its corners a0, b0, ... (maxCorners of them) */
      polygonSize: (n: number, r: number, ...corners: number[]) => number;
      /** 1 if the first n corners a0, b0, ... (maxCorners of them) go round a convex polygon in order, either way round, else 0 */
      convexRound: (n: number, ...corners: number[]) => number;
    };
    /** the hyperbolic plane's pictures (Manifold.Disc): the discs' maps, boosts (nine numbers row by row), the geodesic grid, and the same maps as GLSL */
    hyperbolic: {
      fromPoincare: (u: number, w: number) => Vec3;
      toPoincare: (x: number, y: number, z: number) => [number, number];
      fromKlein: (u: number, w: number) => Vec3;
      toKlein: (x: number, y: number, z: number) => [number, number];
      /** the boost carrying the vertex (0, 1, 0) to the point (x, y, z) of the sheet along their geodesic */
      translationTo: (x: number, y: number, z: number) => number[];
      /** a matrix (m0 … m8) times the point (x, y, z) */
      apply: (...mAndPoint: number[]) => Vec3;
      /** the product m n of m0 … m8 and n0 … n8 */
      compose: (...mn: number[]) => number[];
      /** a Lorentz matrix's inverse */
      inverse: (...m: number[]) => number[];
      /** the nearest Lorentz matrix (after round-off) */
      renormalise: (...m: number[]) => number[];
      /** the geodesic grid's coordinates of a point */
      grid: (x: number, y: number, z: number) => [number, number];
      glsl: string;
    };
    /** web/gen/spaces.js: every space, in catalogue order */
    spaceIndex: SpaceEntry[];
    /** the comparisons whose scripts have loaded (web/gen/compare-torus.js: torus) */
    comparisons?: Record<string, ComparisonDef>;
    /** web/gen/presets.js: the preset scenes of scenes/ (Lib/Manifold/Presets.hs), by name */
    presets?: Preset[];
  }

  /** A preset scene: scenes/SPACE-WHAT.json. */
  interface Preset {
    /** the file's name without .json: what #scene=NAME loads */
    name: string;
    space: string;
    /** what it shows: the name's part after the space, in words */
    title: string;
    scene: Scene;
  }

  // ---- the scripting API (window.manifold) ----

  type Antialias = "fxaa" | "ssaa" | "off";
  /** How a hyperbolic space is drawn: the Poincaré disc, the Klein disc (flat views, web/js/disc.js), or the hyperboloid traced in 3-D. */
  type Model = "poincare" | "klein" | "hyperboloid";
  /** Where the flat views look: the boost (world → view, nine numbers row by row, a Lorentz matrix of x² − y² + z²), and the disc's radius as a fraction of half the canvas's smaller side. On a quotient (bolza) the boost is kept with the view's centre in the fundamental domain: a walk or a boost set that takes the centre out is composed with the group element that brings it back, which shows the same picture. */
  interface DiscViewSpec {
    boost: number[];
    zoom: number;
  }
  /** "auto": each body in the coarsest form that looks the same as its mesh; "mesh": every body as its whole mesh */
  type BodyDetail = "auto" | "mesh";
  interface DisplayOptions {
    curvature: boolean;
    grid: boolean;
    antialias: Antialias;
    bodyDetail: BodyDetail;
    /** sleeping bodies drawn dimmed */
    dimSleeping: boolean;
    /** how a hyperbolic space is drawn (other spaces ignore it) */
    model: Model;
  }
  interface OptionsShown extends DisplayOptions {
    background: { top: Rgb; bottom: Rgb };
    curvatureScale: number;
    gridSpacing: number;
  }
  /** How the last frame drew the bodies: as fans, coarser meshes, whole meshes, and the triangles drawn. */
  interface BodyForms {
    fans: number;
    coarser: number;
    meshes: number;
    triangles: number;
  }
  interface Stats {
    fps: number;
    /** the GPU time of the last full (traced) frame, ms */
    frameMs: number | null;
    frames: number;
    preview: boolean;
    bodies: number;
    /** the movable bodies awake, and the islands (awake and asleep) */
    awake: number;
    islands: number;
    joints: number;
    contacts: number;
    warnings: number;
    droppedContacts: number;
    /** a moving average; null before the first step */
    physicsMsPerStep: number | null;
    steps: number;
    /** the thread stepping the physics now: the physics worker, or the main thread */
    thread: "main" | "worker";
    paused: boolean;
    timeScale: number;
    width: number;
    height: number;
    space: string | null;
    antialias: Antialias;
    curvature: boolean;
    grid: boolean;
    bodyDetail: BodyDetail;
    bodyForms: BodyForms;
  }
  /**
   * The clock and the engine parameters the page offers controls for: the
   * scene keys with a control (Manifold.sceneKeys), in their order; the
   * numbers are null without a world.
   */
  /** Who steps the physics (Simulation.thread). */
  type ThreadSetting = "auto" | "main" | "worker";
  interface Simulation {
    paused: boolean;
    timeScale: number;
    /**
     * who steps the physics: "worker" (a Web Worker, when the page is
     * cross-origin isolated, as `manifold serve` serves it), "main" (the
     * page's own thread), or "auto" (the worker from 1000 bodies on)
     */
    thread: ThreadSetting;
    gravity: boolean;
    substeps: number | null;
    friction: number | null;
    restitution: number | null;
    contactHertz: number | null;
    dampingRatio: number | null;
    pushout: number | null;
    jointHertz: number | null;
    /** islands at rest fall asleep */
    sleep: boolean;
  }
  /**
   * What setSimulation takes: any subset. An engine parameter takes what its
   * scene key's range takes (Manifold.sceneKeys; a bad one throws the key's
   * message, "friction must not be negative"), not only its slider's extent.
   */
  interface SimulationChange {
    paused?: boolean;
    /** 0 … 10 */
    timeScale?: number;
    thread?: ThreadSetting;
    gravity?: boolean;
    /** a whole number from 1 to 64 */
    substeps?: number;
    /** 0 or above */
    friction?: number;
    /** 0 … 1 */
    restitution?: number;
    /** above 0 */
    contactHertz?: number;
    /** 0 or above */
    dampingRatio?: number;
    /** above 0 */
    pushout?: number;
    /** above 0 */
    jointHertz?: number;
    sleep?: boolean;
  }
  type Pane = "torus-embedded" | "torus-flat" | "square-embedded" | "square-flat";
  interface ComparisonState {
    name: string;
    panes: Pane[];
    embedded: Body[];
    flat: Body[];
    /** the held body's index in each world, or -1 */
    grabbed: { embedded: number; flat: number };
    frames: number;
    note: string;
  }

  /** window.manifold (web/README.md, "Scripting API"). Pixels are the canvas's backing-store pixels, origin top-left. */
  /** What a press on empty surface does (web/js/tools.js). */
  type Tool = "grab" | "geodesic" | "joint";
  interface NewBody {
    shape: Shape;
    size: number;
    density: number;
    static: boolean;
  }
  /** A curve on the surface: its points, and the indices of those it jumps to (through a quotient's edge, no segment before them). */
  interface Curve {
    points: Vec3[];
    breaks: number[];
  }
  interface Inspected {
    index: number;
    shape: Shape;
    size: number;
    static: boolean;
    /** in a sleeping island */
    asleep: boolean;
    speed: number;
    omega: number;
    /** kinetic energy, translation and spin */
    energy: number;
    /** the last step's contact rows the body is in */
    contacts: number;
    /** the body's own friction and restitution, where it has them (else the scene's) */
    friction?: number;
    restitution?: number;
  }
  interface Curves {
    /** the geodesic tool's curve */
    geodesic: Curve | null;
    /** while a throw is dragged: the new body's centre after every step of its first second (the body alone, these parameters) */
    preview: Curve | null;
    /** samples held (one every 0.05 s of simulated time, 3 s kept), segments drawn, and the opacity of their oldest and newest ends (null: none) */
    trails: { on: boolean; samples: number; segments: number; oldest: number | null; newest: number | null };
  }
  interface Api {
    /** names of every space, in catalogue order */
    spaces(): string[];
    /** the current space's name ("compare-torus" in the comparison view); null before the first switch */
    space(): string | null;
    /** resolves with the name when the shader is compiled, the default scene loaded and a frame drawn; rejects with the error text */
    setSpace(name: string): Promise<string>;
    /** the latest space switch (the first is the page's own) */
    ready(): Promise<string>;
    /** the surface point under pixel (x, y), or null on background (in a flat view: from the disc's map, in double precision) */
    pick(x: number, y: number): Vec3 | null;
    /** continuous pixel coordinates of a world point (pixel (i, j) spans [i, i+1) × [j, j+1)), or null behind the eye (in a flat view: off the upper sheet) */
    project(p: Vec3): [number, number] | null;
    /** where the flat views of a hyperbolic space look */
    discView(): DiscViewSpec;
    /** any subset; throws on a matrix that is not a Lorentz boost or a zoom out of range */
    setDiscView(v: Partial<DiscViewSpec>): DiscViewSpec;
    /** walks the flat view as a drag from the canvas's centre by (dx, dy) backing-store pixels does; throws when the space is not shown flat */
    walk(dx: number, dy: number): DiscViewSpec;
    /** draws one full-resolution frame now */
    render(): void;
    /** draws a frame now and waits for the GPU: its time in ms (false: reuse the traced surface if the view has not changed); null when nothing can be drawn */
    measureFrame(retrace?: boolean): number | null;
    stats(): Stats;
    camera(): CameraSpec;
    /** any subset; throws on bad input */
    setCamera(c: Partial<CameraSpec>): CameraSpec;
    options(): OptionsShown;
    /** any subset; throws on an unknown antialias or bodyDetail */
    setOptions(o: Partial<DisplayOptions>): DisplayOptions;
    /** the error text on the page, or null */
    error(): string | null;
    /** replaces a space's GLSL (null restores the generated one) and rebuilds it if current */
    setSpaceGlsl(name: string, text: string | null): Promise<string>;

    /** adds a body given as in a scene; its index, or throws naming the problem */
    addBody(spec: SceneBody): number;
    /** adds a joint given as in a scene (bodies by index); its index, or throws naming the problem */
    addJoint(spec: SceneJoint): number;
    /** every joint, as a saved scene holds it */
    joints(): SceneJoint[];
    /** removes joint i (the last joint takes its index) */
    removeJoint(i: number): void;
    /** removes every body */
    clear(): void;
    /** the space's default scene again, cut or filled to n bodies (0 … the engine's maxBodies; a notice when fewer fit); the count */
    resetScene(n?: number | null): number;
    /** n physics steps now (default 1); the body count */
    step(n?: number): number;
    bodies(): Body[];
    /** the hash of the world's state, 16 hex digits: what `manifold sim --hash` prints for the same run */
    hash(): string;
    pause(): void;
    resume(): void;
    simulation(): Simulation;
    /** any subset; throws on bad values */
    setSimulation(o: SimulationChange): Simulation;
    /** grabs the body under pixel (x, y) with the mouse joint; whether one was grabbed */
    grab(x: number, y: number): boolean;
    /** moves the joint's target to the surface under (x, y); false off the surface or when nothing is held */
    drag(x: number, y: number): boolean;
    release(): void;
    /** the held body's index, or -1 */
    grabbed(): number;
    /** what a press on empty surface does: grab a body there, else throw a new one; or draw a geodesic */
    tool(): Tool;
    /** throws naming a tool that is none */
    setTool(tool: Tool): void;
    /** the body the Add button, a click on empty surface and a throw make (size: the space's own unless set) */
    newBody(): NewBody;
    /** changes some of the new body ({size: null}: the space's own again); throws naming the field of a bad value, changing nothing */
    setNewBody(o: Partial<Omit<NewBody, "size">> & { size?: number | null }): NewBody;
    /** adds the new body at a free point of the view; its index, or throws when no free place is found */
    addAtView(): number;
    /** draws the geodesic from surface point p in the tangent direction d, `length` long (default: the tool's), and returns it */
    geodesic(p: Vec3, d: Vec3, length?: number): Curve;
    clearGeodesic(): void;
    /** whether every body's path over the last seconds is drawn */
    trails(): boolean;
    setTrails(on: boolean): void;
    /** what is drawn over the bodies */
    curves(): Curves;
    /** the live plot's samples (one every `every` simulated seconds, `seconds` kept); axialMomentum null where the space has no axis */
    plot(): { on: boolean; seconds: number; every: number; samples: Record<"time" | "kineticEnergy" | "axialMomentum" | "contacts" | "stepMs", number[] | null> };
    setPlot(on: boolean): void;
    /** what the inspector says of the body under backing-store pixel (x, y) (the engine's measureBody), or null */
    inspect(x: number, y: number): Inspected | null;
    /** loads a scene (JSON text or value; one of another space switches to it): the body count, or rejects naming the problem */
    loadScene(json: string | Scene): Promise<number>;
    /** the preset scenes (scenes/, web/gen/presets.js): name, space and title of each */
    presets(): { name: string; space: string; title: string }[];
    /** loads a preset by name (switching to its space): the body count, or rejects naming an unknown one */
    loadPreset(name: string): Promise<number>;
    /** the preset the world was loaded from, while nothing else replaced it, or null */
    preset(): string | null;
    /** the current scene (what Save scene downloads) */
    scene(): SavedScene;
    /** the comparison view's state, or null when it is not shown */
    comparison(): ComparisonState | null;
    /** where body i of a pane's world is drawn, in client (CSS) pixels, or null behind the eye */
    comparisonPoint(pane: Pane, i: number): [number, number] | null;
  }
}

/** What the generated scripts define (web/gen). */
declare var Manifold: Manifold.Generated;
/** The page's scripting API; set when the page starts. */
declare var manifold: Manifold.Api;
