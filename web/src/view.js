// The 3-D scene as the page's main thread knows it: what is where, the
// camera, the labels, and where a point is on the screen — everything but the drawing,
// which render/link.js hands to the drawing worker (render/renderer.js) as messages.
// The main thread keeps, per thing, an undrawn copy of its shape (shapes.js) at the
// position drawn, with its name label (DOM, CSS2D), so that picking (three.js raycasts),
// labels and window.rtamp.project are synchronous and exact; the camera and its orbit
// controls live here and every camera change is sent to the renderer. Things are kept
// by name and moved by `frame` messages (pos = the centre of the thing's base, quat =
// [w, x, y, z]); a thing missing from a frame is gone. Labels are re-placed at most once
// per animation frame, after something moved, and lifted so that none overlaps another.
// The first view holds the table and the arm at home.
// Invariants: `things` holds exactly the things of the last frame (or of hello before
// the first frame); the renderer got every change of things, camera and size made here,
// in order; a thing the person holds (`dragging`) is moved by the person only.
import * as THREE from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { CSS2DRenderer, CSS2DObject } from 'three/examples/jsm/renderers/CSS2DRenderer.js';
import { RenderLink } from './render/link.js';
import { thingObject, UNKNOWN_THING } from './shapes.js';
import { linkFrames, origin } from './kinematics.js';

const PICK = new THREE.MeshBasicMaterial(); // never drawn: picking only

// How far the arm's links reach beyond their frames' origins (m): a link's radius.
const ARM_PAD = 0.08;

// Moves labels up (margin-top; CSS2DRenderer owns their transform) until none overlaps
// another: the lowest on the screen keeps its place, each one above is lifted clear of
// those already placed.
function separateLabels(root) {
  const items = [];
  for (const el of root.children) {
    if (el.style.display === 'none') continue;
    el.style.marginTop = '0px';
    items.push({ el, r: el.getBoundingClientRect() });
  }
  items.sort((a, b) => b.r.bottom - a.r.bottom);
  const placed = [];
  for (const { el, r } of items) {
    let dy = 0;
    for (let moved = true; moved; ) {
      moved = false;
      for (const p of placed) {
        const top = r.top + dy, bottom = r.bottom + dy;
        if (r.left < p.right && r.right > p.left && top < p.bottom && bottom > p.top) {
          dy = p.top - r.bottom - 1;
          moved = true;
        }
      }
    }
    if (dy) el.style.marginTop = `${dy}px`;
    placed.push({ left: r.left, right: r.right, top: r.top + dy, bottom: r.bottom + dy });
  }
}

function label(text, cls) {
  const div = document.createElement('div');
  div.className = cls;
  div.textContent = text;
  return new CSS2DObject(div);
}

export class SceneView {
  // container: the scene's element; renderUrl: the drawing bundle (assets/render.js).
  constructor(container, renderUrl) {
    this.container = container;
    this.canvas = document.createElement('canvas');
    container.appendChild(this.canvas);
    this.labels = new CSS2DRenderer();
    this.labels.domElement.className = 'labels';
    container.appendChild(this.labels.domElement);
    this.scene = new THREE.Scene(); // not drawn: pick shapes and labels
    this.camera = new THREE.PerspectiveCamera(40, 1, 0.01, 50);
    this.camera.up.set(0, 0, 1);
    this.controls = new OrbitControls(this.camera, this.canvas);
    this.controls.enableDamping = false;
    this.controls.addEventListener('change', () => this.cameraChanged());
    this.things = new Map(); // name -> {mesh, info, pos, at}
    this.infos = new Map(); // name -> {class, kind, size, color}
    this.regions = [];
    this.tableTop = 0;
    this.seq = 0; // builds sent
    this.dragging = null;
    this.labelsDirty = true;
    // What the renderer reports: draws, the scale and seq of the last, draw costs (ms),
    // when each draw was made (epoch ms; the latest 20000 at most).
    this.drawn = 0;
    this.drawScale = 1;
    this.drawnSeq = -1;
    this.costs = [];
    this.drawTimes = [];
    this.drawScales = []; // the drawing-buffer scale of each of those draws
    this.link = new RenderLink(this.canvas, renderUrl, {
      onStats: (m) => this.stats(m),
      freshCanvas: () => this.freshCanvas(),
      size: () => this.size(),
    });
    this.resize();
    new ResizeObserver(() => this.resize()).observe(container);
  }

