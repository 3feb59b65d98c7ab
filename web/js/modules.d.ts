// The page's own scripts as the type checker sees them (tsconfig.json): each
// file of web/js is a classic script that registers one module on
// window.ManifoldWeb and also returns it into a global var (ManifoldWebGl,
// …), only so that its type can be named here. The page reaches the modules
// through ManifoldWeb, at run time, so the files may call one another in any
// order once all are loaded. Below, the classes' instance types by name, for
// the JSDoc of the other files.

interface ManifoldWebModules {
  gl: typeof ManifoldWebGl;
  camera: typeof ManifoldWebCamera;
  disc: typeof ManifoldWebDisc;
  tracer: typeof ManifoldWebTracer;
  picking: typeof ManifoldWebPicking;
  world: typeof ManifoldWebWorld;
  bodies: typeof ManifoldWebBodies;
  compare: typeof ManifoldWebCompare;
  ui: typeof ManifoldWebUi;
  page: typeof ManifoldWebPage;
  frame: typeof ManifoldWebFrame;
  input: typeof ManifoldWebInput;
  space: typeof ManifoldWebSpace;
  hash: typeof ManifoldWebHash;
  compareSetup: typeof ManifoldWebCompareSetup;
  simulationSettings: typeof ManifoldWebSimulationSettings;
  scenes: typeof ManifoldWebScenes;
  api: typeof ManifoldWebApi;
  capture: typeof ManifoldWebCapture;
  curves: typeof ManifoldWebCurves;
  tools: typeof ManifoldWebTools;
  plot: typeof ManifoldWebPlot;
  inspector: typeof ManifoldWebInspector;
  physicsThread: typeof ManifoldWebPhysicsThread;
}

/** A physics worker's own global (web/js/physics-worker.js). */
declare function importScripts(...urls: string[]): void;

/** The page's modules (web/js), by file. */
declare var ManifoldWeb: ManifoldWebModules;

declare namespace ManifoldWeb {
  type PageError = InstanceType<typeof ManifoldWebGl.PageError>;
  type Camera = InstanceType<typeof ManifoldWebCamera.Camera>;
  type DiscView = InstanceType<typeof ManifoldWebDisc.DiscView>;
  type Tracer = InstanceType<typeof ManifoldWebTracer.Tracer>;
  type World = InstanceType<typeof ManifoldWebWorld.World>;
  type Clock = InstanceType<typeof ManifoldWebWorld.Clock>;
  type BodyRenderer = InstanceType<typeof ManifoldWebBodies.BodyRenderer>;
  type CurveRenderer = InstanceType<typeof ManifoldWebCurves.CurveRenderer>;
  type Comparison = InstanceType<typeof ManifoldWebCompare.Comparison>;
  type UI = ReturnType<typeof ManifoldWebUi.createUI>;

