// The page (web/) as the browser benchmark and the page profile drive it:
// served cross-origin isolated, so that performance.now() ticks in 5 µs
// rather than 100 µs, and scenes loaded paused.
import fs from "node:fs";
import http from "node:http";
import path from "node:path";

const TYPES = { ".html": "text/html; charset=utf-8", ".js": "text/javascript; charset=utf-8", ".css": "text/css; charset=utf-8",
  ".json": "application/json", ".png": "image/png", ".svg": "image/svg+xml", ".ico": "image/x-icon" };

// A static server for the directory `web` on a free port of 127.0.0.1: { url, stop }.
export function serveWeb(web) {
  const server = http.createServer(function (req, res) {
    const p = decodeURIComponent(new URL(req.url, "http://x").pathname);
    const file = path.join(web, p.endsWith("/") ? p + "index.html" : p);
    if (!file.startsWith(web) || !fs.existsSync(file) || !fs.statSync(file).isFile()) {
      res.writeHead(404, { "Content-Type": "text/plain" });
      res.end("not found");
      return;
    }
    res.writeHead(200, {
      "Content-Type": TYPES[path.extname(file)] || "application/octet-stream",
      "Cache-Control": "no-store",
      "Cross-Origin-Opener-Policy": "same-origin",
      "Cross-Origin-Embedder-Policy": "require-corp",
    });
    fs.createReadStream(file).pipe(res);
  });
  return new Promise(function (resolve) {
    server.listen(0, "127.0.0.1", function () {
      resolve({ url: "http://127.0.0.1:" + server.address().port + "/", stop: () => new Promise((r) => server.close(r)) });
    });
  });
}

// Serves `web` and opens it at `hash` in a new headless Chromium page of
// 800×600 (`before(page)` first, e.g. for routes), the page's world paused,
// its uncaught errors collected: { browser, page, pageErrors, close }.
// Playwright is imported only here, when a page is wanted: loaded, it
// slowed planck.js under node 3–4 times (bench/peers.mjs's node runs).
export async function openBenchPage(web, hash, before) {
  const { launchBrowser } = await import("../test/browser/lib.mjs");
  const server = await serveWeb(web);
  const browser = await launchBrowser();
  const close = async function () { await browser.close(); await server.stop(); };
  try {
    const page = await (await browser.newContext({ viewport: { width: 800, height: 600 } })).newPage();
    const pageErrors = [];
    page.on("pageerror", (e) => pageErrors.push(e.message));
    if (before) await before(page);
    await page.goto(server.url + hash);
    await page.waitForFunction(() => !!window.manifold);
    await page.evaluate(() => window.manifold.ready());
    await page.evaluate(() => window.manifold.pause());
    return { browser, page, pageErrors, close };
  } catch (e) {
    await close();
    throw e;
  }
}

// Loads the scene into the page's world (paused) and waits for the frame it draws.
export async function loadPaused(page, scene) {
  await page.evaluate(async function (scene) {
    const m = window.manifold;
    m.pause();
    await m.loadScene(scene);
    m.pause();
    m.measureFrame(); // draws and waits for the GPU: nothing renders during the timing
  }, scene);
}
