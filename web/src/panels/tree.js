// The behavior-tree panel: the whole tree from the latest `tree` message (nodes in
// pre-order with parent ids), one row per node indented by depth, coloured by status;
// `status` messages ("RSFI…", one character per node id) recolour the rows in place.
// Invariant: row i shows node id i; a status string of another length is ignored.

const names = { I: 'idle', R: 'running', S: 'success', F: 'failure' };
const letter = { IDLE: 'I', RUNNING: 'R', SUCCESS: 'S', FAILURE: 'F' };

export class TreePanel {
  constructor(el) {
    this.el = el;
    this.rows = [];
  }

  setTree(tree) {
    this.el.replaceChildren();
    this.rows = [];
    if (!tree || !tree.nodes) {
      this.el.textContent = 'no tree yet';
      return;
    }
    const depth = [];
    for (const n of tree.nodes) {
      depth[n.id] = n.parent < 0 ? 0 : depth[n.parent] + 1;
      const row = document.createElement('div');
      row.className = 'bt-node';
      row.dataset.id = n.id;
      row.style.paddingLeft = depth[n.id] * 12 + 4 + 'px';
      const kind = document.createElement('span');
      kind.className = 'bt-kind';
      kind.textContent = n.kind;
      row.append(kind, ' ', n.name);
      this.el.appendChild(row);
      this.rows[n.id] = row;
    }
    this.setStatus(tree.nodes.map((n) => letter[n.status] || 'I').join(''));
  }

  setStatus(s) {
    if (!s || s.length !== this.rows.length) return;
    for (let i = 0; i < s.length; i++) this.rows[i].dataset.status = names[s[i]] || 'idle';
  }
}
