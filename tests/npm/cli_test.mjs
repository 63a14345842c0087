// The npm package's command (npm/package/cli.mjs, `npx flipcheck`) under node's test runner, run
// from the package it built (FLIPCHECK_PACKAGE: its folder) in a fresh folder each test:
// - every run's outputs all or nothing (docs/outputs.md, "One run's outputs, all or nothing"):
//   where a later output cannot be put in place (a folder under its name), exit 1 naming it, the
//   earlier files' bytes and inodes kept, and nothing left beside them (no temporary);
// - one route per file (docs/flipcheck.md, "What a scenario may be"): a scenario file named with
//   its extension in any case is read as a scenario JSON, as the command line and Python read it.
import assert from "node:assert/strict";
import { spawnSync } from "node:child_process";
import { mkdirSync, mkdtempSync, readdirSync, readFileSync, statSync, symlinkSync, writeFileSync } from "node:fs";
import { tmpdir } from "node:os";
import { join, resolve } from "node:path";
import { test } from "node:test";
import { fileURLToPath } from "node:url";

const cli = resolve(process.env.FLIPCHECK_PACKAGE, "cli.mjs");
const scenarios = resolve(process.env.FLIPCHECK_PACKAGE, "scenarios");

/** `npx flipcheck ARGS` in `cwd`: {status, stdout, stderr}. */
function npx(cwd, ...args) {
  return spawnSync(process.execPath, [cli, ...args], { cwd, encoding: "utf8" });
}

/** Every name in `dir` with its bytes and inode, sorted by name (a folder: its kind). */
function contents(dir) {
  return readdirSync(dir)
    .sort()
    .map((name) => {
      const s = statSync(join(dir, name));
      return s.isDirectory() ? [name, "folder", s.ino] : [name, readFileSync(join(dir, name), "utf8"), s.ino];
    });
}

test("export: a later output that cannot be put in place keeps every earlier file and leaves nothing", () => {
  const room = mkdtempSync(join(tmpdir(), "flipcheck-cli-"));
  const out = join(room, "out");
  mkdirSync(out);
  // The earlier files of an earlier run, and the last output's name taken by a folder.
  writeFileSync(join(out, "mujoco-test-box.json"), "earlier scenario\n");
  writeFileSync(join(out, "mujoco-test-box-exact.csv"), "earlier motion\n");
  writeFileSync(join(out, "book-intermediate-0.2.json"), "earlier second scenario\n");
  mkdirSync(join(out, "book-intermediate-0.2-exact.csv"));
  const before = contents(out);
  const run = npx(room, "export", "mujoco-test-box", "book-intermediate-0.2", "-o", "out");
  assert.equal(run.status, 1, run.stderr);
  assert.equal(
    run.stderr,
    'flipcheck: error: cannot replace a directory with output file "out/book-intermediate-0.2-exact.csv": Is a directory\n',
  );
  assert.equal(run.stdout, "");
  assert.deepEqual(contents(out), before);
  assert.deepEqual(readdirSync(room), ["out"]);
});

test("export: every file put in place where all can be, earlier ones replaced", () => {
  const room = mkdtempSync(join(tmpdir(), "flipcheck-cli-"));
  mkdirSync(join(room, "out"));
  writeFileSync(join(room, "out", "mujoco-test-box.json"), "earlier scenario\n");
  const run = npx(room, "export", "mujoco-test-box", "-o", "out");
  assert.equal(run.status, 0, run.stderr);
  assert.deepEqual(readdirSync(join(room, "out")).sort(), ["mujoco-test-box-exact.csv", "mujoco-test-box.json"]);
  assert.equal(readFileSync(join(room, "out", "mujoco-test-box.json"), "utf8"), readFileSync(join(scenarios, "mujoco-test-box.json"), "utf8"));
});

test("judge: a judgement CSV whose name is a folder: exit 1, the folder kept, nothing left", () => {
  const room = mkdtempSync(join(tmpdir(), "flipcheck-cli-"));
  assert.equal(npx(room, "export", "mujoco-test-box", "-o", "kit").status, 0);
  mkdirSync(join(room, "out", "mujoco-test-box-judge.csv"), { recursive: true });
  const before = contents(join(room, "out"));
  const run = npx(room, "judge", "mujoco-test-box", "kit/mujoco-test-box-exact.csv", "-o", "out");
  assert.equal(run.status, 1, run.stderr);
  assert.match(run.stderr, /^flipcheck: error: cannot replace a directory with output file "out\/mujoco-test-box-judge.csv": Is a directory\n$/);
  assert.deepEqual(contents(join(room, "out")), before);
  assert.deepEqual(readdirSync(join(room, "out", "mujoco-test-box-judge.csv")), []);
});

