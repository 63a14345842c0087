import { mkdirSync, statSync } from "node:fs";

// What a door may open: only a regular file, checked before it is opened, so that a FIFO with no
// writer or a device (/dev/zero) is refused, never read without end. Shared by the command
// (cli.mjs) and the engines' runner (web/flipcheck-engines.mjs), in bookspin's words; and the one
// check of an output folder both make before they write.

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

/** Why a file could not be read (an error of statSync or readFileSync), in bookspin's words:
 * "no such file", "Permission denied", "its symbolic links make a loop" (kLinkLoop of
 * src/common/text_file.hpp: the command line and Python say it alike), else node's message. */
export function readReason(e) {
  if (e.code === "ENOENT" || e.code === "ENOTDIR") return "no such file";
  if (e.code === "EACCES") return "Permission denied";
  if (e.code === "ELOOP") return "its symbolic links make a loop";
  return e.message;
}

/** Makes the output folder `dir` (and its parents) where missing: "" once it is a folder, or why
 * it cannot be one, in bookspin's words (a regular file, a FIFO or a device at its name: "is a
 * FIFO, not a folder"; an OS error: its strerror text), for the door's one line `cannot write
 * "DIR": reason`, exit 1. Shared by npx (cli.mjs) and the engines' runner, which both refuse
 * such an output before anything is written. */
export function makeOutputFolder(dir) {
  let stats = null;
  try {
    stats = statSync(dir);
  } catch {
    // Missing (or behind a link loop, a file as a parent): mkdirSync says why below.
  }
  if (stats && !stats.isDirectory()) {
    const what = notAFileReason(stats).replace(/, not a regular file$/, "") || "is a regular file";
    return `${what}, not a folder`;
  }
  try {
    mkdirSync(dir, { recursive: true });
    return "";
  } catch (e) {
    const words = { EEXIST: "File exists", ENOTDIR: "Not a directory", EACCES: "Permission denied", ENOSPC: "No space left on device", EROFS: "Read-only file system", ELOOP: "its symbolic links make a loop" };
    return words[e.code] ?? e.message;
  }
}
