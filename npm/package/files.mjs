// What a door may open: only a regular file, checked before it is opened, so that a FIFO with no
// writer or a device (/dev/zero) is refused, never read without end. Shared by the command
// (cli.mjs) and the engines' runner (web/flipcheck-engines.mjs), in bookspin's words.

/** Why `stats` (statSync's, which follows a link and opens nothing) is no file to read, or ""
 * for a regular file: bookspin's not_a_file_reason() (src/common/text_file.hpp), so that a FIFO
 * with no writer or a device (/dev/zero) is refused before it is opened, never read without end. */
export function notAFileReason(stats) {
  if (stats.isFile()) return "";
  if (stats.isDirectory()) return "is a directory";
  if (stats.isFIFO()) return "is a FIFO, not a regular file";
  if (stats.isCharacterDevice() || stats.isBlockDevice()) return "is a device, not a regular file";
  if (stats.isSocket()) return "is a socket, not a regular file";
  return "not a regular file";
}
