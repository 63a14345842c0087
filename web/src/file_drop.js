// The file a panel takes (judge.js, lab.js): chosen with its file input or dropped on its drop
// zone, handed to one callback either way.

/** Calls `onFile(file)` with the file chosen in the input `input` or dropped on `zone` (the
 * zone marked 'over' while a file is held over it). */
export function takeFiles(input, zone, onFile) {
  input.addEventListener('change', (e) => { if (e.target.files[0]) onFile(e.target.files[0]); });
  zone.addEventListener('dragover', (e) => { e.preventDefault(); zone.classList.add('over'); });
  zone.addEventListener('dragleave', () => zone.classList.remove('over'));
  zone.addEventListener('drop', (e) => {
    e.preventDefault();
    zone.classList.remove('over');
    if (e.dataTransfer.files[0]) onFile(e.dataTransfer.files[0]);
  });
}
