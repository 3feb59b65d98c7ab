// Browser tests of the engine parameters' controls and of big worlds (part
// "controls" of run.mjs): the page makes one control per generated scene key
// with a `control` (Manifold.sceneKeys), labelled, titled and ranged as
// generated; the keyboard moves its sliders and the world's parameters
// follow; setSimulation takes what the keys' generated ranges take and
// refuses the rest with their messages; a scene of the engine's maxBodies
// bodies loads and steps and one more is refused; a link asking for more
// bodies than fit places what fits and says how many.
import { openSpace } from "./bodies.mjs";

// (1) every control key has its control, in the generated order, with the
// generated label, title and slider extent, and shows the world's value
async function testControlsMade(check, page) {
  const r = await page.evaluate(function () {
    const keys = window.Manifold.sceneKeys, sim = window.manifold.simulation();
    const decimals = function (step) { let d = 0; while (d < 6 && Math.abs(step * 10 ** d - Math.round(step * 10 ** d)) > 1e-9) d++; return d; };
    const problems = [];
    const controlled = keys.filter(function (k) { return k.control; });
    controlled.forEach(function (k) {
      const c = k.control, el = document.getElementById(k.key);
      if (!el) { problems.push(k.key + ": no #" + k.key); return; }
      const label = el.closest("label");
      if (!label || label.title !== c.help || label.textContent.indexOf(c.label) < 0) {
        problems.push(k.key + ": label " + JSON.stringify(label && label.textContent) + " titled " + JSON.stringify(label && label.title));
      }
      if (k.kind === "switch") {
        if (el.type !== "checkbox" || el.checked !== sim[k.key]) problems.push(k.key + ": " + el.type + " checked " + el.checked + ", world " + sim[k.key]);
        return;
      }
      const out = document.getElementById(k.key + "-value");
      const shown = sim[k.key].toFixed(decimals(c.step));
      if (el.type !== "range" || Number(el.min) !== c.lo || Number(el.max) !== c.hi || Number(el.step) !== c.step) {
        problems.push(k.key + ": " + el.type + " " + el.min + " … " + el.max + " by " + el.step + ", generated " + c.lo + " … " + c.hi + " by " + c.step);
      }
      if (!out || out.tagName !== "OUTPUT" || out.textContent !== shown || Number(el.value) !== sim[k.key]) {
        problems.push(k.key + ": shows " + (out && out.textContent) + " at " + el.value + ", world " + shown);
      }
    });
    keys.filter(function (k) { return !k.control; }).forEach(function (k) {
      if (document.getElementById(k.key)) problems.push(k.key + " has no control but #" + k.key + " exists");
    });
    const order = Array.from(document.querySelectorAll("#engine-controls input")).map(function (e) { return e.id; });
    return {
      problems: problems, order: order, keys: controlled.map(function (k) { return k.key; }),
      shown: controlled.map(function (k) { const o = document.getElementById(k.key + "-value"); return k.key + " " + (o ? o.textContent : document.getElementById(k.key).checked); }),
      simulation: Object.keys(sim),
    };
  });
  check("every scene key with a control has it (checkbox or slider with its output), in the generated order, with the generated label, title and slider extent, showing the world's value",
    r.keys.length > 0 && r.problems.length === 0 && JSON.stringify(r.order) === JSON.stringify(r.keys) &&
      JSON.stringify(r.simulation) === JSON.stringify(["paused", "timeScale", "thread"].concat(r.keys)),
    r.problems.length ? r.problems.join("; ") : r.shown.join(", ") + "; simulation() " + r.simulation.join(" "));
}

