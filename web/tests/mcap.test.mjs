// rtamp's MCAP files read back by a real reader, the npm @mcap/core package:
//   RTAMP_BIN=build/bin/rtamp node tests/mcap.test.mjs [TMPDIR]
// Episodes are run with `--log` and `--mcap` (symbolic world; zstd, lz4 and
// uncompressed chunks) and logs converted with `rtamp log to-mcap`. Each file is
// read twice: record by record (McapStreamReader: every record parses, chunk
// CRCs are checked, schemas and channels come before their messages) and through
// its summary (McapIndexedReader: the summary CRC, statistics, chunk indexes,
// message indexes), and the data-section CRC is recomputed here. Oracles: the
// /rtamp/log channel holds exactly the JSON Lines records, in order; message counts
// equal the statistics; every message satisfies its channel's JSON Schema, and a
// foxglove.* schema is a part of the npm @foxglove/schemas one of that name, whose
// whole schema every message satisfies too; the MuJoCo arm's joint states and
// frame transforms (`rtamp run` and `rtamp batch`) one per tick, a rigid chain;
// every task in force (an episode with `--new-task`) on /task and /automaton as the
// log's `episode` and `task` records give them.
// Bad input: a malformed log and an unwritable --mcap give one line and exit 2.
import assert from 'node:assert/strict';
import { execFileSync, spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import zlib from 'node:zlib';
import { createRequire } from 'node:module';
import { McapIndexedReader, McapStreamReader } from '@mcap/core';

// Foxglove's own JSON Schemas (npm @foxglove/schemas), by title ("foxglove.SceneUpdate").
const foxglove = new Map(Object.values(createRequire(import.meta.url)('@foxglove/schemas/jsonschema')).map((s) => [s.title, s]));

// The JSON Schema keywords those schemas use: type, properties, required, items,
// oneOf of consts, minimum, maximum. Returns the first violation, or null.
function violation(value, schema, where = '$') {
  const types = { object: (v) => v !== null && typeof v === 'object' && !Array.isArray(v), array: Array.isArray,
    string: (v) => typeof v === 'string', number: (v) => typeof v === 'number', boolean: (v) => typeof v === 'boolean',
    integer: Number.isInteger };
  if (schema.type && !types[schema.type](value)) return `${where}: not ${schema.type}`;
  if (schema.oneOf && schema.oneOf.filter((o) => o.const === value).length !== 1) return `${where}: ${value} not one of`;
  if (schema.minimum !== undefined && value < schema.minimum) return `${where}: below ${schema.minimum}`;
  if (schema.maximum !== undefined && value > schema.maximum) return `${where}: above ${schema.maximum}`;
  for (const k of schema.required ?? []) if (!(k in value)) return `${where}: no ${k}`;
  for (const [k, sub] of Object.entries(schema.properties ?? {}))
    if (value[k] !== undefined) { const v = violation(value[k], sub, `${where}.${k}`); if (v) return v; }
  if (schema.items) for (const [i, x] of value.entries()) { const v = violation(x, schema.items, `${where}[${i}]`); if (v) return v; }
  return null;
}

// Every property `ours` declares is in `theirs`, with the same type where theirs has one.
function subschema(ours, theirs, where) {
  if (theirs.type) assert.equal(ours.type, theirs.type, `${where}: type`);
  if (theirs.oneOf) assert.equal(ours.type, 'integer', `${where}: an enumeration`);
  for (const [k, sub] of Object.entries(ours.properties ?? {})) {
    assert.ok(theirs.properties && k in theirs.properties, `${where}.${k} is not in Foxglove's schema`);
    subschema(sub, theirs.properties[k], `${where}.${k}`);
  }
  if (ours.items) subschema(ours.items, theirs.items, `${where}[]`);
}

const bin = process.env.RTAMP_BIN ?? path.resolve('../build/bin/rtamp');
const tmpBase = process.argv[2] ?? process.env.RTAMP_TEST_TMP ?? os.tmpdir();
fs.mkdirSync(tmpBase, { recursive: true });
const tmp = fs.mkdtempSync(path.join(tmpBase, 'mcap-'));

// Chunks are decompressed with Debian's zstd and lz4 programs (node 20 has neither).
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

function streamRecords(bytes) {
  const reader = new McapStreamReader({ decompressHandlers, validateCrcs: true });
  reader.append(bytes);
  const records = [];
  for (let r; (r = reader.nextRecord()); ) records.push(r);
  assert.ok(reader.done(), 'the stream reader reached the end magic');
  return records;
}

async function check(file, logFile, compression, liveArm = false) {
  const bytes = new Uint8Array(fs.readFileSync(file));
  const lines = fs.readFileSync(logFile, 'utf8').split('\n').filter((l) => l.length > 0);

  // Record by record.
  const records = streamRecords(bytes);
  assert.equal(records[0].type, 'Header');
  assert.equal(records[0].profile, '');
  assert.match(records[0].library, /^rtamp \d+\.\d+\.\d+$/, 'the library and its version');
  const metadata = records.filter((r) => r.type === 'Metadata');
  assert.equal(metadata.length, 1, 'one Metadata record');
  assert.equal(metadata[0].name, 'rtamp');
  assert.equal(`rtamp ${metadata[0].metadata.get('version')}`, records[0].library);
  assert.equal(records.at(-1).type, 'Footer');
  const schemas = new Map(), channels = new Map(), counts = new Map();
  const byTopic = new Map();
  let dataEnd;
  for (const r of records) {
    if (r.type === 'Schema') schemas.set(r.id, r);
    else if (r.type === 'Channel') {
      assert.ok(r.schemaId === 0 || schemas.has(r.schemaId), `schema ${r.schemaId} before channel ${r.topic}`);
      channels.set(r.id, r);
    } else if (r.type === 'Message') {
      const ch = channels.get(r.channelId);
      assert.ok(ch, `channel ${r.channelId} before its message`);
      counts.set(r.channelId, (counts.get(r.channelId) ?? 0) + 1);
      const text = new TextDecoder().decode(r.data);
      if (!byTopic.has(ch.topic)) byTopic.set(ch.topic, []);
      byTopic.get(ch.topic).push({ text, logTime: r.logTime });
    } else if (r.type === 'DataEnd') dataEnd = r;
  }
  // Every schema is JSON Schema; a foxglove.* one is Foxglove's (a part of it); every
  // message satisfies its channel's schema, and Foxglove's for a foxglove.* one.
  for (const s of schemas.values()) {
    assert.equal(s.encoding, 'jsonschema');
    s.json = JSON.parse(new TextDecoder().decode(s.data));
    assert.equal(s.json.title, s.name);
    if (s.name.startsWith('foxglove.')) {
      assert.ok(foxglove.has(s.name), `${s.name} is a schema of @foxglove/schemas`);
      subschema(s.json, foxglove.get(s.name), s.name);
    }
  }
  for (const ch of channels.values()) {
    const schema = schemas.get(ch.schemaId);
    for (const m of byTopic.get(ch.topic) ?? []) {
      const j = JSON.parse(m.text);
      assert.equal(violation(j, schema.json), null, `${file}: ${ch.topic}`);
      if (foxglove.has(schema.name)) assert.equal(violation(j, foxglove.get(schema.name)), null, `${file}: ${ch.topic} (Foxglove's ${schema.name})`);
    }
  }

  // The log channel is the log.
  const logged = (byTopic.get('/rtamp/log') ?? []).map((m) => m.text);
  assert.equal(logged.length, lines.length, `${file}: /rtamp/log has every record`);
  assert.deepEqual(logged, lines);

  // Through the summary.
  const readable = {
    size: async () => BigInt(bytes.length),
    read: async (offset, length) => bytes.subarray(Number(offset), Number(offset + length)),
  };
  const indexed = await McapIndexedReader.Initialize({ readable, decompressHandlers });
  const stats = indexed.statistics;
  assert.ok(stats, 'statistics in the summary');
  const total = [...counts.values()].reduce((a, b) => a + b, 0);
  assert.equal(stats.messageCount, BigInt(total));
  assert.equal(stats.channelCount, channels.size);
  assert.equal(stats.schemaCount, schemas.size);
  assert.equal(stats.chunkCount, indexed.chunkIndexes.length);
  for (const [id, n] of counts) assert.equal(stats.channelMessageCounts.get(id), BigInt(n));
  for (const ci of indexed.chunkIndexes) assert.equal(ci.compression, compression === 'none' ? '' : compression);
  let seen = 0;
  const logViaIndex = [];
  for await (const m of indexed.readMessages({ validateCrcs: true })) {
    seen++;
    if (indexed.channelsById.get(m.channelId).topic === '/rtamp/log') logViaIndex.push(new TextDecoder().decode(m.data));
  }
  assert.equal(seen, total, 'the message indexes find every message');
  // Time-ordered through the indexes: the same records, stably sorted by time.
  assert.equal(logViaIndex.length, lines.length);
  assert.deepEqual([...logViaIndex].sort(), [...lines].sort());
  const topics = new Set([...indexed.channelsById.values()].map((c) => c.topic));
  for (const t of ['/rtamp/log', '/scene', '/joint_states', '/tf', '/plan', '/tree', '/task', '/automaton', '/automaton/tracked', '/timeline', '/interventions', '/replans'])
    assert.ok(topics.has(t), `channel ${t}`);

  // The data-section CRC: every byte before the DataEnd record.
  const dataEndAt = Number(indexed.footer.summaryStart) - 13;
  assert.ok(dataEnd && dataEnd.dataSectionCrc !== 0);
  assert.equal(zlib.crc32(bytes.subarray(0, dataEndAt)), dataEnd.dataSectionCrc, 'data section CRC');

  // Foxglove messages carry their schemas' fields.
  const schemaOf = (topic) => schemas.get([...channels.values()].find((c) => c.topic === topic).schemaId).name;
  assert.equal(schemaOf('/timeline'), 'foxglove.Log');
  assert.equal(schemaOf('/scene'), 'foxglove.SceneUpdate');
  assert.equal(schemaOf('/tf'), 'foxglove.FrameTransforms');
  for (const m of byTopic.get('/timeline') ?? []) {
    const j = JSON.parse(m.text);
    assert.ok(Number.isInteger(j.level) && typeof j.message === 'string' && Number.isInteger(j.timestamp.sec));
    assert.equal(BigInt(j.timestamp.sec) * 1000000000n + BigInt(j.timestamp.nsec), m.logTime);
  }
  const scene = (byTopic.get('/scene') ?? []).map((m) => JSON.parse(m.text));
  assert.ok(scene.length > 0, 'the scene is drawn');
  const last = scene.at(-1);
  assert.ok(last.entities.some((e) => e.id.startsWith('region/') && e.cubes.length === 1));
  assert.ok(last.entities.some((e) => e.id.startsWith('thing/') && e.cubes[0].size.x > 0));
  const plans = (byTopic.get('/plan') ?? []).map((m) => JSON.parse(m.text));
  assert.equal(plans.length, lines.filter((l) => JSON.parse(l).ev === 'plan').length);
  assert.ok(plans.every((p) => Array.isArray(p.actions)));
  const interventions = lines.filter((l) => JSON.parse(l).ev === 'intervention').length;
  assert.equal((byTopic.get('/interventions') ?? []).length, interventions);
  assert.equal((byTopic.get('/replans') ?? []).length, lines.filter((l) => JSON.parse(l).ev === 'replan').length);
  assert.equal((byTopic.get('/automaton/tracked') ?? []).length, lines.filter((l) => JSON.parse(l).ev === 'run').length);
  // Every task in force (the episode's, then each applied change), in time order, with
  // its automaton as the log's record has it, on /task and /automaton.
  const inForce = lines.map((l) => JSON.parse(l)).filter((r) => r.ev === 'episode' || (r.ev === 'task' && r.applied));
  const tasks = byTopic.get('/task') ?? [], automata = byTopic.get('/automaton') ?? [];
  assert.equal(tasks.length, inForce.length, `${file}: /task`);
  assert.equal(automata.length, inForce.length, `${file}: /automaton`);
  inForce.forEach((r, i) => {
    const task = JSON.parse(tasks[i].text), automaton = JSON.parse(automata[i].text);
    assert.equal(tasks[i].logTime, BigInt(Math.round(r.t * 1e9)));
    assert.equal(automata[i].logTime, tasks[i].logTime);
    if (i > 0) assert.ok(tasks[i].logTime >= tasks[i - 1].logTime, 'in time order');
    assert.equal(task.task, r.task);
    assert.equal(task.by, r.ev === 'episode' ? 'scenario' : r.by);
    assert.equal(task.automaton_states, r.automaton_states);
    assert.deepEqual(task.automaton, r.automaton);
    assert.deepEqual({ states: automaton.states, edges: automaton.edges, state_based: automaton.state_based }, r.automaton);
    assert.equal(automaton.task, r.task);
  });
  const timeline = (byTopic.get('/timeline') ?? []).map((m) => JSON.parse(m.text).message);
  assert.equal(timeline.filter((m) => m.startsWith('new task from ')).length, lines.filter((l) => JSON.parse(l).ev === 'task').length);
  assert.equal(timeline.filter((m) => m.startsWith('redirected ')).length, lines.filter((l) => JSON.parse(l).ev === 'redirect').length);

  // The arm: joint states from the live MuJoCo world (where it starts, then after each
  // tick) or from `frame` records with joint angles; /tf a chain world -> ur5/base ->
  // ur5/link1 .. link6 at the same times. Each link's offset in its parent has a
  // constant length (a rigid arm), which link frames given in the world would not.
  const logRecords = lines.map((l) => JSON.parse(l));
  const joints = byTopic.get('/joint_states') ?? [], tfs = byTopic.get('/tf') ?? [];
  assert.equal(joints.length, liveArm ? logRecords.filter((r) => r.ev === 'tick').length + 1
    : logRecords.filter((r) => r.ev === 'frame' && Array.isArray(r.q)).length, `${file}: /joint_states`);
  assert.deepEqual(tfs.map((m) => m.logTime), joints.map((m) => m.logTime));
  const lengths = [];
  for (const [k, m] of tfs.entries()) {
    const j = JSON.parse(joints[k].text);
    assert.deepEqual(j.joints.map((x) => x.name), ['shoulder_pan_joint', 'shoulder_lift_joint', 'elbow_joint', 'wrist_1_joint', 'wrist_2_joint', 'wrist_3_joint']);
    const { transforms } = JSON.parse(m.text);
    assert.deepEqual(transforms.map((t) => t.child_frame_id), ['ur5/base', 'ur5/link1', 'ur5/link2', 'ur5/link3', 'ur5/link4', 'ur5/link5', 'ur5/link6']);
    transforms.forEach((t, i) => {
      assert.equal(t.parent_frame_id, i === 0 ? 'world' : transforms[i - 1].child_frame_id);
      const { x, y, z, w } = t.rotation;
      assert.ok(Math.abs(Math.hypot(x, y, z, w) - 1) < 1e-9, 'a unit quaternion');
      const length = Math.hypot(t.translation.x, t.translation.y, t.translation.z);
      if (k === 0) lengths.push(length);
      else assert.ok(Math.abs(length - lengths[i]) < 1e-9, `${t.child_frame_id}: offset ${length} != ${lengths[i]}`);
    });
  }
  return { total, topics: byTopic, joints: joints.length };
}

const runs = [
  { name: 'tray', args: ['3-block-tray', '--world', 'symbolic', '--rate', '0.2', '--seed', '3'], compression: 'zstd' },
  { name: 'lz4', args: ['3-block', '--world', 'symbolic', '--rate', '0.3', '--seed', '5'], compression: 'lz4' },
  { name: 'none', args: ['3-block-tray', '--world', 'symbolic', '--change', 'add', '--seed', '7'], compression: 'none' },
  // Two task changes, the first redirecting the carry of o1 to r2.
  { name: 'tasks', args: ['3-block', '--world', 'symbolic', '--new-task', '1@G "o1 in r1" & F G "o2 in r2"', '--new-task', '6@F G "o3 in r2"'],
    compression: 'zstd', tasks: 3 },
];
for (const r of runs) {
  const log = path.join(tmp, `${r.name}.jsonl`), live = path.join(tmp, `${r.name}.mcap`);
  rtamp(['run', ...r.args, '--quiet', '--log', log, '--mcap', live, '--mcap-compression', r.compression], 'ran');
  const live1 = await check(live, log, r.compression);
  if (r.tasks) assert.equal(live1.topics.get('/task').length, r.tasks, `${r.name}: every task in force`);
  for (const c of ['zstd', 'lz4', 'none']) {
    const converted = path.join(tmp, `${r.name}-${c}.mcap`);
    rtamp(['log', 'to-mcap', log, converted, '--compression', c]);
    await check(converted, log, c);
  }
  // The live file and the converted one hold the same messages.
  const a = await check(live, log, r.compression), b = await check(path.join(tmp, `${r.name}-${r.compression}.mcap`), log, r.compression);
  for (const [topic, msgs] of a.topics) assert.deepEqual(msgs.map((m) => m.text), b.topics.get(topic).map((m) => m.text), topic);
  console.log(`ok ${r.name}: ${a.total} messages`);
}

// Many records (a recurring task: the blocks between r1 and r2), small chunks: many of them.
{
  const patrol = path.join(tmp, 'patrol.yaml');
  fs.writeFileSync(patrol, fs.readFileSync(path.resolve('../scenarios/3-block.yaml'), 'utf8')
    .replace('  all_in_r2: "all block in r2"', '  all_in_r2: "all block in r2"\n  all_in_r1: "all block in r1"')
    .replace('task: "F G all_in_r2"', 'task: "G F all_in_r2 & G F all_in_r1"'));
  const log = path.join(tmp, 'long.jsonl'), out = path.join(tmp, 'long.mcap');
  rtamp(['run', patrol, '--world', 'symbolic', '--cycles', '40', '--rate', '0.05', '--quiet', '--log', log], 'ran');
  rtamp(['log', 'to-mcap', log, out, '--chunk-kib', '8', '--scenario', patrol]);
  const { total } = await check(out, log, 'zstd');
  const chunks = streamRecords(new Uint8Array(fs.readFileSync(out))).filter((r) => r.type === 'ChunkIndex').length;
  assert.ok(chunks > 3, `${chunks} chunks`);
  console.log(`ok long: ${total} messages in ${chunks} chunks`);
}

// A served episode (its log has `frame` records): the same checks.
{
  const log = path.join(tmp, 'served.jsonl'), out = path.join(tmp, 'served.mcap');
  rtamp(['serve', '3-block-tray', '--world', 'symbolic', '--speed', '0', '--exit-at-end', '--port', '0', '--quiet',
    '--web-root', tmp, '--log', log, '--mcap', out], 'ran');
  assert.ok(fs.readFileSync(log, 'utf8').includes('"ev":"frame"'));
  const { total } = await check(out, log, 'zstd');
  console.log(`ok serve: ${total} messages`);
}

// A batch writes one MCAP file beside each episode's log.
{
  const dir = path.join(tmp, 'batch');
  rtamp(['batch', '3-block-tray', '--world', 'symbolic', '--trials', '2', '--algo', 'astar', '--bt', 'online-action',
    '--log-dir', dir, '--mcap', '-q', '-o', path.join(tmp, 'batch.csv')]);
  const logs = fs.readdirSync(dir).filter((f) => f.endsWith('.jsonl'));
  assert.ok(logs.length >= 2);
  for (const l of logs) await check(path.join(dir, l.replace(/\.jsonl$/, '.mcap')), path.join(dir, l), 'zstd');
  const r = rtamp(['batch', '3-block-tray', '--world', 'symbolic', '--trials', '1', '--mcap', '-q'], 2);
  assert.match(r.stderr, /--mcap.*--log-dir/);
  console.log(`ok batch: ${logs.length} episodes`);
}

// The MuJoCo UR5, run and in a batch: the files have the arm (joint states and frames
// after each tick), which the log's conversion has not.
{
  const log = path.join(tmp, 'mujoco.jsonl'), live = path.join(tmp, 'mujoco.mcap'), converted = path.join(tmp, 'mujoco-converted.mcap');
  rtamp(['run', '3-block', '--quiet', '--log', log, '--mcap', live], 'ran');
  const { joints } = await check(live, log, 'zstd', true);
  assert.ok(joints > 10, `${joints} joint states`);
  rtamp(['log', 'to-mcap', log, converted]);
  await check(converted, log, 'zstd');
  const dir = path.join(tmp, 'mujoco-batch');
  rtamp(['batch', '3-block', '--trials', '1', '--change', 'none', '--algo', 'astar', '--log-dir', dir, '--mcap', '-q', '-o', path.join(tmp, 'mujoco-batch.csv')]);
  const logs = fs.readdirSync(dir).filter((f) => f.endsWith('.jsonl'));
  assert.equal(logs.length, 1);
  for (const l of logs) await check(path.join(dir, l.replace(/\.jsonl$/, '.mcap')), path.join(dir, l), 'zstd', true);
  console.log(`ok mujoco: ${joints} joint states`);
}

// Camera perception: per camera, its images (foxglove.CompressedImage, PNG) and the
// detections' boxes (foxglove.ImageAnnotations), one image a world second by default
// (--mcap-image-period 1): the first frame's, then the first frame 1 s or more after the
// last written; every frame with 0; none (no camera channels) with inf. The check above
// holds both to Foxglove's schemas; here the PNGs are decoded (pngjs) to the camera's
// size and every box lies inside its image.
{
  const run = (period) => {
    const log = path.join(tmp, `camera-${period}.jsonl`), out = path.join(tmp, `camera-${period}.mcap`);
    rtamp(['run', '3-block-tray', '--perception', 'camera', '--max-time', '3', '--quiet', '--log', log, '--mcap', out,
      '--mcap-image-period', period], 'ran');
    return { log, out, frames: fs.readFileSync(log, 'utf8').split('\n').filter((l) => l.includes('"ev":"camera"')).map((l) => JSON.parse(l)) };
  };
  const { PNG } = await import('pngjs');
  const nanos = (s) => BigInt(s.sec) * 1000000000n + BigInt(s.nsec);
  const one = run('1');
  const { topics } = await check(one.out, one.log, 'zstd', true);
  const camera = one.frames[0].camera;
  const images = topics.get(`/camera/${camera}/image`), boxes = topics.get(`/camera/${camera}/annotations`);
  let last = -Infinity;
  const expected = [];
  for (const f of one.frames) if (f.t + 1e-9 >= last + 1) expected.push(BigInt(Math.round(f.t * 1e9))), (last = f.t);
  assert.equal(images.length, expected.length, 'one image a world second');
  assert.deepEqual(images.map((m) => m.logTime), expected);
  assert.deepEqual(boxes.map((m) => m.logTime), expected);
  // The scenario names no cameras: the default overhead one, 640 x 480.
  for (const [i, m] of images.entries()) {
    const j = JSON.parse(m.text);
    assert.equal(j.format, 'png');
    assert.equal(j.frame_id, `camera/${camera}`);
    const png = Buffer.from(j.data, 'base64');
    assert.deepEqual([...png.subarray(0, 8)], [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a], 'the PNG signature');
    assert.equal(png.subarray(12, 16).toString('latin1'), 'IHDR');
    assert.deepEqual([png.readUInt32BE(16), png.readUInt32BE(20)], [640, 480], 'the header says 640 x 480');
    const decoded = PNG.sync.read(png);
    assert.deepEqual([decoded.width, decoded.height], [640, 480]);
    const a = JSON.parse(boxes[i].text);
    assert.ok(a.points.length >= 3, `${a.points.length} boxes: the blocks are in view`);
    assert.equal(a.texts.length, a.points.length);
    for (const b of a.points) {
      assert.equal(nanos(b.timestamp), m.logTime);
      assert.equal(b.type, 2);
      for (const p of b.points) assert.ok(p.x >= 0 && p.x <= 640 && p.y >= 0 && p.y <= 480, `(${p.x}, ${p.y}) inside the image`);
    }
    for (const t of a.texts) assert.match(t.text, /^\S+ (visible|occluded|held|out-of-view|missing|new)$/);
  }
  const every = run('0');
  const all = await check(every.out, every.log, 'zstd', true);
  assert.equal(all.topics.get(`/camera/${camera}/image`).length, every.frames.length, 'every frame');
  const none = run('inf');
  const noImages = await check(none.out, none.log, 'zstd', true);
  assert.ok(!noImages.topics.has(`/camera/${camera}/image`) && none.frames.length > 0, 'no images');
  const bad = rtamp(['run', '3-block-tray', '--perception', 'camera', '--mcap-image-period', '-1', '--mcap', path.join(tmp, 'bad-period.mcap')], 2);
  assert.match(bad.stderr, /^rtamp: error: --mcap-image-period: /);
  assert.ok(!fs.existsSync(path.join(tmp, 'bad-period.mcap')));
  console.log(`ok camera: ${images.length} images (${one.frames.length} frames), ${all.topics.get(`/camera/${camera}/image`).length} with period 0`);
}

// Bad input: one line naming what and where, exit 2, no output left behind.
{
  const bad = path.join(tmp, 'bad.jsonl'), out = path.join(tmp, 'bad.mcap');
  fs.writeFileSync(bad, '{"ev":"episode","t":0}\n{"ev":"tick","t":0.1\n');
  const r = rtamp(['log', 'to-mcap', bad, out], 2);
  assert.match(r.stderr, /bad\.jsonl:2: /);
  assert.equal(r.stderr.trim().split('\n').length, 1);
  assert.ok(!fs.existsSync(out));
  const r2 = rtamp(['run', '3-block', '--world', 'symbolic', '--quiet', '--mcap', path.join(tmp, 'no-such-dir', 'x.mcap')], 2);
  assert.match(r2.stderr, /--mcap/);
  assert.equal(r2.stderr.trim().split('\n').length, 1);
  console.log('ok bad input');
}
fs.rmSync(tmp, { recursive: true, force: true });
console.log('mcap: all ok');
