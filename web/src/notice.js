// Messages to the person: a refused request's reason (the server's validator text,
// verbatim), or a short confirmation; the newest stays until the next one. Every
// message is also kept in `history` (the test hook exposes it).

export class Notice {
  constructor(el) {
    this.el = el;
    this.history = [];
  }

  show(text, kind) {
    this.history.push({ text, kind, at: performance.now() });
    this.el.textContent = text;
    this.el.dataset.kind = kind;
    this.el.hidden = false;
  }

  // A reply to one of the page's requests: refused ones show why.
  reply(what, r) {
    if (r.ok) this.show(`${what}: accepted`, 'ok');
    else this.show(`${what}: refused — ${r.error}${r.detail ? '\n' + r.detail : ''}`, 'error');
    return r;
  }
}
