// The files a panel takes (judge.js, lab.js): chosen with its file input or dropped on its drop
// zone, folders included, handed to one callback either way; and the recordings a folder holds
// (docs/phone-lab.md, "A class's recordings").

/** Calls `onFiles(files, paths)` (an array of File, one or more, and each one's path: its name,
 * or for a file of a dropped or chosen folder the folder's path and its name,
 * "class/anna/Raw Data.csv") with the files chosen in the input `input` (or each of an array of
 * inputs: one for files, one with webkitdirectory for a folder) or dropped on `zone` (the zone marked 'over' while
 * files are held over it). */
export function takeFiles(input, zone, onFiles) {
  const hand = (files, paths) => { if (files.length) onFiles(files, paths); };
  // Emptied once taken: the same file chosen again is taken again, and files chosen next
  // replace these rather than join them. `input` may be several (files, and a folder's).
  for (const one of [input].flat()) {
    one.addEventListener('change', (e) => {
      const files = Array.from(e.target.files || []);
      hand(files, files.map((f) => f.webkitRelativePath || f.name));
      e.target.value = '';
    });
  }
  zone.addEventListener('dragover', (e) => { e.preventDefault(); zone.classList.add('over'); });
  zone.addEventListener('dragleave', () => zone.classList.remove('over'));
  zone.addEventListener('drop', (e) => {
    e.preventDefault();
    zone.classList.remove('over');
    filesOfDrop(e.dataTransfer).then(({ files, paths }) => hand(files, paths));
  });
}

/** The files of a drop's `dataTransfer`: each dropped file, and every file inside each dropped
 * folder (walked through the entries API, webkitGetAsEntry, whose folder reader answers in
 * batches until an empty one); a promise of {files, paths}, in the order dropped, each folder's
 * files sorted by path. */
export async function filesOfDrop(dataTransfer) {
  const items = Array.from(dataTransfer.items || []);
  const entries = items.map((item) => (item.webkitGetAsEntry ? item.webkitGetAsEntry() : null));
  if (!entries.some((entry) => entry && entry.isDirectory)) {
    const files = Array.from(dataTransfer.files || []);
    return { files, paths: files.map((f) => f.name) };
  }
  const found = [];
  for (const entry of entries) if (entry) await walk(entry, '', found);
  return { files: found.map((x) => x.file), paths: found.map((x) => x.path) };
}

async function walk(entry, folder, found) {
  const path = folder + entry.name;
  if (entry.isFile) {
    found.push({ file: await new Promise((ok, fail) => entry.file(ok, fail)), path });
    return;
  }
  if (!entry.isDirectory) return;
  const reader = entry.createReader();
  const children = [];
  for (;;) {
    const batch = await new Promise((ok, fail) => reader.readEntries(ok, fail));
    if (!batch.length) break;
    children.push(...batch);
  }
  children.sort((a, b) => (a.name < b.name ? -1 : a.name > b.name ? 1 : 0));
  for (const child of children) await walk(child, `${path}/`, found);
}

/** The recordings among files at `paths` (indices into them), as `bookspin fit` takes them:
 * {recordings: [{path, index, meta: [{name, index}]}], skipped: [path]}.
 * - A phyphox export's `Raw Data.csv` is one recording, named after its folder; its folder's
 *   `meta/time.csv` and `meta/device.csv` go with it (the pauses, the gyroscope's range), and
 *   so do a `time.csv` and a `device.csv` picked beside it.
 * - Any other `.csv` or `.zip` is one recording.
 * - Inside a folder, anything else (an export's other files, `.DS_Store`, a photo) is skipped
 *   and named; a file chosen on its own is never skipped: the fit says what is wrong with it. */
export function recordingsOf(paths) {
  const lower = paths.map((p) => p.toLowerCase());
  const folderOf = (p) => (p.includes('/') ? p.slice(0, p.lastIndexOf('/')) : '');
  const isExport = (k) => /(^|\/)raw data\.csv$/.test(lower[k]);
  const exports = new Set(paths.filter((p, k) => isExport(k)).map(folderOf));
  const recordings = [];
  const skipped = [];
  const byFolder = new Map();
  paths.forEach((path, index) => {
    const folder = folderOf(path);
    const name = path.slice(folder.length ? folder.length + 1 : 0);
    const meta = folder.toLowerCase() === 'meta' || folder.toLowerCase().endsWith('/meta');
    // An export's meta/ files, in its meta/ folder or picked beside its Raw Data.csv (a file
    // input gives names alone: "Raw Data.csv", "time.csv", "device.csv").
    const owner = meta ? folderOf(folder) : folder;
    const metaName = ['time.csv', 'device.csv'].includes(name.toLowerCase());
    if (metaName && exports.has(owner) && (meta || !isExport(index))) {
      if (!byFolder.has(owner)) byFolder.set(owner, []);
      byFolder.get(owner).push({ name: name.toLowerCase(), index });
    } else if (folder && (meta || !/\.(csv|zip)$/.test(lower[index]))) {
      skipped.push(path);
    } else {
      recordings.push({ path, index, meta: [] });
    }
  });
  for (const r of recordings) if (isExport(r.index)) r.meta = byFolder.get(folderOf(r.path)) || [];
  return { recordings, skipped };
}