  /** A scene key the page offers a control for (simulation-settings.js's engineSettings, ui.js's createUI). */
  type ControlledKey = Manifold.SceneKey & { control: Manifold.SceneControl };
  /** Engine parameters by name (World.setParams). */
  type Params = Partial<Record<Manifold.ParamName, number>>;
  type ThreadSetting = Manifold.ThreadSetting;
  /** The arrays a frame reads (world.js's VIEW): a world's own, or a snapshot of them. */
  interface View {
    meta: Float64Array;
    pos: Float64Array;
    vel: Float64Array;
    scalars: Float64Array;
    verts: Float64Array;
    hull: Float64Array;
  }
  /** A world's memory shared with the physics worker (World.share). */
  interface Sharing {
    /** world.js's SHARED slots */
    control: Int32Array;
    /** three snapshot buffers: the worker's, the middle one, the one drawn */
    snapshots: View[];
    /** the one drawn */
    front: number;
    /** the worker held the lock past World.hold's patience: taken for dead */
    unanswered: boolean;
    /** hears of every new set of shared arrays */
    notify: (w: World) => void;
  }
  /** What a World keeps of each body besides the engine's arrays. */
  interface BodyInfo {
    shape: Manifold.Shape;
    /** the size it was given (its circumradius; a box's, a capsule's or a polygon's from its numbers) */
    size: number;
    density: number;
    static: boolean;
    /** one of world.js's palette's colours (shared arrays: compared by reference) */
    colour: Manifold.Rgb;
  }
  /**
   * What BodyRenderer.draw draws: a World, or the comparison's flat world
   * mapped onto the torus (Comparison.flatOnTorus).
   */
  interface DrawnWorld {
    engine: Manifold.Engine;
    info: BodyInfo[];
    capacity: number;
    images: Manifold.Image[];
    count(): number;
    a: { verts: Float64Array; scalars: Float64Array; hull?: Float64Array };
    target: Manifold.Vec3 | null;
  }
  /**
   * A scene as world.js's parseScene gives it: the space, every scene key
   * (Manifold.sceneKeys: given or the default), and the bodies, each with
   * every key. World.load also takes scenes whose bodies are left to it to
   * complete (the default scene's).
   */
  interface ParsedScene {
    space: string;
    bodies: Manifold.SceneBody[];
    joints?: ParsedJoint[];
    camera?: SceneCamera | null;
    [sceneKey: string]: unknown;
  }

  /** A scene's camera as world.js's parseScene gives it: up and fov left out where the scene left them out. */
  interface SceneCamera {
    eye: Manifold.Vec3;
    target: Manifold.Vec3;
    up?: Manifold.Vec3;
    fov?: number;
  }

  /** A scene joint as world.js's parseJoint gives it (from the checked joint): every key, null where the scene left one out. */
  interface ParsedJoint {
    type: Manifold.JointType;
    a: number;
    /** -1: the world */
    b: number;
    anchorA: Manifold.Vec3;
    anchorB: Manifold.Vec3;
    length: number | null;
    minLength: number | null;
    maxLength: number | null;
    hertz: number;
    dampingRatio: number;
    referenceAngle: number | null;
    limit: [number, number] | null;
    motor: [number, number] | null;
    local: number[] | null;
    impulses: number[];
    collide: boolean;
  }

  /** A linked program and its uniforms (gl.js). */
  type Program = ReturnType<typeof ManifoldWebGl.createProgram>;
  /** A framebuffer and its colour attachments (gl.js). */
  type Target = ReturnType<typeof ManifoldWebGl.createFloatTarget>;

  /** What the tracer draws (Tracer.render). */
  interface TraceView {
    camera: Camera;
    bounds: number;
    curvature: boolean;
    curvatureScale: number;
    grid: boolean;
    gridSpacing: number;
    background: { top: Manifold.Rgb; bottom: Manifold.Rgb };
    /** a flat view (web/js/disc.js): its model, the view's inverse boost (row by row), the disc's radius in canvas pixels; null or absent: the traced surface */
    flat?: { model: "poincare" | "klein"; toWorld: Float32Array; radius: number } | null;
  }
  /**
   * What the tracer's overlay hook gets, the colour buffer bound (Tracer.render);
   * the page adds the view it draws the bodies in (BodyRenderer.draw).
   */
  interface OverlayFrame {
    gl: WebGL2RenderingContext;
    framebuffer: WebGLFramebuffer;
    width: number;
    height: number;
    /** trace buffer pixels per canvas pixel */
    scale: number;
    /** the angle a pixel of this buffer spans at the eye */
    pixelAngle: number;
    positionTexture: WebGLTexture;
    normalTexture: WebGLTexture;
    viewProjection?: Float32Array;
    eye?: Manifold.Vec3;
    bodyDetail?: Manifold.BodyDetail;
    /** the radius of the ball the surface is traced in (bodies and curves beyond it are not drawn), or 0 */
    bounds?: number;
    /** a flat view: its model, its boost (world → view, row by row), the disc's radius in pixels of this buffer */
    flat?: { model: "poincare" | "klein"; boost: Float32Array; radius: number } | null;
  }
}
