// rtamp's MCAP files read back by a real reader, the npm @mcap/core package:
//   RTAMP_BIN=build/bin/rtamp node tests/mcap.test.mjs [TMPDIR]
// Episodes are run with `--log` and `--mcap` (symbolic world; zstd, lz4 and
// uncompressed chunks) and logs converted with `rtamp log to-mcap`. Each file is
// read twice: record by record (McapStreamReader: every record parses, chunk
// CRCs are checked, schemas and channels come before their messages) and through
// its summary (McapIndexedReader: the summary CRC, statistics, chunk indexes,
// message indexes), and the data-section CRC is recomputed here. Oracles: the
// /rtamp/log channel holds exactly the JSON Lines records, in order; message counts
// equal the statistics; the Foxglove channels carry the fields their schemas name.
// Bad input: a malformed log and an unwritable --mcap give one line and exit 2.
import assert from 'node:assert/strict';
import { execFileSync, spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import zlib from 'node:zlib';
import { McapIndexedReader, McapStreamReader } from '@mcap/core';

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

async function check(file, logFile, compression) {
  const bytes = new Uint8Array(fs.readFileSync(file));
  const lines = fs.readFileSync(logFile, 'utf8').split('\n').filter((l) => l.length > 0);

  // Record by record.
  const records = streamRecords(bytes);
  assert.equal(records[0].type, 'Header');
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
  for (const s of schemas.values()) {
    assert.equal(s.encoding, 'jsonschema');
    JSON.parse(new TextDecoder().decode(s.data));
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
  for (const t of ['/rtamp/log', '/scene', '/joint_states', '/tf', '/plan', '/tree', '/automaton', '/timeline', '/interventions', '/replans'])
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
  assert.equal((byTopic.get('/automaton') ?? []).length, lines.filter((l) => JSON.parse(l).ev === 'run').length);
  return { total, topics: byTopic };
}

const runs = [
  { name: 'tray', args: ['3-block-tray', '--world', 'symbolic', '--rate', '0.2', '--seed', '3'], compression: 'zstd' },
  { name: 'lz4', args: ['3-block', '--world', 'symbolic', '--rate', '0.3', '--seed', '5'], compression: 'lz4' },
  { name: 'none', args: ['3-block-tray', '--world', 'symbolic', '--change', 'add', '--seed', '7'], compression: 'none' },
];
for (const r of runs) {
  const log = path.join(tmp, `${r.name}.jsonl`), live = path.join(tmp, `${r.name}.mcap`);
  rtamp(['run', ...r.args, '--quiet', '--log', log, '--mcap', live, '--mcap-compression', r.compression], 'ran');
  await check(live, log, r.compression);
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
