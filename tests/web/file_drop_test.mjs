// The lab's drop zone (web/src/file_drop.js, docs/phone-lab.md "A class's recordings") under
// node: a dropped folder walked through the entries API (fake entries that answer as a
// browser's do, the folder reader in batches), and the recordings it holds sorted out of its
// other files. The expected recordings are written out by hand for the tree built here.
// Usage: node tests/web/file_drop_test.mjs SOURCE_DIR
import assert from 'node:assert/strict';
import { test } from 'node:test';
import { pathToFileURL } from 'node:url';
import { join } from 'node:path';

const source = process.argv[2];
if (!source) throw new Error('usage: node tests/web/file_drop_test.mjs SOURCE_DIR');
const { filesOfDrop, recordingsOf } = await import(pathToFileURL(join(source, 'web/src/file_drop.js')).href);

/** A file entry whose file() gives {name, text}. */
const fileEntry = (name) => ({ name, isFile: true, isDirectory: false,
  file(ok) { setTimeout(() => ok({ name, text: `bytes of ${name}` }), 0); } });
/** A folder entry whose reader answers in batches of `batch` entries, then an empty batch, as
 * Chromium's answers in batches of 100. */
const folderEntry = (name, children, batch = 2) => ({ name, isFile: false, isDirectory: true,
  createReader() {
    let at = 0;
    return { readEntries(ok) { const b = children.slice(at, at + batch); at += b.length; setTimeout(() => ok(b), 0); } };
  } });
const item = (entry) => ({ webkitGetAsEntry: () => entry });

// A class's folder: two phyphox exports (one with its meta/), a zip, a plain CSV, and what a
// folder also holds.
const classFolder = folderEntry('class', [
  folderEntry('ben', [fileEntry('Raw Data.csv')]),
  folderEntry('anna', [
    folderEntry('meta', [fileEntry('time.csv'), fileEntry('device.csv'), fileEntry('other.csv')]),
    fileEntry('Raw Data.csv'), fileEntry('photo.jpg')]),
  fileEntry('chloe.zip'), fileEntry('dan.csv'), fileEntry('.DS_Store'),
  folderEntry('meta', [fileEntry('time.csv')]),
]);

test('a dropped folder is walked to its every file, sorted, the reader read to its empty batch', async () => {
  const { files, paths } = await filesOfDrop({ items: [item(classFolder), item(fileEntry('eve.zip'))], files: [] });
  assert.deepEqual(paths, [
    'class/.DS_Store', 'class/anna/Raw Data.csv', 'class/anna/meta/device.csv',
    'class/anna/meta/other.csv', 'class/anna/meta/time.csv', 'class/anna/photo.jpg',
    'class/ben/Raw Data.csv', 'class/chloe.zip', 'class/dan.csv', 'class/meta/time.csv', 'eve.zip']);
  assert.equal(files[1].text, 'bytes of Raw Data.csv');
  assert.equal(files[2].name, 'device.csv');
});

test('files dropped without a folder are the drop\'s files, by name', async () => {
  const list = [{ name: 'a.csv' }, { name: 'b.zip' }];
  const got = await filesOfDrop({ items: [item(fileEntry('a.csv')), item(fileEntry('b.zip'))], files: list });
  assert.deepEqual(got.paths, ['a.csv', 'b.zip']);
  assert.equal(got.files[0], list[0]);
});

test('the recordings of a folder: each export with its meta/, each zip and CSV; the rest skipped', () => {
  const paths = [
    'class/.DS_Store', 'class/anna/Raw Data.csv', 'class/anna/meta/device.csv',
    'class/anna/meta/other.csv', 'class/anna/meta/time.csv', 'class/anna/photo.jpg',
    'class/ben/Raw Data.csv', 'class/chloe.zip', 'class/dan.csv', 'class/meta/time.csv', 'eve.zip'];
  const { recordings, skipped } = recordingsOf(paths);
  assert.deepEqual(recordings, [
    { path: 'class/anna/Raw Data.csv', index: 1, meta: [{ name: 'device.csv', index: 2 }, { name: 'time.csv', index: 4 }] },
    { path: 'class/ben/Raw Data.csv', index: 6, meta: [] },
    { path: 'class/chloe.zip', index: 7, meta: [] },
    { path: 'class/dan.csv', index: 8, meta: [] },
    { path: 'eve.zip', index: 10, meta: [] },
  ]);
  // meta/other.csv is no file the reader reads; class/meta/ belongs to no export.
  assert.deepEqual(skipped, ['class/.DS_Store', 'class/anna/meta/other.csv', 'class/anna/photo.jpg',
    'class/meta/time.csv']);
});

test('a file chosen on its own is never skipped: the fit says what is wrong with it', () => {
  const { recordings, skipped } = recordingsOf(['notes.txt', 'Raw Data.csv']);
  assert.deepEqual(recordings.map((r) => r.path), ['notes.txt', 'Raw Data.csv']);
  assert.deepEqual(skipped, []);
});

test('an export\'s meta files picked beside its Raw Data.csv go with it, not as recordings', () => {
  // A file input gives names alone: the three files of one export chosen together.
  const { recordings, skipped } = recordingsOf(['Raw Data.csv', 'time.csv', 'device.csv']);
  assert.deepEqual(recordings, [
    { path: 'Raw Data.csv', index: 0, meta: [{ name: 'time.csv', index: 1 }, { name: 'device.csv', index: 2 }] },
  ]);
  assert.deepEqual(skipped, []);
  // Without a Raw Data.csv beside it, a time.csv is a file of its own: the fit says what it is.
  assert.deepEqual(recordingsOf(['time.csv', 'a.zip']).recordings.map((r) => r.path), ['time.csv', 'a.zip']);
});
