// The page's start: the controls made and wired to the parts of the page
// (web/js/page.js lists them), window.manifold put in place, the WebGL2
// renderers made, the canvas's size, input and context watched, the first
// space (from the URL hash) switched to, and the frame loop started. A page
// without the generated scripts or without WebGL2 shows why instead.
(function (W) {
  "use strict";
  const MW = W.ManifoldWeb;
  const P = MW.page, state = P.state;
  const PageError = MW.gl.PageError;
  const Manifold = W.Manifold;

  function start() {
    const hash = MW.hash, scenes = MW.scenes, guarded = P.guarded;
    state.ui = MW.ui.createUI(Object.assign({
      onSpace: function (/** @type {string} */ name) { MW.space.setSpace(name).catch(function () {}); },
      onCurvature: function (/** @type {boolean} */ on) { hash.setOptions({ curvature: on }); },
      onGrid: function (/** @type {boolean} */ on) { hash.setOptions({ grid: on }); },
      onDimSleeping: function (/** @type {boolean} */ on) { hash.setOptions({ dimSleeping: on }); },
      onAntialias: function (/** @type {Manifold.Antialias} */ mode) { hash.setOptions({ antialias: mode }); },
      onModel: function (/** @type {Manifold.Model} */ model) { hash.setOptions({ model: model }); },
      onResetView: function () {
        if (state.space) state.camera.set(state.space.camera);
        state.disc.reset();
      },
      onAdd: guarded(function () { scenes.addAtView(); }),
      onNewBody: guarded(MW.tools.setNewBody),
      onTool: guarded(MW.tools.setTool),
      onGeodesicLength: guarded(MW.tools.setGeodesicLength),
      onTrails: guarded(MW.tools.setTrails),
      onPlot: guarded(MW.plot.setPlot),
      onClear: guarded(scenes.clearBodies),
      onPreset: function (/** @type {string} */ name) { scenes.loadPreset(name).catch(function () {}); },
      onReset: guarded(function () { scenes.resetScene(); }),
      onSave: guarded(scenes.saveSceneFile),
      onLoad: guarded(scenes.loadSceneFile),
      onSaveImage: guarded(MW.capture.saveImage),
      onRecord: guarded(MW.capture.toggleRecording),
    }, MW.simulationSettings.controlHandlers()), MW.simulationSettings.engineSettings());
    state.ui.setTool(MW.tools.tools.tool);
    state.ui.setGeodesicLength(MW.tools.tools.geodesicLength);
    state.ui.setTrails(MW.tools.tools.trailsOn);
    const noRecording = MW.capture.recordingUnavailable();
    if (noRecording) state.ui.setRecordingUnavailable(noRecording);
    W.manifold = MW.api.scriptingApi();
    const canvas = state.ui.canvas;

    const index = Manifold.spaceIndex;
    if (!Array.isArray(index) || index.length === 0) {
      state.current = Promise.reject(P.fail("The generated scripts are missing",
        new PageError("load", "web/gen/spaces.js was not found or lists no space. Build it with `manifold build` " +
          "(from the repository root) and reload.")));
      state.current.catch(function () {});
      return;
    }
    state.index = index.slice();
    state.ui.setSpaces(/** @type {{ name: string, label?: string, description: string }[]} */ (state.index).concat([{ name: P.COMPARE, label: "Torus: embedded vs flat", description: "the embedded and the flat torus side by side" }]));

    const params = MW.ui.parseHash(W.location.hash);
    state.debugBrokenShader = params.debugBrokenShader === "1";
    hash.setOptions(hash.optionsFromHash(params));
    const first = hash.spaceFromHash(params);
    const firstBodies = hash.bodiesFromHash(params);

    try {
      state.gl = MW.gl.createContext(canvas);
      state.tracer = new MW.tracer.Tracer(state.gl);
      state.bodyRenderer = new MW.bodies.BodyRenderer(state.gl);
      state.curveRenderer = new MW.curves.CurveRenderer(state.gl);
    } catch (err) {
      state.tracer = null;
      state.current = Promise.reject(P.fail(err.kind === "shader" ? "The surface cannot be drawn" : "WebGL2 is not available", err));
      state.current.catch(function () {});
      return;
    }
    MW.space.watchContext(canvas);
    MW.frame.watchSize(canvas);
    MW.input.watchInput(canvas);
    W.addEventListener("hashchange", hash.onHashChange);
    state.ui.setPresets(scenes.presets(), state.index.map(function (e) { return e.name; }));
    const preset = params.scene !== undefined && !state.debugBrokenShader ? scenes.presetNamed(params.scene) : null;
    if (params.scene !== undefined && !preset) scenes.loadPreset(params.scene).catch(function () {}); // the notice: no such preset
    if (preset) scenes.loadPreset(preset.name).catch(function () {});
    else MW.space.setSpace(first, { bodies: firstBodies }).catch(function () {});
    MW.frame.startLoop();
  }

  if (document.readyState === "loading") document.addEventListener("DOMContentLoaded", start);
  else start();
})(globalThis);
