#pragma once
// Typed, range-checked reads from a TOML table that remember which keys were read, so that
// every other key can be reported as unknown. Internal to src/scene.
#include <toml++/toml.h>

#include <set>
#include <string>
#include <string_view>

#include "scene/scene.hpp"

namespace bookspin::scene {

class TomlReader {
 public:
  /// `origin` names the file in messages; keys in `overridden` came from `--set`.
  /// `key_prefix` is put before every key in messages (a `[[compare]]` entry is read by its
  /// own reader as "compare[2]."), and `anchor` gives the line for a key that is missing.
  TomlReader(const toml::table& root, std::string origin, std::set<std::string> overridden,
             std::string key_prefix = "", const toml::node* anchor = nullptr);

  /// A finite number in [lo, hi] (lo excluded when `lo_open`); integers are accepted.
  double number(std::string_view key, double fallback, double lo, double hi, bool lo_open = false);
  long long integer(std::string_view key, long long fallback, long long lo, long long hi);
  bool boolean(std::string_view key, bool fallback);
  std::string string(std::string_view key, std::string fallback);
  /// An array of exactly three finite numbers, each in [lo, hi] (lo excluded when lo_open).
  Eigen::Vector3d vector3(std::string_view key, const Eigen::Vector3d& fallback, double lo,
                          double hi, bool lo_open = false);
  bool has(std::string_view key) const;
  /// The raw node at `key` (empty view if absent), marking the key as known.
  toml::node_view<const toml::node> node(std::string_view key) { return find(key); }

  /// Throws InputError for the key read-or-present in the table with the earliest line.
  void reject_unknown_keys() const;
  /// Throws InputError "LOCATION: KEY: reason".
  [[noreturn]] void fail(std::string_view key, const std::string& reason) const;

 private:
  toml::node_view<const toml::node> find(std::string_view key);
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
