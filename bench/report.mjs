// Writes the benchmark results into bench/README.md (between the markers
// <!-- results:begin --> and <!-- results:end -->) and draws bench/scaling.png
// (step ms against bodies, log–log, one panel per space, native and browser)
// with a <canvas> in headless Chromium.
//
//   node bench/report.mjs [--native bench/results/native.json] [--browser bench/results/browser.json]
//                         [--node bench/results/node.json] [--readme bench/README.md] [--png bench/scaling.png]
//
// native.json: `manifold bench --json`; browser.json: `node bench/browser.mjs --out`;
// node.json (optional): `node bench/node.mjs DIR`. A missing file leaves its columns empty.
import { execFileSync } from "node:child_process";
import fs from "node:fs";
import os from "node:os";
import path from "node:path";
import url from "node:url";
import { launchBrowser } from "../test/browser/lib.mjs";
import { commandLine } from "./options.mjs";

const HERE = path.dirname(url.fileURLToPath(import.meta.url));
const ROOT = path.resolve(HERE, "..");
const { text: arg } = commandLine({
  usage: "node bench/report.mjs [--native FILE.json] [--browser FILE.json] [--node FILE.json] [--readme FILE.md] [--png FILE.png]",
  known: ["--native", "--browser", "--node", "--readme", "--png"],
});
const files = {
  native: path.resolve(arg("--native", path.join(HERE, "results/native.json"))),
  browser: path.resolve(arg("--browser", path.join(HERE, "results/browser.json"))),
  node: path.resolve(arg("--node", path.join(HERE, "results/node.json"))),
};
const readmeFile = path.resolve(arg("--readme", path.join(HERE, "README.md")));
const pngFile = path.resolve(arg("--png", path.join(HERE, "scaling.png")));

const SPACES = ["plane", "sphere", "torus", "trumpet", "projective-plane", "rectangle"];
const SIZES = [10, 100, 300, 1000, 3000];
const TARGET = { torusMs: 16, torusN: 1000, ratio: 3.5, from: 1000, to: 3000 };
const BEGIN = "<!-- results:begin -->", END = "<!-- results:end -->";

function readJson(file) {
  if (!fs.existsSync(file)) return null;
  return { value: JSON.parse(fs.readFileSync(file, "utf8")), mtime: fs.statSync(file).mtime };
}
const nativeJ = readJson(files.native), browserJ = readJson(files.browser), nodeJ = readJson(files.node);
if (!nativeJ && !browserJ) {
  console.error("neither " + path.relative(process.cwd(), files.native) + " nor " + path.relative(process.cwd(), files.browser) +
    " exists; see bench/README.md for the commands");
  process.exit(2);
}
const browser = browserJ ? browserJ.value.results : [];
const fpsRows = browserJ ? browserJ.value.fps || [] : [];

// The native and node results carry the bodies placed, not the N asked for:
// the scenes are the same (`manifold bench --scenes`), so N is the browser's
// N of the same space and body count; failing that, the position among the
// default sizes when a space has all five; else the body count.
function withN(rows) {
  const bySpace = {};
  rows.forEach((r) => (bySpace[r.space] = bySpace[r.space] || []).push(r));
  return rows.map((r) => {
    const b = browser.find((x) => x.space === r.space && x.bodies === r.bodies);
    const same = bySpace[r.space];
    const n = b ? b.n : same.length === SIZES.length ? SIZES[same.indexOf(r)] : r.bodies;
    return Object.assign({ n }, r);
  });
}
const native = nativeJ ? withN(nativeJ.value) : [];
const node = nodeJ ? withN(nodeJ.value) : [];

