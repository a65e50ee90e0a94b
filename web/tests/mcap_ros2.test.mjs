// rtamp's ros2-profile MCAP files (`--mcap-profile ros2`) read back by independent readers:
//   RTAMP_BIN=build/bin/rtamp node tests/mcap_ros2.test.mjs [TMPDIR]
// The container with npm @mcap/core (record by record, CRCs checked, and through the
// summary); every schema's ros2msg text parsed by npm @foxglove/rosmsg, and every
// message decoded by npm @foxglove/rosmsg2-serialization's MessageReader and written
// again by its MessageWriter: the bytes must come back the same (so rtamp's CDR is
// that library's CDR, padding included). Oracles: the standard types' definitions
// equal those of npm @foxglove/rosmsg-msgs-common (ROS 2 Jazzy); the Header says
// profile ros2, a Metadata record names rtamp and its version; every channel is cdr
// with its offered QoS (latched: /tf_static, /robot_description); /rtamp/log is the
// JSON Lines log; message counts match the log's records; the arm's /tf is its URDF's
// joints at the /joint_states angles; the transform tree has one root, `world`; at the
// end every block sits in the region the log's end placement names; while the log
// says a block is in the hand, it hangs from ur5/tool, and where a thing changes hands
// its world pose composed through the arm's chain stays put; a converted served log's
// joint angles and things' poses are its `frame` records'. Episodes: symbolic (live and
// converted by `rtamp log to-mcap`), served (`rtamp serve --speed 0 --exit-at-end`, live
// and converted), MuJoCo, MuJoCo with a camera, a symbolic batch. Bad input: --mcap-profile x, exit 2.
import assert from 'node:assert/strict';
import { execFileSync, spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { createRequire } from 'node:module';
import { McapIndexedReader, McapStreamReader } from '@mcap/core';
import { parse as parseMsg } from '@foxglove/rosmsg';
import { MessageReader, MessageWriter } from '@foxglove/rosmsg2-serialization';

const require = createRequire(import.meta.url);
const { ros2jazzy } = require('@foxglove/rosmsg-msgs-common');

const bin = process.env.RTAMP_BIN ?? path.resolve('../build/bin/rtamp');
const tmpBase = process.argv[2] ?? process.env.RTAMP_TEST_TMP ?? os.tmpdir();
fs.mkdirSync(tmpBase, { recursive: true });
const tmp = fs.mkdtempSync(path.join(tmpBase, 'mcap-ros2-'));

const decompressHandlers = {
  zstd: (buf, size) => new Uint8Array(execFileSync('zstd', ['-d', '-c', '-q'], { input: buf, maxBuffer: 1 << 30 }).subarray(0, Number(size))),
  lz4: (buf, size) => new Uint8Array(execFileSync('lz4', ['-d', '-c', '-q'], { input: buf, maxBuffer: 1 << 30 }).subarray(0, Number(size))),
};

function rtamp(args, expectCode = 0) {
  const r = spawnSync(bin, args, { encoding: 'utf8' });
  if (expectCode === 'ran') assert.ok(r.status === 0 || r.status === 1, `rtamp ${args.join(' ')}: exit ${r.status}\n${r.stderr}`);
  else assert.equal(r.status, expectCode, `rtamp ${args.join(' ')}: exit ${r.status}\n${r.stderr}`);
  return r;
}

// A definition's fields as plain values, for comparing with msgs-common's.
const fieldsOf = (def) => def.definitions.map((f) => ({ name: f.name, type: f.type.replace('/msg/', '/'), isArray: !!f.isArray,
  arrayLength: f.arrayLength, isConstant: !!f.isConstant, value: f.isConstant ? f.value : undefined,
  upperBound: f.upperBound ?? f.arrayUpperBound, isComplex: !!f.isComplex }));

// Quaternions and rigid transforms (x y z w), for composing /tf.
const qmul = (a, b) => ({ w: a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z, x: a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
  y: a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x, z: a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w });
const rotate = (q, v) => { const p = qmul(qmul(q, { w: 0, ...v }), { w: q.w, x: -q.x, y: -q.y, z: -q.z }); return { x: p.x, y: p.y, z: p.z }; };
const compose = (a, b) => { const t = rotate(a.rotation, b.translation);
  return { translation: { x: a.translation.x + t.x, y: a.translation.y + t.y, z: a.translation.z + t.z }, rotation: qmul(a.rotation, b.rotation) }; };
const fromRpy = (r, p, y) => { const q = (ax, a) => ({ w: Math.cos(a / 2), x: ax === 0 ? Math.sin(a / 2) : 0, y: ax === 1 ? Math.sin(a / 2) : 0, z: ax === 2 ? Math.sin(a / 2) : 0 });
  return qmul(q(2, y), qmul(q(1, p), q(0, r))); };
const near = (a, b, tol, what) => assert.ok(Math.abs(a - b) <= tol, `${what}: ${a} vs ${b}`);
const sameTransform = (a, b, what) => {
  for (const k of ['x', 'y', 'z']) near(a.translation[k], b.translation[k], 1e-9, `${what} translation ${k}`);
  const dot = a.rotation.x * b.rotation.x + a.rotation.y * b.rotation.y + a.rotation.z * b.rotation.z + a.rotation.w * b.rotation.w;
  near(Math.abs(dot), 1, 1e-9, `${what} rotation`);
};

// The URDF's joints (regular expressions are enough for the text rtamp writes).
function urdfJoints(urdf) {
  const joints = new Map();
  for (const m of urdf.matchAll(/<joint name="([^"]+)" type="(\w+)">\s*<parent link="([^"]+)"\/>\s*<child link="([^"]+)"\/>\s*<origin xyz="([^"]+)" rpy="([^"]+)"\/>/g)) {
    const [x, y, z] = m[5].split(' ').map(Number), [r, p, yaw] = m[6].split(' ').map(Number);
    joints.set(m[4], { name: m[1], type: m[2], parent: m[3], origin: { translation: { x, y, z }, rotation: fromRpy(r, p, yaw) } });
  }
  return joints;
}

