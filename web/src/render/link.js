// The main thread's line to the drawing (renderer.js): the scene canvas's control is
// transferred to an OffscreenCanvas and drawn by a dedicated Worker running the drawing
// bundle (assets/render.js, render/entry.js), so that WebGL rasterisation and — with
// software compositing — the canvas readback never block the page's main thread (its
// WebSocket, panels and pointer input). Where that is unavailable (no
// transferControlToOffscreen, no Worker, or the worker cannot make a WebGL context) the
// same bundle is loaded as a script and the Renderer draws on the main thread instead, on
// a fresh canvas; `?render=main` in the page's URL forces that (for tests and
// measurements). Messages sent before the drawing side is up are kept and replayed to it
// in order, so nothing is lost whichever side draws.
// Invariants: every message reaches exactly one Renderer, in the order sent; `mode` is
// 'starting', then 'worker' or 'main'.

export class RenderLink {
  // canvas: the scene's canvas element; url: the drawing bundle; onStats(msg): the
  // renderer's reports; freshCanvas(): a new canvas in place of the transferred one.
  constructor(canvas, url, { onStats, freshCanvas, size }) {
    this.url = url;
    this.onStats = onStats;
    this.freshCanvas = freshCanvas;
    this.size = size; // () => {width, height}
    this.queue = [];
    this.mode = 'starting';
    this.why = null; // why the main thread draws, when it does
    const forced = new URLSearchParams(location.search).get('render') === 'main';
    if (forced || typeof Worker !== 'function' || typeof canvas.transferControlToOffscreen !== 'function') {
      this.fallBack(canvas, forced ? 'asked for by ?render=main' : 'no OffscreenCanvas or Worker');
      return;
    }
    let offscreen;
    try {
      this.worker = new Worker(url);
      offscreen = canvas.transferControlToOffscreen();
    } catch (e) {
      this.worker?.terminate();
      this.fallBack(canvas, `the drawing worker did not start: ${e.message || e}`);
      return;
    }
    this.worker.onmessage = (ev) => {
      const m = ev.data;
      if (m.type === 'ready') {
        this.mode = 'worker';
        for (const [msg, transfer] of this.queue) this.worker.postMessage(msg, transfer);
        this.queue = [];
      } else if (m.type === 'failed') this.workerFailed(m.error);
      else this.onStats(m);
    };
    // An error in the worker once it draws is the page's error (the browser tests fail on
    // console errors); before, it means the worker cannot draw here.
    this.worker.onerror = (ev) => {
      if (this.mode === 'starting') this.workerFailed(ev.message || 'the drawing worker failed to load');
      else console.error(`the drawing worker: ${ev.message} (${ev.filename}:${ev.lineno})`);
    };
    const { width, height } = size();
    this.worker.postMessage({ type: 'init', canvas: offscreen, width, height }, [offscreen]);
  }

  workerFailed(why) {
    if (this.mode !== 'starting') return;
    this.worker.terminate();
    this.worker = null;
    this.fallBack(this.freshCanvas(), `the drawing worker could not draw: ${why}`);
  }

  // Draws on the main thread: loads the drawing bundle as a script, then replays the queue.
  fallBack(canvas, why) {
    this.why = why;
    const start = () => {
      this.renderer = new window.rtampRenderer(canvas, (m) => this.onStats(m), (f) => requestAnimationFrame(f));
      const { width, height } = this.size();
      this.renderer.handle({ type: 'size', width, height });
      this.mode = 'main';
      for (const [msg] of this.queue) this.renderer.handle(msg);
      this.queue = [];
    };
    if (window.rtampRenderer) return start();
    const script = document.createElement('script');
    script.src = this.url;
    script.onload = start;
    document.head.appendChild(script);
  }

  post(msg, transfer = []) {
    if (this.mode === 'worker') this.worker.postMessage(msg, transfer);
    else if (this.mode === 'main') this.renderer.handle(msg);
    else this.queue.push([msg, transfer]);
  }
}
