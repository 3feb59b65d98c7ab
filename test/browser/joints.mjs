// Browser tests of joints (part "joints" of run.mjs), with a real mouse
// and keyboard: the sphere-chain preset loads by URL with its 24 joints and
// swings without warnings; the joints are drawn (at the pins the picture
// differs from the same view with the joints removed; a distance joint
// shows along the great circle between its anchors); the joint tool (j)
// joins the body pressed on to the body released on with a pin, and, with
// Ctrl held at the release on empty surface, a body to the world with a
// distance joint; a joint made by the API that joins a body to itself, and a
// scene with a malformed joint, are refused naming the problem. Sleeping:
// two stacks fall asleep (stats() counts no body awake and two islands),
// drawn dimmed unless "Dim sleeping" is off, saved with "awake": false;
// a real press on a box of one stack wakes that stack only.
import path from "node:path";
import { OUT, canvasShot } from "./lib.mjs";
import { openSpace } from "./bodies.mjs";

// (1) the preset: loaded by URL, its joints counted, stepping cleanly
async function testChainPreset(check, page) {
  await page.waitForFunction(function () { return window.manifold.preset() === "sphere-chain"; }, null, { timeout: 10000 }).catch(function () {});
  const r = await page.evaluate(function () {
    const m = window.manifold;
    m.pause();
    const before = m.stats();
    m.step(200);
    const after = m.stats();
    return { preset: m.preset(), bodies: before.bodies, joints: before.joints, listed: m.joints().length,
      warnings: after.warnings, types: m.joints().map(function (j) { return j.type; }) };
  });
  check("#scene=sphere-chain loads 25 bodies and 24 revolute joints (stats().joints, joints()) and steps 2 s without a warning",
    r.preset === "sphere-chain" && r.bodies === 25 && r.joints === 24 && r.listed === 24 && r.warnings === 0 &&
    r.types.every(function (t) { return t === "revolute"; }),
    JSON.stringify({ preset: r.preset, bodies: r.bodies, joints: r.joints, warnings: r.warnings }));
}

// (2) the joints are drawn: the picture at the pins changes when they are removed
async function testDrawn(check, page) {
  const pins = await page.evaluate(function () {
    const m = window.manifold;
    m.render();
    const e = m.camera().eye;
    // the pins on the side of the sphere that faces the camera
    return m.joints().filter(function (j) {
      const q = j.anchor;
      return (q[0] - e[0]) * q[0] + (q[1] - e[1]) * q[1] + (q[2] - e[2]) * q[2] < -0.2;
    }).map(function (j) { return m.project(j.anchor); }).filter(function (px) { return px; });
  });
  const withJoints = await canvasShot(page, path.join(OUT, "joints-sphere-chain.png"));
  await page.evaluate(function () {
    const m = window.manifold;
    for (let k = m.joints().length - 1; k >= 0; k--) m.removeJoint(k);
    m.render();
  });
  const without = await canvasShot(page, path.join(OUT, "joints-sphere-chain-removed.png"));
  const changed = pins.filter(function (px) {
    for (let dy = -2; dy <= 2; dy++) {
      for (let dx = -2; dx <= 2; dx++) {
        const x = Math.round(px[0]) + dx, y = Math.round(px[1]) + dy;
        if (x < 0 || y < 0 || x >= withJoints.width || y >= withJoints.height) continue;
        const a = withJoints.at(x, y), b = without.at(x, y);
        if (Math.abs(a[0] - b[0]) + Math.abs(a[1] - b[1]) + Math.abs(a[2] - b[2]) > 60) return true;
      }
    }
    return false;
  }).length;
  const left = await page.evaluate(function () { return window.manifold.stats().joints; });
  check("the joints are drawn: at most of the pins in view the picture differs from the same view with the joints removed (removeJoint)",
    pins.length >= 10 && changed >= 0.8 * pins.length && left === 0, changed + " of " + pins.length + " pins, " + left + " joints left");
}

