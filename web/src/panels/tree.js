// The behavior-tree panel: the tree of the latest `tree` message drawn as a tree (SVG):
// a box per node (its name, and its type in small print), coloured by its status (idle,
// running, success, failure), edges parent → child, laid out left to right by
// tree_layout.js. `status` messages ("RSFI…", one character per node id) recolour the
// boxes and edges whose status changed, in place: no relayout, no DOM rebuilt.
// Drag to pan, the wheel to zoom, "fit" shows the whole tree, "follow" the running node.
// The running branch is kept in view: after each status change the deepest running node
// (the last RUNNING one in pre-order) is panned to the middle when it is not inside the
// view, unless the person moved the view in the last FOLLOW_PAUSE_MS.
// Invariants: box i shows node id i; a status string of another length is ignored; the
// layout is computed once per tree.
import { BOX_H, layoutTree } from './tree_layout.js';

const SVG = 'http://www.w3.org/2000/svg';
const names = { I: 'idle', R: 'running', S: 'success', F: 'failure' };
const letter = { IDLE: 'I', RUNNING: 'R', SUCCESS: 'S', FAILURE: 'F' };
export const FOLLOW_PAUSE_MS = 4000;
const CHAR_W = 6.6; // px of an 11 px monospace character
const MIN_W = 70;
const MAX_W = 230;

const el = (tag, attrs = {}) => {
  const e = document.createElementNS(SVG, tag);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  return e;
};
const label = (n) => n.name || n.kind;
const boxWidth = (n) => Math.min(MAX_W, Math.max(MIN_W, 10 + CHAR_W * Math.max(label(n).length, n.kind.length * 0.82)));

export class TreePanel {
  constructor(container) {
    this.container = container;
    this.boxes = []; // SVG groups, by node id
    this.edges = []; // the edge into node i (none for the root)
    this.layout = null;
    this.shown = ''; // the status string shown
    this.view = { x: 0, y: 0, k: 1 };
    this.userMovedAt = -Infinity;
    this.followTimer = null;
    this.followed = -1; // the node last kept in view
    this.buildMs = 0; // what the last tree's layout and drawing took (ms), and the last status change
    this.statusMs = 0;

    const bar = document.createElement('div');
    bar.className = 'bt-bar';
    const fit = document.createElement('button');
    fit.textContent = 'fit';
    fit.title = 'show the whole tree';
    fit.addEventListener('click', () => this.fit());
    const follow = document.createElement('button');
    follow.textContent = 'follow';
    follow.title = 'keep the running node in view';
    follow.addEventListener('click', () => {
      this.userMovedAt = -Infinity;
      this.follow(true);
    });
    this.info = document.createElement('span');
    this.info.className = 'bt-info';
    bar.append(fit, follow, this.info);
    this.svg = el('svg', { class: 'bt-svg' });
    this.g = el('g', { class: 'bt-view' });
    this.svg.appendChild(this.g);
    this.empty = document.createElement('div');
    this.empty.className = 'bt-empty';
    container.replaceChildren(bar, this.svg, this.empty);
    this.installPanZoom();
    this.setTree(null);
  }

  setTree(tree) {
    this.g.replaceChildren();
    this.boxes = [];
    this.edges = [];
    this.shown = '';
    this.followed = -1;
    if (!tree || !tree.nodes || tree.nodes.length === 0) {
      this.layout = null;
      this.empty.textContent = 'no tree yet';
      this.empty.hidden = false;
      this.info.textContent = '';
      return;
    }
    this.empty.hidden = true;
    const nodes = tree.nodes;
    const t0 = performance.now();
    this.layout = layoutTree(nodes, boxWidth);
    const { boxes } = this.layout;
    const edgeLayer = el('g', { class: 'bt-edges' });
    const nodeLayer = el('g', { class: 'bt-nodes' });
    for (const n of nodes) {
      const b = boxes[n.id];
      if (n.parent >= 0) {
        const p = boxes[n.parent];
        const x0 = p.x + p.w;
        const y0 = p.y + BOX_H / 2;
        const x1 = b.x;
        const y1 = b.y + BOX_H / 2;
        const mx = (x0 + x1) / 2;
        const path = el('path', { class: 'bt-edge', d: `M${x0},${y0} C${mx},${y0} ${mx},${y1} ${x1},${y1}` });
        edgeLayer.appendChild(path);
        this.edges[n.id] = path;
      }
      const g = el('g', { class: 'bt-box', transform: `translate(${b.x},${b.y})`, 'data-id': n.id });
      const chars = Math.floor((b.w - 10) / CHAR_W);
      const name = label(n);
      const title = el('title');
      title.textContent = `${n.name} (${n.kind}${n.category ? ', ' + n.category : ''})`;
      const rect = el('rect', { width: b.w, height: BOX_H, rx: 4 });
      const t1 = el('text', { x: 5, y: 12, class: 'bt-name' });
      t1.textContent = name.length > chars ? name.slice(0, Math.max(1, chars - 1)) + '…' : name;
      const t2 = el('text', { x: 5, y: 24, class: 'bt-type' });
      const kchars = Math.floor((b.w - 10) / (CHAR_W * 0.82));
      t2.textContent = n.kind.length > kchars ? n.kind.slice(0, Math.max(1, kchars - 1)) + '…' : n.kind;
      g.append(title, rect, t1, t2);
      nodeLayer.appendChild(g);
      this.boxes[n.id] = g;
    }
    this.g.append(edgeLayer, nodeLayer);
    this.buildMs = performance.now() - t0;
    this.info.textContent = `${nodes.length} nodes`;
    // A new tree starts at its root (top left), unless the person is looking elsewhere.
    if (!this.userMovedRecently()) this.setView(0, 0, this.view.k);
    this.setStatus(nodes.map((n) => letter[n.status] || 'I').join(''));
  }

