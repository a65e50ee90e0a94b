// The entry point of the drawing bundle (assets/render.js). Loaded as a dedicated
// Worker (the normal case), it waits for `init` {canvas: OffscreenCanvas, width, height,
// ...}, answers `ready` (or `failed` {error} when no WebGL context can be made there),
// then hands every message to the Renderer and posts back what it reports. Loaded as a
// classic script on the page (render/link.js's fallback), it only exposes the Renderer
// as window.rtampRenderer for the main thread to drive directly.
import { Renderer } from './renderer.js';

if (typeof window !== 'undefined' && typeof document !== 'undefined') {
  window.rtampRenderer = Renderer;
} else {
  let renderer = null;
  const raf = typeof self.requestAnimationFrame === 'function' ? (f) => self.requestAnimationFrame(f) : (f) => setTimeout(f, 16);
  self.onmessage = (ev) => {
    const m = ev.data;
    if (m.type === 'init') {
      try {
        renderer = new Renderer(m.canvas, (out) => self.postMessage(out), raf);
        renderer.handle({ type: 'size', width: m.width, height: m.height });
        self.postMessage({ type: 'ready' });
      } catch (e) {
        self.postMessage({ type: 'failed', error: String(e?.message || e) });
      }
      return;
    }
    renderer?.handle(m);
  };
}