// every (space, N) in catalogue order
const keyOf = (r) => r.space + " " + r.n;
const cases = [];
for (const r of native.concat(browser, node)) {
  if (!cases.find((c) => keyOf(c) === keyOf(r))) cases.push({ space: r.space, n: r.n });
}
const order = (s) => (SPACES.indexOf(s) < 0 ? 99 : SPACES.indexOf(s));
cases.sort((a, b) => order(a.space) - order(b.space) || a.space.localeCompare(b.space) || a.n - b.n);
const find = (rows, c) => rows.find((r) => r.space === c.space && r.n === c.n) || null;
const spaces = [...new Set(cases.map((c) => c.space))];

// ---- the machine ------------------------------------------------------------------------------
function sh(cmd, args) {
  try { return execFileSync(cmd, args, { encoding: "utf8", stdio: ["ignore", "pipe", "ignore"], cwd: ROOT }).trim(); } catch (e) { return null; }
}
function machine() {
  const cpuinfo = fs.existsSync("/proc/cpuinfo") ? fs.readFileSync("/proc/cpuinfo", "utf8") : "";
  const model = (cpuinfo.match(/^model name\s*:\s*(.*)$/m) || [])[1] || os.cpus()[0]?.model || "?";
  const mhz = (cpuinfo.match(/^cpu MHz\s*:\s*(.*)$/m) || [])[1];
  const osRelease = fs.existsSync("/etc/os-release") ? (fs.readFileSync("/etc/os-release", "utf8").match(/^PRETTY_NAME="?([^"\n]*)/m) || [])[1] : null;
  const env = browserJ ? browserJ.value.environment || {} : {};
  const chromium = env.browserVersion ? "Chromium " + env.browserVersion : (sh("chromium", ["--version"]) || "?").split("\n").pop();
  return [
    ["CPU", model + (mhz ? " (" + Math.round(Number(mhz)) + " MHz)" : "")],
    ["cores (nproc)", sh("nproc", []) || String(os.cpus().length)],
    ["memory", (os.totalmem() / 2 ** 30).toFixed(1) + " GiB"],
    ["OS", (osRelease || os.type()) + ", Linux " + os.release()],
    ["GHC", sh("ghc", ["--numeric-version"]) || "?"],
    ["node", process.version],
    ["browser", chromium + ", headless, software WebGL2 (SwiftShader)" +
      (env.crossOriginIsolated ? ", cross-origin isolated (performance.now() tick " + (env.timerTickMs * 1000).toFixed(0) + " µs)" : "")],
    ["page", env.viewport ? env.viewport + " viewport, canvas " + env.canvas + ", " + env.antialias : "?"],
  ];
}

// ---- tables --------------------------------------------------------------------------------
const ms = (x) => (x === null || x === undefined || !isFinite(x) ? "–" : x < 0.1 ? x.toFixed(3) : x < 10 ? x.toFixed(2) : x < 100 ? x.toFixed(1) : x.toFixed(0));
const ratio = (x) => (x === null || !isFinite(x) ? "–" : x.toFixed(2));
const spread = (r) => (r ? ms(r.medianMs) + " (" + ms(r.p10Ms) + "–" + ms(r.p90Ms) + ")" : "–");
const table = (head, rows) => ["| " + head.join(" | ") + " |", "|" + head.map((h, i) => (i < 2 ? "---" : "---:")).join("|") + "|"]
  .concat(rows.map((r) => "| " + r.join(" | ") + " |")).join("\n");
const pass = (ok) => (ok === null ? "–" : ok ? "**yes**" : "**no**");

// log–log slope of median ms against bodies (least squares over the sizes measured)
function slope(rows) {
  const pts = rows.filter((r) => r && r.bodies > 0 && r.medianMs > 0).map((r) => [Math.log(r.bodies), Math.log(r.medianMs)]);
  if (pts.length < 2) return null;
  const mx = pts.reduce((s, p) => s + p[0], 0) / pts.length, my = pts.reduce((s, p) => s + p[1], 0) / pts.length;
  const sxx = pts.reduce((s, p) => s + (p[0] - mx) ** 2, 0), sxy = pts.reduce((s, p) => s + (p[0] - mx) * (p[1] - my), 0);
  return sxx > 0 ? sxy / sxx : null;
}

