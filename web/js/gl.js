// WebGL2 plumbing: the context, shader compilation with readable errors, and
// render targets (the float framebuffer the tracer writes, colour buffers for
// antialiasing). Nothing here knows about spaces or physics.
/* exported ManifoldWebGl */
var ManifoldWebGl = (function (W) {
  "use strict";

  // An error the page shows in words. `kind` says what failed ("webgl2",
  // "float-framebuffer", "shader", "load", "context-lost"); `log` holds a
  // compiler log or other detail, `source` the shader text it refers to.
  class PageError extends Error {
    /**
     * @param {string} kind
     * @param {string} message
     * @param {string} [log]
     * @param {string} [source]
     */
    constructor(kind, message, log, source) {
      super(message);
      this.name = "PageError";
      this.kind = kind;
      this.log = log || "";
      this.source = source || "";
    }
    // The whole text: message, then the log.
    text() {
      return this.log ? this.message + "\n" + this.log : this.message;
    }
  }

  /** @type {WebGLContextAttributes} */
  const CONTEXT_ATTRIBUTES = {
    alpha: false,
    antialias: false, // the tracer antialiases itself (FXAA or supersampling)
    depth: false,
    stencil: false,
    premultipliedAlpha: false,
    preserveDrawingBuffer: false,
    powerPreference: "high-performance",
  };

  // A WebGL2 context with float colour buffers, or a PageError saying which is missing.
  /** @param {HTMLCanvasElement} canvas @returns {WebGL2RenderingContext} */
  function createContext(canvas) {
    const gl = canvas.getContext("webgl2", CONTEXT_ATTRIBUTES);
    if (!gl) {
      throw new PageError("webgl2",
        "This browser (or its graphics driver) does not offer WebGL2, which the sphere tracer needs. " +
        "Try a current Chrome, Firefox or Safari, or enable hardware acceleration.");
    }
    if (!gl.getExtension("EXT_color_buffer_float")) {
      throw new PageError("float-framebuffer",
        "This browser's WebGL2 cannot render into floating-point framebuffers " +
        "(EXT_color_buffer_float is missing); the traced surface positions used for shading and picking " +
        "need them.");
    }
    return gl;
  }

  /**
   * @param {WebGL2RenderingContext} gl
   * @param {number} type gl.VERTEX_SHADER or gl.FRAGMENT_SHADER
   * @param {string} source
   * @param {string} label
   */
  function compileShader(gl, type, source, label) {
    const shader = /** @type {WebGLShader} */ (gl.createShader(type));
    gl.shaderSource(shader, source);
    gl.compileShader(shader);
    if (!gl.getShaderParameter(shader, gl.COMPILE_STATUS) && !gl.isContextLost()) {
      const log = (gl.getShaderInfoLog(shader) || "(the driver gave no log)").trim();
      gl.deleteShader(shader);
      const stage = type === gl.VERTEX_SHADER ? "vertex" : "fragment";
      throw new PageError("shader", "The " + stage + " shader of the " + label + " failed to compile.", log, source);
    }
    return shader;
  }

  /**
   * A linked program and its uniforms' locations by name (looked up once).
   * @typedef {{ program: WebGLProgram, uniform: (name: string) => WebGLUniformLocation | null }} Program
   */

  // Compiles and links a program; returns { program, uniform(name) → location }.
  /**
   * @param {WebGL2RenderingContext} gl
   * @param {string} vertexSource
   * @param {string} fragmentSource
   * @param {string} label
   * @returns {Program}
   */
  function createProgram(gl, vertexSource, fragmentSource, label) {
    const vs = compileShader(gl, gl.VERTEX_SHADER, vertexSource, label);
    let fs;
    try {
      fs = compileShader(gl, gl.FRAGMENT_SHADER, fragmentSource, label);
    } catch (e) {
      gl.deleteShader(vs);
      throw e;
    }
    const program = /** @type {WebGLProgram} */ (gl.createProgram());
    gl.attachShader(program, vs);
    gl.attachShader(program, fs);
    gl.linkProgram(program);
    gl.deleteShader(vs);
    gl.deleteShader(fs);
    if (!gl.getProgramParameter(program, gl.LINK_STATUS) && !gl.isContextLost()) {
      const log = (gl.getProgramInfoLog(program) || "(the driver gave no log)").trim();
      gl.deleteProgram(program);
      throw new PageError("shader", "The shader program of the " + label + " failed to link.", log, fragmentSource);
    }
    /** @type {Map<string, WebGLUniformLocation | null>} */
    const locations = new Map();
    return {
      program: program,
      uniform: function (name) {
        if (!locations.has(name)) locations.set(name, gl.getUniformLocation(program, name));
        return /** @type {WebGLUniformLocation | null} */ (locations.get(name));
      },
    };
  }

  // The vertex shader of every pass: one triangle covering the viewport,
  // generated from gl_VertexID (no vertex buffers).
  const FULLSCREEN_VERTEX = [
    "#version 300 es",
    "void main() {",
    "  vec2 p = vec2(float((gl_VertexID << 1) & 2), float(gl_VertexID & 2));",
    "  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);",
    "}",
  ].join("\n");

  /** @param {WebGL2RenderingContext} gl @param {WebGLVertexArrayObject} vao */
  function drawFullscreen(gl, vao) {
    gl.bindVertexArray(vao);
    gl.drawArrays(gl.TRIANGLES, 0, 3);
    gl.bindVertexArray(null);
  }

  /**
   * @param {WebGL2RenderingContext} gl
   * @param {number} width
   * @param {number} height
   * @param {number} internalFormat
   * @param {number} format
   * @param {number} type
   * @param {number} filter
   */
  function makeTexture(gl, width, height, internalFormat, format, type, filter) {
    const tex = /** @type {WebGLTexture} */ (gl.createTexture());
    gl.bindTexture(gl.TEXTURE_2D, tex);
    gl.texStorage2D(gl.TEXTURE_2D, 1, internalFormat, width, height);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, filter);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, filter);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
    gl.bindTexture(gl.TEXTURE_2D, null);
    return tex;
  }

  /** @param {WebGL2RenderingContext} gl @param {string} what */
  function checkComplete(gl, what) {
    const status = gl.checkFramebufferStatus(gl.FRAMEBUFFER);
    if (status !== gl.FRAMEBUFFER_COMPLETE) {
      gl.bindFramebuffer(gl.FRAMEBUFFER, null);
      throw new PageError("float-framebuffer",
        "The " + what + " framebuffer is incomplete (status 0x" + status.toString(16) + "); " +
        "this browser cannot render into it.");
    }
  }

  /**
   * A framebuffer and its colour attachments.
   * @typedef {{ fb: WebGLFramebuffer, textures: WebGLTexture[], buffers: number[], width: number, height: number }} Target
   */

  // A framebuffer with `count` RGBA32F colour attachments (nearest filtering).
  /**
   * @param {WebGL2RenderingContext} gl
   * @param {number} width
   * @param {number} height
   * @param {number} count
   * @returns {Target}
   */
  function createFloatTarget(gl, width, height, count) {
    const fb = /** @type {WebGLFramebuffer} */ (gl.createFramebuffer());
    gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
    const textures = [];
    const buffers = [];
    for (let i = 0; i < count; i++) {
      const tex = makeTexture(gl, width, height, gl.RGBA32F, gl.RGBA, gl.FLOAT, gl.NEAREST);
      gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0 + i, gl.TEXTURE_2D, tex, 0);
      textures.push(tex);
      buffers.push(gl.COLOR_ATTACHMENT0 + i);
    }
    gl.drawBuffers(buffers);
    checkComplete(gl, "float (RGBA32F)");
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    return { fb: fb, textures: textures, buffers: buffers, width: width, height: height };
  }

  // A framebuffer with one RGBA8 colour attachment (linear filtering).
  /**
   * @param {WebGL2RenderingContext} gl
   * @param {number} width
   * @param {number} height
   * @returns {Target}
   */
  function createColorTarget(gl, width, height) {
    const fb = /** @type {WebGLFramebuffer} */ (gl.createFramebuffer());
    gl.bindFramebuffer(gl.FRAMEBUFFER, fb);
    const tex = makeTexture(gl, width, height, gl.RGBA8, gl.RGBA, gl.UNSIGNED_BYTE, gl.LINEAR);
    gl.framebufferTexture2D(gl.FRAMEBUFFER, gl.COLOR_ATTACHMENT0, gl.TEXTURE_2D, tex, 0);
    checkComplete(gl, "colour (RGBA8)");
    gl.bindFramebuffer(gl.FRAMEBUFFER, null);
    return { fb: fb, textures: [tex], buffers: [gl.COLOR_ATTACHMENT0], width: width, height: height };
  }

  /** @param {WebGL2RenderingContext} gl @param {Target | null | undefined} target */
  function deleteTarget(gl, target) {
    if (!target) return;
    gl.deleteFramebuffer(target.fb);
    target.textures.forEach(function (t) { gl.deleteTexture(t); });
  }

  // Reads one RGBA32F texel of attachment `index` of a float target;
  // (x, y) in GL convention (origin bottom-left).
  /**
   * @param {WebGL2RenderingContext} gl
   * @param {Target} target
   * @param {number} index
   * @param {number} x
   * @param {number} y
   */
  function readFloatPixel(gl, target, index, x, y) {
    const out = new Float32Array(4);
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, target.fb);
    gl.readBuffer(gl.COLOR_ATTACHMENT0 + index);
    gl.readPixels(x, y, 1, 1, gl.RGBA, gl.FLOAT, out);
    gl.bindFramebuffer(gl.READ_FRAMEBUFFER, null);
    return out;
  }

  const exported = {
    PageError: PageError,
    createContext: createContext,
    createProgram: createProgram,
    FULLSCREEN_VERTEX: FULLSCREEN_VERTEX,
    drawFullscreen: drawFullscreen,
    createFloatTarget: createFloatTarget,
    createColorTarget: createColorTarget,
    deleteTarget: deleteTarget,
    readFloatPixel: readFloatPixel,
  };
  W.ManifoldWeb = W.ManifoldWeb || /** @type {ManifoldWebModules} */ ({});
  W.ManifoldWeb.gl = exported;
  return exported;
})(globalThis);
