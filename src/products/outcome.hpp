#pragma once
// What every product's make() shares: what it did (up to date: nothing made; made; or
// interrupted: nothing put in place), and the note it gives before making an output again.
// The products' callers see these names, not the cache stage's.
#include <functional>
#include <optional>
#include <string>

#include "cache/run_cached.hpp"
#include "common/stop.hpp"

namespace bookspin::products {

using Outcome = cache::CacheOutcome;

/// Told why an existing manifest did not match, before the output is made again: the
/// output's name ("fig09", "fig09-plot", "fig09-sweep", "index.html") and the reason.
using RemakeNote = std::function<void(const std::string& name, const std::string& reason)>;

/// The outputs `make()` returns, or none when a signal stopped it (Interrupted, before it put
/// anything in place): the signal is kept in `signal`, for cache::run_cached, which then leaves
/// the old manifest alone (a throw would make it remove the manifest).
template <typename Make>
std::optional<cache::JobOutputs> unless_interrupted(int& signal, const Make& make) {
  try {
    return make();
  } catch (const Interrupted& stop) {
    signal = stop.signal();
    return std::nullopt;
  }
}

/// `note` bound to the output called `name`, as cache::run_cached takes it (empty if `note` is).
inline std::function<void(const std::string& reason)> remake_note_for(const RemakeNote& note,
                                                                      const std::string& name) {
  if (!note) return {};
  return [note, name](const std::string& reason) { note(name, reason); };
}

}  // namespace bookspin::products
