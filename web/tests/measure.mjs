// Issue 14's bars for the page, measured (docs/benchmarks.md "The page"):
//   node tests/measure.mjs RTAMP_BIN SCENARIO [DRAGS]
// 1. frame rate: requestAnimationFrame callbacks of the page counted over 6 s while the
//    episode runs at real-time speed (headless Chromium, --disable-gpu: software WebGL);
// 2. drag → intervention: for each of DRAGS real mouse drags of a block onto a region,
//    the page's time from the drop (pointerup) to the server's reply and to the
//    `intervention` record for it arriving back (window.rtamp.latencies), at speed 1;
// 3. the same path without the page: a WebSocket client's relocations (reply, record).
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
    // Keep the robot busy: move a block back to the first region (r1) when one is
    // elsewhere, else one of r1's blocks to another region.
    const free = things.filter((t) => t.kind === 'object' && names.includes(t.at));
    if (!free.length) break;
    const away = free.filter((t) => t.at !== names[0]);
    const th = away.length ? away[k % away.length] : free[k % free.length];
    const target = away.length ? regions[0] : regions.find((r) => r.name !== th.at);
    const from = await page.evaluate((n) => window.rtamp.project(n), th.name);
    const to = await page.evaluate((g) => window.rtamp.projectPoint([g.center[0] + 0.12, g.center[1] - 0.12, 0]), target);
    const before = await page.evaluate(() => [window.rtamp.latencies.length, window.rtamp.notices.length]);
    await drag(page, from, to);
    await waitFor(() => page.evaluate(([n, m]) => window.rtamp.latencies.length > n || window.rtamp.notices.slice(m).some((x) => x.kind === 'error'), before), 'the intervention record', 30000);
    const refused = await page.evaluate((m) => window.rtamp.notices.slice(m).filter((x) => x.kind === 'error'), before[1]);
    if (refused.length) console.error(`drag of ${th.name} refused: ${refused[0].text}`);
    await page.waitForTimeout(1500);
  }
  const lat = await page.evaluate(() => window.rtamp.latencies);
  const med = (xs) => xs.sort((a, b) => a - b)[Math.floor(xs.length / 2)];
  console.log(JSON.stringify({
    fps: Number(fps.toFixed(1)),
    seconds: Number(((f1[1] - f0[1]) / 1000).toFixed(2)),
    drags: lat.map((l) => ({ ...l, ms: Math.round(l.ms * 10) / 10, replyMs: Math.round(l.replyMs * 10) / 10 })),
    median_applied_ms: med(lat.map((l) => l.ms)),
    max_applied_ms: Math.max(...lat.map((l) => l.ms)),
    median_reply_ms: med(lat.map((l) => l.replyMs)),
  }, null, 1));
} finally {
  await context.close();
  server.proc.kill('SIGTERM');
}

// 3. The same relocations without the page (no rendering on the path): a WebSocket
//    client sends `intervene relocate` and times the reply and the intervention record.
{
  const { default: WebSocket } = await import('ws');
  const server2 = await startServer([scenarioArg, '--world', 'symbolic', '--speed', '1', '--no-operator']);
  const ws = new WebSocket(server2.url.replace(/^http/, 'ws') + 'ws');
  const out = [];
  let hello = null, pending = null, id = 0;
  const t0 = performance.now();
  ws.on('message', (d) => {
    const m = JSON.parse(d);
    if (m.type === 'hello') hello = m;
    if (!pending) return;
    if (m.type === 'reply' && m.id === pending.id) pending.reply = performance.now() - pending.at;
    if (m.type === 'log' && m.record.ev === 'intervention' && m.record.subject === pending.subject) {
      out.push({ subject: pending.subject, replyMs: pending.reply, appliedMs: performance.now() - pending.at, t: m.record.t, applied: m.record.applied });
      pending = null;
    }
  });
  await waitFor(() => hello, 'hello');
  const regions = hello.scene.regions.map((r) => r.name);
  for (let k = 0; k < drags && performance.now() - t0 < 120000; k++) {
    await new Promise((r) => setTimeout(r, 1500));
    const subject = ['o1', 'o2', 'o3'][k % 3];
    pending = { id: ++id, subject, at: performance.now() };
    ws.send(JSON.stringify({ type: 'intervene', id, kind: 'relocate', subject, location: regions[0] }));
    await waitFor(() => !pending || (pending.reply !== undefined && performance.now() - pending.at > 10000), 'the record', 30000).catch(() => {});
    pending = null;
  }
  ws.close();
  server2.proc.kill('SIGTERM');
  const med = (xs) => xs.sort((a, b) => a - b)[Math.floor(xs.length / 2)];
  console.log(JSON.stringify({ websocket_client: out.map((o) => ({ ...o, replyMs: Math.round(o.replyMs * 10) / 10, appliedMs: Math.round(o.appliedMs * 10) / 10 })), median_reply_ms: med(out.map((o) => o.replyMs)), median_applied_ms: med(out.map((o) => o.appliedMs)) }));
}