  setStatus(s) {
    if (!s || s.length !== this.boxes.length) return;
    const t0 = performance.now();
    const before = this.shown;
    for (let i = 0; i < s.length; i++) {
      if (s[i] === before[i]) continue;
      const st = names[s[i]] || 'idle';
      this.boxes[i].setAttribute('data-status', st);
      if (this.edges[i]) this.edges[i].setAttribute('data-status', st);
    }
    this.shown = s;
    this.follow(false);
    this.statusMs = performance.now() - t0;
  }

  // The deepest running node: the last R in pre-order (-1: none runs).
  runningLeaf() {
    return this.shown.lastIndexOf('R');
  }

  // Keeps the running node in view: pans it to the middle if it is not inside the view
  // (always, with `force`); not while the person moved the view recently.
  follow(force) {
    const id = this.runningLeaf();
    if (id < 0 || !this.layout) return;
    if (!force && this.userMovedRecently()) {
      this.scheduleFollow();
      return;
    }
    this.followed = id;
    const b = this.layout.boxes[id];
    const W = this.svg.clientWidth;
    const H = this.svg.clientHeight;
    if (!W || !H) return;
    const { x, y, k } = this.view;
    const left = b.x * k + x;
    const topPx = b.y * k + y;
    const inside = left >= 0 && topPx >= 0 && left + b.w * k <= W && topPx + b.h * k <= H;
    if (inside && !force) return;
    // Vertically centred; horizontally as far right as shows its ancestors to its left.
    const margin = 8;
    const nx = Math.min(margin, W - margin - (b.x + b.w) * k);
    this.setView(Math.max(nx, margin - b.x * k), H / 2 - (b.y + b.h / 2) * k, k);
  }

  userMovedRecently() {
    return performance.now() - this.userMovedAt < FOLLOW_PAUSE_MS;
  }

  // Once the person's pause is over, the running node is brought back into view.
  scheduleFollow() {
    if (this.followTimer) return;
    const wait = FOLLOW_PAUSE_MS - (performance.now() - this.userMovedAt) + 20;
    this.followTimer = setTimeout(() => {
      this.followTimer = null;
      this.follow(false);
    }, Math.max(20, wait));
  }

  fit() {
    if (!this.layout) return;
    const W = this.svg.clientWidth;
    const H = this.svg.clientHeight;
    if (!W || !H) return;
    const k = Math.min(1.5, W / this.layout.width, H / this.layout.height);
    this.userMovedAt = performance.now();
    this.setView((W - this.layout.width * k) / 2, (H - this.layout.height * k) / 2, k);
  }

  setView(x, y, k) {
    this.view = { x, y, k };
    this.g.setAttribute('transform', `translate(${x},${y}) scale(${k})`);
  }

  installPanZoom() {
    const svg = this.svg;
    let drag = null;
    svg.addEventListener('pointerdown', (e) => {
      if (e.button !== 0) return;
      drag = { x: e.clientX, y: e.clientY, vx: this.view.x, vy: this.view.y };
      svg.setPointerCapture(e.pointerId);
    });
    svg.addEventListener('pointermove', (e) => {
      if (!drag) return;
      this.userMovedAt = performance.now();
      this.setView(drag.vx + e.clientX - drag.x, drag.vy + e.clientY - drag.y, this.view.k);
    });
    const end = () => {
      drag = null;
    };
    svg.addEventListener('pointerup', end);
    svg.addEventListener('pointercancel', end);
    svg.addEventListener(
      'wheel',
      (e) => {
        e.preventDefault();
        const r = svg.getBoundingClientRect();
        const px = e.clientX - r.left;
        const py = e.clientY - r.top;
        const { x, y, k } = this.view;
        const k2 = Math.min(3, Math.max(0.15, k * Math.exp(-e.deltaY * 0.0015)));
        this.userMovedAt = performance.now();
        this.setView(px - ((px - x) * k2) / k, py - ((py - y) * k2) / k, k2);
      },
      { passive: false },
    );
  }
}