function report() {
  const out = [];
  const when = [];
  if (nativeJ) when.push("native " + nativeJ.mtime.toISOString().slice(0, 16).replace("T", " ") + " UTC");
  if (browserJ) when.push("browser " + (browserJ.value.date || browserJ.mtime.toISOString()).slice(0, 16).replace("T", " ") + " UTC");
  if (nodeJ) when.push("node " + nodeJ.mtime.toISOString().slice(0, 16).replace("T", " ") + " UTC");
  out.push("Generated by `node bench/report.mjs` from " + when.join(", ") + ".");
  const settings = [];
  const nSteps = native.length ? native[0].steps : null;
  const fastestOf = (r) => r > 1 ? ", the fastest of " + r + " rounds" : "";
  // runs before the benchmarks learnt to settle once (2026-11-22) left "settle" out and settled for "warmup" steps
  const settled = (settle) => (settle === undefined ? "" : settle === null ? "scenes as `manifold bench --scenes` wrote them, " : "scenes settled " + settle + " steps, ");
  const warmedUp = (w, settle) => (w === undefined ? "" : w + (settle === undefined ? " steps to settle, " : " steps of warm-up, "));
  if (nSteps) settings.push("native: " + settled(native[0].settle) + warmedUp(native[0].warmup, native[0].settle) +
    nSteps + " steps timed" + fastestOf(native[0].rounds || 1));
  if (browserJ) settings.push("browser: " + settled(browserJ.value.settle) + warmedUp(browserJ.value.warmup, browserJ.value.settle) +
    browserJ.value.steps + " timed" + fastestOf(browserJ.value.rounds || 1));
  if (settings.length) out.push("Settings: " + settings.join("; ") + ".");
  out.push("");
  out.push("### Machine\n");
  out.push(table(["", ""], machine()));

  // targets
  out.push("\n### Targets\n");
  const trows = [];
  const torus = find(browser, { space: "torus", n: TARGET.torusN });
  trows.push(["browser torus " + TARGET.torusN + ": median step ≤ " + TARGET.torusMs + " ms",
    torus ? ms(torus.medianMs) + " ms (" + torus.bodies + " bodies; manifold.step " + ms(torus.apiMedianMs) + " ms)" : "not measured",
    pass(torus ? torus.medianMs <= TARGET.torusMs : null)]);
  for (const [label, rows] of [["native", native], ["browser", browser]]) {
    for (const s of spaces) {
      const a = find(rows, { space: s, n: TARGET.from }), b = find(rows, { space: s, n: TARGET.to });
      const r = a && b ? b.medianMs / a.medianMs : null;
      trows.push([label + " " + s + ": t(" + TARGET.to + ") / t(" + TARGET.from + ") ≤ " + TARGET.ratio,
        r === null ? "not measured" : ratio(r) + " (" + ms(b.medianMs) + " / " + ms(a.medianMs) + " ms, " + b.bodies + " / " + a.bodies + " bodies)",
        pass(r === null ? null : r <= TARGET.ratio)]);
    }
  }
  const both = cases.map((c) => [find(native, c), find(browser, c)]).filter(([a, b]) => a && b);
  const slower = both.filter(([a, b]) => a.medianMs > b.medianMs);
  trows.push(["native not slower than the browser (each scene)",
    both.length ? (both.length - slower.length) + " of " + both.length + " scenes" +
      (slower.length ? "; slower on " + slower.map(([a]) => a.space + " " + a.n).join(", ") : "") : "not measured",
    pass(both.length ? slower.length === 0 : null)]);
  out.push(table(["target", "measured", "met"], trows));

  // step times
  out.push("\n### Step time\n");
  out.push("Median ms per step (10 %–90 % quantiles). *native*: `manifold bench`; *browser*: the generated engine in the " +
    "page, each phase timed on its own and summed, as native does; *manifold.step*: `window.manifold.step(1)` timed whole" +
    (node.length ? "; *node*: `bench/node.mjs`" : "") + ". *native / browser* < 1: native is faster.\n");
  const head = ["space", "N", "bodies", "native", "browser", "manifold.step"].concat(node.length ? ["node"] : []).concat(["native / browser"]);
  out.push(table(head, cases.map((c) => {
    const a = find(native, c), b = find(browser, c), d = find(node, c);
    const bodies = [...new Set([a, b, d].filter((r) => r).map((r) => r.bodies))].join(" / ");
    return [c.space, c.n, bodies, spread(a), spread(b), b ? ms(b.apiMedianMs) : "–"].concat(node.length ? [spread(d)] : [])
      .concat([a && b ? ratio(a.medianMs / b.medianMs) : "–"]);
  })));

  // scaling
  out.push("\n### Scaling\n");
  out.push("Slope of log(step ms) against log(bodies), least squares over the sizes measured (1: linear), " +
    "and t(" + TARGET.to + ") / t(" + TARGET.from + ") (" + TARGET.to / TARGET.from + " for linear scaling; target ≤ " + TARGET.ratio + ").\n");
  out.push(table(["space", "native slope", "browser slope", "native t(3000)/t(1000)", "browser t(3000)/t(1000)"], spaces.map((s) => {
    const rs = (rows) => rows.filter((r) => r.space === s);
    const rr = (rows) => {
      const a = find(rows, { space: s, n: TARGET.from }), b = find(rows, { space: s, n: TARGET.to });
      return a && b ? ratio(b.medianMs / a.medianMs) : "–";
    };
    const sl = (x) => (x === null ? "–" : x.toFixed(2));
    return [s, sl(slope(rs(native))), sl(slope(rs(browser))), rr(native), rr(browser)];
  })));
  out.push("\n![step ms against bodies, log–log](scaling.png)");

  // what the scaling ratio is made of: how many more contact rows the larger
  // pile holds, what the contact phases cost per row at each size, and the
  // ratio the step would have if each row cost what it does at the smaller size
  // (the sub-steps hold the bodies' moves too, a small part of them in a pile)
  const contactPhases = ["collide", "prepare", "substeps", "finish"];
  const growth = [];
  for (const s of spaces) for (const [label, rows] of [["native", native], ["browser", browser]]) {
    const a = find(rows, { space: s, n: TARGET.from }), b = find(rows, { space: s, n: TARGET.to });
    if (!a || !b || !a.contacts || !b.contacts || !a.phaseMedianMs || !b.phaseMedianMs) continue;
    const sum = (r) => contactPhases.reduce((t, p) => t + (r.phaseMedianMs[p] || 0), 0);
    const rowsRatio = b.contacts / a.contacts, contactRatio = sum(b) / sum(a);
    const atSmallerCost = (sum(a) * rowsRatio + (b.medianMs - sum(b))) / a.medianMs;
    growth.push([s, label, ratio(a.contacts / a.bodies) + " → " + ratio(b.contacts / b.bodies), ratio(rowsRatio),
      ms(1000 * sum(a) / a.contacts) + " → " + ms(1000 * sum(b) / b.contacts), ratio(contactRatio / rowsRatio),
      ratio(b.medianMs / a.medianMs), ratio(atSmallerCost)]);
  }
  if (growth.length) {
    out.push("\nWhere the ratio comes from, on the spaces with contacts: contact rows per body, the rows' ratio, " +
      "collide + prepare + sub-steps + finish per row (µs) and its ratio, the step's ratio, and the ratio the step would have if every row " +
      "cost what it costs at " + TARGET.from + " bodies (the other phases as measured). Where that last column exceeds " +
      TARGET.ratio + ", the larger pile's extra rows alone break the target.\n");
    out.push(table(["space", "engine", "rows per body", "rows ×", "µs per row", "per row ×", "t(" + TARGET.to + ")/t(" + TARGET.from + ")",
      "at the " + TARGET.from + "-body cost per row"], growth));
  }

  // phases
  const phaseNames = [...new Set(native.concat(browser).flatMap((r) => Object.keys(r.phaseMedianMs || {})))];
  const canon = ["wake", "collide", "prepare", "substeps", "finish", "polygonise", "sleep"];
  const rank = (p) => (canon.indexOf(p) < 0 ? 99 : canon.indexOf(p));
  phaseNames.sort((a, b) => rank(a) - rank(b));
  if (phaseNames.length) {
    out.push("\n### Phases\n");
    out.push("Median ms of each phase of the step, native / browser.\n");
    out.push(table(["space", "N"].concat(phaseNames), cases.map((c) => {
      const a = find(native, c), b = find(browser, c);
      const ph = (r, p) => (r && r.phaseMedianMs && p in r.phaseMedianMs ? ms(r.phaseMedianMs[p]) : "–");
      return [c.space, c.n].concat(phaseNames.map((p) => ph(a, p) + " / " + ph(b, p)));
    })));
  }

  // frame rate
  if (fpsRows.length) {
    const env = browserJ.value.environment || {};
    out.push("\n### Frame rate\n");
    out.push("The page running the scene (clock on, rendering on) for " + browserJ.value.fpsSeconds + " s at " +
      (env.viewport || "800x600") + " (canvas " + (env.canvas || "?") + ", " + (env.antialias || "?") + "), software WebGL2: " +
      "frames per second, physics steps per second, physics ms per step (the page's moving average), and simulated " +
      "seconds per real second (the clock runs at most 10 steps and about 30 ms of physics per frame); and, measured " +
      "paused before, the median time of a frame that reuses the traced surface and draws the bodies after a step " +
      "(waited for), with the triangles the bodies took.\n");
    out.push(table(["space", "N", "bodies", "fps", "steps/s", "physics ms/step", "real time", "draw ms", "triangles"], fpsRows.map((f) =>
      [f.space, f.n, f.bodies, f.fps.toFixed(1), f.stepsPerSecond.toFixed(0), ms(f.physicsMsPerStep), f.realTime.toFixed(2) + "×",
        f.drawMs === undefined ? "–" : f.drawMs.toFixed(1), f.bodyForms ? String(f.bodyForms.triangles) : "–"])));
  }
  return out.join("\n");
}

