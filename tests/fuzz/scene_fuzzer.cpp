// libFuzzer target for the scene parser and `--set` values.
// Input: scene TOML text, optionally followed by a line "%%" and one `key=value` override
// per line. The parser must either return a Scene or throw InputError; anything else (a
// crash, another exception, a sanitizer report) is a finding.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view input(reinterpret_cast<const char*>(data), size);
  const auto split = input.find("\n%%\n");
  const std::string_view text = input.substr(0, split);
  std::vector<std::string> overrides;
  if (split != std::string_view::npos) {
    std::string_view rest = input.substr(split + 4);
    while (!rest.empty()) {
      const auto end = rest.find('\n');
      overrides.emplace_back(rest.substr(0, end));
      if (end == std::string_view::npos) break;
      rest.remove_prefix(end + 1);
    }
  }
  try {
    (void)bookspin::scene::parse_scene_text(text, "fuzz.toml", overrides);
  } catch (const bookspin::InputError&) {
    // Expected for bad input: one clear line.
  }
  return 0;
}