// (2b) a joint is drawn on the surface: a distance joint 1 rad long across
// the sphere's side facing the camera shows along the great circle between
// its anchors (its straight chord would run up to 0.12 under the surface, hidden)
async function testDrawnOnSurface(check, page) {
  const arc = await page.evaluate(async function () {
    const m = window.manifold;
    m.pause();
    const e = m.camera().eye, r = Math.hypot(e[0], e[1], e[2]);
    const c = [e[0] / r, e[1] / r, e[2] / r], h = Math.hypot(c[0], c[2]);
    const t = [-c[2] / h, 0, c[0] / h];
    /** @param {number} a */
    const on = function (a) { return [0, 1, 2].map(function (k) { return Math.cos(a) * c[k] + Math.sin(a) * t[k]; }); };
    await m.loadScene({ space: "sphere", bodies: [{ shape: "circle", size: 0.05, p: on(-0.5) }, { shape: "circle", size: 0.05, p: on(0.5) }],
      joints: [{ type: "distance", a: 0, b: 1, anchorA: on(-0.5), anchorB: on(0.5) }] });
    m.pause();
    m.render();
    return [-0.3, -0.15, 0, 0.15, 0.3].map(function (a) { return m.project(on(a)); });
  });
  const withJoint = await canvasShot(page, path.join(OUT, "joints-sphere-arc.png"));
  await page.evaluate(function () { window.manifold.removeJoint(0); window.manifold.render(); });
  const without = await canvasShot(page, path.join(OUT, "joints-sphere-arc-removed.png"));
  const shown = arc.filter(function (px) {
    if (!px) return false;
    for (let dy = -2; dy <= 2; dy++) {
      for (let dx = -2; dx <= 2; dx++) {
        const a = withJoint.at(Math.round(px[0]) + dx, Math.round(px[1]) + dy), b = without.at(Math.round(px[0]) + dx, Math.round(px[1]) + dy);
        if (Math.abs(a[0] - b[0]) + Math.abs(a[1] - b[1]) + Math.abs(a[2] - b[2]) > 60) return true;
      }
    }
    return false;
  }).length;
  check("a distance joint on the sphere is drawn along the great circle between its anchors: the picture differs at 5 of 5 points of the arc (its middle 0.12 above the straight chord)",
    shown === 5, shown + " of " + arc.length + " points: " + JSON.stringify(arc));
}

// (3) the joint tool with the mouse: a pin between two bodies, a distance joint to the world with Ctrl
async function testJointTool(check, page) {
  const at = await page.evaluate(function () {
    const m = window.manifold;
    return m.loadScene({ space: "plane", gravity: false, bodies: [
      { shape: "circle", size: 0.12, p: [-0.2, 0, 0] }, { shape: "circle", size: 0.12, p: [0.2, 0, 0] }] }).then(function () {
      m.pause();
      m.render();
      const box = document.getElementById("view").getBoundingClientRect(), st = m.stats();
      const css = function (q) { const px = m.project(q); return [box.left + px[0] * box.width / st.width, box.top + px[1] * box.height / st.height]; };
      return { a: css([-0.2, 0, 0]), b: css([0.2, 0, 0]), empty: css([0.2, 0, 0.45]) };
    });
  });
  await page.keyboard.press("j");
  const tool = await page.evaluate(function () { return window.manifold.tool(); });
  await page.mouse.move(at.a[0], at.a[1]);
  await page.mouse.down();
  await page.mouse.move(at.b[0], at.b[1], { steps: 6 });
  await page.mouse.up();
  const pin = await page.evaluate(function () { return window.manifold.joints(); });
  check("j picks the joint tool; pressing on one body and releasing on the other pins them where released (a revolute joint 0–1)",
    tool === "joint" && pin.length === 1 && pin[0].type === "revolute" && pin[0].a === 0 && pin[0].b === 1 &&
    Math.abs(pin[0].anchor[0] - 0.2) < 0.03 && Math.abs(pin[0].anchor[2]) < 0.03,
    JSON.stringify({ tool: tool, joints: pin.map(function (j) { return [j.type, j.a, j.b, j.anchor]; }) }));
  await page.mouse.move(at.b[0], at.b[1]);
  await page.mouse.down();
  await page.mouse.move(at.empty[0], at.empty[1], { steps: 6 });
  await page.keyboard.down("Control");
  await page.mouse.up();
  await page.keyboard.up("Control");
  const rope = await page.evaluate(function () {
    const m = window.manifold, j = m.joints()[1];
    return j ? { type: j.type, a: j.a, b: j.b, length: j.length } : null;
  });
  check("with Ctrl held at the release on empty surface: a distance joint from the body to the world, as long as the drag (0.45)",
    rope !== null && rope.type === "distance" && rope.a === 1 && rope.b === "world" && Math.abs(rope.length - 0.45) < 0.03,
    JSON.stringify(rope));
  await page.keyboard.press("j");
}

