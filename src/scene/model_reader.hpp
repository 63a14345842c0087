#pragma once
// Reading model settings and comparison panels; internal to src/scene.
#include <set>
#include <string>
#include <vector>

#include "scene/scene.hpp"
#include "scene/toml_reader.hpp"

namespace bookspin::scene {

/// The model.* keys of `r`'s table, each missing key taking its value from `fallback`.
/// Checks that the model supports the integrator.
physics::ModelConfig read_model(TomlReader& r, const physics::ModelConfig& fallback);

/// The `[[compare]]` array of `r`'s table (empty if absent): each entry needs a unique
/// `label` and may set model.* keys (falling back to `base`). Errors name the entry as
/// compare[i] (1-based) with the file line, or `--set compare…` where it came from --set.
std::vector<CompareTile> read_compare(TomlReader& r, const std::string& origin,
                                      const std::set<std::string>& overridden,
                                      const physics::ModelConfig& base);

/// The file-name form of a label: lower-case letters and digits, other runs become '-'.
std::string label_to_name(const std::string& label);

}  // namespace bookspin::scene
