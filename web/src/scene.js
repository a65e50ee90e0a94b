// The 3-D scene of issue 14: the table, the regions with their names, the trays and the
// blocks in their classes' colours, as three.js objects in the world frame (z up, metres,
// the table top at z = tableTop). Things are kept by name and moved by `frame` messages
// (pos = the centre of the thing's base, quat = [w, x, y, z]); a thing missing from a
// frame is gone. Meshes have their origin at the base centre.
// Drawing is on demand (issue 14's bar: 30 frames a second, also with software WebGL):
// draw() renders only after invalidate() (a frame moved things or the arm, the camera
// moved, a drag, a resize), at most once per animation frame. While things keep
// changing, the canvas's drawing-buffer scale adapts to what a frame costs (the time
// from a drawing animation frame to the next one): over the 30-frames budget for five
// frames running it steps down by 0.25 (to 0.5 at least), well under it for 30 frames it
// steps back up; once the scene has been still for SETTLE_MS one frame is drawn at full
// resolution. Labels are DOM (CSS2D) and stay sharp at any scale.
// Invariants: `things` holds exactly the things of the last frame (or of hello before
// the first frame); every thing mesh has userData.thing = its name; a still scene is
// shown at scale 1.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { CSS2DRenderer, CSS2DObject } from 'three/examples/jsm/renderers/CSS2DRenderer.js';
import { litMaterial } from './material.js';

const BUDGET_MS = 1000 / 30;
const MIN_SCALE = 0.5;
const SETTLE_MS = 250;

function label(text, cls) {
  const div = document.createElement('div');
  div.className = cls;
  div.textContent = text;
  return new CSS2DObject(div);
}

export class Scene {
  constructor(container) {
    this.container = container;
    this.renderer = new THREE.WebGLRenderer({ antialias: false });
    this.renderer.setPixelRatio(1);
    container.appendChild(this.renderer.domElement);
    this.labels = new CSS2DRenderer();
    this.labels.domElement.className = 'labels';
    container.appendChild(this.labels.domElement);

    this.scene = new THREE.Scene();
    this.scene.background = new THREE.Color('#eef1f4');
    this.camera = new THREE.PerspectiveCamera(40, 1, 0.01, 50);
    this.camera.up.set(0, 0, 1);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.enableDamping = false;
    this.controls.addEventListener('change', () => this.invalidate());
    this.dirty = true;
    this.changedAt = 0;
    this.motionScale = 1; // the drawing-buffer scale while the scene changes
    this.cost = { ema: 0, n: 0 };
    this.lastDraw = null; // {at, scale} of the last drawn animation frame, until the next one
    // No three.js lights: the lit materials (material.js) carry the light rig themselves.

    this.things = new Map(); // name -> {mesh, info}
    this.infos = new Map(); // name -> {class, kind, size, color}
    this.regions = [];
    this.world = new THREE.Group();
    this.scene.add(this.world);
    this.resize();
    new ResizeObserver(() => this.resize()).observe(container);
  }

  resize() {
    const w = Math.max(1, this.container.clientWidth), h = Math.max(1, this.container.clientHeight);
    this.renderer.setSize(w, h, false);
    this.renderer.domElement.style.width = w + 'px';
    this.renderer.domElement.style.height = h + 'px';
    this.labels.setSize(w, h);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.invalidate();
  }

  // Something shown changed: draw at the next animation frame.
  invalidate() {
    this.dirty = true;
    this.changedAt = performance.now();
  }