  stats(m) {
    if (m.type === 'drawn') {
      this.drawn = m.n;
      this.drawScale = m.scale;
      this.drawnSeq = m.seq;
      if (this.drawTimes.length >= 20000) {
        this.drawTimes.splice(0, 10000);
        this.drawScales.splice(0, 10000);
      }
      this.drawTimes.push(m.at);
      this.drawScales.push(m.scale);
    } else if (m.type === 'cost') {
      if (this.costs.length >= 20000) this.costs.splice(0, 10000);
      this.costs.push(m.ms);
    }
  }

  // The drawing moved to the main thread after the canvas was transferred: a new canvas.
  freshCanvas() {
    const fresh = document.createElement('canvas');
    fresh.style.cssText = this.canvas.style.cssText;
    this.canvas.replaceWith(fresh);
    this.canvas = fresh;
    this.controls.disconnect();
    this.controls.connect(fresh);
    return fresh;
  }

  size() {
    return { width: Math.max(1, this.container.clientWidth), height: Math.max(1, this.container.clientHeight) };
  }

  resize() {
    const { width: w, height: h } = this.size();
    this.canvas.style.width = w + 'px';
    this.canvas.style.height = h + 'px';
    this.labels.setSize(w, h);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.link.post({ type: 'size', width: w, height: h });
    this.cameraChanged();
  }

  cameraChanged() {
    const c = this.camera;
    c.updateMatrixWorld();
    this.link.post({ type: 'camera', position: c.position.toArray(), quaternion: c.quaternion.toArray(), fov: c.fov, aspect: c.aspect, near: c.near, far: c.far });
    this.labelsDirty = true;
  }

  // Builds the static scene from hello.scene and shows the things present at start.
  build(scene) {
    for (const o of [...this.scene.children]) this.removeObject(o);
    this.things.clear();
    this.infos.clear();
    this.dragging = null;
    this.classes = new Map(scene.classes.map((c) => [c.name, c]));
    const t = scene.table;
    this.tableTop = t.center[2] + t.size[2] / 2;
    this.regions = scene.regions;
    for (const r of scene.regions) {
      const l = label(r.name, 'region-label');
      l.position.set(r.center[0] - r.size[0] / 2 + 0.03, r.center[1] + r.size[1] / 2 - 0.03, this.tableTop + 0.002);
      this.scene.add(l);
    }
    this.movesKey = null;
    this.link.post({ type: 'build', seq: ++this.seq, scene });
    for (const th of scene.things) {
      this.infos.set(th.name, th);
      this.place(th.name, th.pos || [0, 0, this.tableTop], [1, 0, 0, 0], th.at);
      this.things.get(th.name).mesh.visible = !!th.pos;
    }
    // Look from the side opposite the robot, ~37° down, far enough that the table and
    // the arm at home (its link frames, padded by the links' radius) are all in view.
    const c = t.center, base = scene.robot.base;
    const dir = new THREE.Vector3(c[0] - base[0], c[1] - base[1], 0);
    if (dir.lengthSq() < 1e-6) dir.set(1, 0, 0);
    dir.normalize();
    const box = new THREE.Box3();
    for (const sx of [-0.5, 0.5]) for (const sy of [-0.5, 0.5]) box.expandByPoint(new THREE.Vector3(c[0] + sx * t.size[0], c[1] + sy * t.size[1], this.tableTop));
    for (const p of linkFrames(scene.robot, scene.robot.home).map(origin)) box.expandByPoint(new THREE.Vector3(...p).addScalar(ARM_PAD)).expandByPoint(new THREE.Vector3(...p).addScalar(-ARM_PAD));
    const sphere = box.getBoundingSphere(new THREE.Sphere());
    const vfov = THREE.MathUtils.degToRad(this.camera.fov);
    const hfov = 2 * Math.atan(Math.tan(vfov / 2) * this.camera.aspect);
    const dist = sphere.radius / Math.sin(Math.min(vfov, hfov) / 2);
    const view = new THREE.Vector3(dir.x * 0.8, dir.y * 0.8, 0.6).normalize().multiplyScalar(dist);
    this.camera.position.copy(sphere.center).add(view);
    this.controls.target.copy(sphere.center);
    this.controls.update();
    this.cameraChanged();
  }

