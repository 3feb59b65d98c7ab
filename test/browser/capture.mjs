// Browser tests of the capture buttons (part "capture" of run.mjs), with
// real mouse clicks and the downloads they start (Playwright's download
// events): Save image downloads manifold-SPACE-YYYYMMDD-HHMMSS.png, a PNG of
// the canvas's size showing what the canvas shows (compared with a
// screenshot of it, paused), not a blank buffer, while the context keeps
// preserveDrawingBuffer off; Record turns into a pressed Stop with a visible
// dot, and Stop downloads manifold-SPACE-….webm, a WebM (EBML) file of more
// than 1 KB that the browser plays back at the canvas's size, the button
// Record again; a recording goes on through a space switch (the canvas is
// kept); without MediaRecorder the button is disabled and says why; Save
// image works from file:// too.
import fs from "node:fs";
import path from "node:path";
import url from "node:url";
import { WEB, OUT, canvasShot, decodePNG } from "./lib.mjs";
import { openSpace } from "./bodies.mjs";

const PNG_SIGNATURE = [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a];
const EBML_SIGNATURE = [0x1a, 0x45, 0xdf, 0xa3];

function sleep(ms) { return new Promise(function (resolve) { setTimeout(resolve, ms); }); }

/** @param {string} space @param {string} ext */
function namePattern(space, ext) {
  return new RegExp("^manifold-" + space + "-\\d{8}-\\d{6}\\." + ext + "$");
}

function startsWith(bytes, sig) {
  return bytes.length >= sig.length && sig.every(function (b, i) { return bytes[i] === b; });
}

// Clicks the button (a real mouse click on it, found by its accessible name)
// and waits for the download it starts: { name, bytes }, or { error }.
async function clickForDownload(page, buttonName, timeout) {
  try {
    const [download] = await Promise.all([
      page.waitForEvent("download", { timeout: timeout }),
      page.getByRole("button", { name: buttonName, exact: true }).click(),
    ]);
    const file = await download.path();
    const bytes = fs.readFileSync(file);
    fs.mkdirSync(OUT, { recursive: true });
    fs.writeFileSync(path.join(OUT, "capture-" + download.suggestedFilename()), bytes);
    return { name: download.suggestedFilename(), bytes: bytes, error: null };
  } catch (e) {
    return { name: null, bytes: Buffer.alloc(0), error: String(e && e.message || e).split("\n")[0] };
  }
}

// the spread of a decoded image's pixels: the standard deviation of r + g + b
function spread(img) {
  let n = 0, sum = 0, sq = 0;
  for (let y = 0; y < img.height; y += 2) {
    for (let x = 0; x < img.width; x += 2) {
      const c = img.at(x, y), v = c[0] + c[1] + c[2];
      n++; sum += v; sq += v * v;
    }
  }
  const mean = sum / n;
  return Math.sqrt(Math.max(0, sq / n - mean * mean));
}

// the mean difference per channel of two images of one size, and the share of pixels off by more than 24 (r + g + b)
function difference(a, b) {
  let n = 0, total = 0, off = 0;
  for (let y = 0; y < a.height; y++) {
    for (let x = 0; x < a.width; x++) {
      const p = a.at(x, y), q = b.at(x, y);
      const d = Math.abs(p[0] - q[0]) + Math.abs(p[1] - q[1]) + Math.abs(p[2] - q[2]);
      n++; total += d / 3;
      if (d > 24) off++;
    }
  }
  return { mean: total / n, off: off / n };
}

function recordState(page) {
  return page.evaluate(function () {
    const b = document.getElementById("record"), dot = document.getElementById("record-dot");
    const r = dot.getBoundingClientRect();
    return { label: b.textContent, pressed: b.getAttribute("aria-pressed"), disabled: b.disabled, title: b.title,
      dot: !dot.hidden && r.width > 0 && r.height > 0 && getComputedStyle(dot).visibility !== "hidden" };
  });
}

