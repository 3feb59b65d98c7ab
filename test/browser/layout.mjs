// Browser tests of the page's layout (part "layout" of run.mjs): from 800 px
// wide the controls are a side panel of four titled groups, every label and
// control inside it (nothing cut) and none over another, the status line
// under the view likewise; the panel collapses to a rail (its button or B)
// and the view, its backing store too, takes the room, and opens again. At
// 720 px the controls wrap in a bar above the view, at 640 px they scroll in
// one row: nothing overlaps there either.

import { openSpace } from "./bodies.mjs";

const GROUPS = ["Space and view", "Bodies and tools", "Simulation", "Scene and capture"];

// In the page: every visible control (input, select, button, output) and
// every visible piece of text of the panel and the status line, with its
// box; the pairs whose boxes overlap; the boxes that leave their container
// (the panel's inner box, the status line, the window) sideways.
function measure() {
  const panel = document.getElementById("panel"), status = document.getElementById("status");
  const shown = function (el) {
    const b = el.getBoundingClientRect(), s = getComputedStyle(el);
    return b.width > 0 && b.height > 0 && s.visibility !== "hidden";
  };
  const name = function (el) {
    const label = el.closest("label");
    return el.tagName.toLowerCase() + (el.id ? "#" + el.id : "") + (label && !el.id ? " in " + JSON.stringify(label.textContent.trim().slice(0, 20)) : "");
  };
  const items = [];
  [panel, status].forEach(function (root) {
    const inner = root.getBoundingClientRect();
    const container = {
      left: inner.left + root.clientLeft, right: inner.left + root.clientLeft + root.clientWidth,
      top: inner.top + root.clientTop, bottom: inner.top + root.clientTop + root.clientHeight,
    };
    root.querySelectorAll("input, select, button, output").forEach(function (el) {
      if (el.type === "file" || !shown(el)) return;
      items.push({ name: name(el), box: el.getBoundingClientRect(), container: container, el: el });
    });
    const walk = document.createTreeWalker(root, NodeFilter.SHOW_TEXT);
    for (let n = walk.nextNode(); n; n = walk.nextNode()) {
      const parent = n.parentElement;
      // (an output's text counts: it may run past its box)
      if (!n.textContent.trim() || parent.closest("button, select, datalist")) continue;
      if (!shown(parent)) continue;
      // text its element clips (the status line's description) counts as that element's box
      if (getComputedStyle(parent).overflow === "hidden") {
        items.push({ name: "text of #" + parent.id, box: parent.getBoundingClientRect(), container: container, el: parent });
        continue;
      }
      const range = document.createRange();
      range.selectNodeContents(n);
      Array.from(range.getClientRects()).forEach(function (b) {
        if (b.width > 0 && b.height > 0) items.push({ name: JSON.stringify(n.textContent.trim().slice(0, 24)), box: b, container: container, el: parent });
      });
    }
  });
  // a box the panel has scrolled out of sight is not drawn: clipped to
  // its container's height, or dropped
  const drawn = items.filter(function (a) {
    const top = Math.max(a.box.top, a.container.top), bottom = Math.min(a.box.bottom, a.container.bottom);
    if (bottom - top < 0.5) return false;
    a.box = { left: a.box.left, right: a.box.right, top: top, bottom: bottom };
    return true;
  });
  const overlaps = [], cut = [];
  const seen = new Set();
  drawn.forEach(function (a, i) {
    if (a.box.left < a.container.left - 0.5 || a.box.right > a.container.right + 0.5 || a.box.right > innerWidth + 0.5) {
      cut.push(a.name + " [" + a.box.left.toFixed(0) + ", " + a.box.right.toFixed(0) + "] in [" + a.container.left.toFixed(0) + ", " + a.container.right.toFixed(0) + "]");
    }
    for (let j = i + 1; j < drawn.length; j++) {
      const b = drawn[j];
      if (a.el === b.el) continue; // one text's lines, an output and its text
      if (a.el.contains(b.el) && a.el !== b.el && a.el.tagName !== "LABEL") continue;
      const w = Math.min(a.box.right, b.box.right) - Math.max(a.box.left, b.box.left);
      const h = Math.min(a.box.bottom, b.box.bottom) - Math.max(a.box.top, b.box.top);
      const key = a.name + " / " + b.name;
      // (buttons joined into a group share their one-pixel border)
      if (w > 1.5 && h > 1.5 && !seen.has(key)) { seen.add(key); overlaps.push(key + " (" + w.toFixed(1) + " × " + h.toFixed(1) + " px)"); }
    }
  });
  const p = panel.getBoundingClientRect(), v = document.getElementById("view").getBoundingClientRect();
  const titles = Array.from(panel.querySelectorAll("h2")).filter(shown).map(function (h) { return h.textContent; });
  return {
    items: drawn.length, overlaps: overlaps, cut: cut, titles: titles,
    panel: { left: p.left, right: p.right, top: p.top, bottom: p.bottom, scrollsSideways: panel.scrollWidth > panel.clientWidth + 1 },
    view: { left: v.left, right: v.right, top: v.top, bottom: v.bottom, width: v.width },
    backing: window.manifold.stats().width,
  };
}

