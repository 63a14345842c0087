// The page's own doors into its WebAssembly module (web/src/well_formed.js) under node: a lone
// surrogate in a name the page takes (a recording's file name, the flights by hand, a motion's
// file name for the judge, a student's name and the class code) is refused naming the field, in
// the line the npm package and Python give (tests/npm/index_test.mjs, tests/python/
// test_same_answer.py), and never handed to the module, whose UTF-8 encoder (emscripten's
// stringToUTF8) joined it to the next character: "m\ud800x" arrived as "m\u{10078}". The lab's,
// the judge's and the class's own methods are called with a stand-in module that records what
// reaches it, encoded as emscripten encodes it.
// Usage: node tests/web/well_formed_test.mjs SOURCE_DIR
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { pathToFileURL } from 'node:url';
import { join } from 'node:path';

const source = process.argv[2];
if (!source) throw new Error('usage: node tests/web/well_formed_test.mjs SOURCE_DIR');
const load = (file) => import(pathToFileURL(join(source, 'web/src', file)).href);
const { loneSurrogateProblem, loneSurrogateInArguments } = await load('well_formed.js');
const { FitWorker } = await load('fit_worker.js');
const { LabPanel } = await load('lab.js');
const { JudgePanel } = await load('judge.js');
const { ClassLink } = await load('class_join.js');

/** `text` as emscripten 3.1's stringToUTF8 writes it, read back as UTF-8: a high surrogate
 * takes the next UTF-16 unit as its low half, whatever it is (the fault the page's check keeps
 * from the module). */
function asEmscriptenEncodes(text) {
  let out = '';
  for (let i = 0; i < text.length; ++i) {
    let u = text.charCodeAt(i);
    if (u >= 0xd800 && u <= 0xdfff) u = 0x10000 + ((u & 0x3ff) << 10) | (text.charCodeAt(++i) & 0x3ff);
    out += String.fromCodePoint(u);
  }
  return out;
}

/** A stand-in module: each call's string arguments as they would arrive, kept in `reached`. */
function standIn() {
  const reached = [];
  const wasm = new Proxy({}, {
    get: (_, method) => (...args) => {
      reached.push([method, ...args.filter((a) => typeof a === 'string').map(asEmscriptenEncodes)]);
      return { error: 'stand-in' };
    },
  });
  return { wasm, reached };
}

const line = (argument, json, code, at) =>
  `${argument}: ${json} holds a lone surrogate (U+${code}) at character ${at}: no UTF-8 text holds one`;

test('a lone surrogate is named as every door names it; a pair is one character', () => {
  assert.equal(asEmscriptenEncodes('m\ud800x'), 'm\u{10078}');  // the fault itself
  assert.equal(loneSurrogateProblem('m\ud800x', 'your name'), line('your name', '"m\\ud800x"', 'D800', 2));
  assert.equal(loneSurrogateProblem('\u{1F600}\udc00', 'motion'), line('motion', '"\u{1F600}\\udc00"', 'DC00', 2));
  assert.equal(loneSurrogateProblem('ab\udbff', 'recording'), line('recording', '"ab\\udbff"', 'DBFF', 3));
  for (const fine of ['m\u{1F600}x', '回転', 'bük-ω', '', 'x\uFFFDy']) assert.equal(loneSurrogateProblem(fine, 'x'), '');
  assert.equal(loneSurrogateInArguments('fitRecordings', [[{ name: 'a.csv' }, { name: 'b\udfffc', meta: [] }], 'linear']),
    line('fitRecordings: argument 1[1].name', '"b\\udfffc"', 'DFFF', 2));
  assert.equal(loneSurrogateInArguments('fitRecordings', [[{ name: 'a.csv', bytes: new Uint8Array(2) }], 'linear', '']), '');
});

test('the lab refuses a recording or flights named with a lone surrogate before the module is asked', async () => {
  const { wasm, reached } = standIn();
  const lab = Object.assign(Object.create(LabPanel.prototype), { worker: new FitWorker(wasm) });
  await assert.rejects(lab.fit('m\ud800x.csv', 't,wx,wy,wz\n'), { message: line('recording', '"m\\ud800x.csv"', 'D800', 2) });
  await assert.rejects(lab.fit('m.csv', 't,wx,wy,wz\n', 'linear', '1:2\ud800x'),
    { message: line('flights by hand', '"1:2\\ud800x"', 'D800', 4) });
  await assert.rejects(lab.fitMany([{ name: 'a.csv', bytes: '' }, { name: 'b\udc00.csv', bytes: '' }]),
    { message: line('recording', '"b\\udc00.csv"', 'DC00', 2) });
  assert.deepEqual(reached, []);
  // A name of any script, a pair included, reaches the module as it is.
  await assert.rejects(lab.fit('回転 \u{1F600}.csv', 't,wx,wy,wz\n'), { message: 'stand-in' });
  assert.deepEqual(reached, [['fitRecording', '回転 \u{1F600}.csv', 't,wx,wy,wz\n', 'linear', '']]);
});

test('the module\'s one door refuses any string argument with a lone surrogate, naming its place', async () => {
  const { wasm, reached } = standIn();
  const worker = new FitWorker(wasm);
  await assert.rejects(worker.call('motionPoses', [{}, 't\n', 'm\ud800x.csv']),
    { message: line('motionPoses: argument 3', '"m\\ud800x.csv"', 'D800', 2) });
  assert.deepEqual(reached, []);
});

test('the judge refuses a motion file named with a lone surrogate, before the scenario is looked up', async () => {
  const { wasm, reached } = standIn();
  const judge = Object.assign(Object.create(JudgePanel.prototype), { wasm, worker: new FitWorker(wasm), scenes: [] });
  await assert.rejects(judge.judge('mujoco-test-box', 't\n', 'm\ud800x.csv'), { message: line('motion', '"m\\ud800x.csv"', 'D800', 2) });
  assert.deepEqual(reached, []);
});

test('joining a class, a lone surrogate in the name or the code is said, never asked of the module or the server', () => {
  const fields = { classCode: { value: 'ABC123' }, className: { value: 'm\ud800x' } };
  globalThis.document = { getElementById: (id) => fields[id] ?? { classList: { toggle() {}, remove() {} }, disabled: false } };
  const asked = [];
  const said = [];
  const link = Object.assign(Object.create(ClassLink.prototype), {
    nameProblem: (name) => { asked.push(asEmscriptenEncodes(name)); return ''; },
    say: (text, error) => said.push([text, error]),
  });
  globalThis.fetch = () => { throw new Error('the server was asked'); };
  link.join();
  assert.deepEqual(said, [[`error: ${line('your name', '"m\\ud800x"', 'D800', 2)}`, true]]);
  fields.className.value = 'Mia';
  fields.classCode.value = 'AB\udc00';
  link.join();
  assert.deepEqual(said[1], [`error: ${line('class code', '"AB\\udc00"', 'DC00', 3)}`, true]);
  assert.deepEqual(asked, []);
});
