// The playout of the streamed frames (the page keeps 30 frames a second): the
// server sends a frame every 1/30 s of wall time, but they reach the drawing thread
// unevenly — two in one animation frame, then none for 60 ms (the network, the page's
// main thread relaying them, the compositor). Drawing each frame as it arrives shows
// those bunches as stutter and drops the frames that arrive together. Instead, like a
// networked game's snapshot interpolation, the scene is shown a little in the past: the
// shown episode time τ follows the newest frame's time t at a lag of about 1.5 frame
// periods, advancing with the wall clock at the stream's own rate, and every animation
// frame draws the state at τ, linearly interpolated between the two frames around it
// (positions and joint angles linearly, orientations by normalised lerp; which things
// exist, their classes and the gripper's hold from the earlier frame).
// push(frame, now) takes a frame {t, things: [{name, pos, quat, ...}], q, held} at wall
// time now (ms); sample(now) returns the state to show at now — {t, things, q, held} in
// the frame's shape — or null when it is what the last sample returned.
// Invariants: τ never goes back except on reset (a frame earlier than the newest, a
// replay's scrub); τ ≤ the newest frame's t, and once frames stop τ reaches it, so the
// newest frame is always shown in the end exactly as received; a lag above MAX_FRAMES
// periods (a stall, a jump forward) is cut at once to the target lag.

const TARGET_FRAMES = 1.5; // lag aimed at, in frame periods
const MAX_FRAMES = 4; // lag beyond this is cut at once
const SETTLE_MS = 250; // time constant pulling the lag towards its target
const HISTORY = 30; // frames over which the stream's rate is measured
const GAP_MS = 500; // a longer gap between frames (a pause) starts the measurement anew

export class FramePlayout {
  constructor() {
    this.reset();
  }

  reset() {
    this.frames = []; // received frames not yet behind τ (the last one before τ kept), t ascending
    this.history = []; // [t, wall ms received] of the last HISTORY frames, for the rate
    this.tau = null;
    this.at = null; // wall time of the last sample
    this.period = null; // episode seconds between frames (running estimate)
    this.rate = null; // episode seconds per wall ms (running estimate)
    this.changed = false; // a frame replaced the newest without moving t
  }

  push(frame, now) {
    const last = this.frames[this.frames.length - 1];
    if (last && frame.t < last.t) this.reset();
    const prev = this.frames[this.frames.length - 1];
    if (prev && frame.t === prev.t) {
      // Paused, or a change applied between two steps: the newest state at the same time.
      this.frames[this.frames.length - 1] = frame;
      this.changed = true;
      return;
    }
    if (prev) {
      const dt = frame.t - prev.t;
      this.period = this.period == null ? dt : 0.9 * this.period + 0.1 * dt;
    }
    const h = this.history;
    if (h.length && now - h[h.length - 1][1] > GAP_MS) h.length = 0;
    h.push([frame.t, now]);
    if (h.length > HISTORY) h.shift();
    // Episode time per wall ms over the history (bunched arrivals average out); until it
    // spans 100 ms, the previous estimate stands.
    const span = h[h.length - 1][1] - h[0][1];
    if (span >= 100) this.rate = (h[h.length - 1][0] - h[0][0]) / span;
    this.frames.push(frame);
    if (this.tau == null) this.tau = frame.t;
    this.changed = true;
  }

  // Whether τ is behind the newest frame (more to show as time passes).
  get behind() {
    const last = this.frames[this.frames.length - 1];
    return !!last && this.tau < last.t;
  }

  sample(now) {
    const n = this.frames.length;
    if (!n) return null;
    const newest = this.frames[n - 1];
    const before = this.tau;
    const dt = this.at == null ? 0 : Math.max(0, now - this.at);
    this.at = now;
    if (this.period != null && this.rate != null) {
      const target = TARGET_FRAMES * this.period;
      let tau = this.tau + dt * this.rate;
      const lag = newest.t - tau;
      if (lag > MAX_FRAMES * this.period) tau = newest.t - target;
      else tau += (lag - target) * Math.min(1, dt / SETTLE_MS);
      this.tau = Math.min(newest.t, Math.max(this.tau, tau));
    } else {
      this.tau = newest.t;
    }
    // Drop the frames wholly behind τ (keep the last one at or before it).
    let k = 0;
    while (k + 1 < this.frames.length && this.frames[k + 1].t <= this.tau) k++;
    if (k) this.frames.splice(0, k);
    if (this.tau === before && !this.changed) return null;
    this.changed = false;
    const a = this.frames[0];
    const b = this.frames[1];
    if (!b || this.tau <= a.t) return { ...a, t: Math.max(a.t, this.tau) };
    return interpolate(a, b, (this.tau - a.t) / (b.t - a.t), this.tau);
  }
}

const lerp = (x, y, s) => x + (y - x) * s;
const lerpArray = (x, y, s) => x.map((v, i) => lerp(v, y[i], s));

// Unit quaternions [w, x, y, z]: the normalised lerp along the shorter arc.
function nlerp(p, q, s) {
  const sign = p[0] * q[0] + p[1] * q[1] + p[2] * q[2] + p[3] * q[3] < 0 ? -1 : 1;
  const r = p.map((v, i) => lerp(v, sign * q[i], s));
  const len = Math.hypot(...r) || 1;
  return r.map((v) => v / len);
}

// The state a fraction s of the way from frame a to frame b (shown at episode time t).
export function interpolate(a, b, s, t) {
  const next = new Map(b.things.map((th) => [th.name, th]));
  const things = a.things.map((th) => {
    const to = next.get(th.name);
    if (!to || !th.pos || !to.pos) return th;
    const out = { ...th, pos: lerpArray(th.pos, to.pos, s) };
    if (th.quat && to.quat) out.quat = nlerp(th.quat, to.quat, s);
    return out;
  });
  const q = Array.isArray(a.q) && Array.isArray(b.q) && a.q.length === b.q.length ? lerpArray(a.q, b.q, s) : a.q;
  return { ...a, t, things, q };
}
