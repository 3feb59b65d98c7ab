// Frame times of the page in headless Chromium (software WebGL2, SwiftShader):
// for every space, full frames drawn with manifold.measureFrame() (draw, then
// wait for the GPU with a one-pixel read-back), as frames per second.
//
//   node test/browser/bench.mjs [--size 800x600] [--aa fxaa|ssaa|off] [--seconds 2]
import { launchBrowser, serve } from "./lib.mjs";

function arg(name, dflt) {
  const i = process.argv.indexOf(name);
  return i >= 0 ? process.argv[i + 1] : dflt;
}
const [vw, vh] = arg("--size", "800x600").split("x").map(Number);
const aa = arg("--aa", "fxaa");
const seconds = Number(arg("--seconds", "2"));

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
  console.log("viewport " + vw + "×" + vh + " (canvas " + size + " px), antialiasing " + aa + ", " +
    "full frames: trace + shade + post");
  for (const name of names) {
    const r = await page.evaluate(function (a) {
      const m = window.manifold;
      return m.setSpace(a.name).then(function () {
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
} finally {
  await browser.close();
  await server.stop();
}