// arm: 'ticks' (a live MuJoCo episode: the arm at every tick), 'frames' (a converted log with
// `frame` records: the arm and things of those records) or null (no joint angles).
async function check(file, logFile, { arm = null, holds = arm === 'ticks' } = {}) {
  const mujoco = arm !== null;
  const bytes = new Uint8Array(fs.readFileSync(file));
  const lines = fs.readFileSync(logFile, 'utf8').split('\n').filter((l) => l.length > 0);
  const records = lines.map((l) => JSON.parse(l));

  const reader = new McapStreamReader({ decompressHandlers, validateCrcs: true });
  reader.append(bytes);
  const all = [];
  for (let r; (r = reader.nextRecord()); ) all.push(r);
  assert.ok(reader.done());
  assert.equal(all[0].type, 'Header');
  assert.equal(all[0].profile, 'ros2');
  assert.match(all[0].library, /^rtamp \d+\.\d+\.\d+$/);
  const metadata = all.filter((r) => r.type === 'Metadata');
  assert.equal(metadata.length, 1);
  assert.equal(metadata[0].name, 'rtamp');
  assert.equal(`rtamp ${metadata[0].metadata.get('version')}`, all[0].library);
  assert.equal(metadata[0].metadata.get('scenario'), records[0].scenario);

  const schemas = new Map(), channels = new Map(), byTopic = new Map();
  for (const r of all) {
    if (r.type === 'Schema') {
      assert.equal(r.encoding, 'ros2msg');
      const text = new TextDecoder().decode(r.data);
      const defs = parseMsg(text, { ros2: true });
      // The standard types are ROS 2 Jazzy's, field by field (and so is every dependency).
      for (const [i, d] of defs.entries()) {
        const name = i === 0 ? r.name.replace('/msg/', '/') : d.name.replace('/msg/', '/');
        if (name.startsWith('rtamp_msgs/')) continue;
        assert.ok(ros2jazzy[name], `${name} is a standard type`);
        assert.deepEqual(fieldsOf({ definitions: d.definitions }), fieldsOf(ros2jazzy[name]), `${name}: the definition is ROS 2's`);
      }
      schemas.set(r.id, { name: r.name, defs, reader: new MessageReader(defs), writer: new MessageWriter(defs) });
    } else if (r.type === 'Channel') {
      assert.ok(schemas.has(r.schemaId), `schema before channel ${r.topic}`);
      assert.equal(r.messageEncoding, 'cdr');
      const qos = r.metadata.get('offered_qos_profiles');
      assert.match(qos, /^- history: 1\n  depth: \d+\n  reliability: 1\n  durability: [12]\n/);
      assert.equal(/durability: 1/.test(qos), r.topic === '/tf_static' || r.topic === '/robot_description', `${r.topic}: latched or not`);
      channels.set(r.id, r);
    } else if (r.type === 'Message') {
      const ch = channels.get(r.channelId);
      assert.ok(ch, 'channel before message');
      const s = schemas.get(ch.schemaId);
      assert.deepEqual([...r.data.subarray(0, 4)], [0, 1, 0, 0], 'CDR little-endian encapsulation');
      const value = s.reader.readMessage(r.data);
      const again = s.writer.writeMessage(value);
      assert.deepEqual(Buffer.from(again).toString('hex'), Buffer.from(r.data).toString('hex'), `${ch.topic}: ${s.name} written back the same`);
      if (!byTopic.has(ch.topic)) byTopic.set(ch.topic, []);
      byTopic.get(ch.topic).push({ value, logTime: r.logTime, type: s.name });
    }
  }
  // The summary agrees (and @mcap/core's indexed reader accepts the file).
  const indexed = await McapIndexedReader.Initialize({ readable: { size: async () => BigInt(bytes.length),
    read: async (o, n) => bytes.subarray(Number(o), Number(o + n)) }, decompressHandlers });
  assert.equal(indexed.header.profile, 'ros2');
  assert.equal(Number(indexed.statistics.metadataCount), 1);
  let total = 0;
  for (const list of byTopic.values()) total += list.length;
  assert.equal(Number(indexed.statistics.messageCount), total);

  const topic = (t) => byTopic.get(t) ?? [];
  // Types and the log.
  const types = new Map([...channels.values()].map((c) => [c.topic, schemas.get(c.schemaId).name]));
  assert.equal(types.get('/joint_states'), 'sensor_msgs/msg/JointState');
  assert.equal(types.get('/tf'), 'tf2_msgs/msg/TFMessage');
  assert.equal(types.get('/markers'), 'visualization_msgs/msg/MarkerArray');
  assert.equal(types.get('/rosout'), 'rcl_interfaces/msg/Log');
  assert.deepEqual(topic('/rtamp/log').map((m) => m.value.data), lines, '/rtamp/log is the log');
  const count = (ev) => records.filter((r) => r.ev === ev).length;
  assert.equal(topic('/rtamp/plan').length, count('plan'));
  assert.equal(topic('/rtamp/automaton').length, count('run'));
  assert.equal(topic('/rtamp/intervention').length, count('intervention'));
  assert.equal(topic('/rtamp/task').length, count('task'));
  assert.equal(topic('/rosout').length, records.filter((r) => !['tick', 'run', 'perceived', 'frame', 'camera'].includes(r.ev)).length);
  for (const [i, p] of topic('/rtamp/plan').entries()) {
    const rec = records.filter((r) => r.ev === 'plan')[i];
    assert.deepEqual(p.value.moves.map((m) => m.action), rec.actions);
    assert.deepEqual(p.value.moves.map((m) => m.cost), rec.costs);
    assert.equal(p.value.cost, rec.cost);
    assert.equal(BigInt(p.value.header.stamp.sec) * 1000000000n + BigInt(p.value.header.stamp.nanosec), p.logTime);
  }
  for (const [i, m] of topic('/rtamp/intervention').entries()) {
    const rec = records.filter((r) => r.ev === 'intervention')[i];
    assert.equal(m.value.kind, rec.kind);
    assert.equal(m.value.subject, rec.subject);
    assert.equal(m.value.applied, rec.applied);
  }

  // The robot: its URDF, its fixed frames, and the arm's /tf = the URDF's joints at /joint_states.
  const [description] = topic('/robot_description');
  assert.ok(description, 'a robot description');
  const joints = urdfJoints(description.value.data);
  assert.deepEqual([...joints.values()].filter((j) => j.type === 'revolute').map((j) => j.name),
    ['shoulder_pan_joint', 'shoulder_lift_joint', 'elbow_joint', 'wrist_1_joint', 'wrist_2_joint', 'wrist_3_joint']);
  const fixed = topic('/tf_static').flatMap((m) => m.value.transforms);
  assert.deepEqual(fixed.map((t) => [t.header.frame_id, t.child_frame_id]),
    [['world', 'ur5/base'], ...(mujoco ? [['ur5/link6', 'ur5/flange'], ['ur5/flange', 'ur5/tool']] : [])]);
  for (const t of fixed.slice(1)) sameTransform(t.transform, joints.get(t.child_frame_id).origin, t.child_frame_id);
  const states = topic('/joint_states'), tfs = topic('/tf');
  if (mujoco) {
    if (arm === 'ticks') assert.equal(states.length, count('tick') + 1, 'a joint state where the arm starts and after each tick');
    else {
      const withQ = records.filter((r) => r.ev === 'frame' && Array.isArray(r.q));
      assert.equal(states.length, withQ.length, 'a joint state per frame record');
      for (const [i, s] of states.entries()) {
        assert.deepEqual([...s.value.position], withQ[i].q, 'the frame record\'s joint angles');
        assert.equal(s.logTime, BigInt(Math.round(withQ[i].t * 1e9)));
      }
    }
    const armTfs = tfs.filter((m) => m.value.transforms.some((t) => t.child_frame_id === 'ur5/link1'));
    assert.equal(armTfs.length, states.length);
    for (const [i, s] of states.entries()) {
      assert.equal(armTfs[i].logTime, s.logTime);
      for (let k = 1; k <= 6; ++k) {
        const t = armTfs[i].value.transforms.find((x) => x.child_frame_id === `ur5/link${k}`);
        const j = joints.get(`ur5/link${k}`);
        assert.equal(t.header.frame_id, j.parent);
        const q = s.value.position[s.value.name.indexOf(j.name)];
        sameTransform(t.transform, compose(j.origin, { translation: { x: 0, y: 0, z: 0 }, rotation: fromRpy(0, 0, q) }), `link${k}`);
      }
    }
  } else {
    assert.equal(states.length, 0, 'the symbolic world has no joint angles');
  }

  // One root: every frame's chain of parents ends at world.
  const parent = new Map();
  for (const m of [...topic('/tf_static'), ...tfs]) for (const t of m.value.transforms) parent.set(t.child_frame_id, t.header.frame_id);
  for (const child of parent.keys()) {
    let f = child;
    for (let hops = 0; parent.has(f); ++hops) { f = parent.get(f); assert.ok(hops < 50, 'no cycle'); }
    assert.equal(f, 'world', `${child}'s root`);
  }

  // The things: a marker for each, and at the end each block in the region the log says.
  const scene = (m) => new Map(m.value.transforms.filter((t) => t.child_frame_id.startsWith('thing/')).map((t) => [t.child_frame_id.slice(6), t]));
  const sceneFrames = tfs.filter((m) => scene(m).size > 0);
  assert.ok(sceneFrames.length > 0);
  const last = scene(sceneFrames.at(-1));
  const end = records.at(-1);
  // The regions as the markers draw them (each box, and its label with the region's name).
  const regions = new Map();
  for (const m of topic('/markers')) for (const k of m.value.markers) if (k.ns === 'regions') regions.set(k.id, k);
  const regionLabels = new Map();
  for (const m of topic('/markers')) for (const k of m.value.markers) if (k.ns === 'regions_labels') regionLabels.set(k.text, regions.get(k.id - 1));
  let placed = 0;
  for (const [thing, where] of Object.entries(end.placement)) {
    if (!regionLabels.has(where)) continue;
    ++placed;
    const t = last.get(thing), r = regionLabels.get(where);
    assert.ok(t, `${thing} is on /tf at the end`);
    assert.equal(t.header.frame_id, 'world');
    const p = t.transform.translation;
    assert.ok(Math.abs(p.x - r.pose.position.x) <= r.scale.x / 2 + 1e-6 && Math.abs(p.y - r.pose.position.y) <= r.scale.y / 2 + 1e-6,
      `${thing} at (${p.x}, ${p.y}) is in ${where}`);
  }
  assert.ok(placed > 0, `${placed} things checked in their end regions`);
  const drawn = new Set();
  for (const m of topic('/markers')) for (const k of m.value.markers) if (k.ns === 'things' && k.action === 0) drawn.add(k.header.frame_id);
  for (const name of last.keys()) assert.ok(drawn.has(`thing/${name}`), `${name} has a marker`);
  // While the log's percept says a thing is in the hand, the arm's /tf carries it (MuJoCo).
  if (mujoco) {
    let held = 0;
    const perceived = records.filter((r) => r.ev === 'perceived');
    for (const m of sceneFrames) {
      const seen = perceived.filter((r) => BigInt(Math.round(r.t * 1e9)) <= m.logTime).at(-1);
      if (!seen) continue;
      for (const [thing, t] of scene(m)) {
        if (seen.placement[thing] !== 'hand' || t.header.frame_id !== 'ur5/tool') continue;
        ++held;
        const p = t.transform.translation;
        assert.ok(Math.hypot(p.x, p.y, p.z) < 0.1, `${thing} held within 10 cm of the fingertips`);
      }
    }
    if (holds) assert.ok(held > 0, 'a held block hangs from ur5/tool');
    // Where a thing changes hands (world -> ur5/tool at a grasp, back at a release), its
    // world pose composed through the arm's chain (/tf_static, the frame's /tf) is where it
    // was one tick before: the held transform is the world pose in the gripper's frame.
    const statics = new Map(fixed.map((t) => [t.child_frame_id, t.transform]));
    const toolInWorld = (m) => {
      const links = new Map(m.value.transforms.map((t) => [t.child_frame_id, t.transform]));
      let t = statics.get('ur5/base');
      for (let k = 1; k <= 6; ++k) t = compose(t, links.get(`ur5/link${k}`));
      return compose(compose(t, statics.get('ur5/flange')), statics.get('ur5/tool'));
    };
    const inWorld = (m, t) => (t.header.frame_id === 'world' ? t.transform : compose(toolInWorld(m), t.transform));
    let handovers = 0;
    for (let i = 1; arm === 'ticks' && i < sceneFrames.length; ++i) {  // one tick apart (frame records are 0.5 s)
      const before = scene(sceneFrames[i - 1]), after = scene(sceneFrames[i]);
      for (const [thing, t] of after) {
        const b = before.get(thing);
        if (!b || b.header.frame_id === t.header.frame_id) continue;
        ++handovers;
        const p = inWorld(sceneFrames[i - 1], b).translation, q = inWorld(sceneFrames[i], t).translation;
        assert.ok(Math.hypot(p.x - q.x, p.y - q.y, p.z - q.z) < 0.01, `${thing} moves ${Math.hypot(p.x - q.x, p.y - q.y, p.z - q.z)} m as it changes hands`);
      }
    }
    if (holds && arm === 'ticks') assert.ok(handovers >= 2, `${handovers} grasps and releases`);
    // A converted log's things are where its frame records put them (held ones too, through the chain).
    if (arm === 'frames') {
      const frameRecords = records.filter((r) => r.ev === 'frame');
      assert.equal(sceneFrames.length, frameRecords.length);
      for (const [i, m] of sceneFrames.entries()) {
        const things = scene(m);
        for (const x of frameRecords[i].things.filter((x) => x.at !== 'none')) {
          const t = things.get(x.name);
          assert.ok(t, `${x.name} on /tf`);
          const w = inWorld(m, t);
          for (const [k, j] of [['x', 0], ['y', 1], ['z', 2]]) near(w.translation[k], x.pos[j], 1e-9, `${x.name}.${k}`);
          assert.equal(t.header.frame_id, x.at === 'hand' ? 'ur5/tool' : 'world');
        }
      }
    }
  }
  return { byTopic, records };
}

