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

    return {
      canvas: canvas,
      setSpaces: function (index) {
        spaceSelect.textContent = "";
        index.forEach(function (s) {
          const opt = document.createElement("option");
          opt.value = s.name;
          opt.textContent = s.name;
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
      showNotice: function (text) {
        noticeText.textContent = text;
        notice.hidden = false;
      },
      hideNotice: function () { notice.hidden = true; },
    };
  }

  W.ManifoldWeb = W.ManifoldWeb || {};
  W.ManifoldWeb.ui = { createUI: createUI, parseHash: parseHash, formatHash: formatHash, numberSource: numberSource };
})(globalThis);
