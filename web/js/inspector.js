// The inspector: with Alt (Option) held, the body under the pointer is
// described next to it (its index, shape and size, static or not, its own
// friction and restitution if it has them, speed, spin, kinetic energy and
// the last step's contact rows it is in, by the
// engine's generated measureBody), and kept up to date while it moves
// until Alt is let go or the pointer leaves the view.
/* exported ManifoldWebInspector */
var ManifoldWebInspector = (function (W) {
  "use strict";
  const MW = W.ManifoldWeb;
  const P = MW.page, state = P.state;

  const inspector = {
    /** @type {number} the body shown, or -1 */
    index: -1,
    at: /** @type {[number, number]} */ ([0, 0]), // client pixels of the pointer
    version: -1,          // world.version when last shown
  };

  // a shape and its size (a box's and a capsule's: its numbers; a polygon's: how far it reaches)
  /** @param {Manifold.Shape} s @param {number} size */
  function shapeName(s, size) {
    if (typeof s === "string") return s + " " + fixed(size);
    if ("polygon" in s) return s.polygon + "-gon " + fixed(size);
    if ("box" in s) return "box " + s.box.map(fixed).join(" by ");
    if ("vertices" in s) return s.vertices.length + "-cornered polygon " + fixed(size) + (s.radius ? " rounded " + fixed(s.radius) : "");
    return "capsule " + s.capsule.map(fixed).join(" by ");
  }

  // What the inspector says of body i, or null when there is none.
  /** @param {number} i */
  function describe(i) {
    const w = state.world;
    if (!w || i < 0 || i >= w.count()) return null;
    const m = w.measureBody(i), info = w.info[i], E = w.engine;
    // (how far it reaches: a box's or a capsule's from its numbers)
    const size = MW.world.reachOf(info.shape, info.size), omega = w.a.scalars[i * w.stride() + E.slots.omega];
    const asleep = w.a.scalars[i * w.stride() + E.slots.asleep] > 0;
    return Object.assign({ index: i, shape: info.shape, size: size, static: info.static, asleep: asleep, speed: m.speed, omega: omega, energy: m.energy, contacts: m.contacts },
      w.material(i));
  }

  // three significant digits (a size 0.200, an energy 0.000655)
  /** @param {number} x */
  function fixed(x) { return x === 0 ? "0" : Math.abs(x) >= 1000 ? x.toFixed(0) : x.toPrecision(3); }

  // Shows the body under client pixel (x, y) (backing-store pixel px), or hides the inspector.
  /** @param {number} x @param {number} y @param {[number, number]} px */
  function hover(x, y, px) {
    const w = state.world;
    const q = w && !state.compare ? MW.input.surfacePoint(px[0], px[1]) : null;
    const hit = q ? w.pick(q) : null;
    inspector.index = hit ? hit.index : -1;
    inspector.at = [x, y];
    inspector.version = -1;
    refresh();
  }

  function hide() {
    inspector.index = -1;
    refresh();
  }

  // Writes the inspector's text again when the body moved (the frame loop calls this).
  function refresh() {
    const box = state.ui && state.ui.inspector;
    if (!box) return;
    const d = describe(inspector.index);
    box.hidden = d === null;
    if (!d || (state.world && inspector.version === state.world.version)) return;
    inspector.version = state.world.version;
    box.textContent = "body " + d.index + " · " + shapeName(d.shape, d.size) + (d.static ? " · static" : "") + (d.asleep ? " · asleep" : "") +
      (d.friction !== undefined ? " · μ " + fixed(d.friction) : "") + (d.restitution !== undefined ? " · e " + fixed(d.restitution) : "") +
      " · speed " + fixed(d.speed) + " · ω " + fixed(d.omega) + " · energy " + fixed(d.energy) + " · contacts " + d.contacts;
    const stage = /** @type {HTMLElement} */ (box.parentElement).getBoundingClientRect();
    box.style.left = Math.round(inspector.at[0] - stage.left + 14) + "px";
    box.style.top = Math.round(inspector.at[1] - stage.top + 14) + "px";
  }

  const exported = { inspector: inspector, describe: describe, hover: hover, hide: hide, refresh: refresh };
  W.ManifoldWeb = W.ManifoldWeb || /** @type {ManifoldWebModules} */ ({});
  W.ManifoldWeb.inspector = exported;
  return exported;
})(globalThis);