// (2) the keyboard moves the sliders (focus, ArrowRight, End) and a mouse
// click the checkbox; simulation(), the world's parameters (scene()) and the
// outputs follow
async function testKeyboard(check, page) {
  const state = function () {
    return page.evaluate(function () {
      const m = window.manifold, sim = m.simulation(), scene = m.scene();
      const out = {};
      ["substeps", "contactHertz", "friction", "gravity"].forEach(function (k) {
        const o = document.getElementById(k + "-value");
        out[k] = { sim: sim[k], world: scene[k], shown: o ? o.textContent : document.getElementById(k).checked };
      });
      return out;
    });
  };
  const before = await state();
  for (const key of ["substeps", "contactHertz"]) {
    await page.focus("#" + key);
    await page.keyboard.press("ArrowRight");
  }
  await page.focus("#friction");
  await page.keyboard.press("End");
  await page.click("#gravity");
  const after = await state();
  const ok = function (k, want) { return after[k].sim === want && after[k].world === want; };
  check("the keyboard moves the Sub-steps and Contact Hz sliders one step (ArrowRight) and Friction to its end (End), a click flips Gravity: simulation(), the world and the outputs follow",
    ok("substeps", before.substeps.sim + 1) && after.substeps.shown === String(before.substeps.sim + 1) &&
      ok("contactHertz", before.contactHertz.sim + 1) && after.contactHertz.shown === String(before.contactHertz.sim + 1) &&
      ok("friction", 1) && after.friction.shown === "1.00" && ok("gravity", !before.gravity.sim) && after.gravity.shown === !before.gravity.sim,
    JSON.stringify({ before: before, after: after }));
}

// (3) setSimulation checks values against the keys' generated ranges (not
// the sliders' extents) and refuses with the keys' messages, changing nothing
async function testRanges(check, page) {
  const r = await page.evaluate(function () {
    const m = window.manifold;
    // a key's bounds as the generated scene format gives them
    const bounds = function (name) { return window.Manifold.sceneFormat.record.entries.find(function (e) { return e.field === name; }).format.number; };
    const err = function (o) { try { m.setSimulation(o); return null; } catch (e) { return e.message; } };
    const out = { before: m.simulation() };
    out.friction = err({ friction: -1 });
    out.substeps = err({ substeps: 2.5 });
    out.together = err({ restitution: 0.5, substeps: 0 });
    out.gravity = err({ gravity: "yes" });
    out.unchanged = m.simulation();
    out.frictionMessage = "friction " + bounds("friction").lowest.message;
    out.substepsMessage = "substeps " + bounds("substeps").highest.message;
    // beyond the slider's end, within the key's range: taken, shown, the slider at its end
    out.beyond = err({ friction: 3 });
    out.beyondShown = document.getElementById("friction-value").textContent;
    out.beyondSlider = document.getElementById("friction").value;
    out.world = m.scene().friction;
    return out;
  });
  check("setSimulation refuses friction -1 and substeps 2.5 (and 0, and gravity \"yes\") with the scene keys' generated messages, changing nothing",
    r.friction === r.frictionMessage && r.substeps === r.substepsMessage && /^substeps must be/.test(r.together || "") &&
      r.gravity === "gravity must be true or false" && JSON.stringify(r.unchanged) === JSON.stringify(r.before),
    [r.friction, r.substeps, r.together, r.gravity].join(" | "));
  check("setSimulation takes a value beyond a slider's extent that the key's range takes (friction 3: shown as 3.00, the slider at its end)",
    r.beyond === null && r.world === 3 && r.beyondShown === "3.00" && r.beyondSlider === "1",
    JSON.stringify({ error: r.beyond, world: r.world, shown: r.beyondShown, slider: r.beyondSlider }));
  // a new scene: the controls show its values
  const loaded = await page.evaluate(function () {
    const m = window.manifold;
    return m.loadScene({ space: m.space(), substeps: 7, friction: 0.15, gravity: false, bodies: [] }).then(function () {
      return ["substeps", "friction"].map(function (k) { return document.getElementById(k + "-value").textContent; })
        .concat([document.getElementById("gravity").checked]);
    });
  });
  check("a loaded scene's parameters show in the controls", JSON.stringify(loaded) === JSON.stringify(["7", "0.15", false]), JSON.stringify(loaded));
}

