// The page's entry point: connects to the server (ws://<this host>/ws), builds the scene
// and the panels from `hello`, and routes every server message to them; the person's
// actions (drag, add, delete, take, controls) become requests. The 3-D scene is drawn by
// a worker (view.js, render/): a frame message updates the main thread's copy of the
// things (labels, picking) and is passed on to it; the panels that change per message
// (log-driven panels, tree statuses, clock, gripper) and the labels are updated at most
// once per animation frame, from the latest data. With camera perception, `camera`
// messages go to the Camera panel (panels/camera.js), which draws the latest image.
// Invariant: after every `hello` (connect, seek) the page's state is rebuilt from it
// alone (scene, tree, history).
import { Connection } from './connection.js';
import { SceneView } from './view.js';
import { ArmPose } from './arm.js';
import { Episode } from './episode.js';
import { DragInteraction } from './interaction.js';
import { Notice } from './notice.js';
import { TreePanel } from './panels/tree.js';
import { PlanPanel } from './panels/plan.js';
import { AutomatonPanel } from './panels/automaton.js';
import { TimelinePanel } from './panels/timeline.js';
import { ControlsPanel } from './panels/controls.js';
import { PersonPanel } from './panels/person.js';
import { CameraPanel } from './panels/camera.js';
import { installTestHook } from './testhook.js';

const $ = (s) => document.querySelector(s);
// The drawing bundle, beside this one (assets/render.js).
const renderUrl = new URL('render.js', document.currentScript?.src || new URL('assets/', location.href)).href;

const app = {
  ready: false,
  hello: null,
  t: 0,
  state: null,
  held: null,
  pending: { log: false, status: null, frame: null }, // panel updates for the next animation frame
  framesReceived: 0,
  latencies: [],
  drops: [], // {subject, at}: drops waiting for their intervention record
  episode: new Episode(),
};

app.scene = new SceneView($('#scene'), renderUrl);
app.notice = new Notice($('#notice'));
app.tree = new TreePanel($('#tree'));
app.plan = new PlanPanel($('#plan'));
app.automaton = new AutomatonPanel($('#automaton'));
app.timeline = new TimelinePanel($('#timeline'), $('#scrub'), (t) => control('seek', t));
app.controls = new ControlsPanel($('#controls'), (a, v) => control(a, v));
app.camera = new CameraPanel($('#camera-section'), $('#camera'), $('#camera-caption'));

function control(action, value) {
  return app.conn.control(action, value).then((r) => (r.ok ? r : app.notice.reply(action, r)));
}

function intervene(what, body) {
  return app.conn.intervene(body).then((r) => app.notice.reply(what, r));
}

app.person = new PersonPanel($('#person'), {
  add: (cls, loc) =>
    intervene(`add ${cls.name} to ${loc}`, { kind: cls.kind === 'container' ? 'add-container' : 'add', class: cls.name, location: loc }),
  remove: (name) => {
    const kind = app.scene.things.get(name)?.info?.kind === 'container' ? 'remove-container' : 'remove';
    return intervene(`remove ${name}`, { kind, subject: name });
  },
  take: (loc) => intervene(`take ${app.held ?? 'the held thing'} from the gripper`, loc ? { kind: 'take-from-gripper', location: loc } : { kind: 'take-from-gripper' }),
});

new DragInteraction(app.scene, {
  onSelect: (name) => app.person.select(name),
  onDrop: ({ subject, location, position }) => {
    const drop = { subject, at: performance.now(), replyMs: null };
    app.drops.push(drop);
    const body = { kind: 'relocate', subject, position };
    if (location) body.location = location;
    intervene(`move ${subject}${location ? ' to ' + location : ''}`, body).then((r) => {
      drop.replyMs = performance.now() - drop.at;
      drop.serverMs = r.server_ms ?? null; // the server's receipt -> applied
      if (!r.ok) app.drops.splice(app.drops.indexOf(drop), 1);
      // Refused: the thing goes back to where the server last put it.
      const e = app.scene.things.get(subject);
      if (!r.ok && e && app.scene.dragging !== subject) app.scene.showAt(subject, e.pos);
    });
  },
});

// The header's task field: a new task for the running episode (refused: the reason and the caret line).
$('#task-form').addEventListener('submit', (ev) => {
  ev.preventDefault();
  const task = $('#task-input').value.trim();
  if (!task) return;
  app.conn.task(task).then((r) => app.notice.reply('new task', r));
});

