// Browser tests of the page's keys and its help overlay (part "keys" of
// run.mjs), with real key presses (page.keyboard) on the sphere's default
// scene: Space pauses and resumes (the Pause button's aria-pressed, and the
// step counter stops), and neither scrolls nor presses the focused Pause
// button too; s while paused advances exactly one step; c leaves no body, r
// brings the default scene back; keys typed in a number field, or with Alt
// held, or Space on a focused checkbox, are not the page's; ? opens the
// overlay (a labelled modal dialog listing the keys and the gestures),
// Escape, ? again and its close button close it, and the ? button opens it.
import { openSpace } from "./bodies.mjs";

// the page's clock, counters and key-related state
function readState(page) {
  return page.evaluate(function () {
    const m = window.manifold, st = m.stats(), pause = document.getElementById("pause");
    const a = document.activeElement;
    return {
      steps: st.steps, bodies: m.bodies().length, counted: st.bodies, paused: m.simulation().paused,
      pressed: pause.getAttribute("aria-pressed"), label: pause.textContent, grid: m.options().grid,
      help: document.getElementById("keys-help").open, focus: a ? a.id || a.tagName : null,
      lastKey: window.__lastKey || null,
    };
  });
}

function sleep(ms) { return new Promise(function (resolve) { setTimeout(resolve, ms); }); }

// whether the step counter moves within ms (the frame loop runs the steps due)
async function stepsMoveWithin(page, ms) {
  const s0 = (await readState(page)).steps;
  const t = Date.now() + ms;
  for (;;) {
    const s = (await readState(page)).steps;
    if (s !== s0) return { moved: true, from: s0, to: s };
    if (Date.now() > t) return { moved: false, from: s0, to: s };
    await sleep(100);
  }
}

// (1) Space toggles the clock like the Pause button; the page takes the key
// (defaultPrevented: no scroll, no press of a focused button)
async function testSpace(check, page) {
  const running = await stepsMoveWithin(page, 10000);
  const before = await readState(page);
  await page.keyboard.press("Space");
  const paused = await readState(page);
  const frozen = await stepsMoveWithin(page, 1500);
  check("Space pauses: #pause aria-pressed true (\"Resume\"), simulation().paused, the step counter stops; the key's default prevented",
    running.moved && before.pressed === "false" && !before.paused &&
      paused.pressed === "true" && paused.label === "Resume" && paused.paused && !frozen.moved &&
      paused.lastKey && paused.lastKey.key === " " && paused.lastKey.prevented === true,
    JSON.stringify({ running: running, before: before.pressed, after: paused.pressed, label: paused.label, frozen: frozen, key: paused.lastKey }));

  await page.keyboard.press("Space");
  const resumed = await readState(page);
  const moving = await stepsMoveWithin(page, 10000);
  check("Space again resumes: aria-pressed false (\"Pause\"), the step counter moves again",
    resumed.pressed === "false" && resumed.label === "Pause" && !resumed.paused && moving.moved,
    JSON.stringify({ pressed: resumed.pressed, label: resumed.label, moving: moving }));

  // the Pause button clicked (so focused), then Space: one toggle, not two
  await page.click("#pause");
  const clicked = await readState(page);
  await page.keyboard.press("Space");
  await sleep(100);
  const spaced = await readState(page);
  check("Space with the Pause button focused (after a click) toggles once: the button is not pressed too",
    clicked.focus === "pause" && clicked.pressed === "true" && spaced.pressed === "false" && !spaced.paused &&
      spaced.lastKey.prevented === true,
    JSON.stringify({ afterClick: [clicked.focus, clicked.pressed], afterSpace: spaced.pressed, key: spaced.lastKey }));
  await page.keyboard.press("Space");
  const again = await readState(page);
  check("… and Space there pauses again", again.pressed === "true" && again.paused, again.pressed);

  // a focused checkbox keeps Space (it ticks it)
  await page.focus("#grid");
  await page.keyboard.press("Space");
  const ticked = await readState(page);
  check("Space on a focused checkbox (Grid) ticks it and leaves the clock alone",
    ticked.grid === !again.grid && ticked.paused && ticked.pressed === "true" && ticked.lastKey.prevented === false,
    JSON.stringify({ grid: [again.grid, ticked.grid], paused: ticked.paused, key: ticked.lastKey }));
  await page.keyboard.press("Space");
  await page.evaluate(function () { document.activeElement.blur(); });
}

