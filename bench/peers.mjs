// The peer benchmark: the same flat scenes in Manifold's engine (the
// generated JavaScript of web/gen, on the rectangle) and in the 2-D engines
// a browser user would pick instead, Rapier 2D, planck.js and matter.js, in
// one Chromium page (the page of web/, as bench/browser.mjs drives it) and
// under node; the scenes, engines and measurements are bench/peers-engines.js.
//
//   node bench/peers.mjs [--rows 20,40] [--pile N] [--browser|--node] [--seconds S] [--pile-seconds T]
//                        [--engines manifold,rapier,planck,matter] [--units home|manifold|home,manifold] [--json FILE]
//
// Scenes: a pyramid of R rows of square boxes for each R of --rows (boxes of
// half-side 0.008 and dt = 1/300, so that g·dt²/h is Box2D's 60 Hz pyramid
// of 1 m boxes), run S simulated seconds (default 20); a pile of N circles
// and boxes (default 1000; 0: none) dropped into the rectangle at Manifold's
// default dt, run T simulated seconds (default 10: the pile forms in the
// first 2–3 s, and Rapier's steps in the page took 3–4 times as long until
// then). Each engine's steps are timed one by one; the second half of them
// count (the first half is the warm-up). Reported: the median ms per step (10 %–90 %), µs per body-step,
// the step's time against Manifold's in the same environment, whether the
// pyramid stands at the end, and how far the pile's touching circles overlap.
//
// --units: the peers' length units. home (the default): each peer's world
// scaled so a box is the size of its own examples (Box2D's, planck's and
// Rapier's 1 m boxes, matter.js's 40 px ones), lengths and gravity
// together and dt kept, so the scene is the same in units of the box;
// manifold: Manifold's numbers as they are (boxes of 0.016, g = 4), which
// is outside the range the peers' length tolerances are made for (see
// bench/README.md, "Peers: the pyramid and the pile"). Both: each peer
// runs twice. Progress goes to stderr, the table to stdout, all as JSON to --json.
import fs from "node:fs";
import os from "node:os";
import path from "node:path";
import url from "node:url";
import vm from "node:vm";
import { createRequire } from "node:module";
import { openBenchPage } from "./page.mjs";
import { commandLine } from "./options.mjs";
import { loadSpace } from "./worlds.mjs";

const HERE = path.dirname(url.fileURLToPath(import.meta.url));
const ROOT = path.resolve(HERE, "..");
const WEB = process.env.MANIFOLD_WEB ? path.resolve(process.env.MANIFOLD_WEB) : path.join(ROOT, "web");
const ENGINES_JS = path.join(HERE, "peers-engines.js");
const require = createRequire(import.meta.url);
const ENGINES = ["manifold", "rapier", "planck", "matter"];
// the peers' packages, and the file of each the page loads (as /peers/NAME)
const PACKAGES = {
  rapier: { name: "@dimforge/rapier2d-compat", file: "dist/rapier.mjs" },
  planck: { name: "planck", file: "dist/planck.js" },
  matter: { name: "matter-js", file: "build/matter.js" },
};

// ---- arguments -------------------------------------------------------------------------
const { text: arg, count, positive, flag } = commandLine({
  usage: "node bench/peers.mjs [--rows 20,40] [--pile N] [--browser|--node] [--seconds S] [--pile-seconds T]\n" +
    "                            [--engines manifold,rapier,planck,matter] [--units home|manifold|home,manifold] [--json FILE]",
  known: ["--rows", "--pile", "--seconds", "--pile-seconds", "--engines", "--units", "--json"],
  flags: ["--browser", "--node"],
});
const fail = (message) => { console.error(message); process.exit(2); };
const list = (s) => s.split(",").map((x) => x.trim()).filter((x) => x);
const rows = list(arg("--rows", "20,40")).map(Number);
if (rows.some((n) => !Number.isInteger(n) || n < 1)) fail("--rows must be whole numbers ≥ 1");
const pileN = count("--pile", 1000, 0);
const seconds = positive("--seconds", 20), pileSeconds = positive("--pile-seconds", 10);
const engines = list(arg("--engines", ENGINES.join(",")));
if (!engines.length || engines.some((e) => ENGINES.indexOf(e) < 0)) fail("--engines: a list of " + ENGINES.join(", "));
const units = list(arg("--units", "home"));
if (!units.length || units.some((u) => u !== "home" && u !== "manifold")) fail("--units: home, manifold or both");
if (flag("--browser") && flag("--node")) fail("--browser and --node: give one of them, or neither for both");
// node first: see runBrowser
const where = flag("--browser") ? ["browser"] : flag("--node") ? ["node"] : ["node", "browser"];
const jsonFile = arg("--json", null);
const log = (s) => process.stderr.write(s + "\n");

