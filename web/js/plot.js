// The live plot: the world's kinetic energy, its bodies' angular momentum
// about the space's axis (where it has one: flat for free bodies on a
// surface of revolution, Clairaut), the contact rows and the physics time
// per step over the last 30 s of simulated time, sampled every 0.1 s by
// the engine's generated measures (Manifold.Measures), drawn on a small 2D
// canvas over the view. Each line has its own scale, from 0 (or its
// lowest, if below) to its highest, so that a constant reads as a flat
// line, not as its noise.
/* exported ManifoldWebPlot */
var ManifoldWebPlot = (function (W) {
  "use strict";
  const MW = W.ManifoldWeb;
  const P = MW.page, state = P.state;

  // a sample every `every` simulated seconds, `seconds` of them kept
  const PLOT = { every: 0.1, seconds: 30 };
  const CAPACITY = Math.round(PLOT.seconds / PLOT.every) + 1;
  /** @typedef {"kineticEnergy" | "axialMomentum" | "contacts" | "stepMs"} Series */
  /** @type {{ key: Series, label: string, colour: string }[]} */
  const SERIES = [
    { key: "kineticEnergy", label: "energy", colour: "#ffd75e" },
    { key: "axialMomentum", label: "axial momentum", colour: "#7fd6ff" },
    { key: "contacts", label: "contacts", colour: "#ff8f7a" },
    { key: "stepMs", label: "ms/step", colour: "#a9e37b" },
  ];

  const plot = {
    on: false,
    world: /** @type {ManifoldWeb.World | null} */ (null),
    stepsPerSample: 1,
    lastStep: -Infinity,
    /** @type {number[]} the simulated time of each sample (s) */
    time: [],
    /** @type {Record<Series, number[]>} */
    values: { kineticEnergy: [], axialMomentum: [], contacts: [], stepMs: [] },
    version: 0,           // bumped with each sample
    drawnVersion: -1,
  };

  function reset() {
    plot.world = null;
    plot.time = [];
    SERIES.forEach(function (s) { plot.values[s.key] = []; });
    plot.version++;
  }

  /** @param {boolean} on */
  function setPlot(on) {
    if (typeof on !== "boolean") throw new TypeError("the plot is on (true) or off (false)");
    plot.on = on;
    reset();
    if (state.ui) state.ui.setPlot(on);
  }

  // Takes a sample when the world has stepped on by PLOT.every seconds (the
  // frame loop calls this); a new world starts the plot again.
  function sample() {
    const w = state.world;
    if (!plot.on || !w || state.compare) return;
    if (plot.world !== w) {
      reset();
      plot.world = w;
      plot.stepsPerSample = Math.max(1, Math.round(PLOT.every / w.param("dt")));
      plot.lastStep = -Infinity;
    }
    if (w.steps - plot.lastStep < plot.stepsPerSample) return;
    plot.lastStep = w.steps;
    const m = w.measures();
    plot.time.push(w.steps * w.param("dt"));
    plot.values.kineticEnergy.push(m.kineticEnergy);
    plot.values.axialMomentum.push(m.axialMomentum);
    plot.values.contacts.push(w.meta("contactCount"));
    plot.values.stepMs.push(w.stepMs === null ? 0 : w.stepMs);
    if (plot.time.length > CAPACITY) {
      plot.time.shift();
      SERIES.forEach(function (s) { plot.values[s.key].shift(); });
    }
    plot.version++;
  }

  // the series this space plots: axial momentum only where it has an axis
  function shown() {
    return SERIES.filter(function (s) { return s.key !== "axialMomentum" || (state.space && state.space.axis); });
  }

  /** @param {number} x */
  function short(x) {
    const a = Math.abs(x);
    return a !== 0 && (a < 0.01 || a >= 1e4) ? x.toExponential(2) : x.toFixed(a < 1 ? 3 : a < 100 ? 2 : 0);
  }

  // Draws the plot into its canvas when a sample came since the last draw.
  function draw() {
    const canvas = state.ui && state.ui.plotCanvas;
    if (!canvas) return;
    canvas.hidden = !plot.on || !!state.compare;
    if (canvas.hidden || plot.drawnVersion === plot.version) return;
    plot.drawnVersion = plot.version;
    const dpr = W.devicePixelRatio || 1, r = canvas.getBoundingClientRect();
    const w = Math.max(1, Math.round(r.width * dpr)), h = Math.max(1, Math.round(r.height * dpr));
    if (canvas.width !== w || canvas.height !== h) { canvas.width = w; canvas.height = h; }
    const g = /** @type {CanvasRenderingContext2D} */ (canvas.getContext("2d"));
    g.setTransform(dpr, 0, 0, dpr, 0, 0);
    const cw = r.width, ch = r.height, top = 34, bottom = ch - 6, left = 6, right = cw - 6;
    g.clearRect(0, 0, cw, ch);
    g.fillStyle = "rgba(12, 14, 20, 0.78)";
    g.fillRect(0, 0, cw, ch);
    const n = plot.time.length, t1 = n ? plot.time[n - 1] : 0, t0 = t1 - PLOT.seconds;
    const series = shown();
    g.font = "11px system-ui, sans-serif";
    g.textBaseline = "top";
    series.forEach(function (s, k) {
      const v = plot.values[s.key];
      const x0 = left + (k % 2) * (cw / 2), y0 = 4 + Math.floor(k / 2) * 14;
      g.fillStyle = s.colour;
      g.fillText(s.label + " " + (v.length ? short(v[v.length - 1]) : "–"), x0, y0);
      if (v.length < 2) return;
      let lo = 0, hi = 0;
      for (const x of v) { lo = Math.min(lo, x); hi = Math.max(hi, x); }
      if (hi - lo <= 0) hi = lo + 1;
      const span = (hi - lo) * 1.1;
      g.strokeStyle = s.colour;
      g.lineWidth = 1.5;
      g.beginPath();
      for (let i = 0; i < n; i++) {
        const x = left + (right - left) * (plot.time[i] - t0) / PLOT.seconds;
        const y = bottom - (bottom - top) * (v[i] - lo) / span;
        if (i === 0) g.moveTo(x, y); else g.lineTo(x, y);
      }
      g.stroke();
    });
  }

  // The samples, for window.manifold.plot().
  function samples() {
    /** @type {Record<string, number[] | null>} */
    const out = { time: plot.time.slice() };
    SERIES.forEach(function (s) { out[s.key] = shown().indexOf(s) >= 0 ? plot.values[s.key].slice() : null; });
    return { on: plot.on, seconds: PLOT.seconds, every: PLOT.every, samples: out };
  }

  const exported = { PLOT: PLOT, plot: plot, setPlot: setPlot, sample: sample, draw: draw, samples: samples };
  W.ManifoldWeb = W.ManifoldWeb || /** @type {ManifoldWebModules} */ ({});
  W.ManifoldWeb.plot = exported;
  return exported;
})(globalThis);
