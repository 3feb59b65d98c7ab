// Pictures and videos of the view: "Save image" downloads a PNG of the canvas
// as shown (bodies and all), read right after a frame's draw (frame.js's
// afterDraw: the WebGL context keeps no drawing buffer, so that the frames
// cost no copy); "Record" records the canvas (captureStream, MediaRecorder)
// and "Stop" downloads the WebM file. The files are named
// manifold-SPACE-YYYYMMDD-HHMMSS (local time; a recording by its start). The
// canvas is the same element in every space, so a recording goes on through
// space switches (in the comparison view it holds the top-left pane).
/* exported ManifoldWebCapture */
var ManifoldWebCapture = (function (W) {
  "use strict";
  const MW = W.ManifoldWeb;
  const P = MW.page, state = P.state;

  const FPS = 30; // at most; the stream takes a frame only when the canvas was drawn
  const TIMESLICE_MS = 1000; // the recorder hands over its data every second
  const WEBM = ["video/webm;codecs=vp9", "video/webm;codecs=vp8", "video/webm"];

  /** @param {number} n */
  function two(n) { return String(n).padStart(2, "0"); }

  // manifold-SPACE-YYYYMMDD-HHMMSS.ext
  /** @param {string} ext @param {Date} when */
  function fileName(ext, when) {
    return "manifold-" + (P.currentName() || "page") + "-" + when.getFullYear() + two(when.getMonth() + 1) +
      two(when.getDate()) + "-" + two(when.getHours()) + two(when.getMinutes()) + two(when.getSeconds()) + "." + ext;
  }

  // A download of the blob (an <a download> with an object URL, revoked once the download has it).
  /** @param {Blob} blob @param {string} name */
  function download(blob, name) {
    const a = document.createElement("a");
    a.href = URL.createObjectURL(blob);
    a.download = name;
    document.body.appendChild(a);
    a.click();
    a.remove();
    setTimeout(function () { URL.revokeObjectURL(a.href); }, 10000);
  }

  /** @param {string} what */
  function requireView(what) {
    if (!state.tracer || state.contextLost || state.error || !state.spaceName) {
      throw new Error("There is no view to " + what + (state.error ? ": " + state.error.message : "."));
    }
  }

  // ---- Save image ---------------------------------------------------------------------
  function saveImage() {
    requireView("save");
    const name = fileName("png", new Date());
    MW.frame.afterDraw(function (canvas) {
      if (!canvas) { state.ui.showNotice("The view could not be saved: it could not be drawn."); return; }
      canvas.toBlob(function (blob) {
        if (blob) download(blob, name);
        else state.ui.showNotice("The browser could not make a PNG of the view.");
      }, "image/png");
    });
  }

  // ---- Record / Stop --------------------------------------------------------------------
  // the first WebM type this browser's MediaRecorder writes, or null
  function webmType() {
    return WEBM.find(function (t) { return W.MediaRecorder.isTypeSupported(t); }) || null;
  }

  // Why this browser cannot record the canvas, or null when it can.
  function recordingUnavailable() {
    if (typeof W.MediaRecorder !== "function") return "this browser has no MediaRecorder";
    if (typeof W.HTMLCanvasElement.prototype.captureStream !== "function") return "this browser cannot capture a canvas (captureStream)";
    if (!webmType()) return "this browser's MediaRecorder cannot write WebM";
    return null;
  }

  /**
   * A recording under way: the recorder, its stream, the data so far, the file's name.
   * @typedef {{ recorder: MediaRecorder, stream: MediaStream, chunks: Blob[], name: string, failed: string | null }} Recording
   */
  /** @type {Recording | null} */
  let recording = null;

  function startRecording() {
    const why = recordingUnavailable();
    if (why) throw new Error("The view cannot be recorded: " + why + ".");
    requireView("record");
    const stream = state.ui.canvas.captureStream(FPS);
    const recorder = new W.MediaRecorder(stream, { mimeType: webmType() });
    /** @type {Recording} */
    const r = { recorder: recorder, stream: stream, chunks: [], name: fileName("webm", new Date()), failed: null };
    recorder.addEventListener("dataavailable", function (e) { if (e.data && e.data.size > 0) r.chunks.push(e.data); });
    recorder.addEventListener("error", function (e) {
      const err = /** @type {{ error?: Error }} */ (/** @type {unknown} */ (e)).error;
      r.failed = err && err.message || "the recorder failed";
    });
    // after Stop, or when the recorder gives up: the file, or why there is none
    recorder.addEventListener("stop", function () {
      stream.getTracks().forEach(function (t) { t.stop(); });
      if (recording === r) { recording = null; state.ui.setRecording(false); }
      if (r.failed) state.ui.showNotice("The recording failed: " + r.failed + ".");
      else if (!r.chunks.length) state.ui.showNotice("The recording holds no frames.");
      else download(new Blob(r.chunks, { type: "video/webm" }), r.name);
    });
    recorder.start(TIMESLICE_MS);
    recording = r;
    state.ui.setRecording(true);
    // a frame drawn now is the stream's first, even when the view stands still
    MW.frame.afterDraw(function () {});
  }

  function stopRecording() {
    const r = recording;
    if (!r) return;
    recording = null;
    state.ui.setRecording(false);
    if (r.recorder.state !== "inactive") r.recorder.stop();
  }

  // Record / Stop pressed
  function toggleRecording() {
    if (recording) stopRecording();
    else startRecording();
  }

  const exported = {
    saveImage: saveImage,
    recordingUnavailable: recordingUnavailable,
    toggleRecording: toggleRecording,
    stopRecording: stopRecording,
  };
  W.ManifoldWeb = W.ManifoldWeb || /** @type {ManifoldWebModules} */ ({});
  W.ManifoldWeb.capture = exported;
  return exported;
})(globalThis);
