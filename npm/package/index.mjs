// flipcheck: does your engine get the flip right? bookspin's conformance kit for a free rigid
// body's motion, as an ES module (index.d.ts has the types). The judge and the exact motion are
// bookspin's own C++ compiled to WebAssembly (flipcheck-wasm.cjs); the scenarios are the JSON
// `bookspin flipcheck export` writes (scenarios/). Bad input throws an Error whose message is
// the line `bookspin flipcheck` prints after "bookspin: error: ".
import { AssertionError } from "node:assert";
import { createHash } from "node:crypto";
import { readFileSync, readdirSync } from "node:fs";
import { basename } from "node:path";
import createWasm from "./flipcheck-wasm.cjs";
// The page's own check (web/src/well_formed.js, copied here by npm/build.sh): a lone surrogate
// (U+D800 … U+DFFF without its other half, which no UTF-8 holds) is refused naming its argument,
// in the words of the page and the Python module (python/scene_input.cpp, unicode_arg); unchecked,
// emscripten's UTF-8 encoder took it and the character after it as one pair ("m\ud800x" written
// "m\u{10078}"). Every text reaches the WebAssembly through it.
import { wellFormed } from "./well_formed.js";

const wasm = await createWasm();
/** bookspin's version, this package's (package.json's, `bookspin --version`'s): the WebAssembly's,
 * compiled from bookspin's VERSION, and what every judgement records. */
export const version = wasm.version();
const scenarioFolder = new URL("./scenarios/", import.meta.url);
const NAMES = readdirSync(scenarioFolder)
  .filter((f) => f.endsWith(".json"))
  .map((f) => f.slice(0, -".json".length))
  .sort();
const TEXT_COLUMNS = new Set(["scenario", "motion", "verdict", "failures", "version", "scenario_sha256"]);

/** The wasm's answer, or its error thrown as an Error with the command line's one line. */
function answer(result) {
  if (result && result.error !== undefined) throw new Error(result.error);
  return result;
}

/** The names of the seven scenarios, sorted. */
export function scenarios() {
  return [...NAMES];
}

/** A scenario's JSON as `bookspin flipcheck export` writes it (OUT/<scenario>.json), parsed. */
export function scenario(name) {
  return named(name, "flipcheck.scenario: name");
}

/** The carried scenario `name`, or the Error naming it (`argument` where it holds a lone
 * surrogate). */
function named(name, argument) {
  if (typeof name !== "string" || !NAMES.includes(name))
    throw new Error(`flipcheck: no scenario ${wasm.quotedName(wellFormed(String(name), argument))} (there: ${NAMES.join(", ")})`);
  return JSON.parse(readFileSync(new URL(`${name}.json`, scenarioFolder), "utf8"));
}

/** A scenario given by name, or as an exported scenario JSON (an object), to the function `fn`
 * (its name in a message: "exactMotion"); its name, a string, checked for a lone surrogate. */
function spec(nameOrJson, fn) {
  const argument = `flipcheck.${fn}: scenario`;
  if (typeof nameOrJson === "object" && nameOrJson !== null && !Array.isArray(nameOrJson)) {
    wellFormed(nameOrJson.scenario, `${argument}.scenario`);
    return nameOrJson;
  }
  if (typeof nameOrJson !== "string")
    throw new Error(`flipcheck: a scenario is a name or a scenario JSON object, got ${nameOrJson === null ? "null" : Array.isArray(nameOrJson) ? "an array" : typeof nameOrJson}`);
  return named(nameOrJson, argument);
}

/** How deep the reader reads a scenario JSON (analysis::scenario_from_json: the document is level
 * 0): deeper, a file is refused, and so is an object, at its key path. */
const MAX_DEPTH = 64;

/** A key or an index as JavaScript spells its access from `up` (null at the document): extra.a,
 * ["a b"], [0]. */
function member(up, key) {
  if (typeof key === "number") return `[${key}]`;
  return /^[A-Za-z_$][\w$]*$/.test(key) ? (up ? `.${key}` : key) : `[${JSON.stringify(key)}]`;
}

/** The key path of `at` (a chain of {up, key} links from a value to the document) as
 * common/text_lines.hpp's cut_cell() gives it: whole up to 80 bytes of UTF-8, else its first 60
 * (not inside a character) and its length in bytes. Spelled a piece at a time, so that a path of
 * 65 keys of 10^7 characters each (a cycle through a long key) is measured, never built. */
function cutPath(at) {
  const pieces = [];
  for (let link = at; link; link = link.up) pieces.push(link);
  pieces.reverse();
  let bytes = 0;
  let start = "";
  for (const [i, { key }] of pieces.entries()) {
    const piece = member(i > 0, key);
    bytes += Buffer.byteLength(piece);
    if (start.length < 81) start += piece.slice(0, 81);
  }
  if (bytes <= 80) return start;
  const head = Buffer.from(start);
  let cut = 60;
  while (cut > 0 && (head[cut] & 0xc0) === 0x80) --cut;
  return `${head.subarray(0, cut).toString()}… (${bytes} characters)`;
}

