// Shared helpers of the browser tests: finding and serving the page,
// launching the system Chromium, decoding screenshots, and counting checks.
import { spawn, execFileSync } from "node:child_process";
import fs from "node:fs";
import net from "node:net";
import path from "node:path";
import url from "node:url";
import zlib from "node:zlib";
import { chromium } from "playwright-core";

export const ROOT = path.resolve(path.dirname(url.fileURLToPath(import.meta.url)), "..", "..");
// The page's directory (index.html, js/, css/, gen/); MANIFOLD_WEB serves another copy.
export const WEB = process.env.MANIFOLD_WEB ? path.resolve(process.env.MANIFOLD_WEB) : path.join(ROOT, "web");
export const OUT = path.join(ROOT, "test-output", "browser");

// Software WebGL2 (SwiftShader through ANGLE) in headless Chromium, without
// network chatter. Verified here to give WebGL2 with EXT_color_buffer_float.
export const CHROMIUM_ARGS = [
  "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
  "--disable-background-networking", "--disable-component-update", "--disable-sync",
  "--use-gl=angle", "--use-angle=swiftshader", "--enable-unsafe-swiftshader",
];

export function chromiumPath() {
  const p = process.env.CHROMIUM || "/usr/bin/chromium";
  if (!fs.existsSync(p)) throw new Error(p + " not found: install Debian's chromium (scripts/setup does) or set CHROMIUM");
  return p;
}

export async function launchBrowser() {
  return chromium.launch({ executablePath: chromiumPath(), args: CHROMIUM_ARGS, headless: true });
}

// The manifold executable: $MANIFOLD_EXE, else `cabal list-bin exe:manifold`.
export function manifoldExe() {
  if (process.env.MANIFOLD_EXE) return process.env.MANIFOLD_EXE;
  const exe = execFileSync("cabal", ["list-bin", "--offline", "exe:manifold"], { cwd: ROOT, encoding: "utf8" }).trim();
  if (!fs.existsSync(exe)) throw new Error("manifold is not built (" + exe + "): run `cabal build exe:manifold`");
  return exe;
}

export function freePort() {
  return new Promise(function (resolve, reject) {
    const srv = net.createServer();
    srv.unref();
    srv.on("error", reject);
    srv.listen(0, "127.0.0.1", function () {
      const port = srv.address().port;
      srv.close(function () { resolve(port); });
    });
  });
}