test("a scenario JSON named with its extension in any case is read as a scenario JSON", () => {
  const room = mkdtempSync(join(tmpdir(), "flipcheck-cli-"));
  assert.equal(npx(room, "export", "mujoco-test-box", "-o", "kit").status, 0);
  const json = readFileSync(join(room, "kit", "mujoco-test-box.json"));
  const lower = npx(room, "judge", "kit/mujoco-test-box.json", "kit/mujoco-test-box-exact.csv", "-o", "lower");
  assert.equal(lower.status, 0, lower.stderr);
  for (const spelled of ["scen.JSON", "scen.Json"]) {
    writeFileSync(join(room, spelled), json);
    const run = npx(room, "judge", spelled, "kit/mujoco-test-box-exact.csv", "-o", spelled + "-out");
    assert.equal(run.status, 0, run.stderr);
    assert.equal(readFileSync(join(room, spelled + "-out", "mujoco-test-box-judge.csv"), "utf8"), readFileSync(join(room, "lower", "mujoco-test-box-judge.csv"), "utf8"));
  }
});

test("export into an empty folder whose last output cannot be put in place leaves it empty", () => {
  // No earlier file anywhere: the files put in place before the one that cannot be are taken
  // away again, not left as the half of a run (a file with no earlier one is removed by the undo).
  const room = mkdtempSync(join(tmpdir(), "flipcheck-cli-"));
  const out = join(room, "out");
  mkdirSync(join(out, "book-intermediate-0.2-exact.csv"), { recursive: true });
  const before = contents(out);
  const run = npx(room, "export", "mujoco-test-box", "book-intermediate-0.2", "-o", "out");
  assert.equal(run.status, 1, run.stderr);
  assert.match(run.stderr, /^flipcheck: error: cannot replace a directory with output file "out\/book-intermediate-0.2-exact.csv"/);
  assert.deepEqual(contents(out), before);
  assert.deepEqual(readdirSync(room), ["out"]);
});

test("what is no regular file is refused before it is read, in the command line's words", () => {
  // A FIFO without a writer would be waited on for ever, /dev/zero read without end: both are
  // refused at once, as bookspin's read_text_file() refuses them, and nothing is written. (The
  // timeout only turns a hang into a failure.)
  const room = mkdtempSync(join(tmpdir(), "flipcheck-cli-"));
  assert.equal(npx(room, "export", "mujoco-test-box", "-o", "kit").status, 0);
  assert.equal(spawnSync("mkfifo", [join(room, "m.csv")]).status, 0);
  assert.equal(spawnSync("mkfifo", [join(room, "s.json")]).status, 0);
  const cases = [
    [["judge", "mujoco-test-box", "m.csv"], "m.csv: cannot read the motion file: is a FIFO, not a regular file"],
    [["judge", "mujoco-test-box", "/dev/zero"], "/dev/zero: cannot read the motion file: is a device, not a regular file"],
    [["judge", "s.json", "kit/mujoco-test-box-exact.csv"], "s.json: cannot read the scenario file: is a FIFO, not a regular file"],
    [["export", "/dev/null.json"], "/dev/null.json: cannot read the scenario file: no such file"],
    [["judge", "mujoco-test-box", "kit"], "kit: cannot read the motion file: is a directory"],
  ];
  for (const [args, said] of cases) {
    const run = spawnSync(process.execPath, [cli, ...args, "-o", "out"], { cwd: room, encoding: "utf8", timeout: 30000 });
    assert.equal(run.status, 2, `${args.join(" ")}: ${run.error ?? run.stderr}`);
    assert.equal(run.stderr, `flipcheck: error: ${said}\n`);
  }
  assert.deepEqual(readdirSync(room).sort(), ["kit", "m.csv", "s.json"]);
});

test("an output folder that is no folder (a regular file, a FIFO, /dev/full): one line naming it, exit 1", () => {
  // The engines' runner makes the same check (files.mjs, makeOutputFolder) in the same words
  // (tests/browser/flipcheck_engines_test.py); mkdirSync's own EEXIST named no kind.
  const room = mkdtempSync(join(tmpdir(), "flipcheck-cli-"));
  writeFileSync(join(room, "a-file"), "kept\n");
  assert.equal(spawnSync("mkfifo", [join(room, "a-fifo")]).status, 0);
  const cases = [["a-file", "is a regular file"], ["a-fifo", "is a FIFO"], ["/dev/full", "is a device"]];
  for (const [out, what] of cases) {
    const run = spawnSync(process.execPath, [cli, "export", "mujoco-test-box", "-o", out], { cwd: room, encoding: "utf8", timeout: 30000 });
    assert.equal(run.status, 1, `${out}: ${run.error ?? run.stderr}`);
    assert.equal(run.stderr, `flipcheck: error: cannot write "${out}": ${what}, not a folder\n`);
    assert.equal(run.stdout, "");
  }
  assert.deepEqual(readdirSync(room).sort(), ["a-fifo", "a-file"]);
  assert.equal(readFileSync(join(room, "a-file"), "utf8"), "kept\n");
});

