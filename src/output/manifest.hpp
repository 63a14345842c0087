#pragma once
// A manifest: what produced a set of outputs and what they were when written, so that a
// later run can tell whether it would produce the same and skip the work (`bookspin render`,
// `plot`, `gallery`; docs/outputs.md).
//
// The file is JSON with a fixed layout, written by write_manifest() (through the one JSON
// writer, common/json_writer.hpp, as are the heads and notes of cache/) and read back here
// alone (manifest_stale(), read_manifest()):
//
//   {
//     <head: the caller's members, each line indented by two spaces, the last ending in ','>
//     "head_sha256": "sha256:<64 hex>",   (the head's own hash: where the head ends)
//     <note: more members, recorded but not compared, e.g. the scene file's path and hash>
//     "outputs": [
//       {"path": "fig09.mp4", "size": 1234, "sha256": "<64 hex>"},
//       ...
//     ]
//   }
//
// The head holds everything the outputs depend on (program build, options, the resolved
// scene, the hashes of the inputs read as bytes: textures, meshes); a run is up to date when
// the manifest's head is this run's head byte for byte (the head_sha256 line marks its end,
// so a longer recorded head, of a run with more options, is not this one) and every output is still
// there with its size (and hash, when verifying). The note records what does not decide: the scene
// file's own hash changes with its comments, while its resolved keys are in the head.
// Anything else, a hand-edited or unreadable manifest included, means "render again".
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bookspin::output {

/// Hashes every output (paths relative to `root`, '/'-separated) and writes `manifest`
/// through an AtomicFile, so it appears only complete. Call it last, after the outputs are in
/// place. Throws OutputError if an output cannot be read or the manifest cannot be written.
void write_manifest(const std::filesystem::path& manifest, std::string_view head,
                    std::string_view note, const std::filesystem::path& root,
                    const std::vector<std::string>& outputs);

/// Why the outputs listed in `manifest` are not what a run with `head` would produce
/// ("no manifest", "the scene, options or program changed", "OUT/x.mp4 is missing", "… has
/// 12 bytes, the manifest says 345", "… does not match its SHA-256"), or std::nullopt when
/// they are. `verify`: hash every output too (else sizes only). Never throws for a bad
/// manifest: that is a reason.
std::optional<std::string> manifest_stale(const std::filesystem::path& manifest,
                                          std::string_view head, const std::filesystem::path& root,
                                          bool verify);

/// What a manifest records, whatever its head.
struct ManifestRecord {
  /// The outputs it lists (paths relative to its root, '/'-separated, in its order): what the
  /// run that wrote it made.
  std::vector<std::string> outputs;
  /// The warnings its note holds (warnings_note()), unescaped: what that run warned of.
  std::vector<std::string> warnings;
};

/// Reads `manifest`, whatever its head. Empty when there is no manifest or it is not one
/// bookspin wrote. Never throws for a bad manifest.
ManifestRecord read_manifest(const std::filesystem::path& manifest);

/// `  "warnings": ["…", …],` and a newline: a run's warnings (each written by json_string) as
/// a member of its manifest's note, so that a later run that finds the outputs up to date can
/// repeat them (read_manifest()).
std::string warnings_note(const std::vector<std::string>& warnings);

/// bookspin's version (common/version.hpp: the file VERSION).
std::string program_version();

/// SHA-256 of the running bookspin: the program's file, or the Python module's where the
/// stages run inside python3 (not the interpreter's), computed once per process; "unknown" if
/// it cannot be read. Every manifest and sweep shard records it.
std::string program_build_id();

}  // namespace bookspin::output