// ---- the plot ------------------------------------------------------------------------------
function series(rows, s) {
  return rows.filter((r) => r.space === s && r.bodies > 0 && r.medianMs > 0).sort((a, b) => a.bodies - b.bodies)
    .map((r) => ({ x: r.bodies, y: r.medianMs, lo: r.p10Ms, hi: r.p90Ms }));
}
async function plot() {
  const data = {
    spaces,
    lines: [
      { label: "native (manifold bench)", colour: "#c0392b", dash: [], data: Object.fromEntries(spaces.map((s) => [s, series(native, s)])) },
      { label: "browser (Chromium)", colour: "#2166ac", dash: [10, 5], data: Object.fromEntries(spaces.map((s) => [s, series(browser, s)])) },
    ].concat(node.length ? [{ label: "node", colour: "#1b7837", dash: [3, 4], data: Object.fromEntries(spaces.map((s) => [s, series(node, s)])) }] : []),
    frameMs: TARGET.torusMs,
  };
  const browserP = await launchBrowser();
  try {
    const page = await browserP.newPage({ viewport: { width: 1500, height: 950 }, deviceScaleFactor: 1 });
    await page.setContent("<!doctype html><body style='margin:0;background:#fff'><canvas id=c width=1500 height=950></canvas></body>");
    const dataUrl = await page.evaluate(drawPlot, data);
    fs.mkdirSync(path.dirname(pngFile), { recursive: true });
    fs.writeFileSync(pngFile, Buffer.from(dataUrl.split(",")[1], "base64"));
  } finally {
    await browserP.close();
  }
}

