// A development stand-in for `rtamp serve` that streams a recorded episode to the page at
// exactly 30 frames a wall second (the server's cap), whatever the machine's load, so
// that the page's own frame rate can be measured apart from how many frames the server
// manages to send (docs/benchmarks.md). Never used by the tests.
//   node dev/frame-stream.mjs record WS_URL OUT.jsonl SECONDS
//       records every message of a running `rtamp serve` (hello, frame, log, tree, status)
//       for SECONDS; run the server slower than real time (e.g. --speed 0.5) so that
//       there are more than 30 frames a world second to choose from
//   node dev/frame-stream.mjs serve PAGE_DIR REC.jsonl [--port N] [--web-root DIR]
//       serves PAGE_DIR (or --web-root's) and plays REC to each page at world speed 1:
//       paused until the page resumes (its pause button), then every 1/30 s the latest
//       recorded frame at or before the world time, and the other messages at their world
//       time. Requests get a reply; interventions are refused. Prints the URL first, as
//       `rtamp serve` does, so measure.mjs can start it through a wrapper.
import { createServer } from 'node:http';
import { readFileSync, writeFileSync, existsSync } from 'node:fs';
import { join, extname } from 'node:path';
import { WebSocket, WebSocketServer } from 'ws';

const [mode, ...rest] = process.argv.slice(2);

if (mode === 'record') {
  const [url, out, seconds] = rest;
  const ws = new WebSocket(url);
  const lines = [];
  ws.on('message', (d) => lines.push(d.toString()));
  ws.on('open', () => {
    ws.send(JSON.stringify({ type: 'control', id: 1, action: 'resume' }));
    setTimeout(() => {
      writeFileSync(out, lines.join('\n') + '\n');
      console.log(`${lines.length} messages written to ${out}`);
      process.exit(0);
    }, Number(seconds) * 1000);
  });
} else if (mode === 'serve') {
  const opt = (name) => {
    const i = rest.indexOf(name);
    return i >= 0 ? rest.splice(i, 2)[1] : null;
  };
  const port = Number(opt('--port') ?? 0);
  const root = opt('--web-root');
  const [dirArg, recPath] = rest;
  const dir = root ?? dirArg;
  const msgs = readFileSync(recPath, 'utf8').trim().split('\n').map((l) => JSON.parse(l));
  const hello = msgs.find((m) => m.type === 'hello');
  const frames = msgs.filter((m) => m.type === 'frame');
  const others = msgs.filter((m) => m.type === 'log' || m.type === 'tree' || m.type === 'status');
  const tOf = (m) => (m.type === 'log' ? m.records[0]?.t ?? 0 : m.t);
  others.sort((a, b) => tOf(a) - tOf(b));
  const types = { '.html': 'text/html', '.js': 'text/javascript', '.css': 'text/css' };
  const server = createServer((req, res) => {
    const path = req.url.split('?')[0] === '/' ? '/index.html' : req.url.split('?')[0];
    const file = join(dir, path);
    if (!existsSync(file)) return res.writeHead(404).end();
    res.writeHead(200, { 'content-type': types[extname(file)] || 'application/octet-stream' }).end(readFileSync(file));
  });
  const wss = new WebSocketServer({ server, path: '/ws' });
  wss.on('connection', (ws) => {
    const t0 = frames[0]?.t ?? 0;
    ws.send(JSON.stringify({ ...hello, paused: true, t: t0, history: [], frame: frames[0] }));
    let paused = true, start = 0, fi = 0, oi = 0, timer = null, next = 0;
    const tick = () => {
      const now = performance.now();
      const t = t0 + (now - start) / 1000;
      while (oi < others.length && tOf(others[oi]) <= t) ws.send(JSON.stringify(others[oi++]));
      while (fi + 1 < frames.length && frames[fi + 1].t <= t) fi++;
      ws.send(JSON.stringify(frames[fi]));
      if (fi + 1 >= frames.length) return;
      next += 1000 / 30; // a schedule, not a gap: 30 a second on average
      timer = setTimeout(tick, Math.max(0, next - performance.now()));
    };
    ws.on('message', (d) => {
      const req = JSON.parse(d);
      const reply = (body) => ws.send(JSON.stringify({ type: 'reply', id: req.id, ...body }));
      if (req.type === 'control' && (req.action === 'resume' || (req.action === 'pause' && paused))) {
        reply({ ok: true });
        if (!paused) return;
        paused = false;
        ws.send(JSON.stringify({ type: 'state', speed: 1, paused: false, t: t0, ended: false }));
        start = next = performance.now();
        tick();
      } else reply({ ok: false, error: 'frame-stream: a recorded episode takes no interventions' });
    });
    ws.on('close', () => clearTimeout(timer));
  });
  server.listen(port, '127.0.0.1', () => console.log(`frame-stream: http://127.0.0.1:${server.address().port}/`));
} else {
  console.error('frame-stream.mjs: error: usage: record WS_URL OUT.jsonl SECONDS | serve PAGE_DIR REC.jsonl [--port N] [--web-root DIR]');
  process.exit(2);
}
