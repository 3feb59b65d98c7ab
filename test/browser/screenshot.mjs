// Saves the README's picture of the page: docs/screenshot.png (the torus).
//   node test/browser/screenshot.mjs [space] [out.png]
import fs from "node:fs";
import path from "node:path";
import { ROOT, launchBrowser, serve } from "./lib.mjs";

const space = process.argv[2] || "torus";
const out = path.resolve(ROOT, process.argv[3] || "docs/screenshot.png");
const server = await serve();
const browser = await launchBrowser();
try {
  const page = await browser.newPage({ viewport: { width: 960, height: 640 }, deviceScaleFactor: 1 });
  await page.goto(server.url + "#space=" + space);
  await page.waitForFunction(function () { return !!window.manifold; });
  await page.evaluate(function () { return window.manifold.ready(); });
  await page.waitForTimeout(1500); // let the stats line settle
  fs.mkdirSync(path.dirname(out), { recursive: true });
  await page.screenshot({ path: out });
  console.log("wrote " + path.relative(process.cwd(), out));
} finally {
  await browser.close();
  await server.stop();
}
