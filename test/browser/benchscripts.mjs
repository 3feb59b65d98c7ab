// The documented benchmark commands, end to end on small scenes, so that a
// change to them or to the page they drive is caught here rather than in
// the next full benchmark run: `manifold bench --scenes` and `--from`,
// bench/browser.mjs, bench/report.mjs (into a copy of bench/README.md),
// bench/pile.mjs and bench/profile.mjs.
import { execFileSync } from "node:child_process";
import fs from "node:fs";
import os from "node:os";
import path from "node:path";
import { ROOT, manifoldExe } from "./lib.mjs";

export async function testBenchScripts(check) {
  const dir = fs.mkdtempSync(path.join(os.tmpdir(), "manifold-bench-scripts-"));
  const run = (cmd, args) => execFileSync(cmd, args, { cwd: ROOT, encoding: "utf8", stdio: ["ignore", "pipe", "pipe"] });
  try {
    const scenes = path.join(dir, "scenes");
    const sizes = ["--spaces", "torus,rectangle", "--sizes", "30"];
    run(manifoldExe(), ["bench", "--scenes", scenes, "--settle", "200"].concat(sizes));
    const native = path.join(dir, "native.json"), browser = path.join(dir, "browser.json");
    fs.writeFileSync(native, run(manifoldExe(), ["bench", "--from", scenes, "--rounds", "1", "--warmup", "5", "--steps", "5", "--json"].concat(sizes)));
    run("node", ["bench/browser.mjs", "--scenes", scenes, "--rounds", "1", "--warmup", "5", "--steps", "5",
      "--fps-spaces", "torus", "--fps-seconds", "1", "--out", browser].concat(sizes));
    const n = JSON.parse(fs.readFileSync(native, "utf8")), b = JSON.parse(fs.readFileSync(browser, "utf8"));
    const rowsAgree = n.length === 2 && b.results.length === 2 && n.every(function (r, i) {
      const p = b.results[i];
      return r.space === p.space && r.bodies === p.bodies && r.medianMs > 0 && p.medianMs > 0 && r.contacts > 0 && r.contacts === p.contacts;
    });
    check("manifold bench --scenes/--from and bench/browser.mjs time the same small piles (torus and rectangle, 30 bodies; contact rows equal)",
      rowsAgree && b.fps.length === 1 && b.fps[0].fps > 0,
      JSON.stringify({ native: n.map((r) => [r.space, r.bodies, r.contacts, r.medianMs]), browser: b.results.map((r) => [r.space, r.bodies, r.contacts, r.medianMs]) }));

    // firmer contacts (bench/README.md, "Firmer contacts"): the native benchmark and the
    // pile script put the same settings in place and find the same rows
    const firm = ["--substeps", "2", "--iterations", "3", "--slop", "0.05"];
    const nf = JSON.parse(run(manifoldExe(), ["bench", "--from", scenes, "--spaces", "rectangle", "--sizes", "30", "--rounds", "1",
      "--warmup", "20", "--steps", "1", "--json"].concat(firm)))[0];
    const pf = run("node", ["bench/pile.mjs", scenes, "--steps", "21"].concat(firm)).trim().split("\n").map((l) => JSON.parse(l))
      .find((r) => r.space === "rectangle");
    check("manifold bench --substeps/--iterations/--slop and bench/pile.mjs with the same settings: the same contact rows on the same pile",
      nf.substeps === 2 && pf.substeps === 2 && nf.iterations === 3 && pf.iterations === 3 && Math.abs(nf.slop - pf.slop) < 1e-15 && nf.contacts > 0 && nf.contacts === pf.rowsPerBody * pf.bodies,
      JSON.stringify({ native: [nf.iterations, nf.slop, nf.contacts], pile: [pf.iterations, pf.slop, pf.rowsPerBody * pf.bodies] }));

    const readme = path.join(dir, "README.md"), png = path.join(dir, "scaling.png");
    fs.copyFileSync(path.join(ROOT, "bench/README.md"), readme);
    run("node", ["bench/report.mjs", "--native", native, "--browser", browser, "--node", path.join(dir, "none.json"),
      "--readme", readme, "--png", png]);
    const text = fs.readFileSync(readme, "utf8");
    check("bench/report.mjs rewrites the results of a README copy from those runs and draws the plot",
      /\| torus \| 30 \| 30 \|/.test(text) && /\| rectangle \| 30 \|/.test(text) && fs.statSync(png).size > 1000 &&
        text.slice(0, text.indexOf("<!-- results:begin -->")) === fs.readFileSync(path.join(ROOT, "bench/README.md"), "utf8").slice(0, text.indexOf("<!-- results:begin -->")),
      fs.statSync(png).size + " bytes of PNG");

    // a mistyped option stops the script (exit 2, the usage on standard
    // error) instead of running with the default: report.mjs with a wrong
    // name would rewrite bench/README.md from the checked-in results
    const refused = (args) => {
      try { run("node", args); return "ran"; } catch (e) { return e.status === 2 && /usage: node bench\//.test(e.stderr) ? "refused" : "exit " + e.status; }
    };
    const badLines = [
      ["bench/report.mjs", "--readme", readme, "--nativ", native],
      ["bench/report.mjs", "--readme"],
      ["bench/browser.mjs", "--scenes", scenes, "--round", "1"],
      ["bench/node.mjs", scenes, "--stpes", "5"],
      ["bench/node.mjs"],
      ["bench/pile.mjs", scenes, "--steps", "5", "--mean"],
      ["bench/cells.mjs", "--steps", "1"],
      ["bench/profile.mjs", path.join(scenes, "torus-30.json"), "--setps", "5"],
      ["bench/latency.mjs", "--scenes", scenes, "--move", "5"],
      ["bench/joint-grid.mjs", "--sise", "5"],
    ];
    const outcomes = badLines.map(refused);
    const readmeAfter = fs.readFileSync(readme, "utf8");
    const badNumber = (() => { try { run("node", ["bench/pile.mjs", scenes, "--steps", "ten"]); return "ran"; } catch (e) { return e.status + ": " + e.stderr.trim(); } })();
    const help = run("node", ["bench/report.mjs", "--help"]);
    check("the bench scripts refuse unknown options, missing values and arguments with their usage (exit 2), and a number that is none; --help prints the usage",
      outcomes.every((o) => o === "refused") && readmeAfter === text && /^2: --steps must be a whole number/.test(badNumber) && /^usage: node bench\/report\.mjs/.test(help),
      JSON.stringify({ outcomes, badNumber, help: help.trim() }));

    const profile = run("node", ["bench/profile.mjs", path.join(scenes, "torus-30.json"), "--steps", "100", "--top", "12"]);
    check("bench/profile.mjs profiles the page stepping a scene: the engine's phases by self time",
      // (the polygon walk, and some of the rest: a resting pile keeps its
      // contacts, and its narrow phase may take too little time to be sampled)
      /^torus, 30 bodies, 100 steps/.test(profile) && profile.indexOf("stepPolygonise") >= 0 &&
        ["pairContacts", "keepContacts", "stepCollide", "solveSweep", "relaxSweep", "substepMove"].some((f) => profile.indexOf(f) >= 0),
      profile.split("\n").slice(0, 6).join(" | "));
  } catch (e) {
    check("the benchmark scripts ran", false, (e.stderr || "") + (e.stack || String(e)));
  } finally {
    fs.rmSync(dir, { recursive: true, force: true });
  }
}
