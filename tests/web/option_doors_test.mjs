// The explorer lab's options read as every other door reads them (src/fit/fit_options.hpp):
// tests/web/option_doors_page.cpp, which calls what web/fit_bindings.cpp's tosses_arg and
// drag_arg call with the page's names, compiled to WebAssembly by Debian's em++ as the page's
// module is, and given every value of tests/fit/option_doors.json that the page takes (the
// field's text, the menu's name): each refusal the page's name for the option and the table's
// cause, as the command line's and Python's are (tests/python/test_option_doors.py). The
// causes that need a recording (a reversed range, too few samples) are the recording's judge's,
// hand_flights, whose page answers Browser.ExplorerFitsAsFit checks: here they read.
// Skipped (77) where em++ is missing, a failure under CI=true.
// Usage: node tests/web/option_doors_test.mjs SOURCE_DIR
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { execFileSync } from 'node:child_process';
import { mkdtempSync, readdirSync, readFileSync, rmSync, symlinkSync, mkdirSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

const source = process.argv[2];
if (!source) throw new Error('usage: node tests/web/option_doors_test.mjs SOURCE_DIR');
try {
  execFileSync('em++', ['--version'], { stdio: 'ignore' });
} catch {
  console.log('em++ not found (apt-get install emscripten): the page\'s options are not compiled');
  process.exit(process.env.CI === 'true' ? 1 : 77);
}

const table = JSON.parse(readFileSync(join(source, 'tests/fit/option_doors.json'), 'utf8'));
const work = mkdtempSync(join(tmpdir(), 'bookspin-option-doors-'));
process.on('exit', () => rmSync(work, { recursive: true, force: true }));
// Eigen and Boost are header-only; Boost reached without the host's /usr/include (whose libc
// headers would shadow emscripten's), as web/build-wasm.sh does.
mkdirSync(join(work, 'include'));
symlinkSync('/usr/include/boost', join(work, 'include', 'boost'));
// The options' reader names an invisible character by its code point through the file-name
// rule's utf8proc (src/common/file_name.cpp), Debian's source as the page's build takes it
// (web/build-wasm-deps.sh).
const utf8proc = readdirSync(join(source, 'web/deb-src')).find((d) => d.startsWith('utf8proc-'));
if (!utf8proc) {
  console.log('web/deb-src/utf8proc-*: missing (scripts/install-deps.sh fetches Debian\'s source)');
  process.exit(process.env.CI === 'true' ? 1 : 77);
}
const utf8procDir = join(source, 'web/deb-src', utf8proc);
execFileSync('emcc', ['-O1', '-DUTF8PROC_STATIC', '-c', join(utf8procDir, 'utf8proc.c'), '-o', join(work, 'utf8proc.o')],
  { stdio: 'inherit', env: { ...process.env, NODE_PATH: process.env.NODE_PATH || '/usr/share/nodejs' } });
const page = join(work, 'page.js');
execFileSync('em++', [
  '-std=c++20', '-O1', '-DNDEBUG', `-I${join(source, 'src')}`, '-I/usr/include/eigen3',
  '-isystem', join(work, 'include'), '-fexceptions', '-sSINGLE_FILE=1', '-sENVIRONMENT=node',
  '-sEXIT_RUNTIME=1',
  '-DUTF8PROC_STATIC', '-isystem', utf8procDir,
  ...['tests/web/option_doors_page.cpp', 'src/fit/fit_options.cpp', 'src/common/number_text.cpp',
    'src/common/errors.cpp', 'src/common/file_name.cpp', 'src/physics/drag.cpp'].map((f) => join(source, f)),
  join(work, 'utf8proc.o'), '-o', page], { stdio: 'inherit', env: { ...process.env, NODE_PATH: process.env.NODE_PATH || '/usr/share/nodejs' } });
const answer = (option, text) =>
  execFileSync(process.execPath, [page, option, text], { encoding: 'utf8' }).trim();

test('the page refuses what every door refuses, naming its own field and menu', () => {
  const cases = table.cases.filter((c) => c.option in table.names.page);
  assert.ok(cases.length >= 10);
  for (const c of cases) {
    const want = c.cause.startsWith(':') ? table.names.page[c.option] + c.cause : 'ok';
    assert.equal(answer(c.option, c.text), want, `${c.option} ${JSON.stringify(c.text)}`);
  }
});

test('the page takes what every door takes', () => {
  for (const [option, text] of [['tosses', '0.5:1.5'], ['tosses', ''], ['tosses', ' 1.82:2.71, 2.88:3.22'],
    ['drag', 'none'], ['drag', 'linear'], ['drag', 'quadratic']])
    assert.equal(answer(option, text), 'ok', `${option} ${JSON.stringify(text)}`);
});
