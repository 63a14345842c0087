#pragma once
// What every product's manifest head and note hold (output/manifest.hpp has the file format;
// each product in src/products/ adds its own options and names its manifest's path).
//
// Head, in this order: manifest format, command, bookspin version and build id (SHA-256 of
// the running executable, so any rebuild with changed code or libraries invalidates), the
// output options, the resolved scene (scene::canonical_json) and the SHA-256 of every file
// the scene reads as bytes (textures, the mesh). Everything an output depends on and nothing
// else: not --jobs, not the path the scene was given by, not the scene file's comments. The
// scene file's path and SHA-256 go in the manifest's note (recorded, not compared).
#include <filesystem>
#include <string>
#include <vector>

#include "common/json_writer.hpp"
#include "scene/scene.hpp"

namespace bookspin::cache {

// A head and a note are JSON members written by the one JSON writer (common/json_writer.hpp,
// json_member_lines: indented by two spaces, each line ending in ','), the text that
// output::write_manifest puts between the manifest's "{" and its "outputs".

/// The note of every manifest: the scene file's absolute path and SHA-256. Throws InputError.
std::string manifest_note(const scene::Scene& scene);

/// Files an output is read from, as a head member: one object per file, its file name and
/// "sha256:<hex>" of its bytes, over lines. Throws InputError naming a file that cannot be read.
JsonValue input_files_json(const std::vector<std::filesystem::path>& files);

/// The head of a manifest that names no scene (the explorer page, the gallery): the manifest
/// format, `command`, then `members`.
std::string manifest_head(const std::string& command, const JsonObject& members);

/// The head of a command's manifest for one scene: `options` are its output options (an object
/// written over lines, "{\n  }" when empty). Throws InputError when an input file cannot be
/// read.
std::string manifest_head(const std::string& command, const JsonObject& options,
                          const scene::Scene& scene);

}  // namespace bookspin::cache
