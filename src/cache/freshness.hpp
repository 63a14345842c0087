#pragma once
// What a command says about its product's cached outputs and what it hears back: how an
// up-to-date output is treated (`--force`, `--verify`, the remake note) and whether the
// product was made or found up to date. The one header of the cache stage the command line
// may include: it names no path, no JSON and no manifest (make_cached.hpp has those).
#include <functional>
#include <string>

namespace bookspin::cache {

/// What make_cached() did. A run stopped by a signal is neither: it throws Interrupted
/// (common/stop.hpp), and the earlier outputs and their manifest stay as they were.
enum class Outcome {
  up_to_date,  ///< the manifest matched: nothing made
  made,        ///< made, manifest written
};

/// Told why an existing manifest did not match, before the output is made again: the
/// output's name ("fig09", "fig09-plot", "fig09-sweep", "index.html") and the reason.
using RemakeNote = std::function<void(const std::string& name, const std::string& reason)>;

/// How a command wants its product's outputs treated when its manifest says they are up to
/// date (`--force`, `--verify`; docs/outputs.md).
struct Freshness {
  bool force = false;    ///< make them even when up to date
  bool verify = false;   ///< the up-to-date check hashes every output (else sizes only)
  RemakeNote on_remake;  ///< why a manifest did not match (may be empty)
};

}  // namespace bookspin::cache
