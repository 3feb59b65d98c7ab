// The bodies and scenes of the current space as the controls and
// window.manifold change them: a new world for a space (its default scene,
// cut or filled, or a given scene), a body added from a scene body or at a
// free point of the view, every body cleared, the default scene again, a
// scene loaded (all or nothing; one of another space switches to it), saved
// and downloaded, or read from a file; the preset scenes, loaded by name.
/* exported ManifoldWebScenes */
var ManifoldWebScenes = (function (W) {
  "use strict";
  const MW = W.ManifoldWeb;
  const P = MW.page, state = P.state;

  function bodiesChangedCount() {
    MW.hash.updateHash();
  }

  function showSettings() {
    state.ui.setSimulation(MW.simulationSettings.simulationSettings());
  }

  // After the default scene was filled up to n bodies (null: not filled): a
  // notice when fewer fit (World.fill gives up when it finds no more room).
  /** @param {ManifoldWeb.World} w @param {number | null} n */
  function reportFill(w, n) {
    if (n !== null && w.count() < n) {
      state.ui.showNotice("Placed " + w.count() + " of " + n + " bodies: no room for more of this size.");
    }
  }

  // A new world for the current space holding `scene` (parsed), or the default
  // scene cut or filled to `bodies` bodies (null: as it is; the hash's
  // bodies=N, so more than a world holds is the default scene and a notice).
  // A space script without an engine (an old web/gen) gets no world and a notice.
  /** @param {ManifoldWeb.ParsedScene | null} scene @param {number | null} [bodies] */
  function newWorld(scene, bodies) {
    MW.input.releaseGrab();
    setPreset(null);
    state.world = null;
    state.clock.reset();
    if (!state.space.engine) {
      state.ui.showNotice("gen/" + P.entryOf(state.spaceName).script + " has no engine: rebuild web/gen with `manifold build` to get bodies.");
      return;
    }
    const w = new MW.world.World(state.spaceName, state.space);
    if (scene) {
      w.load(scene);
    } else {
      const n = MW.hash.bodiesFor(bodies === undefined ? null : bodies, state.space.engine);
      w.loadDefault(n === null ? undefined : n);
      reportFill(w, n);
    }
    state.world = w;
    showSettings();
  }

  // Adds a body from a scene body (JSON value); returns its index or throws.
  /** @param {Manifold.SceneBody} spec */
  function addBody(spec) {
    const i = P.requireWorld().add(spec);
    bodiesChangedCount();
    return i;
  }

  // The new body (tools.js's template: shape, size, density, static) at a
  // free visible surface point: the view's centre if free, else random
  // pixels of the view's middle; else a seeded random point of the space.
  function addAtView() {
    const w = P.requireWorld();
    const body = MW.tools.newBody(), size = body.size, placed = MW.tools.newSceneBody();
    const W0 = state.width, H0 = state.height;
    for (let k = 0; k < 60; k++) {
      const x = k === 0 ? W0 / 2 : W0 * (0.2 + 0.6 * Math.random());
      const y = k === 0 ? H0 / 2 : H0 * (0.2 + 0.6 * Math.random());
      const q = MW.input.surfacePoint(x, y);
      if (!q || w.pick(q)) continue;
      const boundary = state.space.boundary;
      if (boundary && boundary(q[0], q[1], q[2]) < size) continue;
      const i = w.addFree(Object.assign({}, placed, { p: q, angle: 2 * Math.PI * Math.random() }));
      if (i < 0) continue;
      bodiesChangedCount();
      return i;
    }
    const before = w.count();
    w.fill(before + 1, [body]);
    bodiesChangedCount();
    if (w.count() === before) throw new Error("no free place for another body was found");
    return before;
  }

  // The space's default scene again, cut or filled to n bodies (default: as
  // it is; at most the engine's maxBodies), with a notice when fewer fit.
  /** @param {number | null} [n] */
  function resetScene(n) {
    const w = P.requireWorld();
    if (n !== undefined && n !== null && !(Number.isInteger(n) && n >= 0 && n <= w.maxBodies())) {
      throw new RangeError("resetScene(n) expects a whole number of bodies from 0 to " + w.maxBodies());
    }
    MW.input.releaseGrab();
    setPreset(null);
    if (state.compare) {
      // the comparison's own scene on both
      const def = state.compare.def, names = state.index.map(function (e) { return e.name; });
      if (state.compare.held) state.compare.held.world.release();
      w.load(MW.world.parseScene(def.scenes.embedded, names));
      state.compare.flat.load(MW.world.parseScene(def.scenes.flat, names));
      state.clock.reset();
      showSettings();
      return w.count();
    }
    w.loadDefault(n === null ? undefined : n);
    reportFill(w, n === undefined ? null : n);
    state.clock.reset();
    showSettings();
    bodiesChangedCount();
    return w.count();
  }

  function clearBodies() {
    P.requireWorld().clear();
    setPreset(null);
    if (state.compare) state.compare.flat.clear();
    bodiesChangedCount();
  }

  // Loads a scene (JSON text or value); a scene of another space switches to it.
  // Resolves with the number of bodies; rejects (and shows why on the page) on bad input.
  /** @param {string | Manifold.Scene} json @returns {Promise<number>} */
  function loadScene(json) {
    setPreset(null);
    if (state.compare) {
      // a scene is one space's: show that space alone
      const parsed = (function () { try { return MW.world.parseScene(json, state.index.map(function (e) { return e.name; })); } catch (err) { return null; } })();
      if (parsed) return MW.space.setSpace(parsed.space, { scene: parsed }).then(function () { return state.world ? state.world.count() : 0; });
    }
    let scene;
    try {
      scene = MW.world.parseScene(json, state.index.map(function (e) { return e.name; }));
    } catch (err) {
      const e = new Error("The scene could not be loaded: " + err.message);
      state.ui.showNotice(e.message);
      return Promise.reject(e);
    }
    const done = function () {
      if (scene.camera) showCamera(scene.camera);
      showSettings();
      MW.hash.updateHash();
      return state.world ? state.world.count() : 0;
    };
    if (scene.space !== state.spaceName) {
      return MW.space.setSpace(scene.space, { scene: scene }).then(function () {
        if (!state.world || state.world.count() !== scene.bodies.length) {
          throw new Error("The scene could not be loaded into " + scene.space + (state.ui ? "; see the notice on the page" : ""));
        }
        return done();
      });
    }
    try {
      P.requireWorld();
      // all or nothing: the world is only replaced when every body fits
      const w = new MW.world.World(state.spaceName, state.space);
      w.load(scene);
      MW.input.releaseGrab();
      state.world = w;
      state.clock.reset();
    } catch (err) {
      const e = new Error("The scene could not be loaded: " + err.message);
      state.ui.showNotice(e.message);
      return Promise.reject(e);
    }
    state.ui.hideNotice();
    return Promise.resolve(done());
  }

  // ---- presets: the scene files of scenes/, generated into web/gen/presets.js ----
  /** @param {string | null} name */
  function setPreset(name) {
    state.preset = name;
    if (state.ui) state.ui.setPreset(name);
  }

  function presetList() { return W.Manifold.presets || []; }

  /** @param {string} name */
  function presetNamed(name) {
    return presetList().find(function (p) { return p.name === name; }) || null;
  }

  // Loads the preset `name` (switching to its space); a Promise of the body count.
  /** @param {string} name @returns {Promise<number>} */
  function loadPreset(name) {
    const p = presetNamed(name);
    if (!p) {
      const e = new Error("There is no preset " + JSON.stringify(name) + "; the presets are " +
        (presetList().map(function (q) { return q.name; }).join(", ") || "none (rebuild web/gen with `manifold build`)") + ".");
      state.ui.showNotice(e.message);
      state.ui.setPreset(state.preset);
      return Promise.reject(e);
    }
    return loadScene(p.scene).then(function (n) {
      setPreset(name);
      MW.hash.updateHash();
      return n;
    });
  }

  function presets() {
    return presetList().map(function (p) { return { name: p.name, space: p.space, title: p.title }; });
  }

  function currentScene() {
    return P.requireWorld().scene();
  }

  // A scene's camera shown: its up and fov, where it leaves them out, the
  // space's camera's.
  /** @param {ManifoldWeb.SceneCamera} c */
  function showCamera(c) {
    const own = state.space.camera;
    state.camera.set({ eye: c.eye, target: c.target, up: c.up || own.up, fov: c.fov || own.fov });
  }

  // The current scene as a download (manifold-SPACE.json), with the view
  // it is shown in.
  function saveSceneFile() {
    const text = JSON.stringify(Object.assign(currentScene(), { camera: state.camera.get() }), null, 2) + "\n";
    const blob = new Blob([text], { type: "application/json" });
    const a = document.createElement("a");
    a.href = URL.createObjectURL(blob);
    a.download = "manifold-" + state.spaceName + ".json";
    document.body.appendChild(a);
    a.click();
    a.remove();
    setTimeout(function () { URL.revokeObjectURL(a.href); }, 1000);
  }

  /** @param {File} file */
  function loadSceneFile(file) {
    const reader = new FileReader();
    reader.onload = function () { loadScene(String(reader.result)).catch(function () {}); };
    reader.onerror = function () { state.ui.showNotice("The file " + file.name + " could not be read."); };
    reader.readAsText(file);
  }

  const exported = {
    newWorld: newWorld,
    addBody: addBody,
    addAtView: addAtView,
    resetScene: resetScene,
    clearBodies: clearBodies,
    loadScene: loadScene,
    loadPreset: loadPreset,
    presetNamed: presetNamed,
    presets: presets,
    currentScene: currentScene,
    saveSceneFile: saveSceneFile,
    loadSceneFile: loadSceneFile,
  };
  W.ManifoldWeb = W.ManifoldWeb || /** @type {ManifoldWebModules} */ ({});
  W.ManifoldWeb.scenes = exported;
  return exported;
})(globalThis);
