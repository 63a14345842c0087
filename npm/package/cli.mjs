#!/usr/bin/env node
// npx flipcheck judge SCENARIO MOTION.csv… [-o DIR]
// npx flipcheck export SCENARIO… [-o DIR]
// `bookspin flipcheck judge` and `export` with the same output and exit statuses (0; 3 when
// judge finds a motion that fails, its FAIL line printed and the CSV written; 2 for bad input,
// its one line on stderr; 1 when an output cannot be written; 70 for a bug). SCENARIO is
// a scenario's name (flipcheck's scenarios()) or a scenario JSON that `export` wrote. Unlike the
// command line it keeps no manifest: it judges and writes every time.
import { linkSync, lstatSync, readFileSync, renameSync, rmSync, statSync, writeFileSync } from "node:fs";
import { basename } from "node:path";
import { makeOutputFolder, notAFileReason, readReason } from "./files.mjs";
import { exportFiles, judgeCsv, readScenario, scenario, scenarios, version } from "./index.mjs";

const USAGE = `usage: flipcheck judge SCENARIO MOTION.csv... [-o DIR]
       flipcheck export SCENARIO... [-o DIR]
       flipcheck --version
SCENARIO: a scenario's name (${scenarios().join(", ")}) or a scenario JSON export wrote.
DIR: the output directory (default out/flipcheck).
Exit status: 0 every motion passes (export: written); 3 a motion fails (its FAIL line printed
and the CSV written: a CI step that runs judge fails on it); 2 bad input (one line, nothing
written); 1 an output could not be written; 70 internal error.`;

/** judge's exit status when a motion fails: bookspin flipcheck judge's (src/cli/run_guarded.hpp). */
const EXIT_JUDGED_FAIL = 3;

class InputError extends Error {}
class OutputError extends Error {}

/** `dir`/`name` as std::filesystem::path's operator/ joins them. */
function join(dir, name) {
  return dir.endsWith("/") ? dir + name : `${dir}/${name}`;
}

/** `dir`/`name` for an output, refused (InputError) unless it names a file right inside `dir`:
 * the scenario's name was checked by the judge (letters, digits, -, _, .), this holds it. */
function inside(dir, name) {
  if (!/^[A-Za-z0-9][A-Za-z0-9._-]*$/.test(name))
    throw new InputError(`flipcheck: "${JSON.stringify(name).slice(1, -1)}" is no file name inside ${dir}`);
  return join(dir, name);
}

/** The reason a file cannot be read, as bookspin's read_text_file() words it: its text, or with
 * `bytes` its bytes (a Buffer), as the command line reads a motion file. Only a regular file is
 * opened: every file npx reads is read here. */
function readText(path, what, { bytes = false } = {}) {
  try {
    const why = notAFileReason(statSync(path));
    if (why) throw new InputError(`${path}: cannot read ${what}: ${why}`);
    return bytes ? readFileSync(path) : readFileSync(path, "utf8");
  } catch (e) {
    if (e instanceof InputError) throw e;
    throw new InputError(`${path}: cannot read ${what}: ${readReason(e)}`);
  }
}

/** A scenario by name, or the JSON file export wrote, read as `bookspin flipcheck` reads it
 * (readScenario: the same reader, so the same refusals in the same words). */
function scenarioArg(arg) {
  // One route per file: its extension read in any case, as the command line and Python read it.
  if (!scenarios().includes(arg) && (/\.json$/i.test(arg) || arg.includes("/")))
    return readScenario(readText(arg, "the scenario file"), String(arg));
  return scenario(String(arg)); // a name, or the package's one line for no such name (the name cut)
}

/** The reason an OS call failed, as bookspin words it (strerror's text): "Is a directory". */
function reason(e) {
  const words = { EISDIR: "Is a directory", ENOTDIR: "Not a directory", EACCES: "Permission denied", ENOSPC: "No space left on device", EROFS: "Read-only file system" };
  return words[e.code] ?? e.message;
}

let serial = 0;
/** A hidden name beside `path` for this run, `.<name>.<tag>-<pid>-<n>`, as bookspin names its
 * temporaries (docs/outputs.md, "One run's outputs, all or nothing"). */
