import WebSocket from 'ws';
const url = process.argv[2];
const ws = new WebSocket(url);
let tree = null, last = null, lastT=0, n = 0;
ws.on('open', () => ws.send(JSON.stringify({type:'control',id:1,action:'resume'})));
ws.on('message', (d) => {
  const m = JSON.parse(d);
  if (m.type === 'hello') { tree = m.tree; console.log('hello t', m.t, 'nodes', tree && tree.nodes.length); }
  if (m.type === 'tree') { tree = m; console.log('tree t', m.t, m.nodes.length, 'nodes'); }
  if (m.type === 'status') { last = m.s; lastT = m.t; n++; }
  if (m.type === 'log') for (const r of m.records) if (r.ev !== 'tick' && r.ev !== 'perceived') console.log('rec', r.t, r.ev, r.what||'', r.action||'', r.end||'');
  if (m.type === 'state' && m.ended) { console.log('ended; last status', lastT, last, 'count', n); console.log(JSON.stringify(tree.nodes.map(x=>[x.id,x.parent,x.kind,x.name]))); process.exit(0); }
});
