// Big scenes in the page: how fast it answers input and how fast the
// physics runs, at 1000, 5000 and 10,000 bodies (the sizes the sandbox
// promises to stay usable at). For each size, the scene `manifold bench
// --scenes` writes for it (Poisson-disc placed bodies, settled natively) is
// loaded into the page and run (clock on, rendering on, 800×600); then the
// view is orbited with a real mouse (a right-button drag, K moves) and each
// move's latency is measured: from the pointer event's time stamp to the end
// of the frame that draws its new view (an animation frame callback
// requested in the event handler runs right after the page's own one of the
// same frame: its physics steps and its draw calls; the software GPU's own
// part comes after, and is not counted). Also fps, physics steps per second
// and ms per step (manifold.stats()) while it runs. Each size runs with the
// physics on each thread of --threads (setSimulation's thread: "main", the
// page's own, or "worker", a Web Worker on shared memory), after a row with
// no bodies at all (the page's own latency: the target is 1.5 × it + 20 ms),
// and last the largest size with the clock paused (the bodies drawn, none
// moving: what drawing them costs a move, whatever thread steps them).
//
//   node bench/latency.mjs [--scenes DIR] [--space S] [--sizes N,M] [--threads main,worker] [--moves K] [--seconds T] [--out FILE.json]
//
// Without --scenes it runs `manifold bench --scenes TMPDIR --spaces S --sizes ...`
// itself. Progress goes to stderr, a table to stdout, everything as JSON to --out.
import { execFileSync } from "node:child_process";
import fs from "node:fs";
import os from "node:os";
import path from "node:path";
import url from "node:url";
import { launchBrowser, manifoldExe } from "../test/browser/lib.mjs";
import { serveWeb, loadPaused } from "./page.mjs";
import { commandLine } from "./options.mjs";

const ROOT = path.resolve(path.dirname(url.fileURLToPath(import.meta.url)), "..");
const WEB = process.env.MANIFOLD_WEB ? path.resolve(process.env.MANIFOLD_WEB) : path.join(ROOT, "web");
const VIEWPORT = { width: 800, height: 600 };

const { text: arg, count, positive } = commandLine({
  usage: "node bench/latency.mjs [--scenes DIR] [--space S] [--sizes N,M] [--threads main,worker] [--moves K] [--seconds T] [--out FILE.json]",
  known: ["--scenes", "--space", "--sizes", "--threads", "--moves", "--seconds", "--out"],
});
const space = arg("--space", "sphere");
const sizes = arg("--sizes", "1000,5000,10000").split(",").map(Number);
if (sizes.some((n) => !Number.isInteger(n) || n < 1)) { console.error("--sizes must be whole numbers"); process.exit(2); }
const threads = arg("--threads", "main,worker").split(",");
if (threads.some((t) => t !== "main" && t !== "worker")) { console.error("--threads takes main and worker"); process.exit(2); }
const moves = count("--moves", 20, 1);
const seconds = positive("--seconds", 3);
const outFile = arg("--out", null);
const log = (s) => process.stderr.write(s + "\n");

let scenesDir = arg("--scenes", null);
if (!scenesDir) {
  scenesDir = fs.mkdtempSync(path.join(os.tmpdir(), "manifold-latency-"));
  log("writing the settled scenes: manifold bench --scenes " + scenesDir + " --spaces " + space + " --sizes " + sizes.join(","));
  execFileSync(manifoldExe(), ["bench", "--scenes", scenesDir, "--spaces", space, "--sizes", sizes.join(",")],
    { cwd: ROOT, stdio: ["ignore", "ignore", "inherit"] });
}

const quantile = (xs, q) => { const s = xs.slice().sort((a, b) => a - b); return s[Math.min(s.length - 1, Math.floor(q * s.length))]; };

