// Issue 14's bars for the page, measured (docs/benchmarks.md "The page of `rtamp serve`"):
//   node tests/measure.mjs RTAMP_BIN SCENARIO [DRAGS] [--world mujoco|symbolic]
//        [--seconds S] [--speed X] [--gpu] [--web-root DIR[?QUERY]]...
// Each --web-root is a built page (e.g. an older one built from git, and this tree's
// build/share/rtamp/web), optionally with a query for the page's URL (`?render=main`:
// the page draws on its main thread, its fallback); every page gets the same run, one
// after the other, each with two runs of `rtamp serve SCENARIO --world W --speed X
// --no-operator --paused --port 0` (X: 1, real time, unless --speed), resumed by the
// page's pause button once the page is up (so the arm moves from t = 0; 3-block-tray
// with MuJoCo ends at about t = 19 s), one per part:
// 1. frame rate while the episode runs (headless Chromium with
//    --disable-gpu: software WebGL and software compositing; with --gpu: GPU compositing
//    on SwiftShader, harness.mjs GPU_SWIFTSHADER_ARGS): scene draws (window.rtamp.frames)
//    and `frame` messages received, per second over S seconds (default 10); for a page
//    that reports window.rtamp.drawTimes, the gaps between draws (median, p95, max) and
//    the fewest draws in any one-second stretch of those S seconds; the cost of
//    a drawn frame = the time from the animation-frame callback that drew to the next
//    animation-frame callback in the thread that draws (it includes the WebGL raster and
//    the canvas readback, which block that thread), median and p95: a page that reports
//    window.rtamp.drawCosts (the drawing worker's own timing) is taken at its word, an
//    older page is timed by a wrapper around the main thread's requestAnimationFrame
//    installed before the page loads; the same wrapper gives the main thread's
//    animation-frame interval (median, p95, max: how long the page's main thread was
//    busy between two chances to handle input and messages), for every page; the draw
//    gaps over 80 ms and how many of them overlap a main-thread long task (PerformanceObserver
//    'longtask') or a main-thread animation-frame gap over 80 ms;
// 2. drag → intervention: DRAGS real mouse drags of a block onto a region, the page's
//    times from the drop (pointerup) to the server's reply and to the `intervention`
//    record arriving back (window.rtamp.latencies), and the server's own receipt →
//    applied (the reply's server_ms; the summary `rtamp serve` prints on stderr at exit).
// Prints one JSON object per page. Not a test: it asserts nothing about the figures.
import { drag, launch, openPage, startServer, waitFor } from './harness.mjs';

const args = process.argv.slice(2);
const opt = (name, dflt) => {
  const out = [];
  for (let i = args.indexOf(name); i >= 0; i = args.indexOf(name)) out.push(args.splice(i, 2)[1]);
  return out.length ? out : dflt;
};
const gpu = args.includes('--gpu');
if (gpu) args.splice(args.indexOf('--gpu'), 1);
const world = opt('--world', ['mujoco'])[0];
const seconds = Number(opt('--seconds', ['10'])[0]);
const speed = opt('--speed', ['1'])[0];
const roots = opt('--web-root', [null]);
const [bin, scenarioArg, dragsArg] = args;
process.env.RTAMP_BIN = bin;
const drags = Number(dragsArg ?? 4);
const round = (x) => (x == null ? null : Math.round(x * 10) / 10);
const quantile = (xs, q) => {
  const s = [...xs].sort((a, b) => a - b);
  return s.length ? s[Math.min(s.length - 1, Math.floor(q * s.length))] : null;
};