// Runs in the page: draws the panels on the canvas and returns its PNG as a data URL.
function drawPlot(data) {
  const canvas = document.getElementById("c"), g = canvas.getContext("2d");
  const W = canvas.width, H = canvas.height;
  g.fillStyle = "#fff";
  g.fillRect(0, 0, W, H);
  const all = [];
  data.lines.forEach((l) => data.spaces.forEach((s) => l.data[s].forEach((p) => all.push(p))));
  const lx = all.map((p) => Math.log10(p.x)), ly = all.map((p) => Math.log10(p.y));
  // the ranges (log10): the points and the frame line with a margin, at least a decade
  const pad = 0.12;
  const x0 = Math.min(...lx) - pad, x1 = Math.max(x0 + 1, Math.max(...lx) + pad);
  const y0 = Math.min(...ly, Math.log10(data.frameMs)) - pad, y1 = Math.max(y0 + 1, Math.max(...ly, Math.log10(data.frameMs)) + pad);
  const n = data.spaces.length, cols = n <= 1 ? 1 : n <= 4 ? 2 : 3, rows = Math.ceil(n / cols);
  const top = 70, left = 20, right = 20, bottom = 20, gap = 20;
  const cw = (W - left - right - gap * (cols - 1)) / cols, ch = (H - top - bottom - gap * (rows - 1)) / rows;
  const fmt = (e) => (e >= 0 ? String(10 ** e) : String(10 ** e).replace(/^0/, ""));

  g.fillStyle = "#111";
  g.font = "bold 24px sans-serif";
  g.textBaseline = "alphabetic";
  g.fillText("Median step time against bodies (log–log; bars: 10 %–90 %)", left + 10, 32);
  // legend
  let lxp = left + 10;
  g.font = "17px sans-serif";
  const legend = data.lines.map((l) => [l.label, l.colour, l.dash, 3])
    .concat([["linear (slope 1)", "#888", [2, 4], 1.5], [data.frameMs + " ms (one 60 Hz frame)", "#e08a00", [], 1.5]]);
  for (const [label, colour, dash, width] of legend) {
    g.strokeStyle = colour; g.lineWidth = width; g.setLineDash(dash);
    g.beginPath(); g.moveTo(lxp, 55); g.lineTo(lxp + 40, 55); g.stroke();
    g.setLineDash([]);
    g.fillStyle = "#222"; g.fillText(label, lxp + 48, 61);
    lxp += 48 + g.measureText(label).width + 30;
  }

  data.spaces.forEach((s, k) => {
    const px = left + (k % cols) * (cw + gap), py = top + Math.floor(k / cols) * (ch + gap);
    const pl = px + 70, pr = px + cw - 12, pt = py + 34, pb = py + ch - 48;
    const X = (x) => pl + (Math.log10(x) - x0) / (x1 - x0) * (pr - pl);
    const Y = (y) => pb - (Math.log10(y) - y0) / (y1 - y0) * (pb - pt);
    g.strokeStyle = "#ccc"; g.lineWidth = 1; g.strokeRect(px + 0.5, py + 0.5, cw - 1, ch - 1);
    g.fillStyle = "#111"; g.font = "bold 19px sans-serif"; g.textAlign = "left"; g.fillText(s, pl + 6, py + 24);
    // grid: decades (labelled) and 2…9 (light)
    g.font = "14px sans-serif";
    for (let e = Math.floor(x0); e <= x1; e++) {
      for (let m = 1; m <= 9; m++) {
        const x = 10 ** e * m;
        if (Math.log10(x) < x0 || Math.log10(x) > x1) continue;
        g.strokeStyle = m === 1 ? "#bbb" : "#eee"; g.lineWidth = 1;
        g.beginPath(); g.moveTo(Math.round(X(x)) + 0.5, pt); g.lineTo(Math.round(X(x)) + 0.5, pb); g.stroke();
        if (m === 1 || m === 3) { g.fillStyle = "#333"; g.textAlign = "center"; g.fillText(fmt(e).replace(/^1/, String(m)), X(x), pb + 18); }
      }
    }
    for (let e = Math.floor(y0); e <= y1; e++) {
      for (let m = 1; m <= 9; m++) {
        const y = 10 ** e * m;
        if (Math.log10(y) < y0 || Math.log10(y) > y1) continue;
        g.strokeStyle = m === 1 ? "#bbb" : "#eee"; g.lineWidth = 1;
        g.beginPath(); g.moveTo(pl, Math.round(Y(y)) + 0.5); g.lineTo(pr, Math.round(Y(y)) + 0.5); g.stroke();
        if (m === 1 || (m === 3 && y1 - y0 < 2.5)) { g.fillStyle = "#333"; g.textAlign = "right"; g.fillText(fmt(e).replace(/1/, String(m)), pl - 6, Y(y) + 5); }
      }
    }
    g.strokeStyle = "#555"; g.strokeRect(pl, pt, pr - pl, pb - pt);
    g.fillStyle = "#333"; g.textAlign = "center"; g.fillText("bodies", (pl + pr) / 2, pb + 38);
    g.save(); g.translate(px + 18, (pt + pb) / 2); g.rotate(-Math.PI / 2); g.fillText("ms per step", 0, 0); g.restore();
    g.save(); g.beginPath(); g.rect(pl, pt, pr - pl, pb - pt); g.clip();
    // 60 Hz frame budget
    g.strokeStyle = "#e08a00"; g.lineWidth = 1.5; g.setLineDash([]);
    g.beginPath(); g.moveTo(pl, Y(data.frameMs)); g.lineTo(pr, Y(data.frameMs)); g.stroke();
    // slope-1 reference through the browser's (else native's) smallest point
    const ref = (data.lines[1].data[s][0] || data.lines[0].data[s][0]);
    if (ref) {
      g.strokeStyle = "#888"; g.lineWidth = 1.5; g.setLineDash([2, 4]);
      const xa = 10 ** x0, xb = 10 ** x1;
      g.beginPath(); g.moveTo(X(xa), Y(ref.y * xa / ref.x)); g.lineTo(X(xb), Y(ref.y * xb / ref.x)); g.stroke();
    }
    for (const l of data.lines) {
      const pts = l.data[s];
      if (!pts.length) continue;
      g.strokeStyle = l.colour; g.fillStyle = l.colour; g.lineWidth = 3; g.setLineDash(l.dash);
      g.beginPath();
      pts.forEach((p, i) => (i ? g.lineTo(X(p.x), Y(p.y)) : g.moveTo(X(p.x), Y(p.y))));
      g.stroke();
      g.setLineDash([]); g.lineWidth = 1.5;
      for (const p of pts) {
        // 10 %–90 % bar and the median's dot
        if (p.lo > 0 && p.hi > 0) { g.beginPath(); g.moveTo(X(p.x), Y(p.lo)); g.lineTo(X(p.x), Y(p.hi)); g.stroke(); }
        g.beginPath(); g.arc(X(p.x), Y(p.y), 5, 0, 2 * Math.PI); g.fill();
      }
    }
    g.restore();
  });
  return canvas.toDataURL("image/png");
}

// ---- write ---------------------------------------------------------------------------------
const body = report();
let readme = fs.existsSync(readmeFile) ? fs.readFileSync(readmeFile, "utf8") : "# Benchmarks\n\n" + BEGIN + "\n" + END + "\n";
const i = readme.indexOf(BEGIN), j = readme.indexOf(END);
readme = i >= 0 && j > i
  ? readme.slice(0, i + BEGIN.length) + "\n" + body + "\n" + readme.slice(j)
  : readme.trimEnd() + "\n\n## Results\n\n" + BEGIN + "\n" + body + "\n" + END + "\n";
fs.writeFileSync(readmeFile, readme);
console.error("wrote " + path.relative(process.cwd(), readmeFile));
await plot();
console.error("wrote " + path.relative(process.cwd(), pngFile));
console.log(body);
