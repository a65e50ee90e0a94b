// The shape of a thing in the scene, shared by the two sides of the page that need it:
// the renderer (render/renderer.js, in the drawing worker) draws it with lit materials,
// the main thread (view.js) keeps an undrawn copy to pick things under the pointer.
// A block is a box, a tray a floor with four rims; the origin is the centre of the
// thing's base (frame `pos`, docs/serve.md). Invariant: both sides build the same
// geometry from the same `info` (class, kind, size), so a pick hits what is drawn.
import * as THREE from 'three';

const RIM = 0.006; // a tray's floor thickness and rim width (m)

// A three.js object for a thing of `info` ({kind, size}) with `material` on every part;
// every part has userData.thing = name.
export function thingObject(name, info, material) {
  const [sx, sy, sz] = info.size || [0.04, 0.04, 0.04];
  let obj;
  if (info.kind === 'container') {
    obj = new THREE.Group();
    const floor = new THREE.Mesh(new THREE.BoxGeometry(sx, sy, RIM), material);
    floor.position.z = RIM / 2;
    obj.add(floor);
    for (const [dx, dy, lx, ly] of [
      [0, sy / 2 - RIM / 2, sx, RIM],
      [0, -sy / 2 + RIM / 2, sx, RIM],
      [sx / 2 - RIM / 2, 0, RIM, sy],
      [-sx / 2 + RIM / 2, 0, RIM, sy],
    ]) {
      const rim = new THREE.Mesh(new THREE.BoxGeometry(lx, ly, sz), material);
      rim.position.set(dx, dy, sz / 2);
      obj.add(rim);
    }
  } else {
    obj = new THREE.Mesh(new THREE.BoxGeometry(sx, sy, sz).translate(0, 0, sz / 2), material);
  }
  obj.traverse((o) => (o.userData.thing = name));
  return obj;
}

// The thing's info when neither hello nor a frame described it.
export const UNKNOWN_THING = { class: '?', kind: 'object', size: [0.04, 0.04, 0.04] };
