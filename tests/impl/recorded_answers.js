#!/usr/bin/env node
// An implementation of acconform.protocol/1 in JavaScript, written as a porter would write one
// from docs/protocol.md, that computes no physics: it answers each scene with ACE's outcome
// looked up in the recorded corpus it is given, so `acconform check --impl` must find it agrees
// with the whole corpus. It exercises what a JavaScript port meets: JSON.stringify writes -0 as 0,
// so negative zero goes out as its float32 bit pattern "0x80000000" (docs/protocol.md, "Floats").
//
//   node tests/impl/recorded_answers.js CORPUS_DIR...     e.g. tests/data/corpus/coreclr
//   node tests/impl/recorded_answers.js --plain-zero DIR  writes -0 as JSON.stringify does (0): the
//                                                         mistake the bit pattern avoids, for a test
//
// Scenes are found by the recorded oracle's key (oracle/recorded.py, scene_key): the SHA-256 of
// the scene's JSON without its name, keys sorted, no whitespace, each number and string exactly
// as the harness wrote it. JSON.parse would lose how a number was written (1.0 against 1), so
// the scene is read by a small parser that keeps each value's text. A scene the corpus does not
// hold, or a request for another runtime than the corpus's, ends the process with one line on
// stderr (the harness reports it as a crash).
'use strict';

const fs = require('fs');
const path = require('path');
const zlib = require('zlib');
const crypto = require('crypto');
const readline = require('readline');

const SHARD = /^[a-z0-9_]+-\d{4,}\.jsonl\.gz$/;
const NEGATIVE_ZERO = '0x80000000';

// ---------------------------------------------------------------- JSON that keeps its text

// A value is {raw} (a number, string, true, false or null as written), {arr: [values]} or
// {obj: [[key, value]...]} (key: {raw, str}); objects and arrays keep [start, end) in the text.
function parseKeepingText(text) {
  let i = 0;
  const n = text.length;
  function skip() {
    while (i < n) {
      const c = text.charCodeAt(i);
      if (c === 32 || c === 10 || c === 13 || c === 9) i++;
      else break;
    }
  }
  function fail(what) {
    throw new Error(`bad JSON at offset ${i}: ${what}`);
  }
  function string() {
    const start = i++;
    let escaped = false;
    while (i < n && text.charCodeAt(i) !== 34) {
      if (text.charCodeAt(i) === 92) { escaped = true; i++; }
      i++;
    }
    if (i >= n) fail('unterminated string');
    i++;
    const raw = text.slice(start, i);
    return { raw, str: escaped ? JSON.parse(raw) : raw.slice(1, -1) };
  }
  function value() {
    skip();
    const start = i;
    const c = text.charCodeAt(i);
    if (c === 123) { // {
      i++;
      const obj = [];
      skip();
      if (text.charCodeAt(i) === 125) { i++; return { obj, start, end: i }; }
      for (;;) {
        skip();
        if (text.charCodeAt(i) !== 34) fail('expected a key');
        const key = string();
        skip();
        if (text.charCodeAt(i) !== 58) fail("expected ':'");
        i++;
        obj.push([key, value()]);
        skip();
        const d = text.charCodeAt(i++);
        if (d === 125) return { obj, start, end: i };
        if (d !== 44) fail("expected ',' or '}'");
      }
    }
    if (c === 91) { // [
      i++;
      const arr = [];
      skip();
      if (text.charCodeAt(i) === 93) { i++; return { arr, start, end: i }; }
      for (;;) {
        arr.push(value());
        skip();
        const d = text.charCodeAt(i++);
        if (d === 93) return { arr, start, end: i };
        if (d !== 44) fail("expected ',' or ']'");
      }
    }
    if (c === 34) return { raw: string().raw };
    while (i < n) { // a number, true, false or null: up to the next delimiter
      const d = text.charCodeAt(i);
      if (d === 44 || d === 93 || d === 125 || d === 32 || d === 10 || d === 13 || d === 9) break;
      i++;
    }
    if (i === start) fail('expected a value');
    return { raw: text.slice(start, i) };
  }
  const v = value();
  skip();
  if (i !== n) fail('trailing text');
  return v;
}

function member(obj, name) {
  const pair = obj.obj.find(([k]) => k.str === name);
  return pair ? pair[1] : undefined;
}