// Symbolic, live and converted: the same rtamp topics, byte for byte.
{
  const log = path.join(tmp, 'sym.jsonl'), live = path.join(tmp, 'sym.mcap'), conv = path.join(tmp, 'sym-conv.mcap');
  rtamp(['run', '3-block-tray', '--world', 'symbolic', '--quiet', '--log', log, '--mcap', live, '--mcap-profile', 'ros2']);
  const a = await check(live, log);
  rtamp(['log', 'to-mcap', log, conv, '--mcap-profile', 'ros2', '--compression', 'lz4']);
  const b = await check(conv, log);
  for (const t of ['/rtamp/plan', '/rtamp/tree', '/rtamp/automaton', '/rtamp/intervention', '/rosout', '/robot_description', '/tf_static'])
    assert.deepEqual(b.byTopic.get(t), a.byTopic.get(t), `${t}: converted = live`);
  console.log(`ok symbolic: ${a.records.length} records, ${a.byTopic.get('/tf').length} /tf messages`);
}

// A served episode, live and its log converted: the converted file's arm and things are the
// log's `frame` records (the symbolic world's arm is serve's inverse kinematics of the tool).
{
  const log = path.join(tmp, 'served.jsonl'), live = path.join(tmp, 'served.mcap'), conv = path.join(tmp, 'served-conv.mcap');
  rtamp(['serve', '3-block-tray', '--world', 'symbolic', '--speed', '0', '--exit-at-end', '--port', '0', '--quiet',
    '--web-root', tmp, '--log', log, '--mcap', live, '--mcap-profile', 'ros2'], 'ran');
  assert.ok(fs.readFileSync(log, 'utf8').includes('"ev":"frame"'));
  await check(live, log);
  rtamp(['log', 'to-mcap', log, conv, '--mcap-profile', 'ros2']);
  const r = await check(conv, log, { arm: 'frames', holds: true });
  console.log(`ok serve: ${r.byTopic.get('/joint_states').length} joint states from frame records`);
}

