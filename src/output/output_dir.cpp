#include "output/output_dir.hpp"

#include <unistd.h>

#include <cerrno>
#include <system_error>

#include "common/errors.hpp"

namespace bookspin::output {

void prepare_output_dir(const std::filesystem::path& dir) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) throw_output_error("cannot create output directory", dir, ec.value());
  if (access(dir.c_str(), W_OK) != 0) throw_output_error("cannot write to", dir, errno);
}

}  // namespace bookspin::output
