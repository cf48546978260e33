#!/usr/bin/env node
// An implementation of acconform.protocol/1 in JavaScript, written as a porter would write one
// from docs/protocol.md, that computes no physics: it answers each scene with ACE's outcome
// looked up in the recorded corpus it is given, so `acconform check --impl` must find it agrees
// with the whole corpus. It answers at once: the handshake goes out before the corpus is read (a
// corpus takes seconds to read), and an answer is the recorded outcome's text as written.
//
//   node tests/impl/recorded_answers.js CORPUS_DIR...     e.g. tests/data/corpus/coreclr
//   node tests/impl/recorded_answers.js --stringify DIR   builds each answer with JSON.stringify, as a
//                                                         port holding its outcome as objects does: -0
//                                                         goes out as its bit pattern "0x80000000"
//                                                         (JSON.stringify writes -0 as 0; docs/protocol.md,
//                                                         "Floats")
//   node tests/impl/recorded_answers.js --plain-zero DIR  writes -0 as JSON.stringify does (0): the
//                                                         mistake the bit pattern avoids, for a test
//
// A scene is found by its text: first as sent (the harness sends a recorded scene as it was
// written), then by the recorded oracle's key (oracle/recorded.py, scene_key): the SHA-256 of the
// scene's JSON without its name, keys sorted, no whitespace, each number and string exactly as
// the harness wrote it. JSON.parse would lose how a number was written (1.0 against 1), so the
// key is made by a small parser that keeps each value's text; the keys are made the first time a
// scene is not found as sent. A scene the corpus does not hold, or a request for another runtime
// than the corpus's, ends the process with one line on stderr (the harness reports it as a crash).
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

// The top-level members of an object's text, as name -> [start, end), nested values skipped
// without being read (a scene is tens of kilobytes: finding it must not cost a parse).
function members(text) {
  const out = new Map();
  const n = text.length;
  let i = text.indexOf('{') + 1;
  while (i > 0 && i < n) {
    const q = text.indexOf('"', i);
    if (q < 0) break;
    const kEnd = text.indexOf('"', q + 1);
    const name = text.slice(q + 1, kEnd);
    let j = text.indexOf(':', kEnd) + 1;
    while (text.charCodeAt(j) === 32) j++;
    const start = j;
    let depth = 0;
    for (; j < n; j++) {
      const c = text.charCodeAt(j);
      if (c === 34) { // a string: to its closing quote
        j++;
        while (j < n && text.charCodeAt(j) !== 34) j += text.charCodeAt(j) === 92 ? 2 : 1;
      } else if (c === 123 || c === 91) depth++;
      else if (c === 125 || c === 93) {
        if (depth === 0) break;
        depth--;
        if (depth === 0) { j++; break; }
      } else if (c === 44 && depth === 0) break;
    }
    out.set(name, [start, j]);
    while (j < n && text.charCodeAt(j) !== 44 && text.charCodeAt(j) !== 125) j++;
    i = text.charCodeAt(j) === 44 ? j + 1 : -1;
  }
  return out;
}

