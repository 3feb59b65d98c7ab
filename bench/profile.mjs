// Chromium's CPU profile of the page (its sampling profiler, over the
// DevTools protocol) while it runs one scene: where the page's time goes, by
// function (self time), for the generated engine and the page's own code alike.
//
//   node bench/profile.mjs SCENE.json [--steps N] [--running T] [--interval US] [--top K] [--out FILE.cpuprofile]
//
// SCENE.json is a scene file, e.g. one that `manifold bench --scenes DIR`
// wrote. By default the scene is loaded paused, run 50 steps (the JIT), and
// N steps (default 300) of manifold.step are profiled, nothing drawn; with
// --running T the page runs the scene for T seconds as a user sees it (clock
// and rendering on, 800×600). Samples every US microseconds (default 100).
// Prints the K functions (default 25) with the most self time, and writes
// the whole profile to FILE.cpuprofile if asked (it opens in Chromium's
// DevTools, Performance panel).
import fs from "node:fs";
import path from "node:path";
import url from "node:url";
import { launchBrowser } from "../test/browser/lib.mjs";
import { serveWeb, loadPaused } from "./page.mjs";
import { commandLine } from "./options.mjs";

const ROOT = path.resolve(path.dirname(url.fileURLToPath(import.meta.url)), "..");
const WEB = process.env.MANIFOLD_WEB ? path.resolve(process.env.MANIFOLD_WEB) : path.join(ROOT, "web");
const line = commandLine({
  usage: "node bench/profile.mjs SCENE.json [--steps N] [--running T] [--interval US] [--top K] [--out FILE.cpuprofile]",
  positional: 1,
  known: ["--steps", "--running", "--interval", "--top", "--out"],
});
const { positive } = line;
const sceneFile = line.positional[0];
if (!fs.existsSync(sceneFile)) { console.error(sceneFile + ": no such scene file"); process.exit(2); }
const scene = JSON.parse(fs.readFileSync(sceneFile, "utf8"));
const steps = Math.round(positive("--steps", 300));
const running = positive("--running", null);
const interval = Math.round(positive("--interval", 100));
const top = Math.round(positive("--top", 25));
const outFile = line.text("--out", null);

// Self time by function: the samples' time deltas summed over the nodes of
// the same function (name, script, line), in ms.
function selfTimes(profile) {
  const byId = new Map(profile.nodes.map((n) => [n.id, n]));
  const totals = new Map();
  let all = 0;
  profile.samples.forEach(function (id, i) {
    const ms = (profile.timeDeltas[i] || 0) / 1000;
    const f = byId.get(id).callFrame;
    const where = f.url ? path.basename(new URL(f.url).pathname) + ":" + (f.lineNumber + 1) : "";
    const key = (f.functionName || "(anonymous)") + (where ? " " + where : "");
    totals.set(key, (totals.get(key) || 0) + ms);
    all += ms;
  });
  return { all, rows: [...totals.entries()].sort((a, b) => b[1] - a[1]) };
}

const server = await serveWeb(WEB);
const browser = await launchBrowser();
let profile;
try {
  const context = await browser.newContext({ viewport: { width: 800, height: 600 }, deviceScaleFactor: 1 });
  const page = await context.newPage();
  const errors = [];
  page.on("pageerror", (e) => errors.push(e.message));
  await page.goto(server.url + "#space=" + scene.space);
  await page.waitForFunction(function () { return !!window.manifold; });
  await page.evaluate(function () { return window.manifold.ready(); });
  await loadPaused(page, scene);
  await page.evaluate(function () { window.manifold.step(50); });
  const cdp = await context.newCDPSession(page);
  await cdp.send("Profiler.enable");
  await cdp.send("Profiler.setSamplingInterval", { interval });
  await cdp.send("Profiler.start");
  if (running === null) {
    await page.evaluate(function (n) { window.manifold.step(n); }, steps);
  } else {
    await page.evaluate(function () { window.manifold.resume(); });
    await page.waitForTimeout(1000 * running);
    await page.evaluate(function () { window.manifold.pause(); });
  }
  profile = (await cdp.send("Profiler.stop")).profile;
  if (errors.length) throw new Error("the page reported: " + errors.join("; "));
} finally {
  await browser.close();
  await server.stop();
}

if (outFile) fs.writeFileSync(outFile, JSON.stringify(profile));
const { all, rows } = selfTimes(profile);
const what = running === null ? steps + " steps of manifold.step, paused" : running + " s running and drawn";
console.log(scene.space + ", " + scene.bodies.length + " bodies, " + what + ": " + all.toFixed(0) + " ms sampled every " + interval + " µs");
console.log("self ms   share  function");
for (const [name, ms] of rows.slice(0, top)) {
  console.log(ms.toFixed(1).padStart(7) + "  " + (100 * ms / all).toFixed(1).padStart(5) + " %  " + name);
}
if (outFile) console.log("profile written to " + outFile);
