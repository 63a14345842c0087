#include "common/version.hpp"

#ifndef BOOKSPIN_VERSION
#error \
    "BOOKSPIN_VERSION is set from VERSION by src/common/CMakeLists.txt, npm/build.sh, web/build-wasm.sh"
#endif

namespace bookspin {

std::string version() { return BOOKSPIN_VERSION; }

}  // namespace bookspin
