// The behavior-tree panel's layout (src/panels/tree_layout.js), checked in node without a
// browser:   node tests/tree_layout.test.mjs [TREES]
// Random trees (pre-order ids, 1 to 600 nodes, fan-outs 0–12, depths up to 9, box widths
// 40–230 px) and the planner's shape (a Sequence of Choosers, each a post-condition and a
// Sequence of pre-conditions and a move). The oracles are the layout's promises, checked
// on the boxes alone: each depth one column (same x, boxes as wide as its widest),
// columns left to right with the depth; no two boxes overlap (any two boxes of one depth
// at least `gap` apart); siblings top to bottom in their order; a parent centred between
// its first and last child; everything inside the reported size, the topmost box at the
// margin; and the layout compact where it can be (a leaf is tucked in beside its deeper
// sibling subtree: the planner's 5-node chooser takes 2 rows, not 3, one a leaf).
import assert from 'node:assert/strict';
import { BOX_H, layoutTree } from '../src/panels/tree_layout.js';

const trees = Number(process.argv[2] ?? 400);
let seed = 4242;
const rand = () => (seed = (seed * 1103515245 + 12345) % 2147483648) / 2147483648;
const GAP = 6;
const MARGIN = 8;

// A random tree in pre-order: each node's children are generated right after it.
function randomTree(n) {
  const nodes = [];
  const widths = [];
  const grow = (parent, depth) => {
    if (nodes.length >= n) return;
    const id = nodes.length;
    nodes.push({ id, parent });
    widths.push(40 + Math.floor(rand() * 190));
    const fan = depth >= 8 ? 0 : Math.floor(rand() * rand() * 13);
    for (let k = 0; k < fan && nodes.length < n; k++) grow(id, depth + 1);
  };
  grow(-1, 0);
  return { nodes, width: (node) => widths[node.id] };
}

// The planner's tree: plan → k × (chooser → post, do → pre, move).
function plannerTree(k) {
  const nodes = [{ id: 0, parent: -1 }];
  for (let i = 0; i < k; i++) {
    const c = nodes.length;
    nodes.push({ id: c, parent: 0 }, { id: c + 1, parent: c }, { id: c + 2, parent: c }, { id: c + 3, parent: c + 2 }, { id: c + 4, parent: c + 2 });
  }
  return { nodes, width: () => 120 };
}

function check({ nodes, width }) {
  const { boxes, width: W, height: H } = layoutTree(nodes, width, { gap: GAP, margin: MARGIN });
  assert.equal(boxes.length, nodes.length);
  const depth = [];
  const kids = nodes.map(() => []);
  for (const n of nodes) {
    depth[n.id] = n.parent < 0 ? 0 : depth[n.parent] + 1;
    if (n.parent >= 0) kids[n.parent].push(n.id);
  }
  // Columns: one x and one width per depth, the widest box's; deeper columns further right.
  const colX = new Map();
  const colW = new Map();
  for (const n of nodes) {
    const b = boxes[n.id];
    assert.equal(b.h, BOX_H);
    colW.set(depth[n.id], Math.max(colW.get(depth[n.id]) ?? 0, width(n)));
    if (colX.has(depth[n.id])) assert.equal(b.x, colX.get(depth[n.id]), `node ${n.id}: not in its depth's column`);
    colX.set(depth[n.id], b.x);
  }
  for (const n of nodes) assert.equal(boxes[n.id].w, colW.get(depth[n.id]));
  for (let d = 1; colX.has(d); d++) assert.ok(colX.get(d) >= colX.get(d - 1) + colW.get(d - 1), `column ${d} overlaps column ${d - 1}`);
  // No overlap within a column (sorted by y: each at least GAP below the one above).
  const byDepth = new Map();
  for (const n of nodes) (byDepth.get(depth[n.id]) ?? byDepth.set(depth[n.id], []).get(depth[n.id])).push(boxes[n.id]);
  for (const [d, list] of byDepth) {
    list.sort((a, b) => a.y - b.y);
    for (let i = 1; i < list.length; i++) assert.ok(list[i].y >= list[i - 1].y + BOX_H + GAP - 1e-6, `depth ${d}: boxes ${list[i - 1].y} and ${list[i].y} overlap`);
  }
  // Siblings in order, the parent centred between its first and last child.
  for (const n of nodes) {
    const cs = kids[n.id];
    for (let i = 1; i < cs.length; i++) assert.ok(boxes[cs[i]].y > boxes[cs[i - 1]].y, `children of ${n.id} out of order`);
    if (cs.length) assert.ok(Math.abs(boxes[n.id].y - (boxes[cs[0]].y + boxes[cs.at(-1)].y) / 2) < 1e-6, `node ${n.id} not centred over its children`);
  }
  // Inside the reported size, the topmost box at the margin.
  let top = Infinity;
  for (const b of boxes) {
    top = Math.min(top, b.y);
    assert.ok(b.x >= 0 && b.y >= 0 && b.x + b.w <= W + 1e-6 && b.y + b.h <= H + 1e-6, 'a box outside the drawing');
  }
  assert.ok(Math.abs(top - MARGIN) < 1e-6);
  return { boxes, height: H };
}

for (let i = 0; i < trees; i++) check(randomTree(1 + Math.floor(rand() * 600)));
// A single node, and a chain.
check({ nodes: [{ id: 0, parent: -1 }], width: () => 50 });
check({ nodes: Array.from({ length: 30 }, (_, i) => ({ id: i, parent: i - 1 })), width: () => 60 });
// The planner's shape, compact: a chooser's post-condition is tucked in beside its `do`
// sequence's children, so k choosers take 2k + 1/2 rows of boxes (one row a leaf: 3k).
for (const k of [1, 7, 100]) {
  const { height } = check(plannerTree(k));
  const rows = (height - 2 * MARGIN + GAP) / (BOX_H + GAP);
  assert.ok(rows <= 2 * k + 0.5 + 1e-6, `${k} choosers take ${rows} rows`);
}
console.log(`ok: ${trees} random trees and the planner's shape laid out as promised`);
