#pragma once
// Where a test finds the source tree, the build tree and the built programs: absolute paths,
// fixed when the build is configured (tests/CMakeLists.txt generates their one definition,
// BUILD/tests/test_paths.cpp). Every suite's sources see this header first (-include), and the
// macros below name its functions, so that no other object holds a path: a clone elsewhere
// compiles every other file to the same object, which the compiler cache then reuses
// (docs/performance.md, "CI").
namespace bookspin::test_paths {
const char* source_dir();     ///< the repository's root
const char* binary_dir();     ///< the build tree's root
const char* bookspin_exe();   ///< the bookspin program
const char* bench_exe();      ///< the bookspin-bench program
const char* one_frame_exe();  ///< examples/one_frame
}  // namespace bookspin::test_paths

#define BOOKSPIN_SOURCE_DIR (::bookspin::test_paths::source_dir())
#define BOOKSPIN_BINARY_DIR (::bookspin::test_paths::binary_dir())
#define BOOKSPIN_EXE (::bookspin::test_paths::bookspin_exe())
#define BOOKSPIN_BENCH_EXE (::bookspin::test_paths::bench_exe())
#define BOOKSPIN_ONE_FRAME_EXE (::bookspin::test_paths::one_frame_exe())
