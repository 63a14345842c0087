#include "scene/toml_reader.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <utility>

namespace bookspin::scene {

namespace {

std::string range_text(double lo, double hi, bool lo_open) {
  return std::string(lo_open ? "> " : ">= ") + format_number(lo) + " and <= " + format_number(hi);
}

/// What a value is, for "expected X, got Y": a float where an integer belongs (300.0 for
/// 300) is easy to miss without it.
std::string type_name(const toml::node& node) {
  using toml::node_type;
  static constexpr std::pair<node_type, const char*> kNames[] = {
      {node_type::string, "a string"},
      {node_type::integer, "an integer"},
      {node_type::floating_point, "a floating-point number"},
      {node_type::boolean, "a boolean"},
      {node_type::array, "an array"},
      {node_type::table, "a table"}};
  for (const auto& [type, name] : kNames)
    if (node.type() == type) return name;
  return "a date or time";
}

/// Whether some key in `keys` lies below `key` ("time" for "time.dt").
template <typename Keys>
bool has_key_below(const Keys& keys, const std::string& key) {
  const std::string prefix = key + ".";
  const auto next = keys.lower_bound(prefix);
  return next != keys.end() && std::string_view(*next).substr(0, prefix.size()) == prefix;
}

}  // namespace

std::string format_number(double value) {
  std::string text;
  for (int digits = 10; digits <= 17; ++digits) {
    std::ostringstream out;
    out.precision(digits);
    out << value;
    text = out.str();
    if (!std::isfinite(value) || std::strtod(text.c_str(), nullptr) == value) break;
  }
  return text;
}

std::string escape_controls(std::string_view text) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto u = static_cast<unsigned char>(text[i]);
    char buffer[8];
    if (u == '\n' || u == '\t' || u == '\r') {
      out += '\\';
      out += u == '\n' ? 'n' : u == '\t' ? 't' : 'r';
    } else if (u < 0x20 || u == 0x7f) {
      std::snprintf(buffer, sizeof buffer, "\\x%02x", u);
      out += buffer;
    } else if (u == 0xc2 && i + 1 < text.size() &&
               static_cast<unsigned char>(text[i + 1]) >= 0x80 &&
               static_cast<unsigned char>(text[i + 1]) <= 0x9f) {
      std::snprintf(buffer, sizeof buffer, "\\u%04x", static_cast<unsigned char>(text[++i]));
      out += buffer;
    } else {
      out += text[i];
    }
  }
  return out;
}

TomlReader::TomlReader(const toml::table& root, std::string origin,
                       std::set<std::string> overridden, std::string key_prefix,
                       const toml::node* anchor)
    : root_(root),
      origin_(std::move(origin)),
      overridden_(std::move(overridden)),
      key_prefix_(std::move(key_prefix)),
      anchor_(anchor) {}

toml::node_view<const toml::node> TomlReader::find(std::string_view key) {
  known_.emplace(key);
  return root_.at_path(key);
}

bool TomlReader::has(std::string_view key) const { return static_cast<bool>(root_.at_path(key)); }

/// A key at, above or below an override came from --set: `--set time.dt.x=1` made time.dt a
/// table, and `--set compare=[…]` replaced every compare[i].… key.
bool TomlReader::from_override(const std::string& full_key) const {
  if (overridden_.count(full_key) || has_key_below(overridden_, full_key)) return true;
  for (const auto& key : overridden_) {
    const bool above = full_key.size() > key.size() && full_key.compare(0, key.size(), key) == 0 &&
                       (full_key[key.size()] == '.' || full_key[key.size()] == '[');
    if (above) return true;
  }
  return false;
}

InputError TomlReader::error_at(std::string_view key, const toml::node* node,
                                std::string_view reason) const {
  // Built with append: GCC 12 warns falsely (-Wrestrict) on "literal" + std::string here.
  std::string full_key = key_prefix_;
  full_key.append(key);
  if (from_override(full_key)) {
    std::string where = "--set ";
    where.append(full_key).append(": ").append(reason);
    return InputError(escape_controls(where));
  }
  if (!node) node = anchor_;
  const int line = node ? static_cast<int>(node->source().begin.line) : 0;
  return InputError(escape_controls(origin_), line, escape_controls(full_key),
                    escape_controls(reason));
}

void TomlReader::fail(std::string_view key, const std::string& reason) const {
  throw error_at(key, root_.at_path(key).node(), reason);
}

void TomlReader::check_range(const Limit& limit, double value, bool component) const {
  if (!std::isfinite(value)) fail(limit.key, "must be finite, got " + format_number(value));
  if (value < limit.min || value > limit.max || (limit.min_open && value == limit.min)) {
    fail(limit.key, std::string(component ? "each component must be " : "must be ") +
                        range_text(limit.min, limit.max, limit.min_open) + ", got " +
                        format_number(value));
  }
}