// (4) refusals: the API's and a scene's, naming the problem
async function testRefusals(check, page) {
  const r = await page.evaluate(function () {
    const m = window.manifold;
    let api = null;
    try { m.addJoint({ type: "revolute", a: 0, b: 0, anchor: [0, 0, 0] }); } catch (e) { api = e.message; }
    const joints = m.joints().length;
    return m.loadScene({ space: "sphere", bodies: [{ shape: "circle", size: 0.1, p: [1, 0, 0] }],
      joints: [{ type: "distance", a: 0, b: "world", anchorA: [1, 0, 0], anchorB: [0, 1, 0], length: -1 }] })
      .then(function () { return "loaded"; }, function (e) { return e.message; })
      .then(function (scene) { return { api: api, joints: joints, scene: scene, space: m.space() }; });
  });
  check("addJoint joining a body to itself throws naming it; a scene with a negative length is refused with its JSON path, the world kept",
    r.api === "joint.b: joins body 0 to itself" && r.joints === 2 && /\$\.joints\[0\]\.length: must not be negative/.test(r.scene) && r.space === "plane",
    JSON.stringify(r));
}

// (5) sleeping: two stacks on a floor fall asleep, dimmed; a press wakes one
async function testSleeping(check, page) {
  const at = await page.evaluate(function () {
    const m = window.manifold;
    const h = 0.1, top = -2.5 + 3 / Math.SQRT2;
    const bodies = [{ shape: "square", size: 3, static: true, p: [0, 0, -2.5] }];
    [-0.5, 0.5].forEach(function (x) {
      for (let k = 0; k < 3; k++) bodies.push({ shape: "square", size: h, p: [x, 0, top + h / Math.SQRT2 + k * h * Math.SQRT2] });
    });
    return m.loadScene({ space: "plane", bodies: bodies }).then(function () {
      m.pause();
      m.step(150);
      m.render();
      const box = document.getElementById("view").getBoundingClientRect(), st = m.stats();
      const px = function (i) { return m.project(m.scene().bodies[i].p); };
      const css = function (q) { return [box.left + q[0] * box.width / st.width, box.top + q[1] * box.height / st.height]; };
      return { awake: st.awake, islands: st.islands, saved: m.scene().bodies.map(function (b) { return b.awake !== false; }),
        centres: [1, 2, 3, 4, 5, 6].map(px), press: css(px(2)) };
    });
  });
  check("two stacks on a floor fall asleep within 1.5 s: stats() counts no body awake and two islands; saved, each box has \"awake\": false",
    at.awake === 0 && at.islands === 2 && at.saved.join() === [true, false, false, false, false, false, false].join(),
    JSON.stringify({ awake: at.awake, islands: at.islands, awakeSaved: at.saved }));
  const dim = await canvasShot(page, path.join(OUT, "sleeping-dimmed.png"));
  await page.evaluate(function () { window.manifold.setOptions({ dimSleeping: false }); window.manifold.render(); });
  const bright = await canvasShot(page, path.join(OUT, "sleeping-bright.png"));
  await page.evaluate(function () { window.manifold.setOptions({ dimSleeping: true }); window.manifold.render(); });
  const lum = function (img, q) { const c = img.at(Math.round(q[0]), Math.round(q[1])); return c[0] + c[1] + c[2]; };
  const darker = at.centres.filter(function (q) { return q && lum(dim, q) < lum(bright, q) - 30; }).length;
  check("sleeping bodies are drawn dimmed: darker at every box's centre than with \"Dim sleeping\" off",
    darker === 6, darker + " of 6 darker");
  await page.mouse.move(at.press[0], at.press[1]);
  await page.mouse.down();
  const woke = await page.evaluate(function () {
    const m = window.manifold;
    m.step(1);
    return { awake: m.stats().awake, bodies: m.scene().bodies.map(function (b) { return b.awake !== false; }) };
  });
  await page.mouse.up();
  check("a press on a box of the left stack wakes that stack only (3 awake, the right stack asleep)",
    woke.awake === 3 && woke.bodies.join() === [true, true, true, true, false, false, false].join(), JSON.stringify(woke));
}

export async function testJoints(check, context, base) {
  const errors = [];
  const page = await openSpace(context, base, "#scene=sphere-chain", errors);
  await testChainPreset(check, page);
  await testDrawn(check, page);
  await testDrawnOnSurface(check, page);
  await testJointTool(check, page);
  await testRefusals(check, page);
  await testSleeping(check, page);
  check("joints page: no console errors", errors.length === 0, errors.join("; "));
  await page.close();
}
