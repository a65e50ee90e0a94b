// The page's side of the rtamp serve WebSocket protocol (docs/serve.md, protocol 2): one JSON
// object per text frame. Incoming messages are handed to `onMessage`; requests
// (`intervene`, `control`) get a fresh id and a promise that settles with the server's
// `reply` for that id. Invariants: ids are unique per connection; every pending request
// is settled (rejected with "connection closed") when the socket closes.

export class Connection {
  constructor(url, onMessage, onStatus) {
    this.url = url;
    this.onMessage = onMessage;
    this.onStatus = onStatus;
    this.nextId = 1;
    this.pending = new Map();
    this.open();
  }

  open() {
    this.ws = new WebSocket(this.url);
    this.ws.onopen = () => this.onStatus('connected');
    this.ws.onclose = () => {
      for (const { resolve } of this.pending.values()) resolve({ ok: false, error: 'connection closed' });
      this.pending.clear();
      this.onStatus('disconnected');
    };
    this.ws.onmessage = (ev) => {
      let msg;
      try {
        msg = JSON.parse(ev.data);
      } catch {
        return;
      }
      if (msg.type === 'reply' && msg.id != null && this.pending.has(msg.id)) {
        const p = this.pending.get(msg.id);
        this.pending.delete(msg.id);
        p.resolve(msg);
      }
      this.onMessage(msg);
    };
  }

  // Sends {type, ...body, id}; resolves with the reply ({ok, error?}).
  request(type, body) {
    const id = this.nextId++;
    return new Promise((resolve) => {
      if (this.ws.readyState !== WebSocket.OPEN) {
        resolve({ ok: false, error: 'not connected to the server' });
        return;
      }
      this.pending.set(id, { resolve });
      this.ws.send(JSON.stringify({ type, id, ...body }));
    });
  }

  intervene(body) {
    return this.request('intervene', body);
  }

  task(task) {
    return this.request('task', { task });
  }

  control(action, value) {
    return this.request('control', value === undefined ? { action } : { action, value });
  }
}