// what the browser makes of a downloaded video: its size and whether it plays back
function probeVideo(page, bytes) {
  return page.evaluate(function (b64) {
    const bin = atob(b64), u8 = new Uint8Array(bin.length);
    for (let i = 0; i < bin.length; i++) u8[i] = bin.charCodeAt(i);
    const v = document.createElement("video");
    v.muted = true;
    const src = URL.createObjectURL(new Blob([u8], { type: "video/webm" }));
    return new Promise(function (resolve) {
      const done = function (r) { URL.revokeObjectURL(src); resolve(r); };
      v.onloadeddata = function () { done({ width: v.videoWidth, height: v.videoHeight, error: null }); };
      v.onerror = function () { done({ width: 0, height: 0, error: v.error ? v.error.code + " " + v.error.message : "error" }); };
      setTimeout(function () { done({ width: 0, height: 0, error: "no data loaded in 10 s" }); }, 10000);
      v.src = src;
    });
  }, bytes.toString("base64"));
}

// (a) Save image, paused (the frame loop draws no frame of its own: the capture
// asks for one) and running (the loop's own frame is read)
async function testSaveImage(check, page) {
  await page.evaluate(function () { window.manifold.pause(); window.manifold.render(); });
  await sleep(300);
  const st = await page.evaluate(function () { return window.manifold.stats(); });
  const got = await clickForDownload(page, "Save image", 10000);
  let img = null, decodeError = null;
  try { img = got.error ? null : decodePNG(got.bytes); } catch (e) { decodeError = e.message; }
  const shot = await canvasShot(page, path.join(OUT, "capture-live.png"));
  const s = img ? spread(img) : 0;
  check("Save image (paused sphere): downloads manifold-sphere-YYYYMMDD-HHMMSS.png, a PNG (signature) of the canvas's size (" + st.width + "×" + st.height + ") whose pixels are not uniform",
    got.error === null && namePattern("sphere", "png").test(got.name) && startsWith(got.bytes, PNG_SIGNATURE) &&
      img !== null && img.width === st.width && img.height === st.height && s > 20,
    got.error || decodeError || got.name + ", " + got.bytes.length + " bytes, " + (img ? img.width + "×" + img.height : "?") + ", spread " + s.toFixed(1));
  if (img && shot.width === img.width && shot.height === img.height) {
    const d = difference(img, shot);
    check("the saved image is what the canvas shows (against a screenshot of it: mean difference < 2 a channel, < 1 % of pixels off)",
      d.mean < 2 && d.off < 0.01, "mean " + d.mean.toFixed(2) + ", off " + (100 * d.off).toFixed(2) + " %");
  } else {
    check("the saved image is what the canvas shows", false, "no image, or its size differs from the screenshot's " + shot.width + "×" + shot.height);
  }
  const attributes = await page.evaluate(function () {
    return document.getElementById("view").getContext("webgl2").getContextAttributes().preserveDrawingBuffer;
  });
  check("the WebGL context still keeps no drawing buffer (preserveDrawingBuffer false: the frames cost no copy)", attributes === false, String(attributes));

  await page.evaluate(function () { window.manifold.resume(); });
  await sleep(500);
  const running = await clickForDownload(page, "Save image", 10000);
  let img2 = null;
  try { img2 = running.error ? null : decodePNG(running.bytes); } catch (e) { /* reported below */ }
  const s2 = img2 ? spread(img2) : 0;
  check("Save image while the bodies move: a PNG of the canvas's size, not uniform",
    running.error === null && namePattern("sphere", "png").test(running.name) && img2 !== null &&
      img2.width === st.width && img2.height === st.height && s2 > 20,
    running.error || running.name + ", spread " + s2.toFixed(1));
}

