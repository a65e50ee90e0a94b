// The Büchi automaton panel: the states of hello.automaton on a circle (accepting ones
// with a double ring, the initial one with an incoming stub), the edges as arrows with
// their labels (self-loops as small loops), drawn as SVG; the tracked states (from the
// `run` and `plan` records' automaton_states) are filled. Invariant: the drawing only
// depends on the automaton; highlight() changes classes, not geometry.

const NS = 'http://www.w3.org/2000/svg';

function el(name, attrs, text) {
  const e = document.createElementNS(NS, name);
  for (const [k, v] of Object.entries(attrs)) e.setAttribute(k, v);
  if (text != null) e.textContent = text;
  return e;
}

export class AutomatonPanel {
  constructor(container) {
    this.container = container;
    this.circles = new Map();
  }

  setAutomaton(a) {
    this.container.replaceChildren();
    this.circles.clear();
    if (!a || !a.states?.length) {
      this.container.textContent = 'no automaton';
      return;
    }
    const W = 300, H = 200, R = 18;
    const svg = el('svg', { viewBox: `0 0 ${W} ${H}`, class: 'automaton' });
    const defs = el('defs', {});
    const marker = el('marker', { id: 'ah', viewBox: '0 0 10 10', refX: 9, refY: 5, markerWidth: 6, markerHeight: 6, orient: 'auto-start-reverse' });
    marker.appendChild(el('path', { d: 'M0,0 L10,5 L0,10 z', fill: '#555' }));
    defs.appendChild(marker);
    svg.appendChild(defs);
    const n = a.states.length;
    const pos = new Map();
    a.states.forEach((s, i) => {
      const ang = n === 1 ? Math.PI : Math.PI + (2 * Math.PI * i) / n;
      const rx = n === 1 ? 0 : W / 2 - 60, ry = n === 1 ? 0 : H / 2 - 45;
      pos.set(s.id, [W / 2 + rx * Math.cos(ang), H / 2 + ry * Math.sin(ang)]);
    });
    // Edges with the same endpoints share one drawing and a joined label.
    const grouped = new Map();
    for (const e of a.edges || []) {
      const k = `${e.from}>${e.to}`;
      grouped.set(k, grouped.has(k) ? { ...e, label: grouped.get(k).label + ' | ' + e.label } : e);
    }
    for (const e of grouped.values()) {
      const [x1, y1] = pos.get(e.from), [x2, y2] = pos.get(e.to);
      const lab = e.label.length > 28 ? e.label.slice(0, 27) + '…' : e.label;
      if (e.from === e.to) {
        svg.appendChild(el('path', { d: `M${x1 - 8},${y1 - R + 2} C${x1 - 22},${y1 - R - 30} ${x1 + 22},${y1 - R - 30} ${x1 + 8},${y1 - R + 2}`, class: 'ba-edge', 'marker-end': 'url(#ah)' }));
        svg.appendChild(el('text', { x: x1, y: y1 - R - 26, class: 'ba-label' }, lab));
        continue;
      }
      const dx = x2 - x1, dy = y2 - y1, L = Math.hypot(dx, dy);
      const ux = dx / L, uy = dy / L;
      // Bend two-way edges apart.
      const bend = grouped.has(`${e.to}>${e.from}`) ? 18 : 0;
      const mx = (x1 + x2) / 2 - uy * bend, my = (y1 + y2) / 2 + ux * bend;
      svg.appendChild(el('path', { d: `M${x1 + ux * R},${y1 + uy * R} Q${mx},${my} ${x2 - ux * R},${y2 - uy * R}`, class: 'ba-edge', 'marker-end': 'url(#ah)' }));
      svg.appendChild(el('text', { x: mx, y: my - 4, class: 'ba-label' }, lab));
    }
    for (const s of a.states) {
      const [x, y] = pos.get(s.id);
      const g = el('g', { class: 'ba-state', 'data-id': s.id });
      if (s.initial) g.appendChild(el('path', { d: `M${x - R - 18},${y} L${x - R},${y}`, class: 'ba-edge', 'marker-end': 'url(#ah)' }));
      g.appendChild(el('circle', { cx: x, cy: y, r: R, class: 'ba-circle' }));
      if (s.accepting) g.appendChild(el('circle', { cx: x, cy: y, r: R - 4, class: 'ba-accept' }));
      g.appendChild(el('text', { x, y: y + 4, class: 'ba-id' }, String(s.id)));
      svg.appendChild(g);
      this.circles.set(s.id, g);
    }
    this.container.appendChild(svg);
  }

  highlight(tracked) {
    const on = new Set(tracked || []);
    for (const [id, g] of this.circles) g.classList.toggle('tracked', on.has(id));
  }
}