function onHello(h) {
  app.hello = h;
  app.t = h.t ?? 0;
  app.scene.build(h.scene);
  app.arm = new ArmPose(h.scene.robot);
  app.person.setScene(h.scene);
  $('#task').textContent = h.task;
  $('#mode').textContent = `${h.mode} · ${h.world}`;
  app.automaton.setAutomaton(h.automaton);
  app.taskShown = 0;
  app.timeline.setMode(h.mode, h.replay?.duration);
  app.timeline.reset();
  app.episode.reset();
  for (const r of h.history || []) app.episode.add(r);
  app.tree.setTree(h.tree);
  app.pending = { log: false, status: null, frame: null };
  refreshLog();
  app.controls.setState(h);
  $('#controls').dataset.mode = h.mode;
  if (h.frame) onFrame(h.frame);
  app.ready = true;
}

function refreshLog() {
  const ep = app.episode;
  // A task change redraws the automaton and the header's task (hello's are the task in
  // force when it was sent; the history's task records after it are the same or newer).
  const version = ep.task?.version ?? 0;
  if (version !== app.taskShown) {
    app.taskShown = version;
    $('#task').textContent = ep.task ? ep.task.task : app.hello.task;
    app.automaton.setAutomaton(ep.task ? ep.task.automaton : app.hello.automaton);
  }
  app.plan.update(ep.plan);
  app.scene.setMoves(ep.end ? [] : ep.remaining());
  app.automaton.highlight(ep.tracked);
  app.timeline.update(ep.timeline);
  const outcome = ep.end ? (ep.end.success ? 'succeeded' : 'failed') : '';
  $('#result').textContent = ep.end ? `${outcome}: ${ep.end.end}` : '';
  $('#result').dataset.outcome = outcome; // its colour (style.css): green / red
}

function onFrame(f) {
  app.framesReceived++;
  app.t = f.t;
  app.held = f.held ?? null;
  app.tool = f.tool;
  app.scene.frame(f, app.arm ? app.arm.update(f) : null);
  app.pending.frame = f;
}

// The panels' per-message updates, once per animation frame.
function updatePanels() {
  const p = app.pending;
  if (p.frame) {
    app.person.setHeld(p.frame.held ?? null);
    app.controls.setTime(p.frame.t);
    app.timeline.setTime(p.frame.t);
    p.frame = null;
  }
  if (p.status != null) {
    app.tree.setStatus(p.status);
    p.status = null;
  }
  if (p.log) {
    refreshLog();
    p.log = false;
  }
}

function onLog(r) {
  app.episode.add(r);
  if (r.ev === 'intervention' && r.kind === 'relocate') {
    const i = app.drops.findIndex((d) => d.subject === r.subject);
    if (i >= 0) {
      // ms: drop -> the intervention record (applied in the episode); replyMs: drop -> the
      // server's reply (accepted).
      app.latencies.push({ subject: r.subject, ms: performance.now() - app.drops[i].at, replyMs: app.drops[i].replyMs, serverMs: app.drops[i].serverMs, applied: r.applied, t: r.t });
      app.drops.splice(i, 1);
    }
  }
  // Ticks (50 a second with MuJoCo), percepts, frame and camera records change no panel.
  if (r.ev !== 'tick' && r.ev !== 'perceived' && r.ev !== 'frame' && r.ev !== 'camera') app.pending.log = true;
}

function onMessage(m) {
  switch (m.type) {
    case 'hello':
      onHello(m);
      break;
    case 'frame':
      onFrame(m);
      break;
    case 'log':
      for (const r of m.records) onLog(r);
      break;
    case 'tree':
      app.tree.setTree(m);
      app.pending.status = null; // older than this tree
      break;
    case 'status':
      app.pending.status = m.s;
      break;
    case 'camera':
      app.camera.show(m);
      break;
    case 'state':
      app.state = m;
      app.controls.setState(m);
      break;
    case 'reply':
      if (!m.ok && m.id == null) app.notice.show(`the server refused a message: ${m.error}`, 'error');
      break;
    default:
      break;
  }
}

const wsUrl = `${location.protocol === 'https:' ? 'wss' : 'ws'}://${location.host}/ws`;
app.conn = new Connection(wsUrl, onMessage, (s) => {
  $('#connection').textContent = s;
  $('#connection').dataset.state = s;
});

function loop() {
  updatePanels();
  app.scene.updateLabels();
  requestAnimationFrame(loop);
}
requestAnimationFrame(loop);
installTestHook(app);