function sibling(path, tag) {
  const name = basename(path);
  return join(path.slice(0, path.length - name.length) || ".", `.${name}.${tag}-${process.pid}-${serial++}`);
}

/** Puts the complete `temporary` of `path` in place, keeping what was there under a second
 * name (a hard link; `aside`, null where there was none) until every file of the run is in
 * place. Throws OutputError naming `path`, which is then as it was. */
function putInPlace(temporary, path) {
  let earlier;
  try {
    earlier = lstatSync(path);
  } catch {
    earlier = null;
  }
  if (earlier?.isDirectory()) throw new OutputError(`cannot replace a directory with output file "${path}": Is a directory`);
  const aside = earlier ? sibling(path, "old") : null;
  try {
    if (aside) linkSync(path, aside);
  } catch (e) {
    throw new OutputError(`cannot move the earlier output aside "${path}": ${reason(e)}`);
  }
  try {
    renameSync(temporary, path);
  } catch (e) {
    if (aside) rmSync(aside, { force: true });
    throw new OutputError(`cannot rename temporary into place as "${path}": ${reason(e)}`);
  }
  return { path, aside };
}

/** Undoes putInPlace(): the earlier file back under its name (its bytes and inode), or the new
 * one removed. Never throws. */
function takeBack({ path, aside }) {
  try {
    if (aside) renameSync(aside, path);
    else rmSync(path, { force: true });
  } catch {
    // Tidying: the error that led here is the one reported.
  }
}

/** Writes `files` ([path, text] pairs) as one run's outputs, all or nothing, as `bookspin
 * flipcheck` writes them (output::StagedFiles, docs/outputs.md "One run's outputs, all or
 * nothing"): each written whole under its temporary name, then all put in place in order; where
 * one cannot be, those already in place are undone, the earlier files back under their names, and
 * every temporary removed. Throws OutputError naming the file that could not be written. */
function writeTogether(files) {
  const staged = [];
  const placed = [];
  try {
    for (const [path, text] of files) {
      const temporary = sibling(path, "tmp");
      staged.push({ temporary, path });
      try {
        writeFileSync(temporary, text, { flag: "wx" });
      } catch (e) {
        throw new OutputError(`cannot write "${path}": ${reason(e)}`);
      }
    }
    for (const { temporary, path } of staged) placed.push(putInPlace(temporary, path));
  } catch (e) {
    placed.reverse().forEach(takeBack);
    for (const { temporary } of staged) rmSync(temporary, { force: true });
    throw e;
  }
  for (const { aside } of placed) if (aside) rmSync(aside, { force: true });
}

/** The output folder made where missing (files.mjs, makeOutputFolder: the engines' runner's
 * check too); OutputError `cannot write "DIR": reason` where it is no folder. */
function makeDir(dir) {
  const why = makeOutputFolder(dir);
  if (why) throw new OutputError(`cannot write "${dir}": ${why}`);
}

/** The output folder `dir` given with `option`: an empty name is bad input (exit 2), not a
 * folder at the root that cannot be written (exit 1). */
function given(option, dir) {
  if (dir === "") throw new InputError(`${option}: expected a directory, got an empty name (leave it out for out/flipcheck)`);
  return dir;
}

/** The arguments `args` (process.argv after the command) as the OS gave them: node decodes argv
 * as UTF-8, each byte that is no UTF-8 becoming U+FFFD, so a file named in another encoding
 * (Latin-1's "caf\xe9.csv") could not be opened by its decoded name and was "no such file",
 * where the command line opens it. Where an argument holds U+FFFD, its bytes are read back from
 * /proc/self/cmdline (Linux) as a Buffer, which node's fs opens; elsewhere it stays as given. */
function osArguments(args) {
  if (!args.some((a) => a.includes("\uFFFD"))) return args;
  let cmdline;
  try {
    cmdline = readFileSync("/proc/self/cmdline");
  } catch {
    return args;
  }
  const words = [];
  for (let start = 0, i = 0; i < cmdline.length; ++i)
    if (cmdline[i] === 0) {
      words.push(cmdline.subarray(start, i));
      start = i + 1;
    }
  const ours = words.slice(words.length - args.length);
  if (ours.length !== args.length) return args;
  return args.map((a, i) => (a.includes("\uFFFD") && ours[i].toString("utf8") === a ? ours[i] : a));
}