// (2) s while paused: exactly one step per press, still paused
async function testStep(check, page) {
  const before = await readState(page);
  await page.keyboard.press("s");
  await sleep(600);
  const one = await readState(page);
  await page.keyboard.press("s");
  await page.keyboard.press("s");
  await sleep(600);
  const three = await readState(page);
  check("s while paused advances exactly one step a press (1, then 2 more), the clock stays paused",
    before.paused && one.steps === before.steps + 1 && three.steps === before.steps + 3 && one.paused && three.paused &&
      three.pressed === "true" && one.lastKey.prevented === true,
    "steps " + before.steps + " → " + one.steps + " → " + three.steps + ", paused " + three.paused);
}

// (3) keys typed into a number field, or with Alt held, are not the page's
async function testIgnored(check, page) {
  const before = await readState(page);
  await page.focus("#body-density");
  await page.keyboard.press("c");
  await page.keyboard.press("s");
  await page.keyboard.press("r");
  await page.keyboard.press("Space");
  await page.keyboard.press("?");
  await sleep(300);
  const typed = await readState(page);
  check("c, s, r, Space and ? typed in the density field do nothing to the page (bodies, steps, clock kept, no overlay)",
    before.bodies > 0 && typed.focus === "body-density" && typed.bodies === before.bodies && typed.steps === before.steps &&
      typed.paused && typed.pressed === "true" && !typed.help,
    JSON.stringify({ bodies: [before.bodies, typed.bodies], steps: [before.steps, typed.steps], paused: typed.paused, help: typed.help }));
  await page.evaluate(function () { document.activeElement.blur(); });
  await page.keyboard.press("Alt+c");
  await page.keyboard.press("Alt+s");
  await sleep(300);
  const alt = await readState(page);
  check("Alt+c and Alt+s are left to the browser (no clear, no step)",
    alt.bodies === before.bodies && alt.steps === before.steps && alt.lastKey.prevented === false,
    JSON.stringify({ bodies: alt.bodies, steps: alt.steps, key: alt.lastKey }));
}

// (4) c clears every body, r brings the default scene back
async function testClearReset(check, page) {
  await page.keyboard.press("c");
  const cleared = await readState(page);
  check("c removes every body (0 bodies in the world and in stats())",
    cleared.bodies === 0 && cleared.counted === 0 && cleared.lastKey.prevented === true,
    JSON.stringify({ bodies: cleared.bodies, counted: cleared.counted }));
  await page.keyboard.press("r");
  const r = await page.evaluate(function () {
    const m = window.manifold, scene = window.Manifold.spaces[m.space()].scene, bodies = m.bodies();
    let far = 0;
    scene.forEach(function (b, i) {
      const q = bodies[i] ? bodies[i].p : [Infinity, 0, 0];
      far = Math.max(far, Math.hypot(q[0] - b.p[0], q[1] - b.p[1], q[2] - b.p[2]));
    });
    return { scene: scene.length, bodies: bodies.length, counted: m.stats().bodies, shapes: bodies.map(function (b) { return b.shape; }).join(" "),
      want: scene.map(function (b) { return b.shape; }).join(" "), far: far };
  });
  check("r brings the default scene back (its bodies, shapes and places)",
    r.scene > 0 && r.bodies === r.scene && r.counted === r.scene && r.shapes === r.want && r.far < 1e-3,
    JSON.stringify(r));
}

