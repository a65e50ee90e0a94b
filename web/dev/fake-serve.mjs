// A development stand-in for `rtamp serve` (never used by the tests): serves a built
// page directory and plays a recorded episode log to it over the v1 protocol — hello
// from a JSON file, the log's records in (sped-up) world time, frames placing the
// things in their logged locations. Interventions are refused ("dev server"). For
// working on the page without the C++ server:
//   node dev/fake-serve.mjs PAGE_DIR HELLO.json LOG.jsonl [PORT]
import { createServer } from 'node:http';
import { readFileSync, existsSync } from 'node:fs';
import { join, extname } from 'node:path';
import { WebSocketServer } from 'ws';

const [dir, helloPath, logPath, port = '0'] = process.argv.slice(2);
const hello = JSON.parse(readFileSync(helloPath, 'utf8'));
const records = readFileSync(logPath, 'utf8').trim().split('\n').map((l) => JSON.parse(l));
const types = { '.html': 'text/html', '.js': 'text/javascript', '.css': 'text/css' };

const server = createServer((req, res) => {
  const path = req.url === '/' ? '/index.html' : req.url;
  const file = join(dir, path);
  if (!existsSync(file)) return res.writeHead(404).end();
  res.writeHead(200, { 'content-type': types[extname(file)] || 'application/octet-stream' }).end(readFileSync(file));
});
const wss = new WebSocketServer({ server, path: '/ws' });

function frame(t, placement) {
  const things = hello.scene.things.map((th) => {
    const at = placement?.[th.name] ?? th.at;
    const r = hello.scene.regions.find((x) => x.name === at);
    const k = hello.scene.things.indexOf(th);
    const pos = at === th.at || !r ? th.pos : [r.center[0] - 0.1 + 0.08 * (k % 3), r.center[1] + 0.08 * Math.floor(k / 3) - 0.05, 0];
    return { name: th.name, class: th.class, kind: th.kind, size: th.size, pos, quat: [1, 0, 0, 0], at };
  });
  return { type: 'frame', t, q: null, tool: [0.3, 0, 0.3], held: null, things };
}

wss.on('connection', (ws) => {
  ws.send(JSON.stringify({ type: 'hello', protocol: 1, mode: 'live', world: 'symbolic', speed: 1, paused: false, t: 0, ...hello, history: [], tree: null }));
  ws.send(JSON.stringify(frame(0, null)));
  let i = 0, placement = null;
  const start = Date.now();
  const timer = setInterval(() => {
    const t = ((Date.now() - start) / 1000) * 4;
    const batch = [];
    while (i < records.length && records[i].t <= t) {
      const r = records[i++];
      if (r.ev === 'run') placement = r.state;
      batch.push(r);
    }
    if (batch.length) ws.send(JSON.stringify({ type: 'log', records: batch }));
    ws.send(JSON.stringify(frame(t, placement)));
    if (i >= records.length) clearInterval(timer);
  }, 33);
  ws.on('message', (m) => {
    const req = JSON.parse(m);
    ws.send(JSON.stringify({ type: 'reply', id: req.id, ok: false, error: 'dev server: a recorded episode takes no requests' }));
  });
  ws.on('close', () => clearInterval(timer));
});
server.listen(Number(port), '127.0.0.1', () => console.log(`http://127.0.0.1:${server.address().port}/`));
