// Issue 14's bars for the page, measured (docs/benchmarks.md "The page"):
//   node tests/measure.mjs RTAMP_BIN SCENARIO [DRAGS]
// 1. frame rate: requestAnimationFrame callbacks of the page counted over 6 s while the
//    episode runs at real-time speed (headless Chromium, --disable-gpu: software WebGL);
// 2. drag → intervention: for each of DRAGS real mouse drags of a block onto the other
//    region, the page's time from the drop (pointerup) to the `intervention` record for
//    it arriving back over the WebSocket (window.rtamp.latencies), at speed 1.
// Prints one JSON object. Not a test: it asserts nothing about the figures.
import { drag, launch, openPage, startServer, waitFor } from './harness.mjs';

const [bin, scenarioArg, dragsArg] = process.argv.slice(2);
process.env.RTAMP_BIN = bin;
const drags = Number(dragsArg || 8);
const server = await startServer([scenarioArg, '--world', 'symbolic', '--speed', '1']);
const { context } = await launch();
try {
  const { page } = await openPage(context, server.url);
  const f0 = await page.evaluate(() => [window.rtamp.frames, performance.now()]);
  await page.waitForTimeout(6000);
  const f1 = await page.evaluate(() => [window.rtamp.frames, performance.now()]);
  const fps = ((f1[0] - f0[0]) * 1000) / (f1[1] - f0[1]);
  for (let k = 0; k < drags; k++) {
    const things = await page.evaluate(() => window.rtamp.things());
    const regions = await page.evaluate(() => window.rtamp.regions());
    const names = regions.map((r) => r.name);
    const free = things.filter((t) => t.kind === 'object' && names.includes(t.at));
    if (!free.length) break;
    const th = free[k % free.length];
    const target = regions.find((r) => r.name !== th.at);
    const from = await page.evaluate((n) => window.rtamp.project(n), th.name);
    const to = await page.evaluate((g) => window.rtamp.projectPoint([g.center[0] + 0.12, g.center[1] - 0.12, 0]), target);
    const before = await page.evaluate(() => window.rtamp.latencies.length);
    await drag(page, from, to);
    await waitFor(() => page.evaluate((n) => window.rtamp.latencies.length > n, before), 'the intervention record', 30000);
    await page.waitForTimeout(1500);
  }
  const lat = await page.evaluate(() => window.rtamp.latencies);
  const ms = lat.map((l) => l.ms).sort((a, b) => a - b);
  console.log(JSON.stringify({ fps: Number(fps.toFixed(1)), seconds: Number(((f1[1] - f0[1]) / 1000).toFixed(2)), drags: lat, median_ms: ms[Math.floor(ms.length / 2)], max_ms: ms.at(-1) }, null, 1));
} finally {
  await context.close();
  server.proc.kill('SIGTERM');
}