// (5) the overlay: ? opens it, Escape, ? and × close it, the ? button opens it
async function testOverlay(check, page) {
  const dialog = page.getByRole("dialog", { name: "Keys and gestures" });
  const hiddenAtFirst = !(await dialog.isVisible());
  await page.keyboard.press("?");
  await sleep(100);
  const shown = await dialog.isVisible();
  const text = shown ? await dialog.innerText() : "";
  const opened = await readState(page);
  const listed = ["Space", "S", "R", "C", "G", "J", "T", "P", "B", "?", "Esc", "body", "drag", "throw", "geodesic", "joint", "Ctrl", "orbit", "pan", "right", "wheel", "pinch", "zoom", "Alt", "inspect"]
    .filter(function (w) { return text.indexOf(w) < 0; });
  const kbd = await page.evaluate(function () {
    return Array.from(document.querySelectorAll("#keys-help kbd")).map(function (k) { return k.textContent; });
  });
  check("? opens the help overlay: a modal dialog named \"Keys and gestures\" (hidden before), visible, focus in it, listing the keys and the gestures",
    hiddenAtFirst && shown && opened.help && opened.focus === "keys-help-close" && listed.length === 0 &&
      JSON.stringify(kbd) === JSON.stringify(["Space", "S", "R", "C", "G", "J", "T", "P", "B", "?", "Esc"]),
    "missing " + JSON.stringify(listed) + ", keys " + kbd.join(" ") + ", focus " + opened.focus);

  // modal: the other keys are not the page's while it is open
  await page.keyboard.press("c");
  await page.keyboard.press("s");
  await sleep(300);
  const inside = await readState(page);
  check("while the overlay is open, c and s do nothing (bodies and steps kept)",
    inside.help && inside.bodies === opened.bodies && inside.steps === opened.steps,
    JSON.stringify({ bodies: [opened.bodies, inside.bodies], steps: [opened.steps, inside.steps] }));

  await page.keyboard.press("Escape");
  await sleep(100);
  const escaped = !(await dialog.isVisible());
  await page.keyboard.press("?");
  await sleep(100);
  const reopened = await dialog.isVisible();
  await page.keyboard.press("?");
  await sleep(100);
  const toggled = !(await dialog.isVisible());
  check("Escape closes the overlay; ? opens it again and ? closes it", escaped && reopened && toggled,
    JSON.stringify({ escaped: escaped, reopened: reopened, toggled: toggled }));

  const open = page.getByRole("button", { name: "keys and gestures" });
  const buttons = await open.count();
  const title = buttons === 1 ? await open.getAttribute("title") : null;
  if (buttons === 1) await open.click();
  await sleep(100);
  const byButton = await dialog.isVisible();
  const close = dialog.getByRole("button", { name: "close" });
  const closes = await close.count();
  if (closes === 1) await close.click();
  await sleep(100);
  const closed = !(await dialog.isVisible());
  const after = await readState(page);
  check("the \"keys and gestures\" button (titled so) opens the overlay, its \"close\" button closes it, focus back on the ? button",
    buttons === 1 && title === "keys and gestures" && byButton && closes === 1 && closed && after.focus === "keys-help-open",
    JSON.stringify({ buttons: buttons, title: title, byButton: byButton, closes: closes, closed: closed, focus: after.focus }));
  await page.evaluate(function () { document.activeElement.blur(); });

  // the keys work again once it is closed
  await page.keyboard.press("c");
  const cleared = await readState(page);
  check("with the overlay closed the keys are the page's again (c clears)", cleared.bodies === 0, String(cleared.bodies));
}

export async function testKeys(check, context, base) {
  const errors = [];
  const page = await openSpace(context, base, "#space=sphere", errors);
  // the last key press as the page saw it after its own handlers: whether its default was prevented
  await page.evaluate(function () {
    window.addEventListener("keydown", function (e) { window.__lastKey = { key: e.key, prevented: e.defaultPrevented }; });
  });
  await testSpace(check, page);
  await testStep(check, page);
  await testIgnored(check, page);
  await testClearReset(check, page);
  await testOverlay(check, page);
  check("keys page: no console errors", errors.length === 0, errors.join("; "));
  await page.close();
}
