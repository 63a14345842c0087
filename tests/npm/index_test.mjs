// The npm package's own JavaScript (npm/package/index.mjs) under node's test runner: what it
// does around the WebAssembly. A scenario is a name or an object; what JSON cannot carry (NaN,
// BigInts) is refused in the reader's words and what it can (±Infinity, -0, fields left out)
// reaches the one reader as a file spells it; an object nested at any depth (a cycle) is refused
// at its key path, never a stack overflow; a long name is cut in its message, its length said;
// readScenario() reads a file's text; judge()
// takes flat arrays or rows and names BigInts; a judgement's columns are typed; assertPasses()
// returns a pass and throws node's AssertionError for a fail. Run by tests/npm/npm_package_test.py
// on the package it built (FLIPCHECK_PACKAGE: its folder), and by Stryker (scripts/mutation-js.sh
// --npm).
import assert from "node:assert/strict";
import { createHash } from "node:crypto";
import { readFileSync } from "node:fs";
import { test } from "node:test";
import { pathToFileURL } from "node:url";

const dir = process.env.FLIPCHECK_PACKAGE;
const f = await import(pathToFileURL(`${dir}/index.mjs`).href);
const NAME = "mujoco-test-box";
const box = () => f.scenario(NAME);
const carried = readFileSync(`${dir}/scenarios/${NAME}.json`, "utf8");

/** The message `run` throws; fails where it throws nothing. */
function refusal(run) {
  try {
    run();
  } catch (e) {
    return e.message;
  }
  assert.fail("taken, expected a refusal");
}

/** The text of the carried scenario with `field`'s value spelled `raw`. */
function spelled(field, raw) {
  const json = box();
  json[field] = "@";
  return JSON.stringify(json).replace('"@"', raw);
}

