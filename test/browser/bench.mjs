// Frame times of the page in headless Chromium (software WebGL2, SwiftShader):
//  1. for every space, full frames (trace + shade + bodies + post) drawn with
//     manifold.measureFrame() (draw, then wait for the GPU with a one-pixel read-back);
//  2. physics: ms per step of each space's default scene (manifold.step, paused);
//  3. the running page with N bodies on one space: frames per second (the stats
//     line's fps: physics steps, body frames over the reused traced surface),
//     physics ms per step.
//
//   node test/browser/bench.mjs [--size 800x600] [--aa fxaa|ssaa|off] [--seconds 2]
//                               [--bodies 10,50,100] [--space torus] [--parts frames,physics,bodies]
import { launchBrowser, serve } from "./lib.mjs";

function arg(name, dflt) {
  const i = process.argv.indexOf(name);
  return i >= 0 ? process.argv[i + 1] : dflt;
}
const [vw, vh] = arg("--size", "800x600").split("x").map(Number);
const aa = arg("--aa", "fxaa");
const seconds = Number(arg("--seconds", "2"));
const counts = arg("--bodies", "10,50,100").split(",").map(Number);
const bodySpace = arg("--space", "torus");
const parts = arg("--parts", "frames,physics,bodies").split(",");

const server = await serve();
const browser = await launchBrowser();
try {
  const context = await browser.newContext({ viewport: { width: vw, height: vh }, deviceScaleFactor: 1 });
  const page = await context.newPage();
  await page.goto(server.url + "#space=plane&aa=" + aa);
  await page.waitForFunction(function () { return !!window.manifold; });
  await page.evaluate(function () { return window.manifold.ready(); });
  const names = await page.evaluate(function () { return window.manifold.spaces(); });
  const size = await page.evaluate(function () { const s = window.manifold.stats(); return s.width + "×" + s.height; });
  console.log("viewport " + vw + "×" + vh + " (canvas " + size + " px), antialiasing " + aa);

  if (parts.indexOf("frames") >= 0) {
    console.log("\nfull frames (trace + shade + default scene's bodies + post), paused:");
    for (const name of names) {
      const r = await page.evaluate(function (a) {
        const m = window.manifold;
        return m.setSpace(a.name).then(function () {
          m.pause();
          m.measureFrame(); // warm up
          const t0 = performance.now();
          let n = 0;
          while (performance.now() - t0 < a.ms || n < 2) { m.measureFrame(); n++; }
          return { frames: n, ms: performance.now() - t0 };
        });
      }, { name: name, ms: seconds * 1000 });
      const fps = r.frames * 1000 / r.ms;
      console.log("  " + name.padEnd(18) + fps.toFixed(1).padStart(6) + " fps  " + (r.ms / r.frames).toFixed(0).padStart(5) + " ms/frame");
    }
  }

  if (parts.indexOf("physics") >= 0) {
    console.log("\nphysics of each default scene (200 steps after 20 to warm up, dt 0.01):");
    for (const name of names) {
      const r = await page.evaluate(function (a) {
        const m = window.manifold;
        return m.setSpace(a.name).then(function () {
          m.pause();
          m.resetScene();
          m.step(20);
          const t0 = performance.now();
          m.step(200);
          const ms = (performance.now() - t0) / 200;
          const s = m.stats();
          return { ms: ms, bodies: s.bodies, contacts: s.contacts, dropped: s.droppedContacts, warnings: s.warnings };
        });
      }, { name: name });
      console.log("  " + name.padEnd(18) + (r.bodies + " bodies").padStart(10) + r.ms.toFixed(2).padStart(8) + " ms/step" +
        ("  contacts " + r.contacts).padEnd(14) + "  dropped contacts " + r.dropped + (r.warnings ? "  warnings " + r.warnings : ""));
    }
  }

  if (parts.indexOf("bodies") >= 0) {
    console.log("\nthe running page on " + bodySpace + " (default scene filled up to N bodies, gravity on):");
    await page.evaluate(function (s) { return window.manifold.setSpace(s); }, bodySpace);
    for (const n of counts) {
      await page.evaluate(function (k) { const m = window.manifold; m.resetScene(k); m.resume(); }, n);
      await page.waitForTimeout(1500); // settle: the first frames trace the surface
      const s0 = await page.evaluate(function () { return window.manifold.stats(); });
      const t0 = Date.now();
      await page.waitForTimeout(seconds * 1000);
      const s1 = await page.evaluate(function () { return window.manifold.stats(); });
      const dt = (Date.now() - t0) / 1000;
      console.log("  " + (s1.bodies + " bodies").padStart(10) + ((s1.frames - s0.frames) / dt).toFixed(1).padStart(7) + " fps" +
        ((s1.steps - s0.steps) / dt).toFixed(0).padStart(6) + " steps/s" +
        (s1.physicsMsPerStep === null ? "" : s1.physicsMsPerStep.toFixed(2).padStart(8) + " ms/step") +
        "  contacts " + s1.contacts + "  dropped contacts " + s1.droppedContacts);
    }
  }
} finally {
  await browser.close();
  await server.stop();
}
