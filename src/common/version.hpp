#pragma once
// bookspin's one version (the file VERSION at the top of the source tree, docs/flipcheck.md
// "Versions"), compiled into this one file's object: the program, the Python module, the npm
// package's and the page's WebAssembly all report it from here.
#include <string>

namespace bookspin {

/// The version, "MAJOR.MINOR.PATCH", as VERSION states it.
std::string version();

}  // namespace bookspin
