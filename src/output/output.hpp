#pragma once
// The door of src/output: files and formats. Every file and directory bookspin writes goes
// through here, and the formats that are not video (src/video has those) are written here.
//
//   atomic_output.hpp    AtomicFile, AtomicDirectory, AtomicTextFile: an output built under a
//                        hidden temporary name next to its final path, put in place by
//                        commit(); OutputSet: a run's outputs put in place together or not at
//                        all (docs/outputs.md); write_text_file()
//   staged_files.hpp     StagedFiles: a product's several text and PNG files, each written
//                        whole under its temporary name, then put in place together
//   output_dir.hpp       the one check that an output directory is usable, made before any
//                        work, and make_directories(), which remembers the folders it made
//   png_writer.hpp       PNG frames written with libdeflate in a container of our own (8-bit
//                        RGB or RGBA), read with libpng
//   gltf_writer.hpp      animated glTF 2.0 binaries (.glb) of one rigid body, with tinygltf
//   diagnostics_csv.hpp  the diagnostics CSV of a run, one row per frame with the pose
//                        (docs/physics.md §9)
//   manifest.hpp         manifest files (what produced a set of outputs, and their sizes and
//                        hashes), the program's version and build id
//   sha256.hpp           SHA-256 of files and text (libcrypto)
//   data_url.hpp         bytes as a data: URL (base64, libcrypto)
//
// The CSV and JSON writers and the number formatter every CSV or JSON file goes through are
// common's (common/csv_writer.hpp, common/json_writer.hpp, common/number_text.hpp), since the
// scene's canonical form is JSON too.
//
// Units: image sizes in pixels, images RGBA top row first (common/rgba_image.hpp); numbers in
// a CSV or JSON file in the units of their column or key (docs/outputs.md).
//
// Errors: a file or directory that cannot be written, read back for a manifest or put in
// place → OutputError naming the path and the OS error; a NaN or infinity handed to a writer →
// InternalError naming its column or key (a bug: exit 70); bad arguments (an empty image, a
// glTF animation out of order) → std::invalid_argument (a data: URL over 1 GiB:
// std::length_error); a PNG that cannot be read → std::runtime_error naming the file; a bad
// or missing manifest is no error, only "make it again". An output that failed or was
// interrupted leaves no half-written file under its final name.
#include "output/atomic_output.hpp"
#include "output/data_url.hpp"
#include "output/diagnostics_csv.hpp"
#include "output/gltf_writer.hpp"
#include "output/manifest.hpp"
#include "output/output_dir.hpp"
#include "output/png_writer.hpp"
#include "output/sha256.hpp"
#include "output/staged_files.hpp"
