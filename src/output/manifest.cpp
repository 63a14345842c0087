#include "output/manifest.hpp"

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "common/errors.hpp"
#include "common/json_writer.hpp"
#include "common/sha256.hpp"
#include "common/text_file.hpp"
#include "common/version.hpp"
#include "output/atomic_output.hpp"
#include "output/output_dir.hpp"
#include "output/sha256.hpp"

namespace bookspin::output {

namespace fs = std::filesystem;

namespace {

constexpr std::string_view kOutputsOpen = "  \"outputs\": [\n";
constexpr std::string_view kClose = "  ]\n}\n";
constexpr std::string_view kWarningsOpen = "  \"warnings\": [";

/// The line that ends a manifest's head: its SHA-256, so that a head which is only the start of
/// the recorded one (members added after it by other options) is not read as the same, the
/// rest taken for the note.
std::string head_end_line(std::string_view head) {
  return "  \"head_sha256\": \"" + sha256_text(head) + "\",\n";
}

struct Entry {
  std::string path;
  std::uintmax_t size = 0;
  std::string sha256;
};

bool is_hex64(std::string_view s) {
  if (s.size() != 64) return false;
  for (char c : s)
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  return true;
}

/// `    {"path": "P", "size": N, "sha256": "H"}` with an optional ',' (written by
/// write_manifest through the JSON writer, which leaves output names as they are: they are
/// [A-Za-z0-9._-/]).
std::optional<Entry> parse_entry(std::string_view line) {
  constexpr std::string_view kPath = "    {\"path\": \"",
                             kSize = "\", \"size\": ", kHash = ", \"sha256\": \"", kEnd = "\"}";
  if (!line.empty() && line.back() == ',') line.remove_suffix(1);
  if (line.substr(0, kPath.size()) != kPath) return std::nullopt;
  line.remove_prefix(kPath.size());
  const auto path_end = line.find(kSize);
  if (path_end == std::string_view::npos || path_end == 0) return std::nullopt;
  Entry e;
  e.path = std::string(line.substr(0, path_end));
  if (e.path.find_first_of("\"\\") != std::string::npos) return std::nullopt;
  line.remove_prefix(path_end + kSize.size());
  const auto size_end = line.find(kHash);
  if (size_end == std::string_view::npos || size_end == 0 || size_end > 19) return std::nullopt;
  for (char c : line.substr(0, size_end)) {
    if (c < '0' || c > '9') return std::nullopt;
    e.size = e.size * 10 + static_cast<std::uintmax_t>(c - '0');
  }
  line.remove_prefix(size_end + kHash.size());
  if (line.size() != 64 + kEnd.size() || line.substr(64) != kEnd) return std::nullopt;
  e.sha256 = std::string(line.substr(0, 64));
  if (!is_hex64(e.sha256)) return std::nullopt;
  return e;
}

/// The outputs listed after `head`, or std::nullopt if the text is not a manifest with
/// exactly that head.
std::optional<std::vector<Entry>> entries_after(const std::string& text, std::string_view head,
                                                bool& head_differs) {
  head_differs = false;
  const std::string start =
      "{\n" + std::string(head) + (head.empty() ? std::string() : head_end_line(head));
  if (text.compare(0, start.size(), start) != 0) {
    head_differs = true;
    return std::nullopt;
  }
  // The note (not compared) runs up to the outputs.
  const auto outputs = text.find(kOutputsOpen, start.size());
  if (outputs == std::string::npos || (outputs != start.size() && text[outputs - 1] != '\n'))
    return std::nullopt;
  const std::string expected_start = text.substr(0, outputs) + std::string(kOutputsOpen);
  if (text.size() < expected_start.size() + kClose.size() ||
      text.compare(text.size() - kClose.size(), kClose.size(), kClose) != 0)
    return std::nullopt;
  std::vector<Entry> entries;
  std::istringstream lines(
      text.substr(expected_start.size(), text.size() - expected_start.size() - kClose.size()));
  std::string line;
  while (std::getline(lines, line)) {
    auto e = parse_entry(line);
    if (!e) return std::nullopt;
    entries.push_back(std::move(*e));
  }
  if (entries.empty()) return std::nullopt;
  return entries;
}

/// The JSON strings from `at` up to the line's closing ']', unescaped (json_string writes \",
/// \\ and \u00XX; any other escape keeps the character after the backslash).
std::vector<std::string> strings_in(const std::string& text, std::size_t at) {
  std::vector<std::string> strings;
  std::string current;
  bool inside = false;
  for (std::size_t i = at; i < text.size() && text[i] != '\n'; ++i) {
    const char c = text[i];
    if (!inside) {
      if (c == ']') break;
      inside = c == '"';
    } else if (c == '\\' && i + 1 < text.size()) {
      const char escaped = text[++i];
      const std::string digits = escaped == 'u' ? text.substr(i + 1, 4) : "";
      if (digits.size() == 4 && digits.find_first_not_of("0123456789abcdef") == std::string::npos) {
        current += static_cast<char>(std::strtol(digits.c_str(), nullptr, 16));
        i += 4;
      } else {
        current += escaped;
      }
    } else if (c == '"') {
      strings.push_back(current);
      current.clear();
      inside = false;
    } else {
      current += c;
    }
  }
  return strings;
}

}  // namespace

void write_manifest(const fs::path& manifest, std::string_view head, std::string_view note,
                    const fs::path& root, const std::vector<std::string>& outputs) {
  JsonArray entries;
  for (const std::string& output : outputs) {
    const fs::path file = root / output;
    std::error_code ec;
    const std::uintmax_t size = fs::file_size(file, ec);
    if (ec) throw_output_error("cannot read", file, ec.value());
    const auto hash = sha256_file(file);
    if (!hash) throw_output_error("cannot read", file, errno);
    entries.push_back({JsonObject{
        {"path", {output}}, {"size", {static_cast<std::int64_t>(size)}}, {"sha256", {*hash}}}});
  }
  // The outputs, one a line: what entries_after() reads back.
  const std::string text =
      "{\n" + std::string(head) + head_end_line(head) + std::string(note) +
      json_member_lines({{"outputs", {std::move(entries), true}}}, "manifest outputs", 2, true) +
      "}\n";
  std::error_code ec;
  make_directories(manifest.parent_path(), ec);
  if (ec) throw_output_error("cannot create", manifest.parent_path(), ec.value());
  write_text_file(manifest, text);
}

std::optional<std::string> manifest_stale(const fs::path& manifest, std::string_view head,
                                          const fs::path& root, bool verify) {
  std::error_code ec;
  if (!fs::is_regular_file(manifest, ec)) return "no manifest (" + manifest.string() + ")";
  const std::optional<std::string> text = try_read_text_file(manifest);
  if (!text) return "cannot read " + manifest.string();
  bool head_differs = false;
  const auto entries = entries_after(*text, head, head_differs);
  if (head_differs) return "the scene, its inputs, the options or the program changed";
  if (!entries) return manifest.string() + " is not a manifest bookspin wrote";
  for (const Entry& e : *entries) {
    const fs::path file = root / e.path;
    const std::uintmax_t size = fs::file_size(file, ec);
    if (ec || !fs::is_regular_file(file, ec)) return file.string() + " is missing";
    if (size != e.size)
      return file.string() + " has " + std::to_string(size) + " bytes, the manifest says " +
             std::to_string(e.size);
    if (verify && sha256_file(file) != e.sha256)
      return file.string() + " does not match its SHA-256 in the manifest";
  }
  return std::nullopt;
}

namespace {

/// The outputs and warnings a manifest's `text` lists; none when there is no text or it is not
/// a manifest.
ManifestRecord record_in(const std::optional<std::string>& text) {
  if (!text) return {};
  bool head_differs = false;
  const auto entries = entries_after(*text, "", head_differs);  // any head
  if (!entries) return {};
  ManifestRecord record;
  for (const Entry& e : *entries) record.outputs.push_back(e.path);
  const auto at = text->find(std::string("\n") + std::string(kWarningsOpen));
  if (at != std::string::npos && at < text->find(kOutputsOpen))
    record.warnings = strings_in(*text, at + 1 + kWarningsOpen.size());
  return record;
}

}  // namespace

ManifestRecord read_manifest(const fs::path& manifest) {
  return record_in(try_read_text_file(manifest));
}

std::string warnings_note(const std::vector<std::string>& warnings) {
  JsonArray list;
  for (const std::string& w : warnings) list.push_back({w});
  return json_member_lines({{"warnings", {std::move(list)}}}, "manifest note", 2, false);
}

std::string program_version() { return version(); }

namespace {

/// The file this code was loaded from: the bookspin program, or the Python module that links
/// the stages into another program (python3): the mapping of /proc/self/maps that holds this
/// function's address. /proc/self/exe where none is found.
fs::path own_binary() {
  const auto here = reinterpret_cast<std::uintptr_t>(&own_binary);
  std::ifstream maps("/proc/self/maps");
  std::string line;
  while (std::getline(maps, line)) {
    unsigned long start = 0, end = 0;
    const std::size_t path = line.find('/');
    if (std::sscanf(line.c_str(), "%lx-%lx", &start, &end) == 2 && start <= here && here < end &&
        path != std::string::npos)
      return line.substr(path);
  }
  return "/proc/self/exe";
}

}  // namespace

std::string program_build_id() {
  static const std::string id = sha256_file(own_binary()).value_or("unknown");
  return id;
}

}  // namespace bookspin::output