// Starts a paused episode, opens the page and resumes it from the page; calls body(page).
async function session(rootArg, body) {
  const [root, query] = rootArg ? rootArg.split('?') : [null, null];
  const server = await startServer([scenarioArg, '--world', world, '--speed', speed, '--no-operator', '--paused', ...(root ? ['--web-root', root] : [])]);
  const { context } = await launch({ gpu });
  await context.addInitScript(() => {
    const raf = window.requestAnimationFrame.bind(window);
    window.__rafs = []; // [start ms, drew]
    // Main-thread tasks over 50 ms, [start epoch ms, duration ms] (where the browser reports them).
    window.__longtasks = [];
    try {
      new PerformanceObserver((l) => {
        for (const e of l.getEntries()) window.__longtasks.push([performance.timeOrigin + e.startTime, e.duration]);
      }).observe({ type: 'longtask', buffered: true });
    } catch {}
    window.requestAnimationFrame = (f) =>
      raf((ts) => {
        const at = performance.now(), n = window.rtamp ? window.rtamp.frames : 0;
        f(ts);
        window.__rafs.push([at, (window.rtamp ? window.rtamp.frames : 0) > n]);
      });
  });
  try {
    const { page } = await openPage(context, query ? `${server.url}?${query}` : server.url);
    await page.click('#pause');
    await waitFor(() => page.evaluate(() => window.rtamp.state && window.rtamp.state.paused === false), 'the resumed episode', 30000);
    await body(page);
  } finally {
    await context.close();
    const exited = new Promise((r) => server.proc.once('exit', r));
    server.proc.kill('SIGTERM');
    await exited;
  }
  return server.stderr();
}

