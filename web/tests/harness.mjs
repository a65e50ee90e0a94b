// The browser tests' harness: starts the real `rtamp serve ... --port 0` (the URL is the
// first line of its stdout), launches Debian's Chromium headless through playwright-core
// with a fresh profile, opens the page and waits for its first hello and frame, records
// every WebSocket frame the page receives (an oracle independent of the page's own
// code). Exit code 77 (ctest SKIP_RETURN_CODE) only when node's Chromium is absent.
import { spawn } from 'node:child_process';
import { existsSync, mkdtempSync, mkdirSync, rmSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { createInterface } from 'node:readline';

export const CHROMIUM = process.env.RTAMP_CHROMIUM || '/usr/bin/chromium';
export const BIN = process.env.RTAMP_BIN;
export const SOURCE = process.env.RTAMP_SOURCE_DIR;
export const SKIP = 77;

export function skipUnlessReady() {
  if (!existsSync(CHROMIUM)) {
    console.log(`skipped: Chromium not found at ${CHROMIUM} (install Debian's chromium: scripts/install-deps)`);
    process.exit(SKIP);
  }
  if (!BIN || !existsSync(BIN)) {
    console.error(`browser test: error: RTAMP_BIN '${BIN}' is not the built rtamp binary`);
    process.exit(1);
  }
}

export function scratchDir(name) {
  const base = process.env.RTAMP_TEST_TMP || tmpdir();
  mkdirSync(base, { recursive: true });
  return mkdtempSync(join(base, `${name}-`));
}

const servers = new Set(); // started and not exited
let killOnExit = false;

// Starts `rtamp serve ARGS --port 0`; resolves {url, proc, stderr()} after its first stdout line.
export function startServer(args) {
  const proc = spawn(process.env.RTAMP_BIN, ['serve', ...args, '--port', '0'], { stdio: ['ignore', 'pipe', 'pipe'] });
  let err = '';
  proc.stderr.on('data', (d) => (err += d));
  // The server never outlives the test (a failed assertion, a ctest timeout's SIGTERM).
  servers.add(proc);
  proc.once('exit', () => servers.delete(proc));
  if (!killOnExit) {
    killOnExit = true;
    process.on('exit', () => servers.forEach((p) => p.kill('SIGTERM')));
    for (const sig of ['SIGTERM', 'SIGINT']) process.once(sig, () => process.exit(1));
  }
  const lines = createInterface({ input: proc.stdout });
  return new Promise((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error(`rtamp serve printed no URL in 60 s; stderr:\n${err}`)), 60000);
    proc.on('exit', (code) => reject(new Error(`rtamp serve exited (${code}) before printing its URL; stderr:\n${err}`)));
    lines.once('line', (line) => {
      clearTimeout(timer);
      const m = /(https?:\/\/\S+)/.exec(line);
      if (!m) reject(new Error(`the first stdout line of rtamp serve has no URL: '${line}'`));
      else resolve({ url: m[1], proc, stderr: () => err });
    });
  });
}

// Chromium's flags for GPU compositing on SwiftShader (measure.mjs --gpu; not the tests').
export const GPU_SWIFTSHADER_ARGS = ['--use-angle=swiftshader', '--enable-unsafe-swiftshader', '--ignore-gpu-blocklist'];

// The browser tests' Chromium: --disable-gpu (software WebGL, software compositing);
// gpu: true drops it for GPU_SWIFTSHADER_ARGS.
export async function launch({ gpu = false } = {}) {
  const { chromium } = await import('playwright-core');
  const profile = scratchDir('chromium-profile');
  const context = await chromium.launchPersistentContext(profile, {
    executablePath: CHROMIUM,
    headless: true,
    viewport: { width: 1280, height: 800 },
    args: [
      '--headless',
      '--no-sandbox',
      ...(gpu ? GPU_SWIFTSHADER_ARGS : ['--disable-gpu']),
      '--disable-quic',
      '--no-first-run',
      '--disable-background-networking',
      '--disable-component-update',
      '--disable-sync',
      // --user-data-dir: the fresh `profile` above (Playwright passes it itself).
    ],
  });
  return { context, profile };
}

// Opens the page of a started server; returns {page, ws, errors} where ws.received is
// every message the page got (parsed), ws.sent every message it sent. `another`: in a
// new tab beside the context's first page (a second viewer), not in that page.
export async function openPage(context, url, another = false) {
  const page = (!another && context.pages()[0]) || (await context.newPage());
  const errors = [];
  page.on('pageerror', (e) => errors.push(String(e)));
  page.on('console', (m) => m.type() === 'error' && errors.push(m.text()));
  const ws = { received: [], sent: [] };
  page.on('websocket', (s) => {
    s.on('framereceived', (f) => {
      try {
        ws.received.push(JSON.parse(f.payload));
      } catch {}
    });
    s.on('framesent', (f) => {
      try {
        ws.sent.push(JSON.parse(f.payload));
      } catch {}
    });
  });
  await page.goto(url);
  await page.waitForFunction(() => window.rtamp && window.rtamp.ready && window.rtamp.framesReceived > 0, null, { timeout: 60000 });
  return { page, ws, errors };
}

// The log records the page has received, from the raw WebSocket frames.
export function logRecords(ws) {
  const out = [];
  for (const m of ws.received) {
    if (m.type === 'hello') {
      out.length = 0;
      out.push(...(m.history || []));
    } else if (m.type === 'log') out.push(...m.records);
  }
  return out;
}

export async function waitFor(pred, what, timeoutMs = 90000) {
  const end = Date.now() + timeoutMs;
  for (;;) {
    const v = await pred();
    if (v) return v;
    if (Date.now() > end) throw new Error(`timed out waiting for ${what}`);
    await new Promise((r) => setTimeout(r, 50));
  }
}

// A real mouse drag from one page pixel to another, in small steps.
export async function drag(page, from, to, steps = 12) {
  await page.mouse.move(from.x, from.y);
  await page.mouse.down();
  for (let i = 1; i <= steps; i++) await page.mouse.move(from.x + ((to.x - from.x) * i) / steps, from.y + ((to.y - from.y) * i) / steps);
  await page.mouse.up();
}

export function cleanup(list) {
  for (const f of list) {
    try {
      f();
    } catch {}
  }
}

export { rmSync };