/** `value` as JSON text, as JSON.stringify writes it (toJSON(key) asked first, a value it skips
 * undefined), but for the numbers JSON.stringify writes as null: ±Infinity as ±1e999 (which
 * JSON.parse, and the reader, read back as ±Infinity) and −0 as -0, so that the reader refuses
 * them in its own words, as it refuses them in a file. A value nested deeper than the reader
 * reads (a cycle, through toJSON or not, is nested without end) is refused before anything below
 * it is asked, in the reader's words for a file ("nested more than 64 deep") at its key path
 * (`at`: the chain of keys from the document), so that no object, however deep or long its keys,
 * overflows the stack or a string. */
function jsonText(value, where, key = "", at = null, depth = 0) {
  if ((typeof value === "object" || typeof value === "bigint") && value !== null && typeof value.toJSON === "function")
    value = value.toJSON(key);
  if (value === undefined || typeof value === "function" || typeof value === "symbol") return undefined;
  if (depth > MAX_DEPTH) throw new Error(`${where}: nested more than ${MAX_DEPTH} deep at ${cutPath(at)}`);
  if (value instanceof Number || value instanceof String || value instanceof Boolean) value = value.valueOf();
  if (typeof value === "number") {
    if (Number.isFinite(value)) return Object.is(value, -0) ? "-0" : JSON.stringify(value);
    return Number.isNaN(value) ? "null" : value > 0 ? "1e999" : "-1e999";
  }
  if (typeof value === "bigint") return JSON.stringify(String(value));
  if (typeof value !== "object" || value === null) return JSON.stringify(value);
  if (Array.isArray(value)) {
    const items = []; // a hole is null, as JSON.stringify writes it
    for (let i = 0; i < value.length; ++i) items.push(jsonText(value[i], where, String(i), { up: at, key: i }, depth + 1) ?? "null");
    return `[${items.join(",")}]`;
  }
  const members = [];
  for (const [k, v] of Object.entries(value)) {
    const text = jsonText(v, where, k, { up: at, key: k }, depth + 1);
    if (text !== undefined) members.push(`${JSON.stringify(k)}:${text}`);
  }
  return `{${members.join(",")}}`;
}

/** The fields of a scenario JSON the reader reads (analysis::scenario_from_json); it ignores the rest. */
const READ_FIELDS = ["scenario", "mass", "principal_moments", "omega0_body", "omega0_world", "q0", "dt", "steps"];

/** The scenario's JSON text and the name the reader's messages give it ("scenario JSON"), for the
 * one reader the command line and Python read a scenario file with (analysis::scenario_from_json,
 * compiled). A field the reader reads that JSON cannot carry (a NaN, a BigInt) is refused here,
 * in the reader's words. */
function scenarioText(s) {
  const where = typeof s.scenario === "string" ? wasm.cutName(s.scenario) : "scenario JSON";
  for (const key of READ_FIELDS) {
    const value = s[key];
    const items = Array.isArray(value) ? value.map((v, i) => [`${key}[${i}]`, v]) : [[key, value]];
    for (const [field, v] of items)
      if (typeof v === "bigint" || Number.isNaN(v))
        throw new Error(`${where}: ${field}: expected ${key === "scenario" ? "a name (a string)" : "a number"}, got ${typeof v === "bigint" ? "a bigint" : "NaN"}`);
  }
  return { text: jsonText(s, "scenario JSON") ?? "null", file: "scenario JSON" };
}

/** A scenario JSON file's `text` read as `bookspin flipcheck judge` and Python read it (the same
 * reader, compiled; `file` names it in messages): its scenario as an object (JSON.parse's, which
 * reads every field as the reader does, a key given twice by its last value), which every
 * function here takes; or the command line's one line thrown for a file that is no scenario. */
export function readScenario(text, file = "scenario JSON") {
  answer(wasm.scenarioFile(wellFormed(String(text), "flipcheck.readScenario: text"),
    wellFormed(String(file), "flipcheck.readScenario: file")));
  return JSON.parse(String(text).replace(/^\uFEFF/, ""));
}

/** The SHA-256 (hex) of the scenario's JSON as `bookspin flipcheck export` writes it (for a
 * scenario by name, the carried scenarios/<name>.json byte for byte): a judgement's
 * scenario_sha256, as the command line's. */
export function scenarioSha256(name) {
  const { text, file } = scenarioText(spec(name, "scenarioSha256"));
  return createHash("sha256").update(answer(wasm.scenarioFile(text, file)), "utf8").digest("hex");
}