// Starts `manifold serve` on a free loopback port; resolves with
// { url, stop() } once it prints its URL.
export async function serve() {
  const exe = manifoldExe();
  for (let attempt = 0; attempt < 3; attempt++) {
    const port = await freePort();
    const child = spawn(exe, ["serve", "--port", String(port), "--dir", WEB], { cwd: ROOT, stdio: ["ignore", "pipe", "pipe"] });
    let out = "";
    const started = await new Promise(function (resolve) {
      const timer = setTimeout(function () { resolve(false); }, 15000);
      const onData = function (d) {
        out += d.toString();
        if (/serving .* at http:\/\/127\.0\.0\.1:\d+\//.test(out)) { clearTimeout(timer); resolve(true); }
      };
      child.stdout.on("data", onData);
      child.stderr.on("data", function (d) { out += d.toString(); });
      child.on("exit", function () { clearTimeout(timer); resolve(false); });
    });
    if (started) {
      // never leave the server behind, whatever ends this process
      process.on("exit", function () { if (child.exitCode === null) child.kill("SIGKILL"); });
      return {
        url: "http://127.0.0.1:" + port + "/",
        stop: function () {
          return new Promise(function (resolve) {
            if (child.exitCode !== null) return resolve();
            child.on("exit", function () { resolve(); });
            child.kill("SIGTERM");
            setTimeout(function () { if (child.exitCode === null) child.kill("SIGKILL"); }, 3000);
          });
        },
      };
    }
    if (child.exitCode === null) child.kill("SIGKILL");
    if (!/already in use/.test(out)) throw new Error("manifold serve did not start:\n" + out);
  }
  throw new Error("manifold serve: no free port after 3 attempts");
}

// ---- PNG decoding (8-bit RGB/RGBA, not interlaced: what Chromium's screenshots are) ----
export function decodePNG(buf) {
  if (buf.readUInt32BE(0) !== 0x89504e47) throw new Error("not a PNG");
  let pos = 8, width = 0, height = 0, depth = 0, type = 0, interlace = 0;
  const idat = [];
  while (pos < buf.length) {
    const len = buf.readUInt32BE(pos);
    const kind = buf.toString("ascii", pos + 4, pos + 8);
    const data = buf.subarray(pos + 8, pos + 8 + len);
    if (kind === "IHDR") {
      width = data.readUInt32BE(0); height = data.readUInt32BE(4);
      depth = data[8]; type = data[9]; interlace = data[12];
    } else if (kind === "IDAT") idat.push(data);
    else if (kind === "IEND") break;
    pos += 12 + len;
  }
  if (depth !== 8 || (type !== 2 && type !== 6) || interlace !== 0) {
    throw new Error("unsupported PNG (depth " + depth + ", colour type " + type + ", interlace " + interlace + ")");
  }
  const bpp = type === 6 ? 4 : 3;
  const raw = zlib.inflateSync(Buffer.concat(idat));
  const stride = width * bpp;
  const px = Buffer.alloc(width * height * 4);
  let prev = Buffer.alloc(stride);
  for (let y = 0; y < height; y++) {
    const f = raw[y * (stride + 1)];
    const line = Buffer.from(raw.subarray(y * (stride + 1) + 1, (y + 1) * (stride + 1)));
    for (let i = 0; i < stride; i++) {
      const a = i >= bpp ? line[i - bpp] : 0, b = prev[i], c = i >= bpp ? prev[i - bpp] : 0;
      let add = 0;
      if (f === 1) add = a;
      else if (f === 2) add = b;
      else if (f === 3) add = (a + b) >> 1;
      else if (f === 4) {
        const p = a + b - c, pa = Math.abs(p - a), pb = Math.abs(p - b), pc = Math.abs(p - c);
        add = pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
      }
      line[i] = (line[i] + add) & 255;
    }
    for (let x = 0; x < width; x++) {
      px[(y * width + x) * 4] = line[x * bpp];
      px[(y * width + x) * 4 + 1] = line[x * bpp + 1];
      px[(y * width + x) * 4 + 2] = line[x * bpp + 2];
      px[(y * width + x) * 4 + 3] = bpp === 4 ? line[x * bpp + 3] : 255;
    }
    prev = line;
  }
  return {
    width: width,
    height: height,
    at: function (x, y) {
      const i = (Math.floor(y) * width + Math.floor(x)) * 4;
      return [px[i], px[i + 1], px[i + 2]];
    },
  };
}

// A screenshot of the page's canvas, decoded; its pixels are the canvas's
// backing-store pixels when the device pixel ratio is 1.
export async function canvasShot(page, file) {
  const r = await page.evaluate(function () {
    const b = document.getElementById("view").getBoundingClientRect();
    return { x: b.left, y: b.top, width: b.width, height: b.height };
  });
  const buf = await page.screenshot({ clip: r });
  if (file) {
    fs.mkdirSync(path.dirname(file), { recursive: true });
    fs.writeFileSync(file, buf);
  }
  return decodePNG(buf);
}

// ---- checks ------------------------------------------------------------------------------
export function createChecks() {
  let passed = 0, failed = 0;
  const failures = [];
  return {
    check: function (name, ok, detail) {
      if (ok) {
        passed++;
        console.log("ok   " + name + (detail ? "  (" + detail + ")" : ""));
      } else {
        failed++;
        failures.push(name);
        console.log("FAIL " + name + (detail ? ": " + detail : ""));
      }
      return ok;
    },
    summary: function () { return { passed: passed, failed: failed, failures: failures }; },
  };
}