// (b) Record, ~1.5 s, Stop; (c) a recording through a space switch
async function testRecord(check, page) {
  const before = await recordState(page);
  const recordButtons = await page.getByRole("button", { name: "Record", exact: true }).count();
  await page.getByRole("button", { name: "Record", exact: true }).click();
  await sleep(200);
  const during = await recordState(page);
  const stopButtons = await page.getByRole("button", { name: "Stop", exact: true }).count();
  check("Record (a button so named, aria-pressed false) starts recording: it reads Stop, aria-pressed true, the red dot shown",
    recordButtons === 1 && before.label === "Record" && before.pressed === "false" && !before.dot && !before.disabled &&
      stopButtons === 1 && during.label === "Stop" && during.pressed === "true" && during.dot,
    JSON.stringify({ before: before, during: during }));
  await sleep(1300);
  const got = await clickForDownload(page, "Stop", 15000);
  const after = await recordState(page);
  const st = await page.evaluate(function () { return window.manifold.stats(); });
  const video = got.error ? null : await probeVideo(page, got.bytes);
  check("Stop downloads manifold-sphere-YYYYMMDD-HHMMSS.webm, a WebM (EBML 1A45DFA3) file of more than 1 KB, and the button is Record again (aria-pressed false, no dot)",
    got.error === null && namePattern("sphere", "webm").test(got.name) && startsWith(got.bytes, EBML_SIGNATURE) &&
      got.bytes.length > 1024 && after.label === "Record" && after.pressed === "false" && !after.dot,
    got.error || got.name + ", " + got.bytes.length + " bytes, first bytes " + got.bytes.subarray(0, 4).toString("hex") + "; after " + JSON.stringify(after));
  check("the browser plays the video back at the canvas's size (" + st.width + "×" + st.height + ")",
    video !== null && video.error === null && video.width === st.width && video.height === st.height, JSON.stringify(video));

  // the canvas is kept through a space switch: the recording goes on, named by the space it began in
  await page.getByRole("button", { name: "Record", exact: true }).click();
  await sleep(700);
  await page.selectOption("#space", "torus");
  await page.evaluate(function () { return window.manifold.ready(); });
  await sleep(700);
  const switched = await recordState(page);
  const through = await clickForDownload(page, "Stop", 15000);
  const last = await recordState(page);
  check("a recording goes on through a space switch (sphere → torus: still Stop), and Stop downloads it (manifold-sphere-….webm, EBML, > 1 KB)",
    switched.label === "Stop" && switched.pressed === "true" && through.error === null && namePattern("sphere", "webm").test(through.name) &&
      startsWith(through.bytes, EBML_SIGNATURE) && through.bytes.length > 1024 && last.label === "Record" && last.pressed === "false",
    through.error || through.name + ", " + through.bytes.length + " bytes; during " + switched.label + ", after " + last.label);
}

// (d) a browser without MediaRecorder: Record disabled, its title saying why; Save image still works
async function testUnavailable(check, context, base) {
  const page = await context.newPage();
  const errors = [];
  page.on("pageerror", function (e) { errors.push("pageerror: " + e.message); });
  await page.addInitScript(function () { delete window.MediaRecorder; });
  await page.goto(base + "#space=disc");
  await page.waitForFunction(function () { return !!window.manifold; });
  await page.evaluate(function () { return window.manifold.ready(); });
  const r = await recordState(page);
  const saved = await clickForDownload(page, "Save image", 10000);
  check("without MediaRecorder the Record button is disabled, its title saying why; Save image still downloads a PNG",
    r.disabled && /MediaRecorder/.test(r.title) && r.label === "Record" && saved.error === null &&
      namePattern("disc", "png").test(saved.name) && startsWith(saved.bytes, PNG_SIGNATURE) && errors.length === 0,
    JSON.stringify(r) + "; " + (saved.error || saved.name) + (errors.length ? "; " + errors.join("; ") : ""));
  await page.close();
}

// (e) from file://
async function testFromFile(check, context) {
  const errors = [];
  const page = await openSpace(context, url.pathToFileURL(path.join(WEB, "index.html")).href, "#space=hemisphere", errors);
  const got = await clickForDownload(page, "Save image", 10000);
  let img = null;
  try { img = got.error ? null : decodePNG(got.bytes); } catch (e) { /* reported below */ }
  check("file://: Save image downloads a PNG of the view (manifold-hemisphere-….png, not uniform)",
    got.error === null && namePattern("hemisphere", "png").test(got.name) && img !== null && spread(img) > 20 && errors.length === 0,
    got.error || got.name + (errors.length ? "; " + errors.join("; ") : ""));
  await page.close();
}

export async function testCapture(check, context, base) {
  const errors = [];
  const page = await openSpace(context, base, "#space=sphere", errors);
  await testSaveImage(check, page);
  await testRecord(check, page);
  check("capture page: no console errors, no notice", errors.length === 0 &&
    await page.evaluate(function () { return document.getElementById("notice").hidden; }),
  errors.join("; ") || await page.textContent("#notice-text"));
  await page.close();
  await testUnavailable(check, context, base);
  await testFromFile(check, context);
}