  // Builds the static scene from hello.scene and shows the things present at start.
  build(scene) {
    this.world.clear();
    for (const { mesh } of this.things.values()) mesh.removeFromParent();
    this.things.clear();
    this.infos.clear();
    this.classes = new Map(scene.classes.map((c) => [c.name, c]));
    const t = scene.table;
    this.tableTop = t.center[2] + t.size[2] / 2;
    const table = new THREE.Mesh(
      new THREE.BoxGeometry(...t.size),
      litMaterial('#c8b79a'),
    );
    table.position.set(...t.center);
    table.name = 'table';
    this.world.add(table);
    this.table = table;

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
      const l = label(r.name, 'region-label');
      l.position.set(r.center[0] - r.size[0] / 2 + 0.03, r.center[1] + r.size[1] / 2 - 0.03, this.tableTop + 0.002);
      this.world.add(l);
    }
    for (const th of scene.things) {
      this.infos.set(th.name, th);
      this.place(th.name, th.pos || [0, 0, this.tableTop], [1, 0, 0, 0], th.at);
      this.things.get(th.name).mesh.visible = !!th.pos;
    }
    // Look at the table's centre from the side opposite the robot.
    const c = t.center, base = scene.robot.base;
    const dir = new THREE.Vector3(c[0] - base[0], c[1] - base[1], 0);
    if (dir.lengthSq() < 1e-6) dir.set(1, 0, 0);
    dir.normalize();
    const reach = Math.max(t.size[0], t.size[1]);
    this.camera.position.set(c[0] + dir.x * reach * 1.05, c[1] + dir.y * reach * 1.05, this.tableTop + reach * 0.8);
    this.controls.target.set(c[0] - dir.x * 0.05, c[1] - dir.y * 0.05, this.tableTop + 0.1);
    this.controls.update();
    this.invalidate();
  }

  // A mesh for a thing: a block is a box, a tray a floor with four rims.
  makeMesh(name, info) {
    const color = info.color || this.classes?.get(info.class)?.color || '#888888';
    const mat = litMaterial(color);
    const [sx, sy, sz] = info.size || [0.04, 0.04, 0.04];
    let mesh;
    if (info.kind === 'container') {
      mesh = new THREE.Group();
      const floor = new THREE.Mesh(new THREE.BoxGeometry(sx, sy, 0.006), mat);
      floor.position.z = 0.003;
      mesh.add(floor);
      const w = 0.006;
      for (const [dx, dy, lx, ly] of [
        [0, sy / 2 - w / 2, sx, w],
        [0, -sy / 2 + w / 2, sx, w],
        [sx / 2 - w / 2, 0, w, sy],
        [-sx / 2 + w / 2, 0, w, sy],
      ]) {
        const rim = new THREE.Mesh(new THREE.BoxGeometry(lx, ly, sz), mat);
        rim.position.set(dx, dy, sz / 2);
        mesh.add(rim);
      }
    } else {
      mesh = new THREE.Mesh(new THREE.BoxGeometry(sx, sy, sz).translate(0, 0, sz / 2), mat);
    }
    mesh.traverse((o) => (o.userData.thing = name));
    mesh.userData.thing = name;
    const l = label(name, 'thing-label');
    l.position.set(0, 0, sz + 0.02);
    mesh.add(l);
    this.world.add(mesh);
    return mesh;
  }

  place(name, pos, quat, at) {
    let entry = this.things.get(name);
    if (!entry) {
      const info = this.infos.get(name) || { class: '?', kind: 'object', size: [0.04, 0.04, 0.04] };
      entry = { mesh: this.makeMesh(name, info), info };
      this.things.set(name, entry);
    }
    entry.mesh.visible = true;
    entry.mesh.position.set(...pos);
    entry.mesh.quaternion.set(quat[1], quat[2], quat[3], quat[0]);
    entry.at = at;
    entry.pos = pos;
  }

  // Applies a frame's things: moves, creates the new ones, removes the vanished ones.
  applyThings(list) {
    this.invalidate();
    const seen = new Set();
    for (const th of list) {
      if (th.class && !this.infos.has(th.name)) this.infos.set(th.name, { ...th, kind: th.kind || this.classes?.get(th.class)?.kind });
      seen.add(th.name);
      if (th.name === this.dragging) continue; // the person holds it
      this.place(th.name, th.pos, th.quat || [1, 0, 0, 0], th.at);
    }
    for (const [name, entry] of this.things) {
      if (seen.has(name)) continue;
      entry.mesh.traverse((o) => o.isCSS2DObject && o.element.remove());
      entry.mesh.removeFromParent();
      this.things.delete(name);
    }
  }

  // The region whose footprint contains the point (x, y), or null.
  regionAt(x, y) {
    for (const r of this.regions)
      if (Math.abs(x - r.center[0]) <= r.size[0] / 2 && Math.abs(y - r.center[1]) <= r.size[1] / 2) return r.name;
    return null;
  }

  // Screen pixel (page coordinates) of a world point.
  project(p) {
    const v = new THREE.Vector3(...p).project(this.camera);
    const rect = this.renderer.domElement.getBoundingClientRect();
    return { x: rect.left + ((v.x + 1) / 2) * rect.width, y: rect.top + ((1 - v.y) / 2) * rect.height };
  }

  // Called every animation frame (now: its timestamp, ms); draws when needed (see the
  // header). Returns whether it drew; beforeDraw() runs just before a draw.
  draw(now, beforeDraw) {
    if (this.lastDraw) {
      this.adapt(now - this.lastDraw.at, this.lastDraw.scale);
      this.lastDraw = null;
    }
    let scale = this.motionScale;
    if (!this.dirty) {
      if (this.renderer.getPixelRatio() === 1 || performance.now() - this.changedAt < SETTLE_MS) return false;
      scale = 1; // still: one sharp frame
    }
    this.dirty = false;
    if (this.renderer.getPixelRatio() !== scale) this.renderer.setPixelRatio(scale);
    beforeDraw?.();
    this.renderer.render(this.scene, this.camera);
    this.labels.render(this.scene, this.camera);
    this.lastDraw = { at: now, scale };
    return true;
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