// Every run: a scene, an engine, and (for a peer) its units.
const scenes = rows.map((r) => ({ name: "pyramid " + r, seconds })).concat(pileN > 0 ? [{ name: "pile " + pileN, seconds: pileSeconds }] : []);
const cases = [];
for (const s of scenes) {
  for (const e of engines) {
    for (const u of e === "manifold" ? ["manifold"] : units) cases.push({ scene: s.name, seconds: s.seconds, engine: e, units: u });
  }
}
const versions = Object.fromEntries(Object.entries(PACKAGES).map(([k, p]) =>
  [k, JSON.parse(fs.readFileSync(path.join(ROOT, "node_modules", p.name, "package.json"), "utf8")).version]));
const fmt = (x, d = 3) => (x === null || x === undefined ? "–" : x >= 100 ? x.toFixed(0) : x >= 10 ? x.toFixed(Math.min(d, 1)) : x.toFixed(d));

function describe(r) {
  if (r.refused) return "refused: " + r.refused;
  if (r.kind === "pyramid") {
    return (r.stands ? "stands" : "falls") + ": sideways ≤ " + fmt(r.maxSidewaysHalfSides, 2) + " h, top " +
      (r.topRiseHalfSides >= 0 ? "+" : "") + fmt(r.topRiseHalfSides, 2) + " h";
  }
  return "circles overlap " + fmt(100 * r.circleOverlapMean, 1) + " % / " + fmt(r.circleOverlapMax, 2) + " r (" +
    r.overlappingCirclePairs + " pairs)" + (r.outside ? ", " + r.outside + " bodies outside" : "");
}
function progress(env, c, r) {
  log(`${env}: ${c.scene}, ${c.engine}${c.engine === "manifold" ? "" : " (" + c.units + " units)"}: ` +
    (r.refused ? "refused: " + r.refused : `${r.bodies} bodies, median ${fmt(r.medianMs)} ms (p10 ${fmt(r.p10Ms)}, p90 ${fmt(r.p90Ms)}), ` +
      `${fmt(r.usPerBodyStep, 2)} µs/body-step; ${describe(r)}`));
}

// ---- under node ----------------------------------------------------------------------------
async function runNode() {
  loadSpace("rectangle");
  const R = await import(path.join(ROOT, "node_modules", PACKAGES.rapier.name, PACKAGES.rapier.file));
  globalThis.RAPIER = R.default;
  await globalThis.RAPIER.init();
  globalThis.planck = require(PACKAGES.planck.name);
  globalThis.Matter = require(PACKAGES.matter.name);
  vm.runInThisContext(fs.readFileSync(ENGINES_JS, "utf8"), { filename: ENGINES_JS });
  const P = globalThis.ManifoldPeers, out = [];
  for (const c of cases) {
    const run = P.start(c.engine, P.scene(c.scene), c.seconds, c.units);
    while (!P.advance(run, 1e9));
    const r = P.finish(run);
    progress("node", c, r);
    out.push(r);
  }
  return { environment: { node: process.version }, results: out };
}

