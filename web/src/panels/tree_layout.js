// A tidy-tree layout for the behavior-tree panel, left to right: the root in the first
// column, each depth a column as wide as its widest box, children stacked top to bottom
// in their order, a parent centred (vertically) between its first and last child.
// Subtrees are packed by their contours (the top and bottom edge of each depth they
// reach), so a small subtree tucks in beside a deep one, as in Reingold–Tilford.
// Input: nodes in pre-order with `parent` ids (-1 for the root) and a `width(node)`;
// output: a box {x, y, w, h} per node id, and the size of the whole drawing.
// Invariants: boxes of one depth never overlap (at least `gap` apart); a parent's box is
// left of its children's; cost O(nodes x depth); computed once per tree, never per status.

export const BOX_H = 30;

export function layoutTree(nodes, width, { gap = 6, hgap = 26, margin = 8 } = {}) {
  const n = nodes.length;
  const kids = Array.from({ length: n }, () => []);
  const depth = new Array(n).fill(0);
  let root = -1;
  for (const node of nodes) {
    if (node.parent < 0) root = node.id;
    else {
      kids[node.parent].push(node.id);
      depth[node.id] = depth[node.parent] + 1;
    }
  }
  if (root < 0) return { boxes: [], width: 0, height: 0 };

  // Column widths and x per depth.
  const colW = [];
  for (const node of nodes) colW[depth[node.id]] = Math.max(colW[depth[node.id]] ?? 0, width(node));
  const colX = [margin];
  for (let d = 1; d < colW.length; d++) colX[d] = colX[d - 1] + colW[d - 1] + hgap;

  // Post-order (children after parents in pre-order: walk the ids backwards): each
  // subtree's contour, top[d] / bottom[d] relative to its root's top, and each child's
  // offset from its parent.
  const off = new Float64Array(n);
  const top = new Array(n);
  const bottom = new Array(n);
  for (let i = n - 1; i >= 0; i--) {
    const id = nodes[i].id;
    const cs = kids[id];
    if (cs.length === 0) {
      top[id] = [0];
      bottom[id] = [BOX_H];
      continue;
    }
    // Stack the children: each as high as the contours of those above it allow.
    const accTop = top[cs[0]].slice();
    const accBot = bottom[cs[0]].slice();
    off[cs[0]] = 0;
    for (let k = 1; k < cs.length; k++) {
      const c = cs[k];
      const ct = top[c];
      const cb = bottom[c];
      let o = -Infinity;
      const common = Math.min(ct.length, accBot.length);
      for (let d = 0; d < common; d++) o = Math.max(o, accBot[d] + gap - ct[d]);
      off[c] = o;
      for (let d = 0; d < ct.length; d++) {
        if (d < accTop.length) {
          accTop[d] = Math.min(accTop[d], ct[d] + o);
          accBot[d] = Math.max(accBot[d], cb[d] + o);
        } else {
          accTop.push(ct[d] + o);
          accBot.push(cb[d] + o);
        }
      }
      top[c] = bottom[c] = null; // merged: no longer needed
    }
    top[cs[0]] = bottom[cs[0]] = null;
    // The parent centred between its first and last child.
    const mid = (off[cs[0]] + off[cs[cs.length - 1]]) / 2;
    for (const c of cs) off[c] -= mid;
    top[id] = [0, ...accTop.map((v) => v - mid)];
    bottom[id] = [BOX_H, ...accBot.map((v) => v - mid)];
  }

  // Absolute positions, pre-order; then shifted so the topmost box is at the margin.
  const y = new Float64Array(n);
  let minY = Infinity;
  let maxY = -Infinity;
  for (const node of nodes) {
    const id = node.id;
    y[id] = node.parent < 0 ? 0 : y[node.parent] + off[id];
    minY = Math.min(minY, y[id]);
    maxY = Math.max(maxY, y[id] + BOX_H);
  }
  const boxes = new Array(n);
  for (const node of nodes) {
    const d = depth[node.id];
    boxes[node.id] = { x: colX[d], y: y[node.id] - minY + margin, w: colW[d], h: BOX_H, depth: d };
  }
  const last = colW.length - 1;
  return { boxes, width: colX[last] + colW[last] + margin, height: maxY - minY + 2 * margin };
}