// MuJoCo: the arm and the world's poses at every tick.
{
  const log = path.join(tmp, 'mj.jsonl'), out = path.join(tmp, 'mj.mcap');
  rtamp(['run', '3-block', '--quiet', '--log', log, '--mcap', out, '--mcap-profile', 'ros2', '--mcap-compression', 'none'], 'ran');
  const r = await check(out, log, { arm: 'ticks' });
  console.log(`ok mujoco: ${r.byTopic.get('/joint_states').length} joint states`);
}

// A camera episode: the image, its calibration and the camera in the transform tree, so
// that a block's pose on /tf projects into the picture (and the PNG decodes to the size).
{
  const log = path.join(tmp, 'cam.jsonl'), out = path.join(tmp, 'cam.mcap');
  rtamp(['run', '3-block-tray', '--perception', 'camera', '--max-time', '3', '--quiet', '--log', log, '--mcap', out,
    '--mcap-profile', 'ros2', '--mcap-image-period', '1'], 'ran');
  const { byTopic, records } = await check(out, log, { arm: 'ticks', holds: false });  // 3 s: nothing picked yet
  const { PNG } = await import('pngjs');
  const frames = records.filter((r) => r.ev === 'camera');
  const camera = frames[0].camera;
  const images = byTopic.get(`/camera/${camera}/image/compressed`), infos = byTopic.get(`/camera/${camera}/camera_info`);
  let lastT = -Infinity;
  const expected = [];
  for (const f of frames) if (f.t + 1e-9 >= lastT + 1) expected.push(BigInt(Math.round(f.t * 1e9))), (lastT = f.t);
  assert.deepEqual(images.map((m) => m.logTime), expected, 'one image a world second');
  assert.deepEqual(infos.map((m) => m.logTime), expected);
  let projected = 0;
  for (const [i, m] of images.entries()) {
    assert.equal(m.value.format, 'png');
    assert.equal(m.value.header.frame_id, `camera/${camera}`);
    const png = PNG.sync.read(Buffer.from(m.value.data));
    const info = infos[i].value;
    assert.deepEqual([png.width, png.height], [info.width, info.height]);
    // Where the camera was, and a block seen then: its base centre in the image.
    const cam = byTopic.get('/tf').flatMap((x) => x.logTime === m.logTime ? x.value.transforms : []).find((t) => t.child_frame_id === `camera/${camera}`);
    assert.ok(cam, 'the camera is on /tf at its image time');
    const scene = byTopic.get('/tf').filter((x) => x.logTime <= m.logTime && x.value.transforms.some((t) => t.child_frame_id === 'thing/o1')).at(-1);
    const o1 = scene.value.transforms.find((t) => t.child_frame_id === 'thing/o1');
    if (o1.header.frame_id !== 'world') continue;
    const inv = { w: cam.transform.rotation.w, x: -cam.transform.rotation.x, y: -cam.transform.rotation.y, z: -cam.transform.rotation.z };
    const d = { x: o1.transform.translation.x - cam.transform.translation.x, y: o1.transform.translation.y - cam.transform.translation.y,
      z: o1.transform.translation.z - cam.transform.translation.z };
    const c = rotate(inv, d);
    assert.ok(c.z > 0, 'the block is in front of the camera');
    const [fx, , cx, , fy, cy] = info.k;
    const u = fx * c.x / c.z + cx, v = fy * c.y / c.z + cy;
    assert.ok(u >= 0 && u < info.width && v >= 0 && v < info.height, `o1 projects to (${u}, ${v}) inside the image`);
    ++projected;
  }
  assert.ok(projected > 0);
  console.log(`ok camera: ${images.length} images, o1 projected into ${projected}`);
}

