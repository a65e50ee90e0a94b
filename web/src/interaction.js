// Dragging things in the scene (the person in the loop): press on a block or a tray,
// move — the thing follows the pointer on the table top (a raycast onto the plane
// z = table top) — and release: over a tray the thing is relocated onto that tray, over
// a region into that region, elsewhere the drop point alone is sent (the server maps it
// or refuses with its reason). A press and release without moving selects the thing.
// Picking and the follow run on the main thread against view.js's copy of the things;
// the drawing worker is told (view.hold / view.showAt).
// Invariants: while a drag is on, the camera controls are off and frames do not move
// the dragged thing; every drop sends exactly one `relocate`.
import * as THREE from 'three';

export class DragInteraction {
  constructor(scene, { onDrop, onSelect }) {
    this.scene = scene;
    this.onDrop = onDrop;
    this.onSelect = onSelect;
    this.raycaster = new THREE.Raycaster();
    this.drag = null;
    // Capture on the container: the press is seen before the camera controls on the canvas.
    scene.container.addEventListener('pointerdown', (e) => this.down(e), { capture: true });
    window.addEventListener('pointermove', (e) => this.move(e));
    window.addEventListener('pointerup', (e) => this.up(e));
  }

  ndc(e) {
    const r = this.scene.canvas.getBoundingClientRect();
    return new THREE.Vector2(((e.clientX - r.left) / r.width) * 2 - 1, -((e.clientY - r.top) / r.height) * 2 + 1);
  }

  // The nearest thing under the pointer (its name), skipping `except`.
  thingAt(e, except) {
    this.raycaster.setFromCamera(this.ndc(e), this.scene.camera);
    return this.scene.thingHit(this.raycaster, except);
  }

  tablePoint(e) {
    this.raycaster.setFromCamera(this.ndc(e), this.scene.camera);
    const plane = new THREE.Plane(new THREE.Vector3(0, 0, 1), -this.scene.tableTop);
    const p = new THREE.Vector3();
    return this.raycaster.ray.intersectPlane(plane, p) ? p : null;
  }

  down(e) {
    if (e.button !== 0) return;
    const name = this.thingAt(e);
    if (!name) return;
    e.stopPropagation();
    e.preventDefault();
    this.scene.controls.enabled = false;
    const entry = this.scene.things.get(name);
    this.drag = { name, x: e.clientX, y: e.clientY, moved: false, z: entry.mesh.position.z, start: entry.mesh.position.toArray() };
    this.scene.hold(name);
  }

  move(e) {
    if (!this.drag) return;
    if (Math.hypot(e.clientX - this.drag.x, e.clientY - this.drag.y) > 4) this.drag.moved = true;
    const p = this.tablePoint(e);
    if (p) this.scene.showAt(this.drag.name, [p.x, p.y, this.drag.z + 0.03]);
  }

  up(e) {
    if (!this.drag) return;
    const d = this.drag;
    this.drag = null;
    this.scene.controls.enabled = true;
    this.scene.hold(null);
    if (!d.moved) {
      this.scene.showAt(d.name, d.start);
      this.onSelect(d.name);
      return;
    }
    const p = this.tablePoint(e);
    if (!p) {
      this.scene.showAt(d.name, d.start);
      return;
    }
    const onto = this.thingAt(e, d.name);
    const ontoKind = onto && this.scene.things.get(onto)?.info?.kind;
    const location = ontoKind === 'container' ? onto : this.scene.regionAt(p.x, p.y);
    const position = [p.x, p.y, this.scene.tableTop];
    this.scene.showAt(d.name, [p.x, p.y, d.z]);
    this.onDrop({ subject: d.name, location, position, start: d.start });
  }
}
