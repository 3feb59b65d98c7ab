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
