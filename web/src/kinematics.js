// UR5 forward kinematics from the standard Denavit–Hartenberg table the server sends
// in `hello.scene.robot.dh` (the same table as src/rtamp/robot/ur5_kinematics.cpp):
// A_i = Rz(θ_i) · Tz(d_i) · Tx(a_i) · Rx(α_i), flange = A_1 ··· A_6, the robot base at
// `base` turned by `yaw` about world z, the tool `toolOffset` along the flange's z.
// For the symbolic world (no joint angles) reachTool() finds angles that put the tool at
// a point with the tool pointing down, by damped least squares from the last solution.
// Invariants: all matrices are 4x4 row-major arrays of 16 numbers in world frame (z up).

function mul(A, B) {
  const C = new Array(16).fill(0);
  for (let r = 0; r < 4; r++)
    for (let c = 0; c < 4; c++) {
      let s = 0;
      for (let k = 0; k < 4; k++) s += A[r * 4 + k] * B[k * 4 + c];
      C[r * 4 + c] = s;
    }
  return C;
}

function dhTransform(theta, d, a, alpha) {
  const ct = Math.cos(theta), st = Math.sin(theta), ca = Math.cos(alpha), sa = Math.sin(alpha);
  return [ct, -st * ca, st * sa, a * ct, st, ct * ca, -ct * sa, a * st, 0, sa, ca, d, 0, 0, 0, 1];
}

export function basePose(robot) {
  const c = Math.cos(robot.yaw || 0), s = Math.sin(robot.yaw || 0);
  const [x, y, z] = robot.base;
  return [c, -s, 0, x, s, c, 0, y, 0, 0, 1, z, 0, 0, 0, 1];
}

// Frames 0..6 (base .. flange) and the tool frame, world coordinates.
export function linkFrames(robot, q) {
  const { d, a, alpha } = robot.dh;
  const frames = [basePose(robot)];
  for (let i = 0; i < 6; i++) frames.push(mul(frames[i], dhTransform(q[i], d[i], a[i], alpha[i])));
  const off = robot.tool_offset ?? 0.15;
  frames.push(mul(frames[6], [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, off, 0, 0, 0, 1]));
  return frames;
}

export const origin = (M) => [M[3], M[7], M[11]];
export const zAxis = (M) => [M[2], M[6], M[10]];

// The task error of q: tool position − target (3) and tool z − (0,0,−1) (x, y parts).
function taskError(robot, q, target) {
  const T = linkFrames(robot, q)[7];
  const p = origin(T), z = zAxis(T);
  return [p[0] - target[0], p[1] - target[1], p[2] - target[2], 0.3 * z[0], 0.3 * z[1], 0.3 * (z[2] + 1)];
}

// Solves (JJᵀ + λ²I) y = e for the 6x6 case by Gaussian elimination.
function solve(M, e) {
  const n = e.length;
  const A = M.map((row, i) => [...row, e[i]]);
  for (let c = 0; c < n; c++) {
    let p = c;
    for (let r = c + 1; r < n; r++) if (Math.abs(A[r][c]) > Math.abs(A[p][c])) p = r;
    [A[c], A[p]] = [A[p], A[c]];
    const v = A[c][c] || 1e-12;
    for (let r = 0; r < n; r++) {
      if (r === c) continue;
      const f = A[r][c] / v;
      for (let k = c; k <= n; k++) A[r][k] -= f * A[c][k];
    }
  }
  return A.map((row, i) => row[n] / (row[i] || 1e-12));
}

// Joint angles putting the tool at `target` (pointing down), starting from `q0`.
export function reachTool(robot, target, q0, iterations = 40) {
  const q = [...q0];
  const h = 1e-5, lambda = 0.05;
  for (let it = 0; it < iterations; it++) {
    const e = taskError(robot, q, target);
    if (Math.hypot(...e) < 1e-4) break;
    const J = e.map(() => new Array(6).fill(0));
    for (let j = 0; j < 6; j++) {
      const qp = [...q];
      qp[j] += h;
      const ep = taskError(robot, qp, target);
      for (let i = 0; i < 6; i++) J[i][j] = (ep[i] - e[i]) / h;
    }
    const JJt = J.map((ri, i) => J.map((rk, k) => ri.reduce((s, v, j) => s + v * rk[j], 0) + (i === k ? lambda * lambda : 0)));
    const y = solve(JJt, e);
    for (let j = 0; j < 6; j++) {
      let dq = 0;
      for (let i = 0; i < 6; i++) dq += J[i][j] * y[i];
      q[j] -= Math.max(-0.3, Math.min(0.3, dq));
    }
  }
  return q;
}
