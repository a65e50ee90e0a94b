// The drawing's frame playout (src/render/playout.js), checked in node without a browser:
//   node tests/playout.test.mjs [EPISODES]
// Random streams: an arm and two blocks moving along known paths, a block added and one
// removed mid-stream, frames sampled every 1/30 s of wall time (at 1x, 4x or 0.5x speed,
// with a pause) and delivered with random delays, bunches and stalls; samples taken at
// jittered animation frames. The oracles do not use the playout's code: the shown state
// is compared with the linear interpolation, computed here from the list of frames sent,
// at the shown time τ; τ is checked against the frames received so far; and once the
// stream stops the newest frame must be shown exactly.
import assert from 'node:assert/strict';
import { FramePlayout } from '../src/render/playout.js';

const episodes = Number(process.argv[2] ?? 300);
let seed = 12345;
const rand = () => ((seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648);

// The true state at episode time t (seconds) of a stream: joint angles and things.
function truth(t, spec) {
  const q = [0, 1, 2, 3, 4, 5].map((i) => Math.sin(0.7 * t + i) * (1 + i / 10));
  const things = [
    { name: 'b0', class: 'red', pos: [0.3 + 0.1 * Math.sin(t), -0.2, 0.05], quat: [Math.cos(t / 4), 0, 0, Math.sin(t / 4)] },
    // The same rotation sent as q or -q (both are right; MuJoCo may flip between frames).
    { name: 't0', class: 'tray', pos: [0.5, 0.1 * t, 0.02], quat: [Math.cos(t / 3), 0, Math.sin(t / 3), 0].map((v) => (Math.floor(t * 7) % 2 ? -v : v)) },
  ];
  if (t >= spec.addAt) things.push({ name: 'b9', class: 'blue', pos: [0.1, 0.2 + 0.05 * t, 0.05], quat: [1, 0, 0, 0] });
  if (t >= spec.removeAt) things.splice(0, 1);
  return { t, q, things, held: t % 3 < 1 ? 'b0' : null };
}

// The linear interpolation of the sent frames at τ (the oracle).
function expected(sent, tau) {
  let i = 0;
  while (i + 1 < sent.length && sent[i + 1].t <= tau) i++;
  const a = sent[i], b = sent[i + 1];
  if (!b || tau <= a.t) return { q: a.q, held: a.held, things: a.things.map((th) => ({ name: th.name, pos: th.pos, from: th.quat, to: th.quat })) };
  const s = (tau - a.t) / (b.t - a.t);
  const lerp = (x, y) => x.map((v, k) => v + (y[k] - v) * s);
  const q = lerp(a.q, b.q);
  const things = a.things.map((th) => {
    const to = b.things.find((x) => x.name === th.name);
    return to ? { name: th.name, pos: lerp(th.pos, to.pos), from: th.quat, to: to.quat } : { name: th.name, pos: th.pos, from: th.quat, to: th.quat };
  });
  return { q, things, held: a.held };
}

// The rotation angle between two unit quaternions.
const angle = (p, q) => 2 * Math.acos(Math.min(1, Math.abs(p[0] * q[0] + p[1] * q[1] + p[2] * q[2] + p[3] * q[3])));
const close = (x, y, what) => x.forEach((v, k) => assert.ok(Math.abs(v - y[k]) < 1e-9, `${what}: ${x} vs ${y}`));

let samples = 0, shown = 0;
for (let e = 0; e < episodes; e++) {
  const speed = [1, 4, 0.5][e % 3];
  const spec = { addAt: 1 + rand() * 3, removeAt: 2 + rand() * 3 };
  const pauseAt = rand() < 0.5 ? 1 + rand() * 2 : Infinity; // wall s
  const frames = 60 + Math.floor(rand() * 120);
  // Sent every 1/30 s of wall time; the episode's clock stops for 1 s of wall time at pauseAt.
  const sent = [];
  for (let k = 0; k < frames; k++) {
    const wall = k / 30;
    const t = (wall < pauseAt ? wall : Math.max(pauseAt, wall - 1)) * speed;
    if (sent.length && t === sent[sent.length - 1].t) continue; // a paused stream repeats t: sent once here
    sent.push({ ...truth(t, spec), sentAt: wall * 1000 });
  }
  // Delivery: a delay of 1-20 ms, sometimes held back (bunching), sometimes a 150 ms stall.
  let hold = 0;
  const arrivals = sent.map((f) => {
    if (rand() < 0.03) hold = f.sentAt + 150;
    const at = Math.max(f.sentAt + 1 + rand() * 19, rand() < 0.1 ? f.sentAt + 40 : 0, hold);
    return { at, f };
  });
  for (let k = 1; k < arrivals.length; k++) arrivals[k].at = Math.max(arrivals[k].at, arrivals[k - 1].at); // in order
  const p = new FramePlayout();
  let next = 0, lastTau = -Infinity, lastShown = null, streaming = 0, streamingShown = 0;
  const end = arrivals[arrivals.length - 1].at + 2000;
  for (let now = 0; now < end; now += 16.7 + (rand() < 0.05 ? 60 * rand() : rand() * 3)) {
    while (next < arrivals.length && arrivals[next].at <= now) {
      const { f } = arrivals[next++];
      p.push({ t: f.t, things: f.things, q: f.q, held: f.held }, arrivals[next - 1].at);
    }
    if (!next) continue;
    const s = p.sample(now);
    samples++;
    const received = sent.slice(0, next);
    const newest = received[received.length - 1];
    if (newest.t > lastTau && lastTau > -Infinity) {
      streaming++;
      if (s) streamingShown++;
    }
    if (!s) continue;
    shown++;
    // τ: never back, never past the newest frame received.
    assert.ok(s.t >= lastTau - 1e-12, `τ went back: ${lastTau} -> ${s.t}`);
    assert.ok(s.t <= newest.t + 1e-12, `τ ${s.t} past the newest frame ${newest.t}`);
    lastTau = s.t;
    // The shown state is the sent frames' interpolation at τ.
    const x = expected(received, s.t);
    close(s.q, x.q, `q at τ=${s.t}`);
    assert.equal(s.held, x.held, `held at τ=${s.t}`);
    assert.deepEqual(s.things.map((th) => th.name), x.things.map((th) => th.name), `things at τ=${s.t}`);
    s.things.forEach((th, k) => {
      close(th.pos, x.things[k].pos, `${th.name} at τ=${s.t}`);
      // The orientation: a unit quaternion on the shorter arc between the two frames'.
      const { from, to } = x.things[k];
      assert.ok(Math.abs(Math.hypot(...th.quat) - 1) < 1e-9, `${th.name}: quat not unit`);
      const between = angle(from, to) + 1e-9;
      assert.ok(angle(from, th.quat) <= between && angle(th.quat, to) <= between, `${th.name}: quat off the arc at τ=${s.t}`);
    });
    // The lag behind the newest frame is cut once it passes 4 frame periods.
    assert.ok(newest.t - s.t <= (4 * speed) / 30 + 1e-9, `episode ${e}: lag ${newest.t - s.t} at τ=${s.t}`);
    lastShown = s;
  }
  // Once the stream stops, the newest frame is shown as received.
  const last = sent[sent.length - 1];
  assert.ok(lastShown, 'nothing shown');
  assert.equal(lastShown.t, last.t, `episode ${e}: the last shown time`);
  assert.deepEqual(lastShown.q, last.q);
  assert.deepEqual(lastShown.things, last.things);
  // Every animation frame with something newer than the shown time received shows a new
  // picture (bar the first ones, before the stream's rate is known).
  assert.ok(streamingShown >= 0.9 * streaming, `episode ${e}: ${streamingShown} of ${streaming} animation frames showed a new state`);
}

// A frame earlier than the newest (a replay scrubbed back) is shown at once.
{
  const p = new FramePlayout();
  for (let k = 0; k < 30; k++) p.push(truth(k / 30, { addAt: 9, removeAt: 9 }), k * 33);
  p.sample(1000);
  p.push(truth(0.2, { addAt: 9, removeAt: 9 }), 1010);
  assert.equal(p.sample(1011).t, 0.2);
}
// The same time again (paused, a change applied): the new state replaces the old.
{
  const p = new FramePlayout();
  p.push({ t: 1, things: [{ name: 'a', pos: [0, 0, 0] }], q: null }, 0);
  assert.deepEqual(p.sample(1).things[0].pos, [0, 0, 0]);
  assert.equal(p.sample(2), null);
  p.push({ t: 1, things: [{ name: 'a', pos: [1, 0, 0] }], q: null }, 3);
  assert.deepEqual(p.sample(4).things[0].pos, [1, 0, 0]);
}
console.log(`playout: ${episodes} random streams, ${samples} samples, ${shown} shown: ok`);