function slice(text, found, name) {
  const at = found.get(name);
  if (at === undefined) throw new Error(`no "${name}" member`);
  return text.slice(at[0], at[1]);
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

// The corpus's shards, read one at a time: when a scene is asked for that the shards read so far
// do not hold, and between requests while the process is idle, so the first answers need not wait
// for the whole corpus (seconds; the harness gives each answer --timeout, 10 s by default).
class Corpus {
  constructor(dirs) {
    this.answers = new Map(); // scene text as written -> {outcome: text, runtime}
    this.unread = [];
    for (const dir of dirs) {
      const names = fs.readdirSync(dir).filter((f) => SHARD.test(f)).sort();
      if (names.length === 0) throw new Error(`no corpus shards (<kind>-NNNN.jsonl.gz) in ${dir}`);
      this.unread.push(...names.map((name) => path.join(dir, name)));
    }
    this.byKey = null; // the answers by the recorded oracle's scene key, made when first needed
  }

  readNext() {
    const shard = this.unread.shift();
    const lines = zlib.gunzipSync(fs.readFileSync(shard)).toString('utf8').split('\n');
    lines.forEach((line, k) => {
      if (!line.trim()) return;
      let scene;
      let outcome;
      let versions;
      try {
        const found = members(line);
        scene = slice(line, found, 'scene');
        outcome = slice(line, found, 'outcome');
        versions = JSON.parse(slice(line, found, 'versions'));
      } catch (e) {
        fail(2, `${shard} line ${k + 1}: ${e.message}`);
      }
      this.answers.set(scene, { outcome, runtime: String(versions.runtime || '').split(' ')[0] });
    });
  }

  // The recorded answer to a scene (its text as sent), or undefined; `key` is set to the scene's
  // key when it was looked up by key.
  find(scene) {
    let answer = this.answers.get(scene);
    while (answer === undefined && this.unread.length) {
      this.readNext();
      answer = this.answers.get(scene);
    }
    if (answer !== undefined) return { answer, key: null };
    if (this.byKey === null) {
      this.byKey = new Map();
      for (const [text, a] of this.answers) this.byKey.set(sceneKey(parseKeepingText(text)), a);
    }
    const key = sceneKey(parseKeepingText(scene));
    return { answer: this.byKey.get(key), key };
  }
}

function fail(code, message) {
  process.stderr.write(`recorded_answers.js: ${message}\n`);
  process.exit(code);
}

// -0 as its bit pattern: JSON.stringify would write it as 0, which reads back as +0.
function writeOutcome(text, plainZero) {
  if (plainZero) return JSON.stringify(JSON.parse(text));
  return JSON.stringify(JSON.parse(text), (key, v) => (Object.is(v, -0) ? NEGATIVE_ZERO : v));
}

// ---------------------------------------------------------------- the protocol

function main() {
  const plainZero = process.argv.includes('--plain-zero');
  const stringify = plainZero || process.argv.includes('--stringify');
  const dirs = process.argv.slice(2).filter((a) => a !== '--plain-zero' && a !== '--stringify');
  if (dirs.length === 0) {
    process.stderr.write('usage: node recorded_answers.js [--stringify | --plain-zero] CORPUS_DIR...\n');
    process.exit(2);
  }
  let corpus;
  try {
    corpus = new Corpus(dirs);
  } catch (e) {
    fail(2, e.message);
  }
  // the handshake first: the harness waits for it, and the corpus takes a while to read
  process.stdout.write(JSON.stringify({
    protocol: 'acconform.protocol/1', name: 'recorded-answers.js', version: '1',
    kinds: ['terrain', 'bsp', 'obstacles', 'indoor', 'buildings'],
    features: ['engine.client', 'mover.two_spheres', 'mover.scaled', 'object.scaled', 'water', 'indoor.statics',
      'mover.placement', 'mover.enter_world', 'ticks', 'buildings'],
    modes: ['exact'],
  }) + '\n');
  const idle = () => { // a shard between requests, until all are read
    if (corpus.unread.length) {
      corpus.readNext();
      setImmediate(idle);
    }
  };
  setImmediate(idle);
  const input = readline.createInterface({ input: process.stdin, crlfDelay: Infinity });
  input.on('line', (line) => {
    if (!line.trim()) return;
    const found = members(line);
    const id = slice(line, found, 'id');
    const runtime = JSON.parse(slice(line, found, 'runtime'));
    const { answer, key } = corpus.find(slice(line, found, 'scene'));
    if (answer === undefined) fail(3, `no recorded answer for scene ${key.slice(0, 16)} in ${dirs.join(', ')}`);
    if (answer.runtime !== runtime) fail(3, `asked for ${runtime}'s arithmetic; the corpus holds ACE on ${answer.runtime}`);
    const outcome = stringify ? writeOutcome(answer.outcome, plainZero) : answer.outcome;
    process.stdout.write(`{"id":${id},"outcome":${outcome}}\n`);
  });
}

main();