async function measure(root) {
  const out = { web_root: root ?? '(default)', world, speed: Number(speed), scenario: scenarioArg, browser: gpu ? 'gpu compositing (SwiftShader)' : '--disable-gpu' };
  await session(root, async (page) => {
    await page.waitForTimeout(500); // the arm is moving
    const snap = () =>
      page.evaluate(() => [window.rtamp.frames, window.rtamp.framesReceived, performance.now(), window.__rafs.length, window.rtamp.drawCosts?.length ?? null, window.rtamp.drawTimes?.length ?? null]);
    const s0 = await snap();
    await page.waitForTimeout(seconds * 1000);
    const s1 = await snap();
    const rafs = await page.evaluate(([a, b]) => window.__rafs.slice(a, b + 1), [s0[3], s1[3]]);
    let costs = [];
    const gaps = [];
    for (let i = 0; i + 1 < rafs.length; i++) {
      gaps.push(rafs[i + 1][0] - rafs[i][0]);
      if (rafs[i][1]) costs.push(rafs[i + 1][0] - rafs[i][0]);
    }
    if (s0[4] != null) costs = await page.evaluate(([a, b]) => window.rtamp.drawCosts.slice(a, b), [s0[4], s1[4]]);
    const dt = (s1[2] - s0[2]) / 1000;
    // Gaps between draws and the fewest draws in any whole second of the window (a page
    // that reports window.rtamp.drawTimes: when each draw was made).
    let drawGaps = null, worstSecond = null, longGaps = null;
    if (s0[5] != null) {
      const times = await page.evaluate(([a, b]) => window.rtamp.drawTimes.slice(a, b), [s0[5], s1[5]]);
      const scales = await page.evaluate(([a, b]) => window.rtamp.drawScales?.slice(a, b) ?? [], [s0[5], s1[5]]);
      const g = times.slice(1).map((x, i) => x - times[i]);
      drawGaps = { n: g.length, median: round(quantile(g, 0.5)), p95: round(quantile(g, 0.95)), max: round(Math.max(...g)) };
      for (let i = 0, j = 0; i < times.length && times[i] + 1000 <= times[times.length - 1]; i++) {
        while (j < times.length && times[j] < times[i] + 1000) j++;
        worstSecond = Math.min(worstSecond ?? Infinity, j - i);
      }
      // The draw gaps over 80 ms, and what the main thread did meanwhile: a long task
      // overlapping the gap, or a main-thread animation-frame gap over 80 ms overlapping it.
      const origin = await page.evaluate(() => performance.timeOrigin);
      const tasks = await page.evaluate(() => window.__longtasks);
      const mainGaps = [];
      for (let i = 0; i + 1 < rafs.length; i++)
        if (rafs[i + 1][0] - rafs[i][0] > 80) mainGaps.push([origin + rafs[i][0], origin + rafs[i + 1][0]]);
      const overlaps = (a0, a1, b0, b1) => a0 < b1 && b0 < a1;
      const gapsOver = [];
      const scaleAround = [];  // [scale of the draw before the gap, after it]
      for (let i = 0; i + 1 < times.length; i++)
        if (times[i + 1] - times[i] > 80) {
          gapsOver.push([times[i], times[i + 1]]);
          scaleAround.push([scales[i] ?? null, scales[i + 1] ?? null]);
        }
      const inWindow = tasks.filter(([s, d]) => s + d > times[0] && s < times[times.length - 1]);
      longGaps = {
        n: gapsOver.length,
        with_long_task: gapsOver.filter(([a, b]) => inWindow.some(([s, d]) => overlaps(a, b, s, s + d))).length,
        with_main_frame_gap: gapsOver.filter(([a, b]) => mainGaps.some(([s, e]) => overlaps(a, b, s, e))).length,
        draw_scales_around: scaleAround,
        ms: gapsOver.map(([a, b]) => round(b - a)),
        draws_at_scale: Object.fromEntries([...new Set(scales)].map((s) => [s, scales.filter((x) => x === s).length])),
        long_tasks: { n: inWindow.length, total_ms: round(inWindow.reduce((x, [, d]) => x + d, 0)), max_ms: round(Math.max(0, ...inWindow.map(([, d]) => d))) },
      };
    }
    Object.assign(out, {
      renderer: await page.evaluate(() => window.rtamp.renderer ?? 'main (page without a worker)'),
      seconds: round(dt),
      drawn_per_s: round((s1[0] - s0[0]) / dt),
      frames_received_per_s: round((s1[1] - s0[1]) / dt),
      draw_gap_ms: drawGaps,
      fewest_draws_in_a_second: worstSecond,
      draw_gaps_over_80_ms: longGaps,
      draw_cost_ms: { n: costs.length, median: round(quantile(costs, 0.5)), p95: round(quantile(costs, 0.95)) },
      main_frame_interval_ms: { n: gaps.length, median: round(quantile(gaps, 0.5)), p95: round(quantile(gaps, 0.95)), max: round(Math.max(...gaps)) },
      draw_scale: await page.evaluate(() => window.rtamp.drawScale ?? 1),
    });
  });
  const stderr = await session(root, async (page) => {
    await page.waitForTimeout(1000);
    for (let k = 0; k < drags; k++) {
      const things = await page.evaluate(() => window.rtamp.things());
      const regions = await page.evaluate(() => window.rtamp.regions());
      const names = regions.map((r) => r.name);
      // Keep the robot busy: a block not in the first region goes there, else to the second.
      const blocks = things.filter((t) => t.kind === 'object' && t.at);
      if (!blocks.length || names.length < 2) break;
      const th = blocks[k % blocks.length];
      const target = th.at === names[0] ? regions[1] : regions[0];
      const from = await page.evaluate((n) => window.rtamp.project(n), th.name);
      const [dx, dy] = [[0, 0], [-0.08, 0.08], [0.08, 0.08], [-0.08, -0.08], [0.08, -0.08]][k % 5];
      const to = await page.evaluate(([g, x, y]) => window.rtamp.projectPoint([g.center[0] + x, g.center[1] + y, 0]), [target, dx, dy]);
      const before = await page.evaluate(() => [window.rtamp.latencies.length, window.rtamp.notices.length]);
      await drag(page, from, to);
      await waitFor(() => page.evaluate(([n, m]) => window.rtamp.latencies.length > n || window.rtamp.notices.slice(m).some((x) => x.kind === 'error'), before), 'the intervention record', 15000).catch(() =>
        console.error(`drag of ${th.name}: no intervention record or refusal in 15 s (the drop missed?)`),
      );
      const refused = await page.evaluate((m) => window.rtamp.notices.slice(m).filter((x) => x.kind === 'error'), before[1]);
      if (refused.length) console.error(`drag of ${th.name} refused: ${refused[0].text}`);
      await page.waitForTimeout(1500);
    }
    const lat = await page.evaluate(() => window.rtamp.latencies);
    Object.assign(out, {
      drags: lat.map((l) => ({ subject: l.subject, t: l.t, applied: l.applied, drop_to_record_ms: round(l.ms), drop_to_reply_ms: round(l.replyMs), server_ms: round(l.serverMs) })),
      median_drop_to_record_ms: round(quantile(lat.map((l) => l.ms), 0.5)),
      max_drop_to_record_ms: round(Math.max(...lat.map((l) => l.ms))),
      median_drop_to_reply_ms: round(quantile(lat.map((l) => l.replyMs), 0.5)),
    });
  });
  out.server_stderr = stderr.split('\n').find((l) => l.includes('receipt to applied')) ?? null;
  return out;
}

for (const root of roots) console.log(JSON.stringify(await measure(root), null, 1));
process.exit(0);