const server = await serveWeb(WEB);
const browser = await launchBrowser();
const results = [];
try {
  const page = await (await browser.newContext({ viewport: VIEWPORT })).newPage();
  await page.goto(server.url + "#space=" + space);
  await page.waitForFunction(() => !!window.manifold);
  await page.evaluate(() => window.manifold.ready());
  // each pointer move's latency: from its time stamp to the end of the next frame's work
  await page.evaluate(function () {
    window.__latency = [];
    document.getElementById("view").addEventListener("pointermove", function (e) {
      const t0 = e.timeStamp;
      requestAnimationFrame(function () { window.__latency.push(performance.now() - t0); });
    }, { capture: true });
  });
  const runs = [{ n: 0, thread: "main", paused: false }];
  for (const n of sizes) for (const thread of threads) runs.push({ n, thread, paused: false });
  runs.push({ n: Math.max(...sizes), thread: threads[0], paused: true });
  for (const { n, thread, paused } of runs) {
    const file = path.join(scenesDir, space + "-" + n + ".json");
    if (n > 0 && !fs.existsSync(file)) { log("no scene " + file + ": skipped"); continue; }
    const scene = n > 0 ? JSON.parse(fs.readFileSync(file, "utf8")) : { space, bodies: [] };
    await page.evaluate((t) => window.manifold.setSimulation({ thread: t }), thread);
    await loadPaused(page, scene);
    if (!paused) await page.evaluate(() => window.manifold.resume());
    await page.waitForTimeout(1000 * seconds);
    const stats = await page.evaluate(function () { return window.manifold.stats(); });
    const steps0 = stats.steps, t0 = Date.now();
    await page.waitForTimeout(1000);
    const steps1 = await page.evaluate(() => window.manifold.stats().steps);
    const stepsPerSecond = (steps1 - steps0) * 1000 / (Date.now() - t0);
    const box = await page.locator("#view").boundingBox();
    await page.evaluate(() => { window.__latency = []; });
    await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
    await page.mouse.down({ button: "right" });
    for (let k = 1; k <= moves; k++) {
      await page.mouse.move(box.x + box.width / 2 + 6 * k, box.y + box.height / 2);
      await page.waitForTimeout(60);
    }
    await page.mouse.up({ button: "right" });
    await page.waitForTimeout(300);
    const latency = await page.evaluate(() => window.__latency.slice());
    const r = {
      space, n, thread: paused ? "paused" : stats.thread, bodies: stats.bodies, fps: stats.fps, frameMs: stats.frameMs, physicsMsPerStep: stats.physicsMsPerStep,
      stepsPerSecond: Math.round(stepsPerSecond * 10) / 10, moves: latency.length,
      latencyMedianMs: Math.round(quantile(latency, 0.5)), latencyP90Ms: Math.round(quantile(latency, 0.9)),
    };
    log(JSON.stringify(r));
    results.push(r);
  }
} finally {
  await browser.close();
  await server.stop();
}
console.log("| space | bodies | physics thread | fps | physics ms/step | steps/s | move → frame ms (median, 90 %) |");
console.log("|---|---:|---|---:|---:|---:|---:|");
for (const r of results) {
  console.log("| " + r.space + " | " + r.bodies + " | " + r.thread + " | " + r.fps + " | " + r.physicsMsPerStep + " | " + r.stepsPerSecond + " | " + r.latencyMedianMs + ", " + r.latencyP90Ms + " |");
}
// the target: with the most bodies on the worker, within 1.5 × the empty page's median + 20 ms
const empty = results.find((r) => r.n === 0), biggest = results.filter((r) => r.thread === "worker").pop();
const still = results.find((r) => r.thread === "paused");
if (empty && biggest) {
  const limit = 1.5 * empty.latencyMedianMs + 20;
  console.log("\n" + biggest.bodies + " bodies on the worker: median " + biggest.latencyMedianMs + " ms against " +
    Math.round(limit) + " (1.5 × " + empty.latencyMedianMs + " + 20): " + (biggest.latencyMedianMs <= limit ? "within" : "over") +
    (still ? "; drawn with the clock paused: " + still.latencyMedianMs : ""));
}
if (outFile) fs.writeFileSync(outFile, JSON.stringify({ viewport: VIEWPORT, results }, null, 2) + "\n");
