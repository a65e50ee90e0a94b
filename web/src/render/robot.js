// The UR5 drawn from its kinematics (../kinematics.js), in the drawing worker: a sphere
// at every joint frame's origin, a cylinder between consecutive origins, and a
// two-finger gripper along the tool axis (closed while it holds a thing). The joint
// angles to show come from the main thread (../arm.js: streamed, or solved for the
// symbolic world's tool point).
// Invariant: the drawn tool point is linkFrames(robot, q)[7]'s origin for the q shown.
import * as THREE from 'three';
import { linkFrames, origin } from '../kinematics.js';
import { litMaterial } from './material.js';

const up = new THREE.Vector3(0, 1, 0);

export class Robot {
  constructor(parent, robot) {
    this.robot = robot;
    this.group = new THREE.Group();
    parent.add(this.group);
    const metal = litMaterial('#9aa3ad');
    const joint = litMaterial('#2b4f81');
    this.joints = [];
    this.links = [];
    for (let i = 0; i < 8; i++) {
      const s = new THREE.Mesh(new THREE.SphereGeometry(i === 7 ? 0.012 : 0.045, 20, 12), i === 7 ? metal : joint);
      this.group.add(s);
      this.joints.push(s);
    }
    for (let i = 0; i < 7; i++) {
      const c = new THREE.Mesh(new THREE.CylinderGeometry(0.035, 0.035, 1, 16), metal);
      this.group.add(c);
      this.links.push(c);
    }
    const base = new THREE.Mesh(new THREE.CylinderGeometry(0.075, 0.09, 0.02, 24), joint);
    base.quaternion.setFromUnitVectors(up, new THREE.Vector3(0, 0, 1));
    base.position.set(...robot.base);
    this.group.add(base);
    this.fingers = [0, 1].map(() => {
      const f = new THREE.Mesh(new THREE.BoxGeometry(0.012, 0.012, 0.05), metal);
      this.group.add(f);
      return f;
    });
    this.q = [...robot.home];
    this.show(this.q);
  }

  // One cylinder from a to b.
  static stretch(mesh, a, b) {
    const va = new THREE.Vector3(...a), vb = new THREE.Vector3(...b);
    const d = vb.clone().sub(va);
    const len = d.length();
    mesh.visible = len > 1e-4;
    if (!mesh.visible) return;
    mesh.position.copy(va).add(vb).multiplyScalar(0.5);
    mesh.scale.set(1, len, 1);
    mesh.quaternion.setFromUnitVectors(up, d.normalize());
  }

  // Shows the joint angles q; held: whether the gripper holds a thing.
  show(q, held = this.held) {
    this.q = q;
    this.held = held;
    const F = linkFrames(this.robot, q);
    const pts = F.map(origin);
    pts.forEach((p, i) => this.joints[i].position.set(...p));
    for (let i = 0; i < 7; i++) Robot.stretch(this.links[i], pts[i], pts[i + 1]);
    // Fingers: either side of the tool point along the tool's y axis, hanging along its z.
    const T = F[7];
    const y = [T[1], T[5], T[9]], z = [T[2], T[6], T[10]];
    const open = this.held ? 0.024 : 0.04;
    this.fingers.forEach((f, k) => {
      const s = k ? open : -open;
      f.position.set(pts[7][0] + s * y[0] - 0.01 * z[0], pts[7][1] + s * y[1] - 0.01 * z[1], pts[7][2] + s * y[2] - 0.01 * z[2]);
      f.quaternion.setFromRotationMatrix(new THREE.Matrix4().set(T[0], T[1], T[2], 0, T[4], T[5], T[6], 0, T[8], T[9], T[10], 0, 0, 0, 0, 1));
    });
    this.toolPoint = pts[7];
  }
}