test("a motion file whose name is no UTF-8 is judged, as the command line judges it", () => {
  // node reads argv as UTF-8, Latin-1's byte 0xe9 becoming U+FFFD: "no such file" for a file that
  // is there. Its bytes are read back from /proc/self/cmdline.
  const room = mkdtempSync(join(tmpdir(), "flipcheck-cli-"));
  assert.equal(npx(room, "export", "mujoco-test-box", "-o", "kit").status, 0);
  const motion = readFileSync(join(room, "kit", "mujoco-test-box-exact.csv"));
  writeFileSync(Buffer.concat([Buffer.from(`${room}/caf`), Buffer.from([0xe9]), Buffer.from(".csv")]), motion);
  const run = spawnSync("sh", ["-c", `exec "$0" "$1" judge mujoco-test-box "$(printf 'caf\\351.csv')" -o out`, process.execPath, cli],
    { cwd: room, encoding: "utf8", timeout: 60000 });
  assert.equal(run.status, 0, run.stderr);
  assert.match(run.stdout, /^mujoco-test-box caf\uFFFD\.csv: PASS/);
});

test("a loop of symbolic links is said so, in the command line's words", () => {
  const room = mkdtempSync(join(tmpdir(), "flipcheck-cli-"));
  symlinkSync(join(room, "loop.csv"), join(room, "loop.csv"));
  const run = npx(room, "judge", "mujoco-test-box", "loop.csv", "-o", "out");
  assert.equal(run.status, 2, run.stderr);
  assert.equal(run.stderr, "flipcheck: error: loop.csv: cannot read the motion file: its symbolic links make a loop\n");
});

test("an empty output folder (--out=) is bad input: exit 2, nothing written", () => {
  const room = mkdtempSync(join(tmpdir(), "flipcheck-cli-"));
  for (const args of [["export", "mujoco-test-box", "--out="], ["export", "mujoco-test-box", "-o", ""]]) {
    const run = npx(room, ...args);
    assert.equal(run.status, 2, run.stderr);
    assert.equal(run.stderr, `flipcheck: error: ${args.at(-1) === "" ? "-o" : "--out"}: expected a directory, got an empty name (leave it out for out/flipcheck)\n`);
  }
  assert.deepEqual(readdirSync(room), []);
});

test("a scenario JSON saved as UTF-16 is said to be so", () => {
  const room = mkdtempSync(join(tmpdir(), "flipcheck-cli-"));
  const text = readFileSync(join(scenarios, "mujoco-test-box.json"), "utf8");
  writeFileSync(join(room, "le.json"), Buffer.concat([Buffer.from([0xff, 0xfe]), Buffer.from(text, "utf16le")]));
  writeFileSync(join(room, "be.json"), Buffer.from(text, "utf16le").swap16());
  for (const file of ["le.json", "be.json"]) {
    const run = npx(room, "export", file, "-o", "out");
    assert.equal(run.status, 2, run.stderr);
    assert.equal(run.stderr, `flipcheck: error: ${file}: NUL byte at line 1 (not a text file: a binary file, or text saved as UTF-16)\n`);
  }
  assert.deepEqual(readdirSync(room).sort(), ["be.json", "le.json"]);
});

test("a quote left open in a motion CSV is named so, as the command line names it (tests/bad_motions)", () => {
  // In a column read; in a column quoted on every row, whose next opening quote closed it (once
  // blamed on t two rows on); on the last row (named by its column).
  for (const name of ["quote-left-open", "quote-left-open-in-a-quoted-column", "quote-left-open-at-the-end"]) {
    const room = mkdtempSync(join(tmpdir(), "flipcheck-cli-"));
    const file = fileURLToPath(new URL(`../bad_motions/${name}.csv`, import.meta.url));
    const said = readFileSync(file.replace(/\.csv$/, ".expected"), "utf8").replace("{FILE}", file);
    const run = npx(room, "judge", "mujoco-test-box", file, "-o", "out");
    assert.equal(run.status, 2, `${name}: ${run.stderr}`);
    assert.equal(run.stderr, `flipcheck: error: ${said}`, name);
    assert.deepEqual(readdirSync(room), []);
  }
});
