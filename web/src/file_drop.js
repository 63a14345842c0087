// The files a panel takes (judge.js, lab.js): chosen with its file input or dropped on its drop
// zone, handed to one callback either way.

/** Calls `onFiles(files)` (an array of File, one or more) with the files chosen in the input
 * `input` or dropped on `zone` (the zone marked 'over' while files are held over it). */
export function takeFiles(input, zone, onFiles) {
  const hand = (list) => { if (list && list.length) onFiles(Array.from(list)); };
  // Emptied once taken: the same file chosen again is taken again, and files chosen next
  // replace these rather than join them.
  input.addEventListener('change', (e) => { hand(e.target.files); e.target.value = ''; });
  zone.addEventListener('dragover', (e) => { e.preventDefault(); zone.classList.add('over'); });
  zone.addEventListener('dragleave', () => zone.classList.remove('over'));
  zone.addEventListener('drop', (e) => {
    e.preventDefault();
    zone.classList.remove('over');
    hand(e.dataTransfer.files);
  });
}
