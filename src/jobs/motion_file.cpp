// read_motion_csv(): the motion file read whole, then parsed by motion_csv.cpp (the parser is
// pure, no I/O, and goes into the explorer page's WebAssembly; this file does not).
#include "common/text_file.hpp"
#include "jobs/motion_csv.hpp"

namespace bookspin::jobs {

MotionFile read_motion_csv(const std::filesystem::path& path, double dt, long long steps) {
  return parse_motion_csv(read_text_file(path, "the motion file"), path.string(), dt, steps);
}

}  // namespace bookspin::jobs
