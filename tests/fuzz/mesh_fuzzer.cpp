// libFuzzer target for the mesh validation layer: a mesh file read by the mesh stage, then
// moved into its principal frame (physics::body_from_mesh, docs/physics.md §11–12).
// Input: one byte choosing the format (even: OBJ, odd: binary or ASCII STL), then the file's
// bytes. Reading must either give triangles or throw InputError; body_from_mesh must either
// give a body or an error line. Anything else (a crash, another exception, a sanitizer
// report) is a finding.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "common/errors.hpp"
#include "mesh/mesh.hpp"
#include "physics/body.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const char* extension = (data[0] % 2 == 0) ? ".obj" : ".stl";
  const std::filesystem::path path = std::filesystem::temp_directory_path() /
                                     ("bookspin-mesh-fuzz-" + std::to_string(getpid()) + extension);
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data + 1), static_cast<std::streamsize>(size - 1));
  }
  try {
    const bookspin::mesh::TriangleMesh mesh = bookspin::mesh::load_mesh(path);
    (void)bookspin::physics::body_from_mesh(mesh.vertices, mesh.triangles, 1.0, 1.0);
  } catch (const bookspin::InputError&) {
    // Expected for bad input: one clear line.
  }
  std::filesystem::remove(path);
  return 0;
}