// A batch writes each episode's ros2 file beside its log.
{
  const dir = path.join(tmp, 'batch');
  rtamp(['batch', '3-block', '--world', 'symbolic', '-n', '1', '--log-dir', dir, '--mcap', '--mcap-profile', 'ros2']);
  const files = fs.readdirSync(dir).filter((f) => f.endsWith('.mcap'));
  assert.ok(files.length >= 3);
  for (const f of files) await check(path.join(dir, f), path.join(dir, f.replace(/\.mcap$/, '.jsonl')));
  console.log(`ok batch: ${files.length} files`);
}

// Bad input: one line naming the option, exit 2, no file.
{
  const out = path.join(tmp, 'bad.mcap');
  const r = rtamp(['run', '3-block', '--world', 'symbolic', '--mcap', out, '--mcap-profile', 'ros1'], 2);
  assert.match(r.stderr, /^rtamp: error: --mcap-profile: unknown value 'ros1'/);
  assert.equal(r.stderr.trim().split('\n').length, 1);
  assert.ok(!fs.existsSync(out));
  const r2 = rtamp(['log', 'to-mcap', 'x.jsonl', out, '--mcap-profile', 'cdr'], 2);
  assert.match(r2.stderr, /--mcap-profile/);
  console.log('ok bad input');
}
fs.rmSync(tmp, { recursive: true, force: true });
console.log('mcap_ros2: all ok');