// The canonical text: keys sorted, no whitespace, every number and string as it was written.
function canonical(v) {
  if (v.raw !== undefined) return v.raw;
  if (v.arr) return '[' + v.arr.map(canonical).join(',') + ']';
  const pairs = v.obj.slice().sort((a, b) => (a[0].str < b[0].str ? -1 : a[0].str > b[0].str ? 1 : 0));
  return '{' + pairs.map(([k, x]) => k.raw + ':' + canonical(x)).join(',') + '}';
}

function sceneKey(scene) {
  const unnamed = { obj: scene.obj.filter(([k]) => k.str !== 'name') }; // a name is a label, not physics
  return crypto.createHash('sha256').update(canonical(unnamed)).digest('hex');
}

// ---------------------------------------------------------------- the corpus

function load(dirs) {
  const answers = new Map(); // scene key -> {outcome: text, runtime}
  for (const dir of dirs) {
    // its handshake lists no feature `ticks`, so no tick scene is sent to it: the ticks shards are not read
    const names = fs.readdirSync(dir).filter((f) => SHARD.test(f) && !f.startsWith('ticks-')).sort();
    if (names.length === 0) throw new Error(`no corpus shards (<kind>-NNNN.jsonl.gz) in ${dir}`);
    for (const name of names) {
      const lines = zlib.gunzipSync(fs.readFileSync(path.join(dir, name))).toString('utf8').split('\n');
      lines.forEach((line, k) => {
        if (!line.trim()) return;
        let record;
        try {
          record = parseKeepingText(line);
        } catch (e) {
          throw new Error(`${path.join(dir, name)} line ${k + 1}: ${e.message}`);
        }
        const scene = member(record, 'scene');
        const outcome = member(record, 'outcome');
        const versions = JSON.parse(line.slice(member(record, 'versions').start, member(record, 'versions').end));
        answers.set(sceneKey(scene), {
          outcome: line.slice(outcome.start, outcome.end),
          runtime: String(versions.runtime || '').split(' ')[0],
        });
      });
    }
  }
  return answers;
}

// -0 as its bit pattern: JSON.stringify would write it as 0, which reads back as +0.
function writeOutcome(text, plainZero) {
  if (plainZero) return JSON.stringify(JSON.parse(text));
  return JSON.stringify(JSON.parse(text), (key, v) => (Object.is(v, -0) ? NEGATIVE_ZERO : v));
}

// ---------------------------------------------------------------- the protocol

function main() {
  const plainZero = process.argv.includes('--plain-zero');
  const dirs = process.argv.slice(2).filter((a) => a !== '--plain-zero');
  if (dirs.length === 0) {
    process.stderr.write('usage: node recorded_answers.js [--plain-zero] CORPUS_DIR...\n');
    process.exit(2);
  }
  let answers;
  try {
    answers = load(dirs);
  } catch (e) {
    process.stderr.write(`recorded_answers.js: ${e.message}\n`);
    process.exit(2);
  }
  process.stdout.write(JSON.stringify({
    protocol: 'acconform.protocol/1', name: 'recorded-answers.js', version: '1',
    kinds: ['terrain', 'bsp', 'obstacles', 'indoor', 'buildings'],
    features: ['engine.client', 'mover.two_spheres', 'mover.scaled', 'object.scaled', 'water', 'indoor.statics',
      'mover.placement', 'buildings'],
    modes: ['exact'],
  }) + '\n');
  const input = readline.createInterface({ input: process.stdin, crlfDelay: Infinity });
  input.on('line', (line) => {
    if (!line.trim()) return;
    const request = parseKeepingText(line);
    const id = member(request, 'id').raw;
    const runtime = JSON.parse(member(request, 'runtime').raw);
    const key = sceneKey(member(request, 'scene'));
    const answer = answers.get(key);
    if (answer === undefined) {
      process.stderr.write(`recorded_answers.js: no recorded answer for scene ${key.slice(0, 16)} in ${dirs.join(', ')}\n`);
      process.exit(3);
    }
    if (answer.runtime !== runtime) {
      process.stderr.write(`recorded_answers.js: asked for ${runtime}'s arithmetic; the corpus holds ACE on ${answer.runtime}\n`);
      process.exit(3);
    }
    process.stdout.write(`{"id":${id},"outcome":${writeOutcome(answer.outcome, plainZero)}}\n`);
  });
}

main();
