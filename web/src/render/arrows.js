// The planned next moves as arrows in the scene: for the latest `plan` log record, each
// action "move(THING, TO)" not yet finished becomes an arrow from THING's current place
// to TO (a region's centre, or a container's current position), the next one drawn
// strongest. Part of the drawing (renderer.js, in the drawing worker): `scene` is the
// Renderer. Invariant: arrows are recomputed from the scene every drawn frame, so they
// follow the things as they move; at most `max` arrows are shown.
import * as THREE from 'three';

export function parseMove(action) {
  const m = /^\s*move\(\s*([^,\s]+)\s*,\s*([^)\s]+)\s*\)\s*$/.exec(action);
  return m ? { thing: m[1], to: m[2] } : null;
}

export class PlanArrows {
  constructor(scene, max = 4) {
    this.scene = scene;
    this.max = max;
    this.group = new THREE.Group();
    scene.world.parent.add(this.group);
    this.arrows = [];
    this.moves = [];
  }

  // The remaining moves of the current plan (strings from the plan record).
  setMoves(actions) {
    this.moves = actions.map(parseMove).filter(Boolean);
    this.scene.invalidate();
  }

  target(to) {
    const r = this.scene.regions.find((x) => x.name === to);
    if (r) return [r.center[0], r.center[1], this.scene.tableTop + 0.01];
    const c = this.scene.things.get(to);
    return c ? c.pos : null;
  }

  update() {
    let n = 0;
    for (const mv of this.moves) {
      if (n >= this.max) break;
      const from = this.scene.things.get(mv.thing)?.pos, to = this.target(mv.to);
      if (!from || !to) continue;
      const a = new THREE.Vector3(from[0], from[1], from[2] + 0.05), b = new THREE.Vector3(to[0], to[1], to[2] + 0.05);
      const d = b.clone().sub(a);
      const len = d.length();
      if (len < 0.02) continue;
      if (!this.arrows[n]) {
        this.arrows[n] = new THREE.ArrowHelper(new THREE.Vector3(1, 0, 0), a, 1, '#e67e22', 0.04, 0.025);
        this.group.add(this.arrows[n]);
      }
      const arrow = this.arrows[n];
      arrow.visible = true;
      arrow.position.copy(a);
      arrow.setDirection(d.normalize());
      arrow.setLength(len, Math.min(0.05, len * 0.4), 0.025);
      arrow.setColor(n === 0 ? '#e67e22' : '#f5c28a');
      n++;
    }
    for (let i = n; i < this.arrows.length; i++) this.arrows[i].visible = false;
  }
}