// (4) a scene of maxBodies bodies (small circles on a grid of the rectangle)
// loads and steps, the frame loop goes on; one body more is refused in words
async function testMaxBodies(check, page) {
  const r = await page.evaluate(async function () {
    const m = window.manifold;
    await m.setSpace("rectangle");
    m.pause();
    const n = window.Manifold.spaces.rectangle.engine.maxBodies;
    // the rectangle |x| <= 1.5, |z| <= 1 of the plane y = 0: a grid of cols × rows cells
    const scene = function (count) {
      const cols = Math.ceil(Math.sqrt(count * 1.5)), rows = Math.ceil(count / cols), bodies = [];
      for (let k = 0; k < count; k++) {
        const i = k % cols, j = Math.floor(k / cols);
        bodies.push({ shape: "circle", size: 0.004, p: [-1.5 + 3 * (i + 0.5) / cols, 0, -1 + 2 * (j + 0.5) / rows] });
      }
      return { space: "rectangle", gravity: false, bodies: bodies };
    };
    const t0 = performance.now();
    const count = await m.loadScene(scene(n));
    const loadMs = performance.now() - t0;
    const s0 = m.stats();
    const t1 = performance.now();
    m.step(2);
    const stepMs = (performance.now() - t1) / 2;
    m.resume();
    const frames = await new Promise(function (resolve) {
      const until = performance.now() + 20000;
      const wait = function () {
        const s = m.stats();
        if ((s.frames - s0.frames >= 3 && s.steps - s0.steps >= 4) || performance.now() > until) resolve(s);
        else setTimeout(wait, 100);
      };
      wait();
    });
    m.pause();
    const refused = await m.loadScene(scene(n + 1)).then(function () { return null; }, function (e) { return e.message; });
    const notice = document.getElementById("notice").hidden ? "" : document.getElementById("notice-text").textContent;
    return { n: n, count: count, bodies: s0.bodies, loadMs: Math.round(loadMs), stepMs: Math.round(stepMs),
      frames: frames.frames - s0.frames, steps: frames.steps - s0.steps, afterSteps: m.stats().bodies, refused: refused, notice: notice,
      kept: m.stats().bodies, error: m.error() };
  });
  check("a scene of the engine's maxBodies (" + r.n + ") bodies loads, steps, and the page's frames go on",
    r.n === 32768 && r.count === r.n && r.bodies === r.n && r.afterSteps === r.n && r.frames >= 3 && r.steps >= 4 && r.error === null,
    "loaded in " + r.loadMs + " ms, " + r.stepMs + " ms a step; then " + r.frames + " frames, " + r.steps + " steps");
  check("a scene of maxBodies + 1 bodies is refused in words (on the page too), the world kept",
    new RegExp("\\$\\.bodies: " + (r.n + 1) + " bodies, more than a world of rectangle holds \\(" + r.n + "\\)").test(r.refused || "") &&
      r.notice === r.refused && r.kept === r.n, JSON.stringify({ refused: r.refused, notice: r.notice, kept: r.kept }));
}

// (5) a link asking for more bodies than fit: what fits, and a notice saying how many
async function testTooMany(check, context, base) {
  const errors = [];
  const t0 = Date.now();
  const page = await openSpace(context, base, "#space=sphere&bodies=5000", errors);
  const ms = Date.now() - t0;
  const r = await page.evaluate(function () {
    return { bodies: window.manifold.stats().bodies, hash: location.hash,
      notice: document.getElementById("notice").hidden ? "" : document.getElementById("notice-text").textContent };
  });
  check("#space=sphere&bodies=5000 places the bodies that fit and the notice says how many (the hash their count)",
    r.bodies > 6 && r.bodies < 5000 && r.notice === "Placed " + r.bodies + " of 5000 bodies: no room for more of this size." &&
      r.hash === "#space=sphere&bodies=" + r.bodies && errors.length === 0,
    JSON.stringify(r) + ", page ready in " + ms + " ms" + (errors.length ? "; " + errors.join("; ") : ""));
  await page.close();
}

export async function testControls(check, context, base) {
  const errors = [];
  const page = await openSpace(context, base, "#space=torus", errors);
  await testControlsMade(check, page);
  await testKeyboard(check, page);
  await testRanges(check, page);
  await testMaxBodies(check, page);
  check("controls page: no console errors", errors.length === 0, errors.join("; "));
  await page.close();
  await testTooMany(check, context, base);
}
