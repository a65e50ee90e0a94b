// Bundles the page (issue 14) into one directory the server serves:
//   OUT/index.html, OUT/assets/main.js (the page: WebSocket, panels, input, camera),
//   OUT/assets/render.js (the scene's drawing, run as a Worker on an OffscreenCanvas or,
//   as a fallback, as a script on the page; render/entry.js), OUT/assets/style.css.
// Both bundles include the parts of three.js they use.
// Usage: node build.mjs OUT_DIR. No network, no CDN: everything comes from node_modules.
import { build } from 'esbuild';
import { copyFileSync, mkdirSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const here = dirname(fileURLToPath(import.meta.url));
const out = process.argv[2];
if (!out) {
  console.error('build.mjs: error: usage: node build.mjs OUT_DIR');
  process.exit(2);
}
mkdirSync(join(out, 'assets'), { recursive: true });
const common = {
  bundle: true,
  format: 'iife',
  minify: true,
  sourcemap: false,
  target: ['chrome110', 'firefox110', 'safari16'],
  logLevel: 'warning',
};
await build({ ...common, entryPoints: [join(here, 'src/main.js')], outfile: join(out, 'assets/main.js') });
await build({ ...common, entryPoints: [join(here, 'src/render/entry.js')], outfile: join(out, 'assets/render.js') });
copyFileSync(join(here, 'index.html'), join(out, 'index.html'));
copyFileSync(join(here, 'src/style.css'), join(out, 'assets/style.css'));
