// The page's browser tests (issue 14, "How it is checked"), one case per ctest entry:
//   node tests/browser.mjs CASE      (env RTAMP_BIN, RTAMP_SOURCE_DIR; label `browser`)
// Every case runs the real `rtamp serve` and Debian's Chromium (harness.mjs). The
// oracles are the server's own messages as the browser received them (the raw WebSocket
// frames), the scenario files and the episode log — not the page's code.
//   loads       the page loads: hello, panels filled from it, no page errors
//   scene       the scene shows the scenario's things where the server says they are; the
//               whole arm at home in view; no two labels overlap
//   drag        a real mouse drag of a block onto another region → `relocate` in the log,
//               then `handled_by_tree` or `replan` within a bounded number of ticks
//   paused      the same drag made while paused is applied on resume, before any move
//   add         the palette adds a block → `add` in the log, the thing appears, a reaction
//   remove      click a block, delete → `remove` in the log, the thing disappears
//   take        take the held block out of the gripper → `take-from-gripper`, a reaction
//   refused     an intervention the validator refuses → its reason shown on the page; an
//               add of a class the page does not offer (unicorn) refused
//   replay      a logged episode replayed and scrubbed to its end → the end placement
//   replaycontrols  pause, step and speed shown and working in a replay; scrubbing back
//               while it plays sticks (the frames go on from the time sought); success
//               and failure in different colours
//   tree        the behavior tree drawn as a tree: while a later move runs (paused), the
//               running node's box is inside the panel's view and every box shows the
//               server's last statuses; a drag of the view moves it, "follow" brings the
//               running node back; at the end every box shows the final statuses (the
//               server's, the log's end record's); the log replayed and seeked back and
//               forth shows the log's statuses at each time sought
//   screenshot  the scene's layout at t = 0 (paused) against a committed reference PNG,
//               drawn by the drawing worker (OffscreenCanvas)
//   fallback    the same picture drawn on the main thread (?render=main), and a drag
//   mujoco      --paused makes the first plan; drag in the MuJoCo world (label slow)
//   camera      --perception camera: the Camera panel shows the latest camera image the
//               server sent (the page joins late: the kept one), at its size, with a box
//               and label per detection drawn over it in the label's colour; live
//               images follow once resumed, at most 5 a second (label slow)
import assert from 'node:assert/strict';
import { spawnSync } from 'node:child_process';
import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { PNG } from 'pngjs';
import pixelmatch from 'pixelmatch';
import { BIN, SOURCE, cleanup, drag, launch, logRecords, openPage, rmSync, scratchDir, skipUnlessReady, startServer, waitFor } from './harness.mjs';

const here = dirname(fileURLToPath(import.meta.url));
const scenario = (name) => join(SOURCE, 'scenarios', `${name}.yaml`);
const REACTIONS = new Set(['handled_by_tree', 'replan']);
// "Within a bounded number of ticks": the loop reacts before the robot has started more
// than one further move (the running one may finish or be halted first).
const MAX_MOVES_BEFORE_REACTION = 1;
// Screenshots: share of the scene's pixels that may differ from the reference (0.1 % of
// 900 x 765 is ~690 pixels; one block drawn 40 x 40 px elsewhere changes ~3,200).
const TOLERANCE = 0.001;
// How long the screenshot case waits for the scene's picture to settle on screen.
const SCREENSHOT_SETTLE_MS = 15000;

function hello(ws) {
  return ws.received.find((m) => m.type === 'hello');
}

function lastFrame(ws) {
  for (let i = ws.received.length - 1; i >= 0; i--) if (ws.received[i].type === 'frame') return ws.received[i];
  return null;
}

// Index of the first log record matching `pred`.
function findRecord(ws, pred) {
  const recs = logRecords(ws);
  const i = recs.findIndex(pred);
  return i < 0 ? null : { i, recs };
}

// The loop's reaction to the intervention at records[i]: the first handled_by_tree /
// replan after it, and how many moves started in between.
async function reaction(ws, pred, what) {
  const found = await waitFor(() => {
    if (ws.received.length === 0) return null;
    const f = findRecord(ws, pred);
    if (!f) return null;
    const rest = f.recs.slice(f.i + 1);
    const k = rest.findIndex((r) => REACTIONS.has(r.ev));
    return k < 0 ? null : { intervention: f.recs[f.i], reaction: rest[k], between: rest.slice(0, k) };
  }, what).catch((e) => {
    const seen = logRecords(ws).filter((r) => r.ev !== 'perceived' && r.ev !== 'frame' && r.ev !== 'tick');
    const replies = ws.received.filter((m) => m.type === 'reply' || m.type === 'state');
    throw new Error(`${e.message}\nlog records: ${JSON.stringify(seen)}\nreplies and states: ${JSON.stringify(replies)}`);
  });
  const starts = found.between.filter((r) => r.ev === 'action' && r.what === 'start').length;
  assert.ok(starts <= MAX_MOVES_BEFORE_REACTION, `${starts} moves started before the loop reacted to ${JSON.stringify(found.intervention)}`);
  return found;
}

// query: appended to the page's URL (e.g. '?render=main').
async function withPage(serveArgs, body, query = '') {
  skipUnlessReady();
  const dir = scratchDir('web');
  const log = join(dir, 'episode.jsonl');
  const server = await startServer([...serveArgs, '--log', log]);
  const { context } = await launch();
  try {
    const { page, ws, errors } = await openPage(context, server.url + query);
    await body({ page, ws, log, server, dir });
    assert.deepEqual(errors, [], 'the page logged errors');
  } catch (e) {
    console.error('server stderr:\n' + server.stderr());
    throw e;
  } finally {
    await context.close().catch(() => {});
    server.proc.kill('SIGTERM');
    cleanup([() => rmSync(dir, { recursive: true, force: true })]);
  }
}