function parse(args) {
  const raw = osArguments(args);
  const positional = [];
  let out = "out/flipcheck";
  for (let i = 0; i < args.length; ++i) {
    const a = args[i];
    if (a === "-o" || a === "--out") {
      if (i + 1 >= args.length) throw new InputError(`${a}: expected a directory`);
      out = given(a, args[++i]);
    } else if (a.startsWith("--out=")) out = given("--out", a.slice("--out=".length));
    else if (a === "-h" || a === "--help") {
      console.log(USAGE);
      process.exit(0);
    } else if (a.startsWith("-") && a !== "-") throw new InputError(`${a}: unknown option (${USAGE.split("\n")[0]})`);
    else positional.push(raw[i]);
  }
  return { positional, out };
}

function judgeCommand(args) {
  const { positional, out } = parse(args);
  if (positional.length < 1) throw new InputError("flipcheck judge: SCENARIO is required");
  const [scenarioPath, ...files] = positional;
  const spec = scenarioArg(scenarioPath);
  if (!files.length) throw new InputError("flipcheck judge: nothing to judge: give MOTION files");
  // Every file read and judged before anything is written: a bad one is its one line.
  // A file named in bytes that are no UTF-8 (a Buffer, osArguments) is opened by its bytes and
  // named by their UTF-8 reading, each such byte as U+FFFD.
  const judged = files.map((file) => judgeCsv(spec, readText(file, "the motion file", { bytes: true }), { file: String(file), motion: basename(String(file)) }));
  const name = spec.scenario;
  // Each judgement's CSV is its header line and its row; the row may span lines (a file name
  // holding a line break, in double quotes): everything after the header is the row.
  const header = judged[0].csv.slice(0, judged[0].csv.indexOf("\n") + 1);
  const csv = header + judged.map((j) => j.csv.slice(j.csv.indexOf("\n") + 1)).join("");
  const target = inside(out, `${name}-judge.csv`);
  makeDir(out);
  writeTogether([[target, csv]]);
  judged.forEach((j, i) => console.log(`${name} ${String(files[i])}: ${j.line}`));
  console.log(`wrote: ${target}`);
  return judged.every((j) => j.pass) ? 0 : EXIT_JUDGED_FAIL;
}

function exportCommand(args) {
  const { positional, out } = parse(args);
  if (positional.length < 1) throw new InputError("flipcheck export: SCENARIO is required");
  // Every scenario read, checked and computed before anything is written (a bad one is its one
  // line, exit 2, nothing written), then every file written under a temporary name and only then
  // all renamed into place, as `bookspin flipcheck export` puts a command's files in place.
  const specs = positional.map(scenarioArg);
  const outputs = specs.map((spec) => {
    const files = exportFiles(spec);
    return { json: inside(out, `${spec.scenario}.json`), csv: inside(out, `${spec.scenario}-exact.csv`), files };
  });
  const texts = new Map(); // path → text
  for (const [i, o] of outputs.entries()) {
    if (texts.has(o.json))
      throw new InputError(`flipcheck export: two scenarios named ${specs[i].scenario} (one given twice, or two of one name): give each once`);
    texts.set(o.json, o.files.json).set(o.csv, o.files.csv);
  }
  makeDir(out);
  writeTogether(texts);
  for (const { json, csv } of outputs) console.log(`exported: ${json}, ${csv}`);
}

const [command, ...rest] = process.argv.slice(2);
try {
  if (command === "judge") process.exitCode = judgeCommand(rest);
  else if (command === "export") exportCommand(rest);
  else if (command === "-h" || command === "--help") console.log(USAGE);
  else if (command === "--version") console.log(`flipcheck ${version}`);
  else throw new InputError(command === undefined ? `a command is required\n${USAGE}` : `unknown command "${command}"\n${USAGE}`);
} catch (e) {
  if (e instanceof OutputError) {
    console.error(`flipcheck: error: ${e.message}`);
    process.exit(1);
  }
  const internal = !(e instanceof InputError) && !(e instanceof Error && e.constructor === Error);
  console.error(`flipcheck: ${internal ? "internal error" : "error"}: ${e.message}`);
  process.exit(internal ? 70 : 2);
}