// ---- in the page -----------------------------------------------------------------------------
async function runBrowser() {
  // imported after the node runs (see openBenchPage)
  const { chromiumPath } = await import("../test/browser/lib.mjs");
  const { browser, page, pageErrors, close } = await openBenchPage(WEB, "#space=rectangle", async function (page) {
    // the peers and the benchmark's script, served from this checkout at /peers/ (same origin)
      const files = { "engines.js": ENGINES_JS };
      for (const [k, p] of Object.entries(PACKAGES)) files[k + path.extname(p.file)] = path.join(ROOT, "node_modules", p.name, p.file);
      await page.route("**/peers/*", (route) => {
        const file = files[path.basename(new URL(route.request().url()).pathname)];
        if (!file) return route.fulfill({ status: 404, body: "not found" });
        return route.fulfill({ status: 200, contentType: "text/javascript; charset=utf-8", body: fs.readFileSync(file),
          headers: { "Cross-Origin-Resource-Policy": "same-origin", "Cache-Control": "no-store" } });
      });
  });
  try {
    await page.addScriptTag({ url: "/peers/planck.js" });
    await page.addScriptTag({ url: "/peers/matter.js" });
    await page.addScriptTag({ url: "/peers/engines.js" });
    await page.evaluate(async () => {
      const R = await import("/peers/rapier.mjs");
      window.RAPIER = R.default;
      await window.RAPIER.init();
    });
    const environment = await page.evaluate(() => {
      let tick = Infinity, last = performance.now();
      for (let k = 0; k < 20000; k++) {
        const t = performance.now();
        if (t > last && t - last < tick) tick = t - last;
        last = t;
      }
      return { userAgent: navigator.userAgent, crossOriginIsolated: window.crossOriginIsolated, timerTickMs: tick };
    });
    environment.browserVersion = browser.version();
    environment.chromium = chromiumPath();
    log("Chromium " + environment.browserVersion + ", cross-origin isolated: " + environment.crossOriginIsolated +
      ", performance.now() tick " + (environment.timerTickMs * 1000).toFixed(1) + " µs");
    const out = [];
    for (const c of cases) {
      // one evaluate per second or so of stepping, so that the page stays answerable
      const id = await page.evaluate((c) => {
        const P = window.ManifoldPeers;
        P.runs.push(P.start(c.engine, P.scene(c.scene), c.seconds, c.units));
        return P.runs.length - 1;
      }, c);
      while (!(await page.evaluate((id) => window.ManifoldPeers.advance(window.ManifoldPeers.runs[id], 1000), id)));
      const r = await page.evaluate((id) => {
        const P = window.ManifoldPeers, r = P.finish(P.runs[id]);
        P.runs[id] = null;
        return r;
      }, id);
      progress("browser", c, r);
      out.push(r);
    }
    if (pageErrors.length) log("errors in the page:\n  " + pageErrors.join("\n  "));
    return { environment, results: out };
  } finally {
    await close();
  }
}

// ---- run and report --------------------------------------------------------------------------
const started = new Date(), load0 = os.loadavg();
log(`peers: ${cases.length} runs per environment (${where.join(", ")}); Rapier ${versions.rapier}, planck ${versions.planck}, matter.js ${versions.matter}`);
const measured = {};
for (const env of where) measured[env] = env === "browser" ? await runBrowser() : await runNode();

const pad = (s, n) => String(s).padStart(n);
const header = ["scene".padEnd(12), "engine".padEnd(18), pad("bodies", 6), pad("ms/step", 8), pad("p10–p90", 15),
  pad("µs/body-step", 12), pad("× manifold", 10), "  at the end"].join(" ");
for (const env of where) {
  const m = measured[env];
  console.log("\n" + (env === "browser" ? "in Chromium " + m.environment.browserVersion + " (one page)" : "under node " + m.environment.node) +
    ": ms per step, the median over the timed second half of the steps (h: a box's half-side, r: a circle's radius)");
  const pyr = m.results.find((r) => r.kind === "pyramid"), pl = m.results.find((r) => r.kind === "pile");
  if (pyr) console.log(`  pyramid: boxes h = ${pyr.unit.toPrecision(3)}, dt = 1/${Math.round(1 / pyr.dt)} s, ${pyr.seconds} s simulated`);
  if (pl) console.log(`  pile: circles of r = ${pl.unit.toPrecision(3)} and boxes of h = ${(pl.unit / Math.SQRT2).toPrecision(3)}, dt = ${pl.dt} s, ${pl.seconds} s simulated`);
  console.log(header);
  for (const r of m.results) {
    const base = m.results.find((x) => x.scene === r.scene && x.engine === "manifold" && !x.refused);
    const name = r.engine + (r.engine === "manifold" ? "" : " (" + r.units + ")");
    console.log([r.scene.padEnd(12), name.padEnd(18), pad(r.bodies, 6), pad(r.refused ? "–" : fmt(r.medianMs), 8),
      pad(r.refused ? "–" : fmt(r.p10Ms) + "–" + fmt(r.p90Ms), 15), pad(r.refused ? "–" : fmt(r.usPerBodyStep, 2), 12),
      pad(r.refused || !base ? "–" : (r.medianMs / base.medianMs).toFixed(2), 10), "  " + describe(r)].join(" "));
  }
}
if (jsonFile) {
  const out = { date: started.toISOString(), finished: new Date().toISOString(), options: { rows, pile: pileN, seconds, pileSeconds, engines, units },
    machine: { cpu: os.cpus()[0] && os.cpus()[0].model, cores: os.cpus().length, loadAverageBefore: load0, loadAverageAfter: os.loadavg() },
    versions, measured };
  fs.mkdirSync(path.dirname(path.resolve(jsonFile)), { recursive: true });
  fs.writeFileSync(jsonFile, JSON.stringify(out, null, 2) + "\n");
  log("wrote " + jsonFile);
}
