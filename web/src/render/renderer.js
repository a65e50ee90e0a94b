// The page's 3-D drawing, off the main thread: this runs in a dedicated Worker
// on the scene canvas's OffscreenCanvas (render/entry.js), or on the main thread as the
// fallback where that is unavailable (render/link.js). It owns the three.js scene — the
// table, the regions, the things, the UR5 (robot.js), the plan's arrows (arrows.js), the
// lit materials (material.js) — and draws it; the main thread keeps the camera, the
// labels (DOM), picking and everything else (../view.js) and sends what changed as
// messages, handled by handle(msg):
//   build {seq, scene}        hello.scene: rebuild everything; seq is echoed in `drawn`
//   frame {t, things, q, held} a frame's episode time, things (pos, quat, and
//                             class/kind/size/color for things added later) and the
//                             joint angles to show; frames are played out a little in the
//                             past, interpolated (playout.js)
//   camera {position, quaternion, fov, aspect, near, far}
//   size {width, height}      the canvas's CSS size (drawn at pixel ratio ≤ 1)
//   moves {actions}           the current plan's remaining actions (arrows)
//   hold {name|null}          the person holds this thing: frames do not move it
//   show {name, pos}          draw this thing at pos until a frame received after this
//                             message moves it
// and reports to `emit`: drawn {n, scale, seq, at (epoch ms)} after each draw, cost {ms, scale} once it
// is known (the time from the animation frame that drew to the next one: it includes
// the WebGL raster and, with software compositing, the canvas readback).
// Drawing is on demand: only after a message changed something or while the playout is
// behind the newest frame, at most once per animation frame. While the scene keeps changing, the drawing-buffer scale follows what
// a frame costs: over the 30-frames budget for five frames running it steps down by 0.25
// (to 0.5 at least), well under it for 30 frames it steps back up; once the scene has
// been still for SETTLE_MS one frame is drawn at full resolution.
// Invariants: `things` holds exactly the things of the frame shown (or of build before
// the first frame); once frames stop the newest is shown; a still scene is shown at
// scale 1; every draw is reported.
import * as THREE from 'three';
import { litMaterial } from './material.js';
import { Robot } from './robot.js';
import { PlanArrows } from './arrows.js';
import { FramePlayout } from './playout.js';
import { thingObject, UNKNOWN_THING } from '../shapes.js';

const BUDGET_MS = 1000 / 30;
const MIN_SCALE = 0.5;
const SETTLE_MS = 250;

export class Renderer {
  // canvas: an OffscreenCanvas (worker) or an HTMLCanvasElement (fallback); emit(msg).
  constructor(canvas, emit, raf) {
    this.emit = emit;
    this.raf = raf;
    this.gl = new THREE.WebGLRenderer({ canvas, antialias: false });
    this.gl.setPixelRatio(1);
    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color('#eef1f4');
    this.camera = new THREE.PerspectiveCamera(40, 1, 0.01, 50);
    this.world = new THREE.Group();
    this.scene.add(this.world);
    // No three.js lights: the lit materials (material.js) carry the light rig themselves.
    this.things = new Map(); // name -> {mesh, info, pos}
    this.infos = new Map(); // name -> {class, kind, size, color}
    this.regions = [];
    this.tableTop = 0;
    this.arrows = new PlanArrows(this);
    this.robot = null;
    this.held = null; // the thing the person holds
    this.playout = new FramePlayout();
    this.received = 0; // frames received (their seq)
    this.pins = new Map(); // name -> {pos, seq}: shown at pos until a frame after seq is shown
    this.seq = -1; // of the last build
    this.drawn = 0;
    this.dirty = false;
    this.changedAt = 0;
    this.motionScale = 1;
    this.cost = { ema: 0, n: 0 };
    this.lastDraw = null; // {at, scale} of the last drawn animation frame, until the next one
    this.scheduled = false;
  }

  handle(m) {
    switch (m.type) {
      case 'build':
        this.build(m.scene, m.seq);
        break;
      case 'frame':
        this.playout.push({ t: m.t ?? 0, things: m.things, q: m.q, held: m.held, seq: ++this.received }, performance.now());
        break;
      case 'camera': {
        const c = this.camera;
        c.position.fromArray(m.position);
        c.quaternion.fromArray(m.quaternion);
        Object.assign(c, { fov: m.fov, aspect: m.aspect, near: m.near, far: m.far });
        c.updateProjectionMatrix();
        break;
      }
      case 'size':
        this.gl.setSize(m.width, m.height, false);
        break;
      case 'moves':
        this.arrows.setMoves(m.actions);
        break;
      case 'hold':
        this.held = m.name;
        break;
      case 'show': {
        const e = this.things.get(m.name);
        if (e) e.mesh.position.fromArray(m.pos);
        this.pins.set(m.name, { pos: m.pos, seq: this.received });
        break;
      }
      default:
        return;
    }
    this.invalidate();
  }

  // Something shown changed: draw at the next animation frame.
  invalidate() {
    this.dirty = true;
    this.changedAt = performance.now();
    this.schedule();
  }

  schedule() {
    if (this.scheduled) return;
    this.scheduled = true;
    this.raf(() => this.tick());
  }