test("a scenario is one of the names, or an object", () => {
  const names = f.scenarios();
  assert.equal(names.length, 7);
  assert.deepEqual(names, [...names].sort());
  assert.ok(names.includes(NAME));
  names.push("x");
  assert.equal(f.scenarios().length, 7, "scenarios() hands out a copy");
  const no = "flipcheck: a scenario is a name or a scenario JSON object, got";
  assert.equal(refusal(() => f.exactMotion(null)), `${no} null`);
  assert.equal(refusal(() => f.exactMotion([box()])), `${no} an array`);
  assert.equal(refusal(() => f.exactMotion(3)), `${no} number`);
  assert.equal(refusal(() => f.exactMotion(undefined)), `${no} undefined`);
  assert.match(refusal(() => f.exactMotion("nope")), /^flipcheck: no scenario "nope" \(there: book-/);
  assert.match(refusal(() => f.scenario(3)), /^flipcheck: no scenario "3"/);
  assert.deepEqual(f.scenario(NAME), JSON.parse(carried));
});

test("what JSON cannot carry is refused in the reader's words", () => {
  const said = (change) => refusal(() => f.exactMotion({ ...box(), ...change }));
  assert.equal(said({ mass: NaN }), `${NAME}: mass: expected a number, got NaN`);
  assert.equal(said({ dt: 10n }), `${NAME}: dt: expected a number, got a bigint`);
  assert.equal(said({ principal_moments: [1, 2n, 3] }), `${NAME}: principal_moments[1]: expected a number, got a bigint`);
  assert.equal(said({ omega0_body: [1, 2, NaN] }), `${NAME}: omega0_body[2]: expected a number, got NaN`);
  assert.equal(said({ scenario: 3n }), "scenario JSON: scenario: expected a name (a string), got a bigint");
  assert.equal(said({ scenario: 3, mass: NaN }), "scenario JSON: mass: expected a number, got NaN");
  assert.equal(said({ omega0_world: [NaN, 0, 0] }), `${NAME}: omega0_world[0]: expected a number, got NaN`);
  assert.equal(said({ q0: [1, 0, 0, NaN] }), `${NAME}: q0[3]: expected a number, got NaN`);
  assert.equal(said({ steps: NaN }), `${NAME}: steps: expected a number, got NaN`);
});

test("what JSON can carry reaches the reader as a file spells it", () => {
  const asFile = (field, raw) => refusal(() => f.readScenario(spelled(field, raw)));
  const asObject = (field, value) => refusal(() => f.exactMotion({ ...box(), [field]: value }));
  for (const [field, value, raw] of [
    ["mass", Infinity, "1e999"],
    ["mass", -Infinity, "-1e999"],
    ["dt", -0, "-0"],
    ["steps", 2.5, "2.5"],
    ["principal_moments", [1, undefined, 3], "[1, null, 3]"],
    ["principal_moments", [1, () => 2, 3], "[1, null, 3]"],
    ["principal_moments", [1, Symbol("s"), 3], "[1, null, 3]"],
    ["omega0_body", [-0, 0, 0], "[-0, 0, 0]"],
    ["q0", [1, 0, 0, 1e-300], "[1, 0, 0, 1e-300]"],
    ["mass", null, "null"],
    ["mass", true, "true"],
    ["mass", "1", '"1"'],
    ["mass", new Date(0), '"1970-01-01T00:00:00.000Z"'],
    ["mass", { value: 1 }, '{"value": 1}'],
    ["scenario", 3, "3"],
  ]) {
    const file = asFile(field, raw);
    assert.match(file, new RegExp(`^(${NAME}|scenario JSON): `));
    assert.equal(asObject(field, value), file, `${field} = ${raw}`);
  }
  // A field left out as JSON.stringify leaves it out: missing.
  const missing = `${NAME}: dt: missing (a scenario JSON as flipcheck export writes it)`;
  assert.equal(refusal(() => f.exactMotion({ ...box(), dt: undefined })), missing);
  assert.equal(refusal(() => f.exactMotion({ ...box(), dt: () => 0.01 })), missing);
  assert.equal(refusal(() => f.exactMotion({ ...box(), dt: Symbol("dt") })), missing);
  assert.equal(refusal(() => f.exactMotion({ ...box(), scenario: undefined })), "scenario JSON: scenario: missing (the scenario's name, as flipcheck export writes it)");
  // What the reader ignores may hold anything: the scenario is the carried one.
  const sha = f.scenarioSha256(NAME);
  assert.equal(f.scenarioSha256({ ...box(), units: { x: NaN, y: 1n, z: Infinity, w: [undefined] }, extra: 4n }), sha);
  assert.equal(f.scenarioSha256({ ...box(), when: new Date(0), notes: ["a\u0000\"\\"] }), sha);
  assert.equal(sha, createHash("sha256").update(carried).digest("hex"));
  // A typed array is no array: the reader says so.
  assert.equal(asObject("principal_moments", Float64Array.of(1, 2, 3)), `${NAME}: principal_moments: expected an array of 3 numbers, got an object`);
});

test("an object nested at any depth is refused at its key path, never a crash", () => {
  /** The carried scenario with `levels` levels under extra: objects {a: …}, or arrays [[…]]. */
  const nested = (levels, array = false) => {
    const s = box();
    let at = (s.extra = array ? [] : {});
    for (let i = 1; i < levels; ++i) at = array ? (at[0] = []) : (at.a = {});
    return s;
  };
  // The reader reads 64 levels (the document is level 0); an object one deeper, or 5000 deeper,
  // is refused as a file is, naming where it goes past the limit, not a place in a text it never
  // saw; a cycle is nested without end.
  assert.equal(f.scenarioSha256(nested(64)), f.scenarioSha256(NAME));
  assert.equal(f.scenarioSha256(f.readScenario(JSON.stringify(nested(64)))), f.scenarioSha256(NAME));
  assert.match(refusal(() => f.readScenario(JSON.stringify(nested(65)))), /^scenario JSON: nested more than 64 deep at line 1, column \d+$/);
  const a = `extra${".a".repeat(64)}`;
  const said = `scenario JSON: nested more than 64 deep at ${a.slice(0, 60)}… (${a.length} characters)`;
  assert.equal(refusal(() => f.judge(nested(65), {})), said);
  assert.equal(refusal(() => f.judge(nested(5000), {})), said);
  const rows = refusal(() => f.exportFiles(nested(5000, true)));
  assert.match(rows, /^scenario JSON: nested more than 64 deep at extra\[0\]\[0\]\[0\]/);
  const cycle = box();
  cycle.notes = { "the same": cycle };
  assert.match(refusal(() => f.exactMotion(cycle)), /^scenario JSON: nested more than 64 deep at notes\["the same"\]\.notes\["the same"\]/);
  // The file door's words for the same depth: the same words, at a line and column (deep JSON
  // is valid JSON, which the file door once said it was not).
  const file = refusal(() => f.readScenario(`{"extra": ${"[".repeat(70)}${"]".repeat(70)}}`, "deep.json"));
  assert.equal(file, "deep.json: nested more than 64 deep at line 1, column 75");
  assert.equal(file.split(" at ")[0], rows.replace("scenario JSON", "deep.json").split(" at ")[0]);
});

test("toJSON is asked as JSON.stringify asks it, and its answer is refused at any depth, never a crash", () => {
  // A Date is its toJSON's string (the reader ignores what it does not read).
  assert.equal(f.scenarioSha256({ ...box(), when: new Date(0) }), f.scenarioSha256(NAME));
  // toJSON's answer is what is read: a field given by its toJSON is the field.
  assert.deepEqual(f.exportFiles({ ...box(), mass: { toJSON: () => 2 } }), f.exportFiles({ ...box(), mass: 2 }));
  assert.equal(refusal(() => f.exportFiles({ ...box(), mass: { toJSON: (key) => key } })), `${NAME}: mass: expected a number, got a string`);
  // A toJSON that returns a 200,000-deep array, or leads back to itself (each answer holding
  // the same object again): refused at the key path where it goes past 64, not a RangeError.
  let deep = [];
  for (let i = 0; i < 200000; ++i) deep = [deep];
  const said = refusal(() => f.exportFiles({ ...box(), extra: { toJSON: () => deep } }));
  assert.match(said, /^scenario JSON: nested more than 64 deep at extra(\[0\]){18}\[… \(197 characters\)$/);
  const loop = { toJSON: () => ({ again: loop }) };
  assert.match(refusal(() => f.judge({ ...box(), extra: loop }, {})), /^scenario JSON: nested more than 64 deep at extra\.again\.again/);
  const self = box();
  self.toJSON = () => ({ ...box(), extra: self });
  assert.match(refusal(() => f.scenarioSha256(self)), /^scenario JSON: nested more than 64 deep at extra\.extra/);
  // A toJSON at the document that gives nothing (undefined) is JSON null, as a file of it.
  assert.match(refusal(() => f.exactMotion({ ...box(), toJSON: () => undefined })), /^scenario JSON: holds JSON null, not a scenario/);
});

test("a cycle through a key of 10^7 characters is refused, its path measured, never built", () => {
  const key = "k".repeat(1e7);
  // A scenario that loops back to itself through the key: 63 times the key, then its units'
  // first at the 65th level, a path of 6.3·10^8 characters, past the longest string V8 builds,
  // which the check once built a level at a time ("Invalid string length"): said by its first 60
  // bytes and its length in bytes, measured, never built.
  const cycle = box();
  cycle[key] = cycle;
  const length = key.length + 62 * (1 + key.length) + ".units.time".length;
  assert.equal(refusal(() => f.exportFiles(cycle)), `scenario JSON: nested more than 64 deep at ${"k".repeat(60)}… (${length} characters)`);
  // The same through a field the reader ignores, every other level the key.
  const notes = box();
  notes.notes = { [key]: notes };
  const through = "notes".length + 32 * (1 + key.length) + 31 * ".notes".length + ".scenario".length;
  assert.equal(refusal(() => f.exportFiles(notes)), `scenario JSON: nested more than 64 deep at notes.${"k".repeat(54)}… (${through} characters)`);
  // A path past 80 bytes of UTF-8 is cut by bytes, never inside a character (é is two).
  const wide = box();
  let at = (wide.abc = {});
  for (let i = 1; i < 65; ++i) at = at["é"] = {};
  assert.equal(refusal(() => f.exportFiles(wide)), `scenario JSON: nested more than 64 deep at abc${'["é"]'.repeat(9)}["… (${3 + 6 * 64} characters)`);
});

test("a scenario JSON saved as UTF-16 is said to be so, as a scene or a recording is", () => {
  const utf16 = Buffer.concat([Buffer.from([0xff, 0xfe]), Buffer.from(carried, "utf16le")]);
  const said = "le.json: NUL byte at line 1 (not a text file: a binary file, or text saved as UTF-16)";
  assert.equal(refusal(() => f.readScenario(utf16.toString("utf8"), "le.json")), said);
  assert.equal(refusal(() => f.readScenario(utf16.toString("latin1"), "le.json")), said);
});

test("a long name is cut in a message, its length said", () => {
  // A name any file or person could give (up to 4096 bytes, PATH_MAX) is named whole, as the
  // command line and Python name it: 300 characters were cut to 60, the name no longer named.
  const long = "a".repeat(300);
  assert.equal(refusal(() => f.exactMotion({ ...box(), scenario: long })), `flipcheck: scenario name "${long}" is 300 characters long (at most 128)`);
  assert.equal(refusal(() => f.scenario(long)).split(" (there: ")[0], `flipcheck: no scenario "${long}"`);
  const named = "b".repeat(100);  // within the limit: a field's refusal names it whole
  assert.equal(refusal(() => f.judge({ ...box(), scenario: named, mass: NaN }, {})), `${named}: mass: expected a number, got NaN`);
  const name = "a".repeat(1000000);
  const cut = `"${"a".repeat(60)}…" (1000000 characters)`;
  assert.equal(refusal(() => f.judge({ ...box(), scenario: name }, {})), `flipcheck: scenario name ${cut} is 1000000 characters long (at most 128)`);
  assert.equal(refusal(() => f.scenario(name)).split(" (there: ")[0], `flipcheck: no scenario ${cut}`);
  assert.equal(refusal(() => f.judge({ ...box(), scenario: name, mass: NaN }, {})), `${"a".repeat(60)}… (1000000 characters): mass: expected a number, got NaN`);
});

test("readScenario reads a file's text as the command line does", () => {
  const s = f.readScenario(carried, "box.json");
  assert.deepEqual(s, JSON.parse(carried));
  assert.equal(f.scenarioSha256(s), f.scenarioSha256(NAME));
  assert.equal(f.scenarioSha256(f.readScenario(`\ufeff${carried}`, "bom.json")), f.scenarioSha256(NAME));
  // A key given twice: the last counts, in the reader and in JSON.parse alike.
  const twice = `${carried.trimEnd().slice(0, -1)}, "mass": 5}`;
  assert.equal(f.readScenario(twice, "twice.json").mass, 5);
  assert.deepEqual(f.exportFiles(f.readScenario(twice, "twice.json")), f.exportFiles({ ...box(), mass: 5 }));
  const holds = "holds JSON null, not a scenario (a JSON object as flipcheck export writes it: scenario, mass, principal_moments, omega0_body, dt, steps)";
  assert.equal(refusal(() => f.readScenario("null", "n.json")), `n.json: ${holds}`);
  assert.equal(refusal(() => f.readScenario("null")), `scenario JSON: ${holds}`);
  assert.equal(refusal(() => f.readScenario(spelled("mass", "-1"), "m.json")), `${NAME}: mass: -1: must be finite and > 0`);
  assert.match(refusal(() => f.readScenario("{", "cut.json")), /^cut\.json: not valid JSON: /);
});

test("judge takes flat arrays or rows and names BigInts; a judgement's columns are typed", () => {
  const m = f.exactMotion(NAME);
  const n = m.t.length;
  assert.equal(n, box().steps + 1);
  assert.equal(m.q.length, 4 * n);
  const flat = f.judge(NAME, { t: m.t, q: m.q, omegaWorld: m.omegaWorld });
  const rows = (a, k) => Array.from({ length: n }, (_, i) => Array.from(a.slice(k * i, k * i + k)));
  const byRows = f.judge(NAME, { t: Array.from(m.t), q: rows(m.q, 4), omegaWorld: rows(m.omegaWorld, 3) });
  assert.deepEqual(byRows, flat);
  assert.equal(flat.pass, true);
  assert.equal(flat.verdict, "pass");
  assert.deepEqual(flat.reasons, []);
  assert.equal(flat.scenario, NAME);
  assert.equal(flat.motion, "motion");
  assert.equal(f.judge(NAME, { t: m.t, q: m.q, omegaWorld: m.omegaWorld }, { motion: "mine" }).motion, "mine");
  assert.equal(flat.scenario_sha256, f.scenarioSha256(NAME));
  assert.equal(flat.version, f.version);
  assert.match(flat.line, /^PASS/);
  const numbers = Object.entries(flat).filter(([k]) => !["scenario", "motion", "verdict", "failures", "version", "scenario_sha256", "pass", "reasons", "line"].includes(k));
  assert.ok(numbers.length > 5);
  for (const [k, v] of numbers) assert.ok(v === null || typeof v === "number", `${k} = ${v}`);
  assert.equal(flat.last_step, box().steps);
  assert.equal(flat.tumble_time, null, "an empty cell is null");
  assert.equal(flat.failures, "");
  assert.ok(!Object.keys(flat).includes("csv"));
  assert.ok(flat.csv.startsWith("scenario,"));
  assert.equal(f.judgeCsv(NAME, f.exportFiles(NAME).csv).pass, true);
  // A CSV's bytes (a Buffer, as npx reads a file) judge as its text.
  const text = f.exportFiles(NAME).csv;
  assert.equal(f.judgeCsv(NAME, Buffer.from(text)).csv, f.judgeCsv(NAME, text).csv);
  assert.equal(f.judgeCsv(NAME, new Uint8Array(Buffer.from(text))).csv, f.judgeCsv(NAME, text).csv);
  assert.match(refusal(() => f.judge(NAME, { t: m.t, q: BigInt64Array.of(1n), omegaWorld: m.omegaWorld })), /^q: holds BigInts \(BigInt64Array\): expected numbers/);
  assert.match(refusal(() => f.judge(NAME, { t: m.t, q: m.q, omegaWorld: BigUint64Array.of(1n) })), /^omegaWorld: holds BigInts \(BigUint64Array\)/);
  assert.match(refusal(() => f.judge(NAME, { t: [0n], q: m.q, omegaWorld: m.omegaWorld })), /^t: holds BigInts \(Array\)/);
  assert.match(refusal(() => f.judge(NAME, { t: m.t, q: [[1n, 0n, 0n, 0n]], omegaWorld: m.omegaWorld })), /^q: holds BigInts/);
  assert.match(refusal(() => f.judge(NAME, { t: [0, 1n], q: m.q, omegaWorld: m.omegaWorld })), /^t: holds BigInts \(Array\)/);
  const none = refusal(() => f.judge(NAME, { t: m.t, q: m.q }));
  assert.match(none, /^judge: omegaWorld: expected \d+ numbers/);
  assert.equal(refusal(() => f.judge(NAME, { t: m.t, q: m.q, omegaWorld: null })), none);
  assert.match(refusal(() => f.judge(NAME)), /./);
});

test("a lone surrogate is refused naming its argument, never joined to the next character", () => {
  // emscripten's UTF-8 encoder took U+D800 and the "x" after it as one pair: the label "m\ud800x"
  // came back "m\u{10078}". The Python module says the same line (tests/python/test_same_answer.py);
  // a pair stays one character.
  const m = f.exactMotion(NAME);
  const arrays = { t: m.t, q: m.q, omegaWorld: m.omegaWorld };
  assert.equal(refusal(() => f.judge(NAME, arrays, { motion: "m\ud800x" })),
    'flipcheck.judge: motion: "m\\ud800x" holds a lone surrogate (U+D800) at character 2: no UTF-8 text holds one');
  assert.equal(refusal(() => f.judge(NAME, arrays, { motion: "\u{1F600}\udc00" })),
    'flipcheck.judge: motion: "\u{1F600}\\udc00" holds a lone surrogate (U+DC00) at character 2: no UTF-8 text holds one');
  assert.equal(f.judge(NAME, arrays, { motion: "m\u{1F600}x" }).motion, "m\u{1F600}x");
  const csv = "t,qw,qx,qy,qz,wx_world,wy_world,wz_world\n";
  assert.equal(refusal(() => f.judgeCsv(NAME, csv, { file: "a\udbffb.csv" })),
    'flipcheck.judgeCsv: file: "a\\udbffb.csv" holds a lone surrogate (U+DBFF) at character 2: no UTF-8 text holds one');
  // A scenario's name, given or in its object, and a scenario file's text and name: named at its
  // argument, in the same words (it was "no scenario \"m\u{10078}\"", the "x" eaten).
  const lone = (argument, quoted, at = 2) => `${argument}: "${quoted}" holds a lone surrogate (U+D800) at character ${at}: no UTF-8 text holds one`;
  assert.equal(refusal(() => f.scenario("m\ud800x")), lone("flipcheck.scenario: name", "m\\ud800x"));
  assert.equal(refusal(() => f.exactMotion("m\ud800x")), lone("flipcheck.exactMotion: scenario", "m\\ud800x"));
  assert.equal(refusal(() => f.exactMotion({ ...box(), scenario: "m\ud800x" })),
    lone("flipcheck.exactMotion: scenario.scenario", "m\\ud800x"));
  assert.equal(refusal(() => f.exportFiles({ ...box(), scenario: "m\ud800x" })),
    lone("flipcheck.exportFiles: scenario.scenario", "m\\ud800x"));
  assert.equal(refusal(() => f.judge("m\ud800x", arrays)), lone("flipcheck.judge: scenario", "m\\ud800x"));
  assert.equal(refusal(() => f.readScenario(carried, "m\ud800x.json")), lone("flipcheck.readScenario: file", "m\\ud800x.json"));
  const text = carried.replace(`"${NAME}"`, '"m\ud800x"');
  assert.equal(refusal(() => f.readScenario(text)),
    lone("flipcheck.readScenario: text", JSON.stringify(text).slice(1, -1), text.indexOf("\ud800") + 1));
});

test("assertPasses returns a pass and throws node's AssertionError with judge's line for a fail", () => {
  const m = f.exactMotion(NAME);
  const passed = f.assertPasses(NAME, { t: m.t, q: m.q, omegaWorld: m.omegaWorld });
  assert.equal(passed.pass, true);
  const turned = Float64Array.from(m.q);
  for (let i = 4 * 100 + 1; i < turned.length; i += 4) turned[i] = -turned[i];
  const failed = f.judge(NAME, { t: m.t, q: turned, omegaWorld: m.omegaWorld });
  assert.equal(failed.pass, false);
  assert.ok(failed.reasons.length > 0);
  assert.throws(
    () => f.assertPasses(NAME, { t: m.t, q: turned, omegaWorld: m.omegaWorld }, { motion: "turned" }),
    (e) => e instanceof assert.AssertionError && e.message === `${NAME} turned: ${failed.line}` && e.actual === "fail" && e.expected === "pass" && e.operator === "assertPasses",
  );
  const csv = f.exportFiles(NAME).csv;
  assert.equal(f.assertPasses(NAME, csv, { file: "out/exact.csv" }).motion, "exact.csv");
  assert.equal(f.assertPasses(NAME, csv, { file: "out/exact.csv", motion: "mine" }).motion, "mine");
  assert.equal(f.assertPasses(box(), csv).motion, "motion.csv");
});