// Resumes a --paused episode from the page and waits until the robot's first move runs
// (the person then acts on a running episode, as in the paper).
async function resumeAndWaitForAMove(page, ws) {
  await page.click('#pause');
  await waitFor(() => logRecords(ws).some((r) => r.ev === 'action' && r.what === 'start'), 'the first move').catch((e) => {
    const seen = logRecords(ws).filter((r) => r.ev !== 'perceived' && r.ev !== 'frame' && r.ev !== 'tick');
    const control = ws.received.filter((m) => m.type === 'reply' || m.type === 'state');
    throw new Error(`${e.message}\nlog records: ${JSON.stringify(seen)}\nsent: ${JSON.stringify(ws.sent)}\nreplies and states: ${JSON.stringify(control)}`);
  });
}

// Where the page draws a thing / a region (page pixels), through its read-only test hook.
const at = (page, name) => page.evaluate((n) => window.rtamp.project(n), name);

// Drags `subject` onto `region` with the real mouse, aiming at a free spot of the region.
async function dragTo(page, subject, region, dx = 0.1, dy = 0.1) {
  const from = await at(page, subject);
  const to = await page.evaluate(
    ([r, ox, oy]) => {
      const g = window.rtamp.regions().find((x) => x.name === r);
      return window.rtamp.projectPoint([g.center[0] + ox, g.center[1] + oy, 0]);
    },
    [region, dx, dy],
  );
  await drag(page, from, to);
}

// The scene's picture against the committed reference (RTAMP_UPDATE_REFERENCE=1 rewrites it).
async function compareScreenshot(page) {
  await page.waitForTimeout(300); // a few animation frames after the first server frame
  const refPath = join(here, 'reference', 'scene-3-block-tray.png');
  if (process.env.RTAMP_UPDATE_REFERENCE === '1' || !existsSync(refPath)) {
    await page.waitForTimeout(SCREENSHOT_SETTLE_MS); // the worker's first picture is on screen
    writeFileSync(refPath, await page.locator('#scene').screenshot());
    assert.ok(process.env.RTAMP_UPDATE_REFERENCE === '1', `no reference image: wrote ${refPath}; check it and commit it`);
    return;
  }
  const ref = PNG.sync.read(readFileSync(refPath));
  // The scene is drawn by a worker on an OffscreenCanvas: its first picture reaches the
  // screen asynchronously, with software compositing up to ~2 s after the page is ready
  // under load. Like Playwright's toHaveScreenshot, compare again until the picture
  // matches or SCREENSHOT_SETTLE_MS have passed; the last comparison decides.
  const until = Date.now() + SCREENSHOT_SETTLE_MS;
  let diff, n;
  do {
    const shot = PNG.sync.read(await page.locator('#scene').screenshot());
    assert.equal(shot.width, ref.width);
    assert.equal(shot.height, ref.height);
    diff = new PNG({ width: ref.width, height: ref.height });
    n = pixelmatch(ref.data, shot.data, diff.data, ref.width, ref.height, { threshold: 0.15 });
  } while (n / (ref.width * ref.height) > TOLERANCE && Date.now() < until);
  const share = n / (ref.width * ref.height);
  console.log(`${n} of ${ref.width * ref.height} pixels differ from the reference`);
  if (share > TOLERANCE) writeFileSync(join(scratchDir('screenshot'), 'diff.png'), PNG.sync.write(diff));
  assert.ok(share <= TOLERANCE, `${(share * 100).toFixed(3)} % of the scene's pixels differ from the reference (tolerance ${TOLERANCE * 100} %)`);
}

