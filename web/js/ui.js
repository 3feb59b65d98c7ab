// The page's controls and messages: the space selector, the curvature and
// antialiasing options, the stats line, the error panel, and the URL hash.
(function (W) {
  "use strict";

  function $(id) {
    const el = document.getElementById(id);
    if (!el) throw new Error("index.html lacks #" + id);
    return el;
  }

  // "#space=torus&curvature=1" → { space: "torus", curvature: "1" }
  function parseHash(hash) {
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
  function formatHash(params) {
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
  function numberSource(source) {
    let line = 1, string = 0;
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

  function createUI(handlers) {
    const spaceSelect = $("space");
    const curvatureBox = $("curvature");
    const gridBox = $("grid");
    const antialiasSelect = $("antialias");
    const resetButton = $("reset-view");
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
    const canvas = $("view");

    spaceSelect.addEventListener("change", function () { handlers.onSpace(spaceSelect.value); });
    curvatureBox.addEventListener("change", function () { handlers.onCurvature(curvatureBox.checked); });
    gridBox.addEventListener("change", function () { handlers.onGrid(gridBox.checked); });
    antialiasSelect.addEventListener("change", function () { handlers.onAntialias(antialiasSelect.value); });
    resetButton.addEventListener("click", function () { handlers.onResetView(); });
    $("notice-close").addEventListener("click", function () { notice.hidden = true; });

    // bodies and simulation
    const sides = $("polygon-sides");
    const pause = $("pause");
    const timeScale = $("time-scale");
    const gravity = $("gravity");
    const friction = $("friction"), frictionValue = $("friction-value");
    const restitution = $("restitution"), restitutionValue = $("restitution-value");
    const sceneFile = $("scene-file");
    $("add-circle").addEventListener("click", function () { handlers.onAdd("circle"); });
    $("add-square").addEventListener("click", function () { handlers.onAdd("square"); });
    $("add-polygon").addEventListener("click", function () {
      const n = Math.round(Number(sides.value));
      if (!(n >= 3 && n <= 64)) {
        showNotice("A polygon has 3 to 64 sides.");
        return;
      }
      sides.value = n;
      handlers.onAdd({ polygon: n });
    });
    $("clear").addEventListener("click", function () { handlers.onClear(); });
    $("reset-scene").addEventListener("click", function () { handlers.onReset(); });
    pause.addEventListener("click", function () { handlers.onPause(); });
    $("step").addEventListener("click", function () { handlers.onStep(); });
    timeScale.addEventListener("change", function () { handlers.onTimeScale(Number(timeScale.value)); });
    gravity.addEventListener("change", function () { handlers.onGravity(gravity.checked); });
    friction.addEventListener("input", function () {
      frictionValue.textContent = Number(friction.value).toFixed(2);
      handlers.onFriction(Number(friction.value));
    });
    restitution.addEventListener("input", function () {
      restitutionValue.textContent = Number(restitution.value).toFixed(2);
      handlers.onRestitution(Number(restitution.value));
    });
    $("save-scene").addEventListener("click", function () { handlers.onSave(); });
    $("load-scene").addEventListener("click", function () { sceneFile.click(); });
    sceneFile.addEventListener("change", function () {
      const f = sceneFile.files && sceneFile.files[0];
      sceneFile.value = "";
      if (f) handlers.onLoad(f);
    });

    function showNotice(text) {
      noticeText.textContent = text;
      notice.hidden = false;
    }
    function setPaused(on) {
      if (pause.getAttribute("aria-pressed") === String(on)) return;
      pause.textContent = on ? "Resume" : "Pause";
      pause.setAttribute("aria-pressed", String(on));
    }

    return {
      canvas: canvas,
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
      setSpace: function (entry) {
        spaceSelect.value = entry.name;
        description.textContent = entry.description;
        description.title = entry.description;
        document.title = "Manifold: " + entry.name;
      },
      setCurvature: function (on) {
        curvatureBox.checked = on;
        legend.hidden = !on;
      },
      setGrid: function (on) { gridBox.checked = on; },
      setAntialias: function (mode) { antialiasSelect.value = mode; },
      setStats: function (text) { stats.textContent = text; },
      // err: a PageError (or any Error); title: the panel's heading
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
      // {paused, timeScale, gravity, friction, restitution} → the controls
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
        gravity.checked = !!o.gravity;
        if (typeof o.friction === "number") {
          friction.value = o.friction;
          frictionValue.textContent = o.friction.toFixed(2);
        }
        if (typeof o.restitution === "number") {
          restitution.value = o.restitution;
          restitutionValue.textContent = o.restitution.toFixed(2);
        }
      },
      hideNotice: function () { notice.hidden = true; },
    };
  }

  W.ManifoldWeb = W.ManifoldWeb || {};
  W.ManifoldWeb.ui = { createUI: createUI, parseHash: parseHash, formatHash: formatHash, numberSource: numberSource };
})(globalThis);
