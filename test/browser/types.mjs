// Checks that web/manifold.d.ts names what the page and the generated
// scripts really have (part "types" of run.mjs): the keys of every generated
// space, its engine and the engine's layout objects, the catalogue's entries,
// the scene keys (and their controls) and the comparison, read under node from web/gen; and the
// calls of window.manifold and the keys of what stats(), simulation(),
// options() and camera() return, read in the page. The type checker sees the
// page's own scripts against the declarations (tsconfig.json); the generated
// scripts it cannot type (see there), so their keys are compared here.
import fs from "node:fs";
import path from "node:path";
import vm from "node:vm";
import { ROOT, WEB } from "./lib.mjs";

// The declarations of web/manifold.d.ts's namespace: interfaces as
// { required, optional } member names (with those of what they extend), and
// unions of string literals as their strings.
export function readDeclarations(text) {
  const interfaces = {}, unions = {};
  const lines = text.split("\n");
  for (let i = 0; i < lines.length; i++) {
    let m = /^ {2}interface (\w+)(?: extends (\w+))? \{/.exec(lines[i]);
    if (m) {
      const it = { required: [], optional: [], extends: m[2] || null };
      for (i++; i < lines.length && !/^ {2}\}/.test(lines[i]); i++) {
        const member = /^ {4}(\w+)(\??)[:(]/.exec(lines[i]);
        if (member) (member[2] ? it.optional : it.required).push(member[1]);
      }
      interfaces[m[1]] = it;
      continue;
    }
    m = /^ {2}type (\w+) =/.exec(lines[i]);
    if (m) {
      let body = lines[i].slice(m[0].length);
      while (!/;\s*$/.test(body) && i + 1 < lines.length) body += lines[++i];
      if (/^[\s|"\w-]*;\s*$/.test(body)) unions[m[1]] = (body.match(/"[^"]*"/g) || []).map((s) => s.slice(1, -1));
    }
  }
  for (const it of Object.values(interfaces)) {
    for (let base = it.extends; base && interfaces[base]; base = interfaces[base].extends) {
      it.required = it.required.concat(interfaces[base].required);
      it.optional = it.optional.concat(interfaces[base].optional);
    }
  }
  return { interfaces, unions };
}

// What differs between an object's keys and an interface's members: missing
// required ones and keys the interface does not name.
function keyProblems(what, keys, it) {
  const missing = it.required.filter((k) => keys.indexOf(k) < 0);
  const extra = keys.filter((k) => it.required.indexOf(k) < 0 && it.optional.indexOf(k) < 0);
  return (missing.length ? [what + " lacks " + missing.join(", ")] : [])
    .concat(extra.length ? [what + " has undeclared " + extra.join(", ")] : []);
}
function setProblems(what, keys, names) {
  const a = [...keys].sort().join(" "), b = [...names].sort().join(" ");
  return a === b ? [] : [what + " is [" + a + "], declared [" + b + "]"];
}

// The generated scripts, loaded as the page loads them (one context).
function loadGenerated() {
  const context = vm.createContext({});
  context.globalThis = context;
  const gen = path.join(WEB, "gen");
  const run = (file) => vm.runInContext(fs.readFileSync(path.join(gen, file), "utf8"), context, { filename: file });
  run("spaces.js");
  for (const e of context.Manifold.spaceIndex) run(e.script);
  run("compare-torus.js");
  return context.Manifold;
}

function generatedProblems(d) {
  const I = d.interfaces, U = d.unions, M = loadGenerated();
  let out = keyProblems("window.Manifold", Object.keys(M), I.Generated);
  M.spaceIndex.forEach((e) => {
    out = out.concat(keyProblems("spaceIndex " + e.name, Object.keys(e), I.SpaceEntry));
    if (U.Quotient.indexOf(e.quotient) < 0) out.push("spaceIndex " + e.name + ": quotient " + e.quotient + " not in Quotient");
  });
  M.sceneKeys.forEach((k) => {
    out = out.concat(keyProblems("sceneKey " + k.key, Object.keys(k), I.SceneKey));
    if (k.control) out = out.concat(keyProblems("sceneKey " + k.key + ".control", Object.keys(k.control), I.SceneControl));
    if (U.ParamName.indexOf(k.param) < 0) out.push("sceneKey " + k.key + ": param " + k.param + " not in ParamName");
  });
  for (const [name, s] of Object.entries(M.spaces)) {
    out = out.concat(keyProblems("space " + name, Object.keys(s), I.Space));
    const E = s.engine;
    out = out.concat(keyProblems("engine of " + name, Object.keys(E), I.Engine));
    [["arrays", E.arrays, "ArrayName"], ["sizes", Object.keys(E.sizes), "ArrayName"], ["meta", Object.keys(E.meta), "MetaName"],
      ["params", Object.keys(E.params), "ParamName"], ["defaults", Object.keys(E.defaults), "ParamName"],
      ["slots", Object.keys(E.slots), "SlotName"], ["contact", Object.keys(E.contact), "ContactField"],
      ["prev", Object.keys(E.prev), "PrevField"], ["mouse", Object.keys(E.mouse), "MouseField"], ["joint", Object.keys(E.joint), "JointField"],
      ["path.slots", Object.keys(E.path.slots), "PathField"], ["measures.slots", Object.keys(E.measures.slots), "MeasureField"], ["keys.groups", Object.keys(E.keys.groups), "ContactGroup"]].forEach(function (c) {
      out = out.concat(setProblems("engine." + c[0] + " of " + name, c[1], U[c[2]]));
    });
  }
  for (const [name, c] of Object.entries(M.comparisons)) out = out.concat(keyProblems("comparison " + name, Object.keys(c), I.ComparisonDef));
  return out;
}

export async function testTypes(check, context, base) {
  const file = path.join(ROOT, "web", "manifold.d.ts");
  const d = readDeclarations(fs.readFileSync(file, "utf8"));
  const wanted = ["Generated", "SpaceEntry", "SceneKey", "SceneControl", "Space", "Engine", "ComparisonDef", "Api", "Stats", "Simulation", "OptionsShown", "CameraSpec"]
    .filter((n) => !d.interfaces[n]).concat(["Quotient", "ArrayName", "MetaName", "ParamName", "SlotName", "ContactField", "PrevField", "MouseField", "JointField", "PathField", "MeasureField", "ContactGroup"]
      .filter((n) => !d.unions[n]));
  if (!check("web/manifold.d.ts declares the interfaces and unions these checks read", wanted.length === 0, "not found: " + wanted.join(", "))) return;

  const gen = generatedProblems(d);
  check("web/manifold.d.ts names every key of the generated catalogue, spaces, engines (and their layouts), scene keys and comparison",
    gen.length === 0, gen.slice(0, 8).join("; "));

  const page = await context.newPage();
  await page.goto(base + "#space=torus");
  await page.waitForFunction(function () { return !!window.manifold; });
  const keys = await page.evaluate(function () {
    const m = window.manifold;
    return m.ready().then(function () {
      return { api: Object.keys(m), stats: Object.keys(m.stats()), simulation: Object.keys(m.simulation()),
        options: Object.keys(m.options()), camera: Object.keys(m.camera()), bodyForms: Object.keys(m.stats().bodyForms) };
    });
  });
  const I = d.interfaces;
  const api = keyProblems("window.manifold", keys.api, I.Api).concat(keyProblems("stats()", keys.stats, I.Stats),
    keyProblems("stats().bodyForms", keys.bodyForms, I.BodyForms), keyProblems("simulation()", keys.simulation, I.Simulation),
    keyProblems("options()", keys.options, I.OptionsShown), keyProblems("camera()", keys.camera, I.CameraSpec));
  check("web/manifold.d.ts names every call of window.manifold and every key of stats(), simulation(), options(), camera()",
    api.length === 0, api.join("; "));
  await page.close();
}