const cases = {
  // The person types a new task (blocks onto the tray r3 instead of into r2): a bad one is
  // refused with the caret line; the accepted one's automaton is drawn, the header shows
  // it, the timeline has its line, and the robot's plan now ends with blocks in r3.
  async newtask() {
    await withPage([scenario('3-block-tray'), '--world', 'symbolic', '--no-operator', '--paused'], async ({ page, ws }) => {
      const h = hello(ws);
      const drawnBefore = await page.textContent('#automaton');
      await page.fill('#task-input', 'F G ((all_in_r2');
      await page.click('#task-send');
      await waitFor(async () => (await page.textContent('#notice')).includes('refused'), 'the refusal');
      assert.match(await page.textContent('#notice'), /\^/);
      const task = 'F G "all block in r3"';
      await page.fill('#task-input', task);
      await page.click('#task-send');
      await resumeAndWaitForAMove(page, ws);
      await waitFor(() => logRecords(ws).some((r) => r.ev === 'task' && r.applied), 'the task record');
      const rec = logRecords(ws).find((r) => r.ev === 'task' && r.applied);
      await waitFor(async () => (await page.textContent('#task')) === task, 'the header task');
      assert.notDeepEqual(rec.automaton, h.automaton);
      await waitFor(async () => (await page.textContent('#automaton')) !== drawnBefore, 'the new automaton drawn');
      assert.equal(await page.locator('.ba-state').count(), rec.automaton.states.length);
      await waitFor(async () => (await page.textContent('#timeline')).includes('new task from page'), 'the timeline line');
      await waitFor(() => logRecords(ws).some((r) => r.ev === 'plan' && r.t >= rec.t && r.actions.some((a) => a.endsWith(', r3)'))), 'a plan into r3');
      // A page that joins now: its hello names the new task, and it draws its automaton.
      const late = await openPage(page.context(), page.url(), true);
      const h2 = hello(late.ws);
      assert.equal(h2.task, task);
      assert.deepEqual(h2.automaton, rec.automaton);
      await waitFor(async () => (await late.page.textContent('#task')) === task, 'the late page\'s header task');
      assert.equal(await late.page.locator('.ba-state').count(), rec.automaton.states.length);
      assert.deepEqual(late.errors, [], 'the late page logged errors');
    });
  },

  async loads() {
    await withPage([scenario('3-block-tray'), '--world', 'symbolic'], async ({ page, ws }) => {
      const h = hello(ws);
      assert.equal(h.protocol, 2);
      assert.equal(await page.textContent('#task'), h.task);
      assert.equal(await page.locator('.ba-state').count(), h.automaton.states.length);
      assert.equal(await page.locator('#palette .class-button').count(), h.scene.classes.length);
      await waitFor(() => page.locator('.bt-box').count(), 'the behavior tree panel');
      const tree = [...ws.received].reverse().find((m) => m.type === 'tree') || h.tree;
      assert.equal(await page.locator('.bt-box').count(), tree.nodes.length);
      await waitFor(() => page.locator('.plan-step').count(), 'the plan panel');
      const plan = logRecords(ws).filter((r) => r.ev === 'plan').at(-1);
      assert.equal(await page.locator('.plan-step').count(), plan.actions.length);
      const css = await (await fetch(new URL('assets/style.css', page.url()))).text();
      assert.match(css, /\.bt-box/);
    });
  },

  async scene() {
    await withPage([scenario('3-block-tray'), '--world', 'symbolic', '--no-operator', '--paused'], async ({ page, ws }) => {
      const h = hello(ws);
      const frame = lastFrame(ws);
      const shown = await page.evaluate(() => window.rtamp.things());
      assert.deepEqual(shown.map((t) => t.name).sort(), frame.things.map((t) => t.name).sort());
      assert.deepEqual(shown.map((t) => t.name).sort(), h.scene.things.map((t) => t.name).sort());
      // The scenario file's things (o1..o3 and the tray r3), in the regions it puts them.
      const yaml = readFileSync(scenario('3-block-tray'), 'utf8');
      for (const name of ['o1', 'o2', 'o3', 'r3']) assert.match(yaml, new RegExp(`name: ${name}\\b`));
      const byName = Object.fromEntries(shown.map((t) => [t.name, t]));
      for (const t of frame.things) {
        assert.deepEqual(byName[t.name].pos, t.pos);
        assert.equal(byName[t.name].at, t.at);
        assert.equal(byName[t.name].class, h.scene.things.find((x) => x.name === t.name).class);
      }
      for (const o of ['o1', 'o2', 'o3', 'r3']) assert.equal(byName[o].at, 'r1', `${o} starts in r1`);
      // Every thing is drawn inside the scene's canvas, and the blocks of r1 lie left of
      // those of r2 on the screen as on the table seen from the front (+y to the right).
      const box = await page.locator('#scene canvas').boundingBox();
      // The whole arm at home is in view (its link frames, padded by a link's radius upwards).
      const arm = await page.evaluate(() => window.rtamp.armPoints.map((p) => window.rtamp.projectPoint([p[0], p[1], p[2] + 0.06])));
      for (const [k, p] of arm.entries()) assert.ok(p.x > box.x && p.x < box.x + box.width && p.y > box.y && p.y < box.y + box.height, `arm frame ${k} at ${JSON.stringify(p)} off the canvas ${JSON.stringify(box)}`);
      // No two labels overlap.
      await page.evaluate(() => new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r))));
      const labels = await page.evaluate(() =>
        [...document.querySelectorAll('#scene .labels > *')].filter((e) => e.style.display !== 'none').map((e) => {
          const r = e.getBoundingClientRect();
          return { text: e.textContent, left: r.left, right: r.right, top: r.top, bottom: r.bottom };
        }),
      );
      assert.ok(labels.length >= 6, `labels: ${JSON.stringify(labels)}`);
      for (let i = 0; i < labels.length; i++)
        for (let j = i + 1; j < labels.length; j++) {
          const [a, b] = [labels[i], labels[j]];
          assert.ok(a.right <= b.left || b.right <= a.left || a.bottom <= b.top || b.bottom <= a.top, `labels ${a.text} and ${b.text} overlap: ${JSON.stringify([a, b])}`);
        }
      for (const t of shown) {
        const p = await at(page, t.name);
        assert.ok(p.x > box.x && p.x < box.x + box.width && p.y > box.y && p.y < box.y + box.height, `${t.name} is on screen`);
      }
      const r1 = await at(page, 'r1'), r2 = await at(page, 'r2');
      assert.ok(r1.x > r2.x, 'r1 (y = +0.32) is drawn right of r2 (y = -0.32) from the front');
    });
  },

  async drag() {
    await withPage([scenario('3-block-tray'), '--world', 'symbolic', '--no-operator', '--paused'], async ({ page, ws, log }) => {
      await resumeAndWaitForAMove(page, ws); // the plan moves o3 third: it stays in r1 meanwhile
      await dragTo(page, 'o3', 'r2');
      const { intervention, reaction: r } = await reaction(ws, (x) => x.ev === 'intervention' && x.kind === 'relocate', 'the relocation and the reaction');
      assert.equal(intervention.subject, 'o3');
      assert.equal(intervention.location, 'r2');
      assert.equal(intervention.applied, true);
      assert.ok(REACTIONS.has(r.ev));
      await waitFor(async () => (await page.evaluate(() => window.rtamp.things())).find((t) => t.name === 'o3' && t.at === 'r2'), 'o3 drawn in r2');
      // The same record is in the episode's JSON Lines log file.
      const lines = readFileSync(log, 'utf8').trim().split('\n').map((l) => JSON.parse(l));
      assert.ok(lines.some((l) => l.ev === 'intervention' && l.kind === 'relocate' && l.subject === 'o3' && l.location === 'r2' && l.applied));
    });
  },

  async paused() {
    // The person pauses, fixes the scene, resumes: the drag made while paused is applied
    // when the episode goes on, before the robot's first move.
    await withPage([scenario('3-block-tray'), '--world', 'symbolic', '--no-operator', '--paused'], async ({ page, ws }) => {
      await dragTo(page, 'o3', 'r2');
      await waitFor(() => ws.received.some((m) => m.type === 'reply' && m.ok), 'the reply to the drag');
      await page.click('#pause'); // resume
      const { intervention, reaction: r, between } = await reaction(ws, (x) => x.ev === 'intervention' && x.kind === 'relocate', 'the relocation and the reaction');
      assert.equal(intervention.subject, 'o3');
      assert.equal(intervention.applied, true);
      assert.ok(REACTIONS.has(r.ev));
      assert.ok(!between.some((x) => x.ev === 'action'), 'no move ran between the intervention and the reaction');
    });
  },

  async add() {
    await withPage([scenario('3-block-tray'), '--world', 'symbolic', '--no-operator', '--paused'], async ({ page, ws }) => {
      const before = (await page.evaluate(() => window.rtamp.things())).map((t) => t.name);
      await resumeAndWaitForAMove(page, ws);
      await page.selectOption('#add-at', 'r2');
      await page.click('#palette .class-button[data-class="block"]');
      const { intervention } = await reaction(ws, (x) => x.ev === 'intervention' && x.kind === 'add', 'the addition and the reaction');
      assert.equal(intervention.applied, true);
      assert.equal(intervention.location, 'r2');
      assert.ok(!before.includes(intervention.subject));
      await waitFor(async () => (await page.evaluate(() => window.rtamp.things())).find((t) => t.name === intervention.subject), 'the new block drawn');
      const drawn = (await page.evaluate(() => window.rtamp.things())).find((t) => t.name === intervention.subject);
      assert.equal(drawn.class, 'block');
    });
  },

  async remove() {
    await withPage([scenario('3-block-tray'), '--world', 'symbolic', '--no-operator', '--paused'], async ({ page, ws }) => {
      await resumeAndWaitForAMove(page, ws);
      const p = await at(page, 'o3');
      await page.mouse.click(p.x, p.y);
      assert.match(await page.textContent('#selected'), /o3/);
      await page.click('#delete');
      const { intervention } = await reaction(ws, (x) => x.ev === 'intervention' && x.kind === 'remove', 'the removal and the reaction');
      assert.equal(intervention.subject, 'o3');
      assert.equal(intervention.applied, true);
      await waitFor(async () => !(await page.evaluate(() => window.rtamp.things())).some((t) => t.name === 'o3'), 'o3 gone from the scene');
    });
  },

  async take() {
    await withPage([scenario('3-block-tray'), '--world', 'symbolic', '--no-operator'], async ({ page, ws }) => {
      // Pause while the robot holds something and take it. The page knows what the last
      // frame showed; the world may have put the thing down after that frame and before
      // the pause took effect: then the take is refused ("nothing in the gripper"),
      // and the test resumes and waits for the next thing held.
      let held = null;
      for (let attempt = 0; attempt < 10 && !held; attempt++) {
        await waitFor(() => page.evaluate(() => window.rtamp.held), 'the robot holding a thing');
        await page.click('#pause');
        await waitFor(() => page.evaluate(() => window.rtamp.state?.paused), 'the pause');
        // Frames the server sent before the pause took effect may still arrive and show
        // the gripper empty (the take button is then disabled): let them land first.
        await page.waitForTimeout(300);
        held = await page.evaluate(() => window.rtamp.held);
        if (!held || !(await page.isEnabled('#take'))) {
          held = null;
          await page.click('#pause');
          continue;
        }
        // While it carries something the arm is drawn from the streamed joint angles (the
        // server's IK for the symbolic world's tool point) reaching that point, elbow and
        // wrist above it (never through the table or a tray).
        const [tool, streamed, points] = await page.evaluate(() => [window.rtamp.tool, window.rtamp.streamedTool, window.rtamp.armPoints]);
        const q = lastFrame(ws)?.q;
        assert.equal(q?.length, 6, 'the frame carries six joint angles');
        assert.ok(Math.hypot(...tool.map((v, i) => v - streamed[i])) < 0.01, `drawn tool ${tool} vs streamed ${streamed}`);
        for (const k of [2, 3, 4]) assert.ok(points[k][2] > streamed[2], `link frame ${k} at ${points[k]} below the tool ${streamed}`);
        const replies = () => ws.received.filter((m) => m.type === 'reply');
        const before = replies().length;
        await page.selectOption('#take-to', 'r1');
        try {
          await page.click('#take', { timeout: 3000 });
        } catch (e) {
          // A late frame disabled the button after all: resume and try the next thing held.
          held = null;
          await page.click('#pause');
          continue;
        }
        const reply = await waitFor(() => replies()[before], 'the reply to the take');
        await page.click('#pause'); // resume
        if (!reply.ok) {
          assert.match(reply.error, /nothing in the gripper/, JSON.stringify(reply));
          held = null;
          await waitFor(() => page.evaluate(() => !window.rtamp.held), 'a frame with the gripper empty');
        }
      }
      assert.ok(held, 'took a thing from the gripper while the robot held it');
      // A refused attempt is logged too (applied: false): the reaction is to the applied one.
      const { intervention } = await reaction(ws, (x) => x.ev === 'intervention' && x.kind === 'take-from-gripper' && x.applied, 'the take and the reaction');
      const refused = logRecords(ws).filter((x) => x.ev === 'intervention' && x.kind === 'take-from-gripper' && !x.applied);
      for (const r of refused) assert.match(r.detail, /nothing in the gripper/, JSON.stringify(r));
      assert.equal(intervention.subject, held);
      await waitFor(async () => (await page.evaluate(() => window.rtamp.things())).find((t) => t.name === held && t.at === 'r1'), `${held} drawn in r1`);
    });
  },

  async refused() {
    await withPage([scenario('3-block-tray'), '--world', 'symbolic', '--no-operator', '--paused'], async ({ page, ws }) => {
      // r1 holds four things and has capacity 4: a fifth is refused by the validator.
      await page.selectOption('#add-at', 'r1');
      await page.click('#palette .class-button[data-class="block"]');
      const reply = await waitFor(() => ws.received.find((m) => m.type === 'reply' && m.ok === false), 'the refusal');
      assert.ok(reply.error && reply.error.length > 0);
      await waitFor(async () => (await page.textContent('#notice')).includes(reply.error), `the reason '${reply.error}' on the page`);
      assert.equal(await page.getAttribute('#notice', 'data-kind'), 'error');
      // The scene is unchanged: four things, none added.
      assert.equal((await page.evaluate(() => window.rtamp.things())).length, 4);
      // A class the page does not offer is refused (a second connection, as a hand-made page).
      const unicorn = await page.evaluate(
        () =>
          new Promise((resolve) => {
            const s = new WebSocket(`ws://${location.host}/ws`);
            s.onopen = () => s.send(JSON.stringify({ type: 'intervene', id: 1, kind: 'add', class: 'unicorn', location: 'r2' }));
            s.onmessage = (e) => {
              const m = JSON.parse(e.data);
              if (m.type === 'reply') {
                s.close();
                resolve(m);
              }
            };
          }),
      );
      assert.equal(unicorn.ok, false, JSON.stringify(unicorn));
      assert.match(unicorn.error, /unknown class 'unicorn'/);
    });
  },

  async replay() {
    skipUnlessReady();
    const dir = scratchDir('replay');
    const log = join(dir, 'run.jsonl');
    const run = spawnSync(BIN, ['run', scenario('3-block-tray'), '--world', 'symbolic', '--quiet', '--log', log], { encoding: 'utf8' });
    assert.equal(run.status, 0, run.stderr);
    const records = readFileSync(log, 'utf8').trim().split('\n').map((l) => JSON.parse(l));
    const end = records.at(-1);
    assert.equal(end.ev, 'end');
    const server = await startServer([scenario('3-block-tray'), '--replay', log]);
    const { context } = await launch();
    try {
      const { page, ws, errors } = await openPage(context, server.url);
      assert.equal(hello(ws).mode, 'replay');
      // Scrub with the keyboard: focus the slider, End jumps to the episode's end.
      await page.focus('#scrub');
      await page.keyboard.press('End');
      await waitFor(() => page.evaluate(() => window.rtamp.records.some((r) => r.ev === 'end')), 'the end record after seeking');
      await waitFor(async () => {
        const shown = await page.evaluate(() => window.rtamp.things());
        return Object.entries(end.placement).every(([name, loc]) => shown.find((t) => t.name === name)?.at === loc);
      }, 'the logged end placement drawn');
      assert.match(await page.textContent('#result'), end.success ? /succeeded/ : /failed/);
      assert.deepEqual(errors, []);
    } finally {
      await context.close().catch(() => {});
      server.proc.kill('SIGTERM');
      rmSync(dir, { recursive: true, force: true });
    }
  },

  async replaycontrols() {
    skipUnlessReady();
    const dir = scratchDir('replaycontrols');
    const ok = join(dir, 'ok.jsonl');
    const failed = join(dir, 'failed.jsonl');
    for (const [log, extra] of [[ok, []], [failed, ['--max-time', '3']]]) {
      const run = spawnSync(BIN, ['run', scenario('3-block-tray'), '--world', 'symbolic', '--quiet', '--log', log, ...extra], { encoding: 'utf8' });
      assert.ok(run.status === 0 || run.status === 1, run.stderr);
    }
    const frames = (ws) => ws.received.filter((m) => m.type === 'frame');
    const colour = (page) => page.evaluate(() => getComputedStyle(document.querySelector('#result')).color);
    let outcomeColours = [];
    for (const log of [ok, failed]) {
      const end = readFileSync(log, 'utf8').trim().split('\n').map((l) => JSON.parse(l)).at(-1);
      assert.equal(end.success, log === ok, JSON.stringify(end));
      const server = await startServer([scenario('3-block-tray'), '--replay', log, '--paused']);
      const { context } = await launch();
      try {
        const { page, ws, errors } = await openPage(context, server.url);
        assert.equal(hello(ws).mode, 'replay');
        if (log === ok) {
          // Pause / resume, step and speed are shown in replay mode, and work.
          for (const id of ['#pause', '#step', '#speed']) assert.ok(await page.isVisible(id), `${id} shown in replay mode`);
          assert.equal(await page.evaluate(() => window.rtamp.records.length), 0);
          await page.click('#step');
          await waitFor(() => page.evaluate(() => window.rtamp.records.length > 0), 'a step to play the first records');
          const afterStep = await page.evaluate(() => window.rtamp.records.length);
          await page.selectOption('#speed', '8');
          await waitFor(() => ws.received.some((m) => m.type === 'state' && m.speed === 8), 'the speed in a state message');
          assert.equal(await page.evaluate(() => window.rtamp.records.length), afterStep, 'paused: nothing plays');
          await page.click('#pause'); // resume
          await waitFor(() => page.evaluate(() => window.rtamp.t > 6), 'the replay playing past 6 s');
          // Scrub back while it plays (Home: to 0): the frames go on from there, not from before.
          const before = await page.evaluate(() => window.rtamp.t);
          const seen = ws.received.length;
          await page.focus('#scrub');
          await page.keyboard.press('Home');
          await waitFor(() => ws.received.slice(seen).some((m) => m.type === 'hello'), 'the hello after the seek');
          const start = seen + ws.received.slice(seen).findIndex((m) => m.type === 'hello');
          await waitFor(() => frames({ received: ws.received.slice(start) }).length >= 5, 'frames after the seek');
          for (const f of frames({ received: ws.received.slice(start) }).slice(0, 5)) assert.ok(f.t < before - 2, `a frame at ${f.t} after seeking to 0 from ${before}`);
        }
        await page.focus('#scrub');
        await page.keyboard.press('End');
        await waitFor(() => page.evaluate(() => window.rtamp.records.some((r) => r.ev === 'end')), 'the end record');
        assert.match(await page.textContent('#result'), end.success ? /^succeeded/ : /^failed/);
        outcomeColours.push(await colour(page));
        assert.deepEqual(errors, []);
      } finally {
        await context.close().catch(() => {});
        server.proc.kill('SIGTERM');
      }
    }
    // Success and failure are told apart by colour too.
    assert.notEqual(outcomeColours[0], outcomeColours[1], `success and failure both drawn ${outcomeColours[0]}`);
    rmSync(dir, { recursive: true, force: true });
  },

  async tree() {
    skipUnlessReady();
    const dir = scratchDir('tree');
    const log = join(dir, 'served.jsonl');
    const letters = (tree) => (tree ? tree.nodes.map((n) => ({ IDLE: 'I', RUNNING: 'R', SUCCESS: 'S', FAILURE: 'F' })[n.status]).join('') : null);
    // The statuses the server sent last (raw frames: hello's tree, tree, status).
    const sentStatuses = (ws) => {
      let s = null;
      for (const m of ws.received) {
        if (m.type === 'hello') s = letters(m.tree);
        if (m.type === 'tree') s = letters(m);
        if (m.type === 'status') s = m.s;
      }
      return s;
    };
    const shown = (page) => page.evaluate(() => window.rtamp.tree);
    // The page shows exactly what the server sent last (the page updates once per animation frame).
    const showsSent = (page, ws, what) =>
      waitFor(async () => (await shown(page)).statuses === sentStatuses(ws), what).catch(async (e) => {
        throw new Error(`${e.message}: page ${(await shown(page)).statuses}, server ${sentStatuses(ws)}`);
      });
    // The box of node `id` lies inside the panel's drawing (page pixels, as Playwright measures them).
    const inView = async (page, id) => {
      await page.locator('#tree').scrollIntoViewIfNeeded();
      const view = await page.locator('#tree svg').boundingBox();
      const box = await page.locator(`#tree .bt-box[data-id="${id}"]`).boundingBox();
      const ok = box && box.x >= view.x - 0.5 && box.y >= view.y - 0.5 && box.x + box.width <= view.x + view.width + 0.5 && box.y + box.height <= view.y + view.height + 0.5;
      return { ok, view, box };
    };
    const server = await startServer([scenario('3-block-tray'), '--world', 'symbolic', '--no-operator', '--paused', '--speed', '2', '--log', log]);
    const { context } = await launch();
    try {
      const { page, ws, errors } = await openPage(context, server.url);
      const moves = () => logRecords(ws).filter((r) => r.ev === 'action' && r.what === 'start').length;
      await page.click('#pause'); // resume
      // Paused while the fourth move runs (its node is far down the tree, below the first view).
      await waitFor(() => moves() >= 4, 'the fourth move');
      let running = -1;
      for (let tries = 0; tries < 10 && running < 0; tries++) {
        if (tries > 0) {
          await page.click('#pause'); // resume a little
          const n = moves();
          await waitFor(() => moves() > n, 'another move');
        }
        await page.click('#pause');
        await waitFor(() => ws.received.some((m) => m.type === 'state' && m.paused) && (ws.received.findLast((m) => m.type === 'state')).paused, 'paused');
        await showsSent(page, ws, 'the page showing the server\'s statuses while paused');
        running = sentStatuses(ws).lastIndexOf('R');
      }
      assert.ok(running >= 0, `no node running while paused: ${sentStatuses(ws)}`);
      const t = await shown(page);
      assert.equal(t.nodes, sentStatuses(ws).length);
      assert.equal(t.running, running);
      const seen = await inView(page, running);
      assert.ok(seen.ok, `the running node's box ${JSON.stringify(seen.box)} is outside the panel's view ${JSON.stringify(seen.view)}`);
      assert.ok(t.size.height > seen.view.height, `the tree (${t.size.height} px) fits the view (${seen.view.height} px): nothing to follow`);
      assert.ok(t.view.y < 0, `the view was not moved to the running node: ${JSON.stringify(t.view)}`);
      // The person drags the view: it stays where they put it; "follow" brings the node back.
      const from = { x: seen.view.x + seen.view.width / 2, y: seen.view.y + 20 };
      await drag(page, from, { x: from.x, y: from.y + 250 });
      const moved = await shown(page);
      assert.ok(Math.abs(moved.view.y - (t.view.y + 250)) < 1, `the view after a drag of 250 px: ${JSON.stringify(moved.view)} (before ${JSON.stringify(t.view)})`);
      assert.ok(!(await inView(page, running)).ok, 'the drag moved the running node out of view');
      await page.click('#tree .bt-bar button:nth-child(2)'); // follow
      assert.ok((await inView(page, running)).ok, '"follow" brought the running node back into view');
      // To the end: every box shows the final statuses.
      await page.selectOption('#speed', '8');
      await page.click('#pause'); // resume
      await waitFor(() => ws.received.some((m) => m.type === 'state' && m.ended), 'the end', 120000);
      await showsSent(page, ws, 'the page showing the final statuses');
      const present = await page.evaluate(() => fetch('/api/hello').then((r) => r.json()));
      const end = readFileSync(log, 'utf8').trim().split('\n').map((l) => JSON.parse(l)).at(-1);
      assert.equal(end.ev, 'end');
      assert.ok(end.success, JSON.stringify(end));
      const final = (await shown(page)).statuses;
      assert.equal(final, letters(present.tree), 'the server\'s present tree');
      assert.equal(final, end.statuses, 'the end record\'s statuses');
      assert.ok(!final.includes('R') && final[0] === 'S', `final statuses ${final}`);
      assert.deepEqual(errors, [], 'the page logged errors');
    } catch (e) {
      console.error('server stderr:\n' + server.stderr());
      throw e;
    } finally {
      await context.close().catch(() => {});
      server.proc.kill('SIGTERM');
    }

    // The replay, seeked back and forth: the statuses the log has at each time sought.
    const records = readFileSync(log, 'utf8').trim().split('\n').map((l) => JSON.parse(l));
    const end = records.at(-1);
    const logged = records.filter((r) => r.ev === 'statuses');
    const at = (time) => (time >= end.t ? end.statuses : logged.filter((r) => r.t <= time + 1e-9).at(-1)?.s);
    const withR = logged.filter((r) => r.s.includes('R'));
    assert.ok(withR.length >= 3, `statuses with a running node in the log: ${withR.length}`);
    const times = [withR.at(-2).t + 0.01, withR[1].t + 0.01, end.t, withR[0].t + 0.01, withR.at(-1).t + 0.01];
    const replay = await startServer([scenario('3-block-tray'), '--replay', log, '--paused']);
    const { context: context2 } = await launch();
    try {
      const { page, ws, errors } = await openPage(context2, replay.url);
      for (const time of times) {
        const hellos = ws.received.filter((m) => m.type === 'hello').length;
        await page.evaluate((v) => {
          const s = document.querySelector('#scrub');
          s.value = String(v);
          s.dispatchEvent(new Event('change'));
        }, time);
        await waitFor(() => ws.received.filter((m) => m.type === 'hello').length > hellos, `the hello after seeking to ${time}`);
        await waitFor(async () => (await shown(page)).statuses === at(time), `the log's statuses at ${time}`).catch(async (e) => {
          throw new Error(`${e.message}: page ${(await shown(page)).statuses}, log ${at(time)}`);
        });
        const running = at(time).lastIndexOf('R');
        if (running >= 0) assert.ok((await inView(page, running)).ok, `the running node at ${time} is in view`);
      }
      assert.deepEqual(errors, [], 'the replay page logged errors');
    } catch (e) {
      console.error('server stderr:\n' + replay.stderr());
      throw e;
    } finally {
      await context2.close().catch(() => {});
      replay.proc.kill('SIGTERM');
      rmSync(dir, { recursive: true, force: true });
    }
  },

  async screenshot() {
    await withPage([scenario('3-block-tray'), '--world', 'symbolic', '--no-operator', '--paused'], async ({ page }) => {
      // In Chromium the scene is drawn by the worker (an OffscreenCanvas), not by the
      // fallback on the main thread.
      assert.equal(await page.evaluate(() => window.rtamp.renderer), 'worker', await page.evaluate(() => window.rtamp.renderWhy));
      await compareScreenshot(page);
    });
  },

  async fallback() {
    // The page's fallback where a worker cannot draw (forced by ?render=main): the same
    // picture, drawn on the main thread, and picking aims at what is drawn.
    await withPage(
      [scenario('3-block-tray'), '--world', 'symbolic', '--no-operator', '--paused'],
      async ({ page, ws }) => {
        assert.equal(await page.evaluate(() => window.rtamp.renderer), 'main');
        await compareScreenshot(page);
        await dragTo(page, 'o3', 'r2');
        const reply = await waitFor(() => ws.received.find((m) => m.type === 'reply' && m.ok), 'the reply to the drag');
        assert.equal(reply.subject, 'o3');
      },
      '?render=main',
    );
  },

  async mujoco() {
    await withPage([scenario('3-block-tray'), '--world', 'mujoco', '--no-operator', '--paused'], async ({ page, ws }) => {
      // --paused: the first plan is made (docs/serve.md), time has not started.
      await waitFor(() => logRecords(ws).some((r) => r.ev === 'plan'), 'the first plan while paused');
      const frame = lastFrame(ws);
      assert.equal(frame.q.length, 6);
      // The page's forward kinematics of the streamed joint angles puts the tool where
      // MuJoCo does (the server's tool point).
      const tool = await page.evaluate(() => window.rtamp.tool);
      assert.ok(Math.hypot(...tool.map((v, i) => v - frame.tool[i])) < 0.01, `drawn tool ${tool} vs streamed ${frame.tool}`);
      await resumeAndWaitForAMove(page, ws);
      await dragTo(page, 'o3', 'r2');
      const { intervention, reaction: r } = await reaction(ws, (x) => x.ev === 'intervention' && x.kind === 'relocate', 'the relocation and the reaction');
      assert.equal(intervention.subject, 'o3');
      assert.equal(intervention.applied, true, JSON.stringify(intervention));
      assert.ok(REACTIONS.has(r.ev));
    });
  },

  async camera() {
    await withPage([scenario('3-block-tray'), '--world', 'mujoco', '--perception', 'camera', '--no-operator', '--paused'], async ({ page, ws }) => {
      const cameraMessages = () => ws.received.filter((m) => m.type === 'camera');
      // Paused, the first frame was taken (the first plan's percept): the page, which
      // joined after it, gets it right after its hello.
      await waitFor(() => cameraMessages().length > 0, 'the kept camera message');
      await page.waitForFunction(() => window.rtamp.camera.drawn > 0, null, { timeout: 30000 });
      const sent = cameraMessages().at(-1);
      const shown = await page.evaluate(() => {
        const c = document.querySelector('#camera');
        const g = c.getContext('2d');
        const at = (x, y) => [...g.getImageData(Math.round(x), Math.round(y), 1, 1).data.slice(0, 3)];
        const last = window.rtamp.camera.last;
        return {
          hidden: document.querySelector('#camera-section').hidden,
          size: [c.width, c.height],
          onScreen: c.getBoundingClientRect().width,
          caption: document.querySelector('#camera-caption').textContent,
          t: last.t,
          // The outline's colour on each box's left edge, halfway down (a 2-px stroke).
          edges: last.boxes.map((b) => ({ label: b.label, rgb: b.rgb, edge: at(b.x0, (b.y0 + b.y1) / 2) })),
          // Not a blank canvas: the image's pixels vary.
          distinct: new Set(Array.from({ length: 64 }, (_, i) => at((i * 97) % c.width, (i * 53) % c.height).join(','))).size,
        };
      });
      assert.equal(shown.hidden, false, 'the Camera panel is shown');
      assert.deepEqual(shown.size, [sent.width, sent.height]);
      assert.deepEqual(shown.size, [640, 480]);
      assert.ok(shown.onScreen > 100, `the image is ${shown.onScreen} px wide on the page`);
      assert.equal(shown.t, sent.t);
      assert.ok(shown.distinct > 8, `${shown.distinct} distinct colours in 64 samples: an image`);
      assert.ok(shown.edges.length >= 3, `${shown.edges.length} boxes`);
      assert.deepEqual(shown.edges.map((e) => e.label), sent.boxes.map((b) => b.label));
      for (const e of shown.edges) {
        assert.ok(e.edge.every((v, i) => Math.abs(v - e.rgb[i]) <= 40), `${e.label}: the box's edge ${e.edge} in its colour ${e.rgb}`);
        assert.match(e.label, /^\S+ (visible|occluded|held|out-of-view|missing|new)$/);
      }
      for (const n of ['o1', 'o2', 'o3']) assert.ok(sent.boxes.some((b) => b.label === `${n} visible`), `${n} visible`);
      assert.match(shown.caption, /^overhead · t = /);
      // Resumed: newer images follow, at most 5 a wall second.
      const before = cameraMessages().length, start = Date.now();
      await page.click('#pause');
      await waitFor(() => cameraMessages().length >= before + 5, 'five more camera messages');
      const wall = (Date.now() - start) / 1000, got = cameraMessages().length - before;
      assert.ok(got <= 5 * wall + 1, `${got} camera messages in ${wall.toFixed(2)} s`);
      const ts = cameraMessages().map((m) => m.t);
      assert.ok(ts.every((t, i) => i === 0 || t > ts[i - 1]), 'newer and newer');
      await page.waitForFunction((t) => window.rtamp.camera.last && window.rtamp.camera.last.t >= t, ts.at(-2), { timeout: 30000 });
    });
  },
};

const name = process.argv[2];
if (!cases[name]) {
  console.error(`browser.mjs: error: unknown case '${name}' (one of: ${Object.keys(cases).join(', ')})`);
  process.exit(2);
}
try {
  await cases[name]();
  console.log(`ok: ${name}`);
  process.exit(0);
} catch (e) {
  console.error(`FAILED: ${name}: ${e.stack || e}`);
  process.exit(1);
}
