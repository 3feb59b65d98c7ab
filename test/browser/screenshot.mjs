// Saves the README's picture of the page: docs/screenshot.png (bodies on the torus).
//   node test/browser/screenshot.mjs [space] [out.png] [added bodies]   (default: torus docs/screenshot.png 14)
// The comparison view's picture (docs/torus-comparison.png: curvature on, 12 s of motion):
//   node test/browser/screenshot.mjs compare-torus docs/torus-comparison.png
// The hyperbolic plane in the Poincaré disc, walked away from the vertex (docs/hyperbolic-disc.png):
//   node test/browser/screenshot.mjs hyperbolic-plane docs/hyperbolic-disc.png 24
// The Bolza surface's tiling of the disc, the thrown bodies of its preset 2 s on (docs/bolza-disc.png):
//   node test/browser/screenshot.mjs bolza docs/bolza-disc.png
import fs from "node:fs";
import path from "node:path";
import { ROOT, launchBrowser, serve } from "./lib.mjs";

const space = process.argv[2] || "torus";
const out = path.resolve(ROOT, process.argv[3] || "docs/screenshot.png");
const extra = Number(process.argv[4] || 14);
const server = await serve();
const browser = await launchBrowser();
try {
  const viewport = space === "compare-torus" ? { width: 1200, height: 960 } : { width: 960, height: 640 };
  const page = await browser.newPage({ viewport: viewport, deviceScaleFactor: 1 });
  await page.goto(server.url + "#space=" + space);
  await page.waitForFunction(function () { return !!window.manifold; });
  await page.evaluate(function () { return window.manifold.ready(); });
  // the default scene and more bodies added with the page's buttons (at free
  // points of the view), without gravity (which soon gathers the torus's bodies
  // on the side this camera does not see)
  if (space === "compare-torus") {
    // both simulations from the shared scene, 12 s on, the curvature coloured
    await page.evaluate(function () {
      const m = window.manifold;
      m.resetScene();
      m.pause();
      m.setOptions({ curvature: true });
      m.step(1200);
      m.render();
    });
  } else if (space === "bolza") {
    await page.evaluate(function () {
      const m = window.manifold;
      return m.loadPreset("bolza-billiards").then(function () { m.pause(); m.step(200); m.render(); });
    });
  } else {
    await page.evaluate(function () {
      const m = window.manifold;
      m.resetScene();
      m.setSimulation({ gravity: false });
    });
    const shapes = ["circle", "square", "polygon"];
    for (let k = 0; k < extra; k++) {
      await page.selectOption("#body-shape", shapes[k % 3]);
      await page.click("#add-body");
    }
  }
  if (space === "hyperbolic-plane") {
    // a walk: the plane dragged from the disc's centre by (170, -60) px with the right button
    const box = await page.locator("#view").boundingBox();
    const c = [box.x + box.width / 2, box.y + box.height / 2];
    await page.mouse.move(c[0], c[1]);
    await page.mouse.down({ button: "right" });
    await page.mouse.move(c[0] + 170, c[1] - 60, { steps: 10 });
    await page.mouse.up({ button: "right" });
  }
  await page.waitForTimeout(1500); // let the stats line settle
  fs.mkdirSync(path.dirname(out), { recursive: true });
  await page.screenshot({ path: out });
  console.log("wrote " + path.relative(process.cwd(), out));
} finally {
  await browser.close();
  await server.stop();
}