  removeObject(o) {
    o.traverse((x) => x.isCSS2DObject && x.element.remove());
    o.removeFromParent();
  }

  place(name, pos, quat, at) {
    let entry = this.things.get(name);
    if (!entry) {
      const info = this.infos.get(name) || UNKNOWN_THING;
      const mesh = thingObject(name, info, PICK);
      const l = label(name, 'thing-label');
      l.position.set(0, 0, (info.size || UNKNOWN_THING.size)[2] + 0.02);
      mesh.add(l);
      this.scene.add(mesh);
      entry = { mesh, info };
      this.things.set(name, entry);
    }
    entry.mesh.visible = true;
    entry.mesh.position.fromArray(pos);
    entry.mesh.quaternion.set(quat[1], quat[2], quat[3], quat[0]);
    entry.at = at;
    entry.pos = pos;
  }

  // A frame: moves the things (creates the new ones, removes the vanished ones) and has
  // the renderer draw them with the arm at joint angles q.
  frame(f, q) {
    const seen = new Set();
    for (const th of f.things) {
      if (th.class && !this.infos.has(th.name)) this.infos.set(th.name, { ...th, kind: th.kind || this.classes?.get(th.class)?.kind });
      seen.add(th.name);
      if (th.name === this.dragging) continue; // the person holds it
      this.place(th.name, th.pos, th.quat || [1, 0, 0, 0], th.at);
    }
    for (const [name, entry] of this.things) {
      if (seen.has(name)) continue;
      this.removeObject(entry.mesh);
      this.things.delete(name);
    }
    this.labelsDirty = true;
    this.link.post({ type: 'frame', t: f.t, things: f.things, q, held: f.held ?? null });
  }

  // The current plan's remaining moves, drawn as arrows.
  setMoves(actions) {
    const key = actions.join('\n');
    if (key === this.movesKey) return;
    this.movesKey = key;
    this.link.post({ type: 'moves', actions });
  }

  // The person holds a thing (name), or lets go (null): frames do not move a held thing.
  hold(name) {
    this.dragging = name;
    this.link.post({ type: 'hold', name });
  }

  // Shows a thing at pos (a drag), until a frame moves it.
  showAt(name, pos) {
    const e = this.things.get(name);
    if (!e) return;
    e.mesh.position.fromArray(pos);
    this.labelsDirty = true;
    this.link.post({ type: 'show', name, pos });
  }

  // Re-places the labels if something moved (once per animation frame).
  updateLabels() {
    if (!this.labelsDirty) return;
    this.labelsDirty = false;
    this.labels.render(this.scene, this.camera);
    separateLabels(this.labels.domElement);
  }

  // The nearest thing hit by the raycaster (set from this camera), skipping `except`.
  thingHit(raycaster, except) {
    this.scene.updateMatrixWorld();
    const meshes = [...this.things.values()].filter((t) => t.mesh.visible && t.mesh.userData.thing !== except).map((t) => t.mesh);
    const hit = raycaster.intersectObjects(meshes, true)[0];
    return hit ? hit.object.userData.thing : null;
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
    const rect = this.canvas.getBoundingClientRect();
    return { x: rect.left + ((v.x + 1) / 2) * rect.width, y: rect.top + ((1 - v.y) / 2) * rect.height };
  }
}
