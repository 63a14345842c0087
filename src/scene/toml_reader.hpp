#pragma once
// Typed, range-checked reads from a TOML table that remember which keys were read, so that
// every other key can be reported as unknown. Internal to src/scene.
#include <toml++/toml.h>

#include <limits>
#include <set>
#include <string>
#include <string_view>

#include "scene/limits.hpp"
#include "scene/scene.hpp"

namespace bookspin::scene {

/// `value` as it reads in messages: 10 significant digits where they tell it apart from
/// every other double ("1e+12", "0.001"), more (up to 17, which always do) where they do
/// not, so that a value just past a bound never prints as the bound itself.
std::string format_number(double value);

/// `text` with every control character written as an escape, so that a value quoted in a
/// message keeps the message on one line and sends nothing to the terminal: newline, tab and
/// carriage return as `\n`, `\t`, `\r`, any other C0 control and DEL as `\xHH` (ESC:
/// `\x1b`), a C1 control (U+0080 … U+009F, two bytes in UTF-8) as `\u00HH`. Other bytes are
/// kept, so escaped text passes through unchanged. The command line writes every error line
/// through it (CLI11's own messages too).
std::string escape_controls(std::string_view text);

class TomlReader {
 public:
  /// `origin` names the file in messages; keys in `overridden` came from `--set`.
  /// `key_prefix` is put before every key in messages (a `[[compare]]` entry is read by its
  /// own reader as "compare[2]."), and `anchor` gives the line for a key that is missing.
  TomlReader(const toml::table& root, std::string origin, std::set<std::string> overridden,
             std::string key_prefix = "", const toml::node* anchor = nullptr);

  /// A finite number in the range of `limit` (src/scene/limits.hpp; integers are accepted),
  /// `fallback` when the key is missing (the table's default when not given).
  double number(const Limit& limit);
  double number(const Limit& limit, double fallback);
  /// An integer in the range of `limit`, and at most `hi` where another key caps it.
  long long integer(const Limit& limit);
  long long integer(const Limit& limit, long long fallback,
                    long long hi = std::numeric_limits<long long>::max());
  bool boolean(std::string_view key, bool fallback);
  std::string string(std::string_view key, std::string fallback);
  /// An array of exactly three finite numbers, each in the range of `limit`.
  Eigen::Vector3d vector3(const Limit& limit, const Eigen::Vector3d& fallback);
  bool has(std::string_view key) const;
  /// The raw node at `key` (empty view if absent), marking the key as known.
  toml::node_view<const toml::node> node(std::string_view key) { return find(key); }

  /// Throws InputError for the key read-or-present in the table with the earliest line.
  void reject_unknown_keys() const;
  /// Throws InputError "LOCATION: KEY: reason".
  [[noreturn]] void fail(std::string_view key, const std::string& reason) const;

 private:
  toml::node_view<const toml::node> find(std::string_view key);
  /// Fails unless `value` (finite) lies in the range of `limit` ("each component" for a vector).
  void check_range(const Limit& limit, double value, bool component) const;
  /// Fails for a value (a vector's length when `vector`) that is neither 0 nor as large in
  /// magnitude as limit.smallest_nonzero.
  void check_smallest(const Limit& limit, double value, bool vector) const;
  /// The InputError "FILE:LINE: KEY: reason" (or "--set KEY: reason") for `key` at `node`.
  InputError error_at(std::string_view key, const toml::node* node, std::string_view reason) const;
  bool from_override(const std::string& full_key) const;
  void collect_unknown(const toml::table& table, const std::string& prefix,
                       const toml::node*& first, std::string& first_key) const;

  const toml::table& root_;
  std::string origin_;
  std::set<std::string> overridden_;
  std::string key_prefix_;
  const toml::node* anchor_;
  std::set<std::string, std::less<>> known_;
};

}  // namespace bookspin::scene
