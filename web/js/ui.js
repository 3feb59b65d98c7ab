// The page's controls and messages: the space selector, the curvature and
// antialiasing options, the new body's controls, the tool and trails, the
// engine parameters' controls (made from the generated scene keys they
// set), the keys (Space, s, r, c, g, t, p, ?) and the help
// overlay listing them and the gestures, the stats line, the error panel,
// the capture buttons (Save image, Record / Stop), and the URL hash.
/* exported ManifoldWebUi */
var ManifoldWebUi = (function (W) {
  "use strict";

  // The element of index.html with this id; its kind (HTMLInputElement, …) is
  // the one the caller's declaration says, as index.html has it.
  /** @template {HTMLElement} T @param {string} id @returns {T} */
  function $(id) {
    const el = document.getElementById(id);
    if (!el) throw new Error("index.html lacks #" + id);
    return /** @type {T} */ (el);
  }

  // "#space=torus&curvature=1" → { space: "torus", curvature: "1" }
  /** @param {string} hash @returns {Record<string, string>} */
  function parseHash(hash) {
    /** @type {Record<string, string>} */
    const out = {};
    String(hash || "").replace(/^#/, "").split("&").forEach(function (kv) {
      if (!kv) return;
      const i = kv.indexOf("=");
      const k = decodeURIComponent(i < 0 ? kv : kv.slice(0, i));
      const val = i < 0 ? "" : decodeURIComponent(kv.slice(i + 1));
      out[k] = val;
    });
    return out;
  }

  // The inverse, keys in the given order, skipping null/undefined values.
  /** @param {Record<string, string | number | null | undefined>} params */
  function formatHash(params) {
    /** @type {string[]} */
    const parts = [];
    Object.keys(params).forEach(function (k) {
      const val = params[k];
      if (val === null || val === undefined) return;
      parts.push(encodeURIComponent(k) + "=" + encodeURIComponent(String(val)).replace(/%2C/g, ","));
    });
    return parts.length ? "#" + parts.join("&") : "";
  }

  // Numbers a shader's lines the way the compiler's log does: "S:L" with S
  // the source-string number set by `#line L S` directives.
  /** @param {string} source */
  function numberSource(source) {
    let line = 1, string = 0;
    /** @type {string[]} */
    const out = [];
    String(source).split("\n").forEach(function (text) {
      const m = /^\s*#line\s+(\d+)(?:\s+(\d+))?/.exec(text);
      out.push((string + ":" + line).padStart(6) + "  " + text);
      if (m) {
        line = parseInt(m[1], 10);
        if (m[2] !== undefined) string = parseInt(m[2], 10);
      } else {
        line++;
      }
    });
    return out.join("\n");
  }

  /**
   * What the controls call (web/js/app.js and simulation-settings.js give them).
   * @typedef {object} Handlers
   * @property {(name: string) => void} onSpace
   * @property {(on: boolean) => void} onCurvature
   * @property {(on: boolean) => void} onGrid
   * @property {(on: boolean) => void} onDimSleeping
   * @property {(mode: Manifold.Antialias) => void} onAntialias
   * @property {(model: Manifold.Model) => void} onModel
   * @property {() => void} onResetView
   * @property {() => void} onAdd add the new body at a free point of the view
   * @property {(o: { shape?: Manifold.Shape, size?: number, density?: number, static?: boolean }) => void} onNewBody a control of the new body changed
   * @property {(tool: string) => void} onTool
   * @property {(length: number) => void} onGeodesicLength
   * @property {(on: boolean) => void} onTrails
   * @property {(on: boolean) => void} onPlot
   * @property {(name: string) => void} onPreset a preset scene was chosen
   * @property {() => void} onClear
   * @property {() => void} onReset
   * @property {() => void} onPause
   * @property {() => void} onStep
   * @property {(x: number) => void} onTimeScale
   * @property {(thread: string) => void} onThread
   * @property {(key: string, value: number | boolean) => void} onSetting an engine parameter's control changed (its scene key)
   * @property {() => void} onSave
   * @property {(file: File) => void} onLoad
   * @property {() => void} onSaveImage Save image: a PNG of the view
   * @property {() => void} onRecord Record / Stop: starts the recording, or stops it and downloads it
   */
  /**
   * What the error panel shows: a PageError (message, compiler log, shader source) or any Error.
   * @typedef {{ message: string, log?: string, source?: string }} Shown
   */

  // The help line under the view while a hyperbolic space is drawn flat (web/js/disc.js).
  const FLAT_HELP = "drag a body: move it · right-drag or drag off the disc: walk · wheel or pinch: size the disc · ?: keys";

  // The decimals a slider's value is shown with: as many as its step has.
  /** @param {number} step */
  function decimalsOf(step) {
    let d = 0;
    while (d < 6 && Math.abs(step * Math.pow(10, d) - Math.round(step * Math.pow(10, d))) > 1e-9) d++;
    return d;
  }

  /**
   * An engine parameter's control (for its scene key): a checkbox for a
   * switch; for a number a slider over the control's lo … hi by its step,
   * with an output showing the value. Ids: the key (the input) and, for a
   * slider, the key + "-value" (the output).
   * @typedef {{ key: ManifoldWeb.ControlledKey, input: HTMLInputElement, output: HTMLOutputElement | null, decimals: number }} Setting
   */
  /** @param {ManifoldWeb.ControlledKey} k @param {Handlers} handlers @returns {{ label: HTMLLabelElement, setting: Setting }} */
  function makeSetting(k, handlers) {
    const c = k.control;
    const label = document.createElement("label");
    label.title = c.help;
    const input = document.createElement("input");
    input.id = k.key;
    if (k.kind === "switch") {
      label.className = "toggle";
      input.type = "checkbox";
      input.checked = !!k.default;
      label.append(input, " " + c.label);
      input.addEventListener("change", function () { handlers.onSetting(k.key, input.checked); });
      return { label: label, setting: { key: k, input: input, output: null, decimals: 0 } };
    }
    const decimals = decimalsOf(c.step);
    label.className = "slider";
    input.type = "range";
    input.min = String(c.lo);
    input.max = String(c.hi);
    input.step = String(c.step);
    input.value = String(k.default);
    const output = document.createElement("output");
    output.id = k.key + "-value";
    output.htmlFor.add(k.key);
    output.textContent = Number(k.default).toFixed(decimals);
    label.append(c.label + " ", input, " ", output);
    input.addEventListener("input", function () {
      // the slider's value to the step's decimals (no 0.30000000000000004)
      const x = Number(Number(input.value).toFixed(decimals));
      output.textContent = x.toFixed(decimals);
      handlers.onSetting(k.key, x);
    });
    return { label: label, setting: { key: k, input: input, output: output, decimals: decimals } };
  }

  // Whether a key pressed in this element is the element's, not the page's:
  // a text-like input (not a checkbox, radio, range, button or file input), a
  // select, a textarea or an editable element.
  const UNTYPED_INPUTS = ["checkbox", "radio", "range", "button", "submit", "reset", "image", "color", "file"];
  /** @param {EventTarget | null} t */
  function typingIn(t) {
    if (t instanceof HTMLInputElement) return UNTYPED_INPUTS.indexOf(t.type) < 0;
    return t instanceof HTMLSelectElement || t instanceof HTMLTextAreaElement || (t instanceof HTMLElement && t.isContentEditable);
  }
  // Whether Space is this element's own key: a checkbox's or radio button's
  // (it ticks them; a button has Enter too, so there Space is the page's).
  /** @param {EventTarget | null} t */
  function ticksWithSpace(t) {
    return t instanceof HTMLInputElement && (t.type === "checkbox" || t.type === "radio");
  }

  // handlers: what the controls call; settings: the scene keys whose
  // controls the page shows, in order (simulation-settings.js's engineSettings)
  /** @param {Handlers} handlers @param {ManifoldWeb.ControlledKey[]} settings */
  function createUI(handlers, settings) {
    /** @type {HTMLSelectElement} */
    const spaceSelect = $("space");
    /** @type {HTMLInputElement} */
    const curvatureBox = $("curvature");
    /** @type {HTMLInputElement} */
    const gridBox = $("grid");
    /** @type {HTMLInputElement} */
    const dimBox = $("dim-sleeping");
    /** @type {HTMLSelectElement} */
    const antialiasSelect = $("antialias");
    /** @type {HTMLSelectElement} */
    const modelSelect = $("model");
    const modelControl = $("model-control");
    const resetButton = $("reset-view");
    const help = $("help");
    const tracedHelp = help.textContent;
    const stats = $("stats");
    const description = $("description");
    const legend = $("curvature-legend");
    const message = $("message");
    const messageTitle = $("message-title");
    const messageText = $("message-text");
    const messageLog = $("message-log");
    const messageSource = $("message-source");
    const messageSourceBox = $("message-source-box");
    const notice = $("notice");
    const noticeText = $("notice-text");
    /** @type {HTMLCanvasElement} */
    const canvas = $("view");

    spaceSelect.addEventListener("change", function () { handlers.onSpace(spaceSelect.value); });
    curvatureBox.addEventListener("change", function () { handlers.onCurvature(curvatureBox.checked); });
    gridBox.addEventListener("change", function () { handlers.onGrid(gridBox.checked); });
    dimBox.addEventListener("change", function () { handlers.onDimSleeping(dimBox.checked); });
    antialiasSelect.addEventListener("change", function () { handlers.onAntialias(/** @type {Manifold.Antialias} */ (antialiasSelect.value)); });
    modelSelect.addEventListener("change", function () { handlers.onModel(/** @type {Manifold.Model} */ (modelSelect.value)); });
    resetButton.addEventListener("click", function () { handlers.onResetView(); });
    $("notice-close").addEventListener("click", function () { notice.hidden = true; });

    // bodies and simulation
    /** @type {HTMLInputElement} */
    const sides = $("polygon-sides");
    const pause = $("pause");
    /** @type {HTMLSelectElement} */
    const timeScale = $("time-scale");
    /** @type {HTMLSelectElement} */
    const physicsThread = $("physics-thread");
    const engineControls = $("engine-controls");
    engineControls.textContent = "";
    /** @type {Setting[]} */
    const engineSettings = settings.map(function (k) {
      const made = makeSetting(k, handlers);
      engineControls.appendChild(made.label);
      return made.setting;
    });
    /** @type {HTMLInputElement} */
    const sceneFile = $("scene-file");
    // the new body: shape, size (a slider around the space's own, marked), density, static
    /** @type {HTMLSelectElement} */
    const shapeSelect = $("body-shape");
    /** @type {HTMLInputElement} */
    const sizeSlider = $("body-size");
    const sizeValue = $("body-size-value");
    /** @type {HTMLOptionElement} */
    const sizeMark = $("body-size-mark");
    /** @type {HTMLInputElement} */
    const densityInput = $("body-density");
    /** @type {HTMLInputElement} */
    const staticBox = $("body-static");
    /** @type {HTMLInputElement} */
    const aspect = $("body-aspect");
    /** @type {HTMLOptionElement} */
    const vertexOption = $("body-shape-vertices");
    // only the chosen kind's number shows: a polygon's sides, a box's or a capsule's length over width
    const showShapeNumber = function () {
      sides.hidden = shapeSelect.value !== "polygon";
      aspect.hidden = shapeSelect.value !== "box" && shapeSelect.value !== "capsule";
    };
    // the convex polygon the new body has (given by setNewBody: the control offers it while it is chosen)
    /** @type {Manifold.Vertices | null} */
    let ownPolygon = null;
    const shapeChosen = function () {
      showShapeNumber();
      const kind = shapeSelect.value;
      if (kind !== "vertices") {
        ownPolygon = null;
        vertexOption.hidden = true;
      } else if (ownPolygon !== null) {
        // the same polygon, scaled to reach the size
        const k = Number(sizeSlider.value) / W.ManifoldWeb.world.reachOf(ownPolygon, 0), own = ownPolygon;
        /** @type {Manifold.Vertices} */
        const scaled = { vertices: own.vertices.map(function (c) { return /** @type {[number, number]} */ ([k * c[0], k * c[1]]); }) };
        if (own.radius) scaled.radius = k * own.radius;
        return handlers.onNewBody({ shape: scaled });
      }
      if (kind === "box" || kind === "capsule") {
        // its numbers from the size (how far it reaches from its centre) and the aspect
        const size = Number(sizeSlider.value), k = Number(aspect.value);
        if (!(k >= 1 && k <= 400) || (kind === "capsule" && k === 1)) {
          showNotice(kind === "box" ? "A box's length over its width is 1 to 400." : "A capsule's length over its width is above 1, to 400.");
          return undefined;
        }
        if (kind === "box") {
          const q = size / Math.hypot(k, 1);
          return handlers.onNewBody({ shape: { box: [k * q, q] } });
        }
        return handlers.onNewBody({ shape: { capsule: [size - size / k, size / k] } });
      }
      if (kind !== "polygon") return handlers.onNewBody({ shape: /** @type {"circle" | "square"} */ (kind) });
      const n = Math.round(Number(sides.value));
      if (!(n >= 3 && n <= 64)) {
        showNotice("A polygon has 3 to 64 sides.");
        return undefined;
      }
      sides.value = String(n);
      return handlers.onNewBody({ shape: { polygon: n } });
    };
    shapeSelect.addEventListener("change", shapeChosen);
    sides.addEventListener("change", function () { if (shapeSelect.value === "polygon") shapeChosen(); });
    aspect.addEventListener("change", shapeChosen);
    sizeSlider.addEventListener("input", function () {
      // a box's, a capsule's or a polygon's size is its numbers': they are made anew from the slider
      if (!aspect.hidden || shapeSelect.value === "vertices") shapeChosen();
      else handlers.onNewBody({ size: Number(sizeSlider.value) });
    });
    densityInput.addEventListener("change", function () { handlers.onNewBody({ density: Number(densityInput.value) }); });
    staticBox.addEventListener("change", function () { handlers.onNewBody({ static: staticBox.checked }); });
    $("add-body").addEventListener("click", function () { handlers.onAdd(); });
    // the tool, the geodesic's length, trails
    /** @type {HTMLSelectElement} */
    const toolSelect = $("tool");
    /** @type {HTMLInputElement} */
    const lengthInput = $("geodesic-length");
    /** @type {HTMLInputElement} */
    const trailsBox = $("trails");
    toolSelect.addEventListener("change", function () { handlers.onTool(toolSelect.value); });
    lengthInput.addEventListener("change", function () { handlers.onGeodesicLength(Number(lengthInput.value)); });
    trailsBox.addEventListener("change", function () { handlers.onTrails(trailsBox.checked); });
    /** @type {HTMLInputElement} */
    const plotBox = $("plot-toggle");
    plotBox.addEventListener("change", function () { handlers.onPlot(plotBox.checked); });
    /** @type {HTMLSelectElement} */
    const presetSelect = $("preset");
    presetSelect.addEventListener("change", function () { if (presetSelect.value) handlers.onPreset(presetSelect.value); });
    $("clear").addEventListener("click", function () { handlers.onClear(); });
    $("reset-scene").addEventListener("click", function () { handlers.onReset(); });
    pause.addEventListener("click", function () { handlers.onPause(); });
    $("step").addEventListener("click", function () { handlers.onStep(); });
    timeScale.addEventListener("change", function () { handlers.onTimeScale(Number(timeScale.value)); });
    physicsThread.addEventListener("change", function () { handlers.onThread(physicsThread.value); });
    $("save-scene").addEventListener("click", function () { handlers.onSave(); });
    $("load-scene").addEventListener("click", function () { sceneFile.click(); });
    sceneFile.addEventListener("change", function () {
      const f = sceneFile.files && sceneFile.files[0];
      sceneFile.value = "";
      if (f) handlers.onLoad(f);
    });
    // capture: the Record button reads Stop (pressed, its red dot shown) while recording
    /** @type {HTMLButtonElement} */
    const record = $("record");
    const recordLabel = $("record-label");
    const recordDot = $("record-dot");
    const recordTitle = record.title;
    $("save-image").addEventListener("click", function () { handlers.onSaveImage(); });
    record.addEventListener("click", function () { handlers.onRecord(); });

    // the controls' panel collapses (to a rail beside the view, to its head
    // above it on narrow screens) and opens again; the view takes the room
    const panel = $("panel"), panelToggle = $("panel-toggle");
    const showPanel = function (/** @type {boolean} */ shown) {
      panel.classList.toggle("collapsed", !shown);
      panelToggle.setAttribute("aria-expanded", String(shown));
      panelToggle.setAttribute("aria-label", shown ? "hide the controls" : "show the controls");
      panelToggle.title = shown ? "hide the controls (the view takes their room)" : "show the controls";
      /** @type {HTMLElement} */ (panelToggle.firstElementChild).textContent = shown ? "«" : "»";
    };
    panelToggle.addEventListener("click", function () { showPanel(panel.classList.contains("collapsed")); });

    // keys: what each does (the help overlay, #keys-help in index.html, lists
    // them with the gestures); Space, s and r and c act as Pause, Step, Reset
    // and Clear, g switches the geodesic tool on and off, t the trails, p the plot; a
    // held s steps on, the others act once; b hides
    // and shows the controls
    /** @type {HTMLDialogElement} */
    const keysHelp = $("keys-help");
    /** @type {Map<string, () => void>} */
    const keys = new Map([
      [" ", function () { handlers.onPause(); }],
      ["s", function () { handlers.onStep(); }],
      ["r", function () { handlers.onReset(); }],
      ["c", function () { handlers.onClear(); }],
      ["g", function () { handlers.onTool(toolSelect.value === "geodesic" ? "grab" : "geodesic"); }],
      ["j", function () { handlers.onTool(toolSelect.value === "joint" ? "grab" : "joint"); }],
      ["t", function () { handlers.onTrails(!trailsBox.checked); }],
      ["p", function () { handlers.onPlot(!plotBox.checked); }],
      ["b", function () { panelToggle.click(); }],
      ["?", function () { keysHelp.showModal(); }],
    ]);
    $("keys-help-open").addEventListener("click", function () { if (!keysHelp.open) keysHelp.showModal(); });
    $("keys-help-close").addEventListener("click", function () { keysHelp.close(); });
    // a click on the backdrop (the dialog itself, around its body) closes it too
    keysHelp.addEventListener("click", function (e) { if (e.target === keysHelp) keysHelp.close(); });
    document.addEventListener("keydown", function (e) {
      // Ctrl, Alt and Meta are the browser's (and the system's)
      if (e.defaultPrevented || e.ctrlKey || e.altKey || e.metaKey || e.isComposing) return;
      const key = e.key.length === 1 ? e.key.toLowerCase() : e.key;
      if (keysHelp.open) {
        // the overlay is modal: ? and Escape close it, the other keys are its close button's
        if (key === "?" || key === "Escape") {
          e.preventDefault();
          if (!e.repeat) keysHelp.close();
        }
        return;
      }
      const act = keys.get(key);
      if (!act || typingIn(e.target) || (key === " " && ticksWithSpace(e.target))) return;
      // the page acts: Space neither scrolls nor presses the focused button too
      e.preventDefault();
      if (e.repeat && key !== "s") return;
      act();
    });

    /** @param {string} text */
    function showNotice(text) {
      noticeText.textContent = text;
      notice.hidden = false;
    }
    /** @param {boolean} on */
    function setPaused(on) {
      if (pause.getAttribute("aria-pressed") === String(on)) return;
      pause.textContent = on ? "Resume" : "Pause";
      pause.setAttribute("aria-pressed", String(on));
    }

    return {
      canvas: canvas,
      /** @type {HTMLCanvasElement} */
      plotCanvas: $("plot"),
      inspector: $("inspector"),
      /** @param {{ name: string, label?: string, description: string }[]} index */
      setSpaces: function (index) {
        spaceSelect.textContent = "";
        index.forEach(function (s) {
          const opt = document.createElement("option");
          opt.value = s.name;
          opt.textContent = s.label || s.name;
          opt.title = s.description;
          spaceSelect.appendChild(opt);
        });
        spaceSelect.disabled = index.length === 0;
      },
      /** @param {{ name: string, description: string, metric?: Manifold.Metric }} entry */
      setSpace: function (entry) {
        spaceSelect.value = entry.name;
        description.textContent = entry.description;
        description.title = entry.description;
        document.title = "Manifold: " + entry.name;
        // (the model control is for hyperbolic spaces)
        modelControl.hidden = entry.metric !== "minkowski";
      },
      /** @param {Manifold.Model} model */
      setModel: function (model) { modelSelect.value = model; },
      // the help line for a flat view (dragging walks) or the traced surface (dragging orbits)
      /** @param {boolean} flat */
      setFlatHelp: function (flat) {
        if (help.classList.contains("flat") === flat) return;
        help.classList.toggle("flat", flat);
        help.textContent = flat ? FLAT_HELP : tracedHelp;
      },
      /** @param {boolean} on */
      setCurvature: function (on) {
        curvatureBox.checked = on;
        legend.hidden = !on;
      },
      /** @param {boolean} on */
      setGrid: function (on) { gridBox.checked = on; },
      /** @param {boolean} on */
      setDimSleeping: function (on) { dimBox.checked = on; },
      // the new body's controls: its template, and the space's own size (the slider spans a quarter to three times it)
      /** @param {{ shape: Manifold.Shape, size: number | null, density: number, static: boolean }} t @param {number} own */
      setNewBody: function (t, own) {
        // a box's, a capsule's or a polygon's size (its reach), and a box's or a capsule's aspect, from its numbers
        const world = W.ManifoldWeb.world;
        const shaped = world.sizedByShape(t.shape) ? world.reachOf(t.shape, 0) : null;
        ownPolygon = null;
        if (typeof t.shape === "string") shapeSelect.value = t.shape;
        else if ("polygon" in t.shape) {
          shapeSelect.value = "polygon";
          sides.value = String(t.shape.polygon);
        } else if ("box" in t.shape) {
          shapeSelect.value = "box";
          aspect.value = String(Number((t.shape.box[0] / t.shape.box[1]).toPrecision(4)));
        } else if ("vertices" in t.shape) {
          shapeSelect.value = "vertices";
          ownPolygon = t.shape;
        } else {
          shapeSelect.value = "capsule";
          aspect.value = String(Number(((t.shape.capsule[0] + t.shape.capsule[1]) / t.shape.capsule[1]).toPrecision(4)));
        }
        vertexOption.hidden = ownPolygon === null;
        showShapeNumber();
        const step = Number((own / 50).toPrecision(1));
        sizeSlider.min = String(Math.max(step, own / 4));
        sizeSlider.max = String(3 * own);
        sizeSlider.step = String(step);
        sizeMark.value = String(own);
        const size = shaped !== null ? shaped : t.size === null ? own : t.size;
        sizeSlider.value = String(size);
        sizeValue.textContent = Number(size.toPrecision(3)) + (shaped === null && t.size === null ? " (the space's)" : "");
        densityInput.value = String(t.density);
        staticBox.checked = t.static;
      },
      /** @param {string} tool */
      setTool: function (tool) { toolSelect.value = tool; },
      /** @param {number} len */
      setGeodesicLength: function (len) { lengthInput.value = String(Number(len.toPrecision(4))); },
      /** @param {boolean} on */
      setTrails: function (on) { trailsBox.checked = on; },
      /** @param {boolean} on */
      setPlot: function (on) { plotBox.checked = on; },
      /** @param {Manifold.Antialias} mode */
      setAntialias: function (mode) { antialiasSelect.value = mode; },
      /** @param {string} text */
      setStats: function (text) { stats.textContent = text; },
      // err: a PageError (or any Error); title: the panel's heading
      /** @param {string} title @param {Shown} err */
      showError: function (title, err) {
        messageTitle.textContent = title;
        messageText.textContent = err.message || String(err);
        const log = err.log || "";
        messageLog.textContent = log;
        messageLog.hidden = !log;
        messageSource.textContent = err.source ? numberSource(err.source) : "";
        messageSourceBox.hidden = !err.source;
        message.hidden = false;
        canvas.classList.add("failed");
      },
      clearError: function () {
        message.hidden = true;
        messageLog.textContent = "";
        messageSource.textContent = "";
        canvas.classList.remove("failed");
      },
      showNotice: showNotice,
      setPaused: setPaused,
      // {paused, timeScale, gravity, substeps, friction, …} → the controls
      // (a number outside its slider's extent: the slider at its end, the
      // output the value)
      /** @param {Manifold.Simulation} o */
      setSimulation: function (o) {
        setPaused(!!o.paused);
        const ts = String(o.timeScale);
        if (!Array.from(timeScale.options).some(function (opt) { return opt.value === ts; })) {
          const opt = document.createElement("option");
          opt.value = ts;
          opt.textContent = ts + "×";
          timeScale.appendChild(opt);
        }
        timeScale.value = ts;
        physicsThread.value = o.thread;
        const values = /** @type {Record<string, unknown>} */ (/** @type {unknown} */ (o));
        engineSettings.forEach(function (s) {
          const v = values[s.key.key];
          if (s.output === null) {
            s.input.checked = !!v;
          } else if (typeof v === "number") {
            s.input.value = String(v);
            s.output.textContent = v.toFixed(s.decimals);
          }
        });
      },
      hideNotice: function () { notice.hidden = true; },
      /** @param {boolean} on */
      setRecording: function (on) {
        recordLabel.textContent = on ? "Stop" : "Record";
        record.setAttribute("aria-pressed", String(on));
        recordDot.hidden = !on;
        record.title = on ? "stop recording and download the video" : recordTitle;
      },
      // the presets, grouped by space in the catalogue's order; "" heads the list (none)
      /** @param {{ name: string, space: string, title: string }[]} presets @param {string[]} spaces */
      setPresets: function (presets, spaces) {
        presetSelect.textContent = "";
        const none = document.createElement("option");
        none.value = "";
        none.textContent = presets.length ? "—" : "(none built)";
        presetSelect.appendChild(none);
        spaces.forEach(function (space) {
          const mine = presets.filter(function (p) { return p.space === space; });
          if (!mine.length) return;
          const group = document.createElement("optgroup");
          group.label = space;
          mine.forEach(function (p) {
            const opt = document.createElement("option");
            opt.value = p.name;
            opt.textContent = p.title;
            opt.title = p.name;
            group.appendChild(opt);
          });
          presetSelect.appendChild(group);
        });
        presetSelect.disabled = presets.length === 0;
      },
      /** @param {string | null} name */
      setPreset: function (name) { presetSelect.value = name || ""; },
      // the browser cannot record: the Record button disabled, its title saying why
      /** @param {string} why */
      setRecordingUnavailable: function (why) {
        record.disabled = true;
        record.title = "Recording is not available: " + why;
      },
    };
  }

  const exported = { createUI: createUI, parseHash: parseHash, formatHash: formatHash, numberSource: numberSource };
  W.ManifoldWeb = W.ManifoldWeb || /** @type {ManifoldWebModules} */ ({});
  W.ManifoldWeb.ui = exported;
  return exported;
})(globalThis);