async function openAt(browser, base, width) {
  const context = await browser.newContext({ viewport: { width: width, height: 900 }, deviceScaleFactor: 1 });
  const errors = [];
  const page = await openSpace(context, base, "#space=sphere", errors);
  return { context: context, page: page, errors: errors };
}

const report = function (r) {
  return r.items + " boxes" + (r.overlaps.length ? "; overlapping: " + r.overlaps.slice(0, 6).join("; ") : "") +
    (r.cut.length ? "; cut: " + r.cut.slice(0, 6).join("; ") : "") + (r.panel.scrollsSideways ? "; the panel scrolls sideways" : "");
};

// the layout once the view's width has changed from `before` and its
// backing store has followed
async function afterResize(page, before) {
  await page.waitForFunction(function (w0) {
    const w = document.getElementById("view").getBoundingClientRect().width;
    return Math.abs(w - w0) > 1 && Math.abs(window.manifold.stats().width - w) <= 1;
  }, before, { timeout: 5000 }).catch(function () {});
  return page.evaluate(measure);
}

export async function testLayout(check, browser, base) {
  for (const width of [800, 1200, 1920]) {
    const { context, page, errors } = await openAt(browser, base, width);
    const r = await page.evaluate(measure);
    check(width + " px: the controls are a side panel left of the view in four titled groups, every label and control in it, none over another, nor in the status line",
      r.items > 40 && r.overlaps.length === 0 && r.cut.length === 0 && !r.panel.scrollsSideways &&
        JSON.stringify(r.titles) === JSON.stringify(GROUPS) && r.view.left >= r.panel.right - 0.5 && r.panel.left === 0 &&
        r.view.right === width && Math.abs(r.backing - r.view.width) <= 1,
      report(r) + "; groups " + r.titles.join(", ") + "; panel [" + r.panel.left + ", " + r.panel.right + "], view [" + r.view.left + ", " + r.view.right + "] backing " + r.backing);

    // collapsed by its button: the view takes the room, every control hidden;
    // B opens it again
    await page.click("#panel-toggle");
    const folded = await afterResize(page, r.view.width);
    const state = await page.evaluate(function () {
      const t = document.getElementById("panel-toggle");
      return { expanded: t.getAttribute("aria-expanded"), label: t.getAttribute("aria-label"), spaceShown: document.getElementById("space").getClientRects().length > 0 };
    });
    await page.locator("#view").focus().catch(function () {});
    await page.keyboard.press("b");
    const opened = await afterResize(page, folded.view.width);
    check(width + " px: the panel's button folds it to a rail (controls hidden, the view and its backing store take the room) and B opens it again as it was",
      state.expanded === "false" && state.label === "show the controls" && !state.spaceShown &&
        folded.panel.right < 60 && folded.view.width > r.view.width + 200 && Math.abs(folded.backing - folded.view.width) <= 1 &&
        opened.panel.right === r.panel.right && opened.view.width === r.view.width && opened.overlaps.length === 0,
      JSON.stringify(state) + "; folded panel right " + folded.panel.right + ", view " + folded.view.width + " (backing " + folded.backing + "), opened view " + opened.view.width);
    check(width + " px: no console errors", errors.length === 0, errors.join("; "));
    await context.close();
  }
  for (const width of [720, 640]) {
    const { context, page, errors } = await openAt(browser, base, width);
    const r = await page.evaluate(measure);
    const wraps = width > 640;
    check(width + " px: the controls are a bar above the view (" + (wraps ? "wrapping, nothing cut" : "one row that scrolls") + "), none over another, the view the window's width",
      r.items > 40 && r.overlaps.length === 0 && (!wraps || r.cut.length === 0) && r.view.top >= r.panel.bottom - 0.5 &&
        r.view.left === 0 && r.view.right === width && r.titles.length === 0,
      report(r) + "; panel bottom " + r.panel.bottom + ", view [" + r.view.left + ", " + r.view.right + "] from " + r.view.top);
    check(width + " px: no console errors", errors.length === 0, errors.join("; "));
    await context.close();
  }
}