/** The exact motion at every step n = 0 … steps: t (N), q (N×4 w, x, y, z, body → world),
 * omegaBody, omegaWorld, L (N×3, L in the world frame), E (N): Float64Arrays, row-major. */
export function exactMotion(name) {
  const { text, file } = scenarioText(spec(name, "exactMotion"));
  return answer(wasm.exactMotion(text, file));
}

/** The two files `bookspin flipcheck export` writes, byte for byte: {json, csv}. */
export function exportFiles(name) {
  const { text, file } = scenarioText(spec(name, "exportFiles"));
  return answer(wasm.exportFiles(text, file));
}

/** The judgement CSV's row as an object: each column (numbers as numbers, null for an empty
 * cell), then pass, reasons (the failures, one phrase each) and line (what the command prints). */
function judgement(result) {
  const out = {};
  result.columns.forEach((column, i) => {
    const cell = result.cells[i];
    out[column] = TEXT_COLUMNS.has(column) ? cell : cell === "" ? null : Number(cell);
  });
  out.pass = result.pass;
  out.reasons = [...result.failures];
  out.line = result.line;
  Object.defineProperty(out, "csv", { value: result.csv, enumerable: false });
  return out;
}

/** A flat Float64Array of an array-like of numbers, or of rows (arrays) of numbers; `name` names
 * it where it holds BigInts (a BigInt64Array), which are no numbers to judge. */
function flat(values, name) {
  if (values === undefined || values === null) return new Float64Array(0);
  const bigints = () =>
    new Error(`${name}: holds BigInts (${values.constructor?.name ?? "bigint"}): expected numbers, a Float64Array or rows of numbers (Float64Array.from(${name}, Number) converts it)`);
  if (values instanceof BigInt64Array || values instanceof BigUint64Array) throw bigints();
  if (ArrayBuffer.isView(values)) return Float64Array.from(values);
  const list = Array.from(values);
  const items = list.length && typeof list[0] === "object" && list[0] !== null ? list.flatMap((r) => Array.from(r)) : list;
  if (items.some((v) => typeof v === "bigint")) throw bigints();
  return Float64Array.from(items);
}

/** Judges a motion given as arrays: t (N), q (N×4: w, x, y, z, body → world, any norm but 0,
 * either sign), omegaWorld (N×3, rad per time unit): flat, row-major, or as rows. */
export function judge(name, { t, q, omegaWorld } = {}, { motion = "motion" } = {}) {
  const s = spec(name, "judge");
  const { text, file } = scenarioText(s);
  return judgement(answer(wasm.judgeArrays(text, file, scenarioSha256(s), flat(t, "t"), flat(q, "q"), flat(omegaWorld, "omegaWorld"), "judge", wellFormed(motion, "flipcheck.judge: motion"))));
}

/** Judges a motion CSV's text, or its bytes (a Uint8Array: a Buffer as readFileSync gives it, read
 * byte for byte as the command line reads the file), as `bookspin flipcheck judge SCENARIO FILE`
 * judges the file (`file` names it in messages and in the judgement's motion column). */
export function judgeCsv(name, text, { file = "motion.csv", motion = file } = {}) {
  const s = spec(name, "judgeCsv");
  const scenarioJson = scenarioText(s);
  const csv = text instanceof Uint8Array ? text : wellFormed(String(text), "flipcheck.judgeCsv: text");
  return judgement(answer(wasm.judgeCsv(scenarioJson.text, scenarioJson.file, scenarioSha256(s), csv,
    wellFormed(file, "flipcheck.judgeCsv: file"), wellFormed(motion, "flipcheck.judgeCsv: motion"))));
}

/** The in-process equivalent of `npx flipcheck judge`'s exit status for a test runner: judges
 * `motion` ({t, q, omegaWorld} as judge() takes it, or a motion CSV's text as judgeCsv() takes
 * it, `file` naming it) and returns the judgement when it passes; throws node's
 * assert.AssertionError whose message is "SCENARIO MOTION: " and the line `judge` prints (FAIL
 * and its reasons) when it fails, MOTION the `motion` option or the file's name. Bad input
 * throws an Error, as judge() does. */
export function assertPasses(name, motion, { motion: label = "motion", file = "motion.csv" } = {}) {
  const s = spec(name, "assertPasses");
  const j =
    typeof motion === "string"
      ? judgeCsv(s, motion, { file, motion: label === "motion" ? basename(file) : label })
      : judge(s, motion, { motion: label });
  if (!j.pass)
    throw new AssertionError({ message: `${s.scenario} ${j.motion}: ${j.line}`, actual: j.verdict, expected: "pass", operator: "assertPasses" });
  return j;
}
