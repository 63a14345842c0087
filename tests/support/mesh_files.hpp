#pragma once
// Mesh files written by tests: the box [0, a] × [0, b] × [0, c] as OBJ (quads), ASCII and
// binary STL (36 unwelded corners, as exporters write them) and glTF 2.0 (.gltf with an
// embedded buffer, .glb).
#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace bookspin::test {

using Point = std::array<float, 3>;

/// Corner i of the box: x = a where bit 0 of i is set, y = b for bit 1, z = c for bit 2.
inline Point box_corner(int i, const Point& size) {
  return {(i & 1) ? size[0] : 0.0f, (i & 2) ? size[1] : 0.0f, (i & 4) ? size[2] : 0.0f};
}

/// The six faces as quads of corner indices, counter-clockwise seen from outside.
inline std::vector<std::array<int, 4>> box_quads() {
  return {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
}

/// The 12 outward triangles of the box, corner indices.
inline std::vector<std::array<int, 3>> box_triangles() {
  std::vector<std::array<int, 3>> out;
  for (const auto& q : box_quads()) {
    out.push_back({q[0], q[1], q[2]});
    out.push_back({q[0], q[2], q[3]});
  }
  return out;
}

/// OBJ with quad faces (the loader triangulates); `skip_faces` leaves out the last ones.
inline void write_box_obj(const std::filesystem::path& path, const Point& size,
                          int skip_faces = 0) {
  std::ofstream out(path);
  out << "# box\n";
  for (int i = 0; i < 8; ++i) {
    const Point p = box_corner(i, size);
    out << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  }
  const auto quads = box_quads();
  for (std::size_t f = 0; f + skip_faces < quads.size(); ++f) {
    const auto& q = quads[f];
    out << "f " << q[0] + 1 << ' ' << q[1] + 1 << ' ' << q[2] + 1 << ' ' << q[3] + 1 << '\n';
  }
}

inline void write_box_ascii_stl(const std::filesystem::path& path, const Point& size) {
  std::ofstream out(path);
  out << "solid box\n";
  for (const auto& t : box_triangles()) {
    out << "facet normal 0 0 0\nouter loop\n";
    for (int k : t) {
      const Point p = box_corner(k, size);
      out << "vertex " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
    }
    out << "endloop\nendfacet\n";
  }
  out << "endsolid box\n";
}

template <typename T>
void append_bytes(std::string& out, const T& value) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));  // little-endian on the machines we build on
  out.append(bytes, sizeof(T));
}

/// Binary STL bytes: 80-byte header, `claimed` triangle count, then the box's triangles.
inline std::string box_binary_stl(const Point& size, std::uint32_t claimed = 12) {
  std::string out(80, ' ');
  out.replace(0, 10, "binary box");
  append_bytes(out, claimed);
  for (const auto& t : box_triangles()) {
    for (int k = 0; k < 3; ++k) append_bytes(out, 0.0f);  // normal: readers recompute it
    for (int k : t)
      for (float x : box_corner(k, size)) append_bytes(out, x);
    append_bytes(out, std::uint16_t{0});
  }
  return out;
}

inline void write_bytes(const std::filesystem::path& path, const std::string& bytes) {
  std::ofstream(path, std::ios::binary) << bytes;
}

inline std::string base64(const std::string& bytes) {
  static const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    std::uint32_t chunk = static_cast<unsigned char>(bytes[i]) << 16;
    if (i + 1 < bytes.size()) chunk |= static_cast<unsigned char>(bytes[i + 1]) << 8;
    if (i + 2 < bytes.size()) chunk |= static_cast<unsigned char>(bytes[i + 2]);
    out += digits[(chunk >> 18) & 63];
    out += digits[(chunk >> 12) & 63];
    out += i + 1 < bytes.size() ? digits[(chunk >> 6) & 63] : '=';
    out += i + 2 < bytes.size() ? digits[chunk & 63] : '=';
  }
  return out;
}

/// The box's glTF 2.0 buffer: 8 float corners, then 36 uint16 indices.
inline std::string box_gltf_buffer(const Point& size) {
  std::string buffer;
  for (int i = 0; i < 8; ++i)
    for (float x : box_corner(i, size)) append_bytes(buffer, x);
  for (const auto& t : box_triangles())
    for (int k : t) append_bytes(buffer, static_cast<std::uint16_t>(k));
  return buffer;
}

/// The glTF 2.0 document: one node translated by `offset`, its mesh the box; `buffer_uri`
/// empty for a .glb (the buffer is the binary chunk).
inline std::string box_gltf_json(const Point& size, const Point& offset, std::size_t buffer_bytes,
                                 const std::string& buffer_uri) {
  std::ostringstream json;
  json << R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}],)"
       << R"("nodes": [{"mesh": 0, "translation": [)" << offset[0] << ", " << offset[1] << ", "
       << offset[2] << "]}],"
       << R"("meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],)"
       << R"("buffers": [{"byteLength": )" << buffer_bytes;
  if (!buffer_uri.empty()) json << R"(, "uri": ")" << buffer_uri << '"';
  json << "}],"
       << R"("bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 96},)"
       << R"({"buffer": 0, "byteOffset": 96, "byteLength": 72}],)"
       << R"("accessors": [{"bufferView": 0, "componentType": 5126, "count": 8, "type": "VEC3",)"
       << R"("min": [0, 0, 0], "max": [)" << size[0] << ", " << size[1] << ", " << size[2] << "]},"
       << R"({"bufferView": 1, "componentType": 5123, "count": 36, "type": "SCALAR"}]})";
  return json.str();
}

/// glTF 2.0 text, the buffer embedded as a base64 data URI.
inline void write_box_gltf(const std::filesystem::path& path, const Point& size,
                           const Point& offset) {
  const std::string buffer = box_gltf_buffer(size);
  std::ofstream(path) << box_gltf_json(size, offset, buffer.size(),
                                       "data:application/octet-stream;base64," + base64(buffer))
                      << '\n';
}

/// Binary glTF 2.0 (.glb): 12-byte header, a JSON chunk padded with spaces and a BIN chunk
/// padded with zeros, each to a multiple of 4 bytes.
inline void write_box_glb(const std::filesystem::path& path, const Point& size,
                          const Point& offset) {
  std::string buffer = box_gltf_buffer(size);
  std::string json = box_gltf_json(size, offset, buffer.size(), "");
  json.resize((json.size() + 3) / 4 * 4, ' ');
  buffer.resize((buffer.size() + 3) / 4 * 4, '\0');
  std::string glb = "glTF";
  append_bytes(glb, std::uint32_t{2});
  append_bytes(glb, static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + buffer.size()));
  append_bytes(glb, static_cast<std::uint32_t>(json.size()));
  glb += "JSON" + json;
  append_bytes(glb, static_cast<std::uint32_t>(buffer.size()));
  glb += std::string("BIN\0", 4) + buffer;
  write_bytes(path, glb);
}

}  // namespace bookspin::test
