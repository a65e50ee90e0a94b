// Issue 14's server-overhead bar, measured from outside (docs/benchmarks.md
// "`rtamp serve`: server overhead"): one episode, either
//   node --experimental-websocket tests/serve_overhead.mjs serve RTAMP_BIN SCENARIO [ARGS...]
//     `rtamp serve SCENARIO --speed 0 --paused --exit-at-end --port 0 --quiet ARGS` (ARGS may
//     give another --speed, e.g. 1: paced to wall time) with one
//     WebSocket client in this (separate) process that JSON-parses every message, as a page
//     does; it resumes the episode once its hello arrived, so the whole episode is watched;
//   node tests/serve_overhead.mjs run RTAMP_BIN SCENARIO [ARGS...]
//     `rtamp run SCENARIO --quiet ARGS` (the baseline: the same node start-up around it).
// Time the whole command (e.g. /usr/bin/time, or a pairing of the two): both pay node's
// start-up, so the ratio is the server's and its client's share. Prints on stderr the
// messages received by type, the episode's own wall time (`wall_seconds` of its metrics:
// the loop's, from its start to its end; serve: from the end record the client received,
// run: from --json) and the child's exit code; exits with the child's code.
// serve --live: the episode starts at once (no --paused) and the client attaches while it
// runs, so the episode's wall time holds no wait for the client.
// Node's own WebSocket (--experimental-websocket, Node >= 20.10): no npm package needed.
import { spawn } from 'node:child_process';
import { createInterface } from 'node:readline';

const [mode, bin, scenario, ...given] = process.argv.slice(2);
const live = given.includes('--live');
const rest = given.filter((a) => a !== '--live');
if (!['serve', 'run'].includes(mode) || !bin || !scenario) {
  console.error('usage: serve_overhead.mjs serve|run RTAMP_BIN SCENARIO [ARGS...]');
  process.exit(2);
}

const args =
  mode === 'serve'
    ? ['serve', scenario, ...(rest.includes('--speed') ? [] : ['--speed', '0']), ...(live ? [] : ['--paused']),
       '--exit-at-end', '--port', '0', '--quiet', ...rest]
    : ['run', scenario, '--json', ...rest];
const child = spawn(bin, args, { stdio: ['ignore', 'pipe', 'inherit'] });
const counts = {};
let wallSeconds = null;  // the episode's metrics.wall_seconds
let socketDone = Promise.resolve();  // settles when the client's socket (run: stdout) has closed

if (mode === 'serve') {
  const lines = createInterface({ input: child.stdout });
  lines.once('line', (line) => {
    const m = /http:\/\/([^/]+)\//.exec(line);
    if (!m) {
      console.error(`serve_overhead: no URL in '${line}'`);
      child.kill('SIGTERM');
      return;
    }
    if (typeof WebSocket === 'undefined') {
      console.error('serve_overhead: no WebSocket (run node with --experimental-websocket)');
      child.kill('SIGTERM');
      return;
    }
    const ws = new WebSocket(`ws://${m[1]}/ws`);
    socketDone = new Promise((resolve) => ws.addEventListener('close', resolve));
    ws.onmessage = (ev) => {
      const msg = JSON.parse(ev.data);
      counts[msg.type] = (counts[msg.type] ?? 0) + 1;
      if (msg.type === 'log')
        for (const r of msg.records) if (r.ev === 'end') wallSeconds = r.metrics.wall_seconds;
      if (!live && msg.type === 'hello' && counts.hello === 1)
        ws.send(JSON.stringify({ type: 'control', id: 1, action: 'resume' }));
    };
    ws.onerror = () => {};
  });
  lines.on('line', () => {});
} else {
  let out = '';
  child.stdout.on('data', (d) => (out += d));
  socketDone = new Promise((resolve) =>
    child.stdout.on('end', () => {
      try {
        wallSeconds = JSON.parse(out).wall_seconds;
      } catch {}
      resolve();
    }));
}

// Every message the server sent before it exited is read before this process ends.
child.on('exit', async (code, signal) => {
  await Promise.race([socketDone, new Promise((resolve) => setTimeout(resolve, 5000))]);
  console.error(`serve_overhead: ${mode} exit ${code ?? signal}; episode wall_seconds ${wallSeconds}; messages ${JSON.stringify(counts)}`);
  process.exit(code ?? 1);
});