  build(scene, seq) {
    this.seq = seq;
    this.playout.reset();
    this.pins.clear();
    this.world.clear();
    this.things.clear();
    this.infos.clear();
    this.classes = new Map(scene.classes.map((c) => [c.name, c]));
    const t = scene.table;
    this.tableTop = t.center[2] + t.size[2] / 2;
    const table = new THREE.Mesh(new THREE.BoxGeometry(...t.size), litMaterial('#c8b79a'));
    table.position.set(...t.center);
    this.world.add(table);
    this.regions = scene.regions;
    for (const r of scene.regions) {
      const patch = new THREE.Mesh(
        new THREE.PlaneGeometry(r.size[0], r.size[1]),
        new THREE.MeshBasicMaterial({ color: r.color || '#5b8def', transparent: true, opacity: 0.3 }),
      );
      patch.position.set(r.center[0], r.center[1], this.tableTop + 0.001);
      this.world.add(patch);
      const edge = new THREE.LineSegments(
        new THREE.EdgesGeometry(new THREE.PlaneGeometry(r.size[0], r.size[1])),
        new THREE.LineBasicMaterial({ color: '#2f5fb3' }),
      );
      edge.position.copy(patch.position);
      this.world.add(edge);
    }
    for (const th of scene.things) {
      this.infos.set(th.name, th);
      this.place(th.name, th.pos || [0, 0, this.tableTop], [1, 0, 0, 0]);
      this.things.get(th.name).mesh.visible = !!th.pos;
    }
    this.robot = new Robot(this.world, scene.robot);
    this.arrows.setMoves([]);
  }

  place(name, pos, quat) {
    let entry = this.things.get(name);
    if (!entry) {
      const info = this.infos.get(name) || UNKNOWN_THING;
      const color = info.color || this.classes?.get(info.class)?.color || '#888888';
      entry = { mesh: thingObject(name, info, litMaterial(color)), info };
      this.world.add(entry.mesh);
      this.things.set(name, entry);
    }
    entry.mesh.visible = true;
    entry.mesh.position.fromArray(pos);
    entry.mesh.quaternion.set(quat[1], quat[2], quat[3], quat[0]);
    entry.pos = pos;
  }

  // The state to show (a frame, or between two): moves the things, creates the new ones,
  // removes the vanished ones, poses the arm.
  show(state) {
    const seen = new Set();
    for (const th of state.things) {
      if (th.class && !this.infos.has(th.name)) this.infos.set(th.name, { ...th, kind: th.kind || this.classes?.get(th.class)?.kind });
      seen.add(th.name);
      if (th.name === this.held) continue; // the person holds it
      const pin = this.pins.get(th.name);
      if (pin && state.seq <= pin.seq) {
        this.place(th.name, pin.pos, th.quat || [1, 0, 0, 0]);
        continue;
      }
      this.pins.delete(th.name);
      this.place(th.name, th.pos, th.quat || [1, 0, 0, 0]);
    }
    for (const [name, entry] of this.things) {
      if (seen.has(name)) continue;
      entry.mesh.removeFromParent();
      this.things.delete(name);
    }
    if (state.q) this.robot?.show(state.q, !!state.held);
  }

  // One animation frame: account for the last draw's cost, draw if needed, and keep
  // animation frames coming while a draw's cost is pending or a sharp frame is due.
  tick() {
    this.scheduled = false;
    const now = performance.now();
    if (this.lastDraw) {
      const ms = now - this.lastDraw.at;
      this.emit({ type: 'cost', ms, scale: this.lastDraw.scale });
      this.adapt(ms, this.lastDraw.scale);
      this.lastDraw = null;
    }
    const state = this.playout.sample(now);
    if (state) {
      this.show(state);
      this.dirty = true;
      this.changedAt = now;
    }
    let scale = this.motionScale;
    if (!this.dirty) {
      if (this.gl.getPixelRatio() === 1) return;
      if (now - this.changedAt < SETTLE_MS) return this.schedule();
      scale = 1; // still: one sharp frame
    }
    this.dirty = false;
    if (this.gl.getPixelRatio() !== scale) this.gl.setPixelRatio(scale);
    this.arrows.update();
    this.gl.render(this.scene, this.camera);
    this.drawn++;
    this.lastDraw = { at: now, scale };
    this.emit({ type: 'drawn', n: this.drawn, scale, seq: this.seq, at: performance.timeOrigin + now });
    this.schedule();
  }

  // A drawn frame cost `ms` at drawing-buffer scale `scale`: adapt the motion scale.
  adapt(ms, scale) {
    if (scale !== this.motionScale) return; // the still frame does not count
    const c = this.cost;
    c.ema = c.n ? 0.8 * c.ema + 0.2 * ms : ms;
    c.n++;
    let next = this.motionScale;
    if (c.n >= 5 && c.ema > BUDGET_MS * 1.1 && next > MIN_SCALE) next = Math.max(MIN_SCALE, next - 0.25);
    else if (c.n >= 30 && c.ema < BUDGET_MS * 0.6 && next < 1) next = Math.min(1, next + 0.25);
    if (next !== this.motionScale) {
      this.motionScale = next;
      this.cost = { ema: 0, n: 0 };
    }
  }
}