void TomlReader::check_smallest(const Limit& limit, double value, bool vector) const {
  const double magnitude = std::abs(value);
  if (magnitude != 0.0 && magnitude < limit.smallest_nonzero) {
    fail(limit.key,
         std::string(vector ? "must be [0, 0, 0] or at least " : "must be 0 or at least ") +
             format_number(limit.smallest_nonzero) +
             (vector ? " long, got length " : " in magnitude, got ") + format_number(value));
  }
}

double TomlReader::number(const Limit& limit) { return number(limit, limit.fallback.value()); }

double TomlReader::number(const Limit& limit, double fallback) {
  const auto view = find(limit.key);
  if (!view) return fallback;
  double value = 0.0;
  if (auto i = view.value_exact<int64_t>()) {
    value = static_cast<double>(*i);
  } else if (auto f = view.value_exact<double>()) {
    value = *f;
  } else {
    fail(limit.key, "expected a number, got " + type_name(*view.node()));
  }
  check_range(limit, value, false);
  check_smallest(limit, value, false);
  return value;
}

long long TomlReader::integer(const Limit& limit) {
  const double fallback = limit.fallback.value();
  return integer(limit, static_cast<long long>(fallback));
}

long long TomlReader::integer(const Limit& limit, long long fallback, long long hi) {
  const auto view = find(limit.key);
  if (!view) return fallback;
  const auto value = view.value_exact<int64_t>();
  if (!value) fail(limit.key, "expected an integer, got " + type_name(*view.node()));
  const auto lo = static_cast<long long>(limit.min);
  // 2⁶³ − 1 rounds up to 2⁶³ as a double, which no long long holds.
  if (limit.max < kInt64Max) hi = std::min(hi, static_cast<long long>(limit.max));
  if (*value < lo || *value > hi) {
    fail(limit.key, "must be >= " + std::to_string(lo) + " and <= " + std::to_string(hi) +
                        ", got " + std::to_string(*value));
  }
  return *value;
}

bool TomlReader::boolean(std::string_view key, bool fallback) {
  const auto view = find(key);
  if (!view) return fallback;
  const auto value = view.value_exact<bool>();
  if (!value) fail(key, "expected true or false, got " + type_name(*view.node()));
  return *value;
}

std::string TomlReader::string(std::string_view key, std::string fallback) {
  const auto view = find(key);
  if (!view) return fallback;
  const auto value = view.value_exact<std::string>();
  if (!value) fail(key, "expected a string, got " + type_name(*view.node()));
  return *value;
}

Eigen::Vector3d TomlReader::vector3(const Limit& limit, const Eigen::Vector3d& fallback) {
  const std::string_view key = limit.key;
  const auto view = find(key);
  if (!view) return fallback;
  const toml::array* array = view.as_array();
  if (!array) fail(key, "expected an array of 3 numbers, got " + type_name(*view.node()));
  if (array->size() != 3) {
    fail(key, "expected an array of 3 numbers, got " + std::to_string(array->size()) + " elements");
  }
  Eigen::Vector3d out;
  for (int d = 0; d < 3; ++d) {
    const toml::node& item = *array->get(d);
    if (auto i = item.value_exact<int64_t>()) {
      out[d] = static_cast<double>(*i);
    } else if (auto f = item.value_exact<double>()) {
      out[d] = *f;
    } else {
      fail(key, "expected an array of 3 numbers, but element " + std::to_string(d + 1) + " is " +
                    type_name(item));
    }
    check_range(limit, out[d], true);
  }
  check_smallest(limit, std::hypot(out[0], out[1], out[2]), true);
  return out;
}

void TomlReader::collect_unknown(const toml::table& table, const std::string& prefix,
                                 const toml::node*& first, std::string& first_key) const {
  for (const auto& [name, node] : table) {
    const std::string key = prefix + std::string(name.str());
    if (known_.count(key) > 0) continue;
    // A known table ([render]) is searched, and may be empty; an unknown table ([camera]) is
    // reported whole, at its header, rather than by its first key.
    const toml::table* sub = node.as_table();
    if (sub && has_key_below(known_, key)) {
      collect_unknown(*sub, key + ".", first, first_key);
      continue;
    }
    if (!first || node.source().begin.line < first->source().begin.line) {
      first = &node;
      first_key = key;
    }
  }
}

void TomlReader::reject_unknown_keys() const {
  const toml::node* first = nullptr;
  std::string first_key;
  collect_unknown(root_, "", first, first_key);
  if (!first) return;
  // A known table given a value (`time = 5`) is a wrong type, not an unknown key.
  const char* reason = first->is_table()                  ? "unknown table"
                       : has_key_below(known_, first_key) ? "expected a table"
                                                          : "unknown key";
  throw error_at(first_key, first, reason);
}

}  // namespace bookspin::scene
