#include "output/staged_files.hpp"

#include <cerrno>
#include <cstdio>
#include <memory>

#include "common/errors.hpp"
#include "output/png_writer.hpp"

namespace bookspin::output {

namespace {

struct FileCloser {
  void operator()(std::FILE* f) const { std::fclose(f); }
};

/// `bytes` written to `file`'s temporary, closed and checked (fclose is where a full disk often
/// shows first).
template <typename Write>
void write_temporary(const AtomicFile& file, const Write& write) {
  std::unique_ptr<std::FILE, FileCloser> out(std::fopen(file.temp_path().c_str(), "wb"));
  if (!out) throw_output_error("cannot create", file.final_path(), errno);
  write(out.get());
  if (std::fclose(out.release()) != 0) throw_output_error("cannot write", file.final_path(), errno);
}

}  // namespace

void StagedFiles::text(const std::filesystem::path& path, std::string_view text) {
  auto file = std::make_unique<AtomicFile>(path);
  write_temporary(*file, [&](std::FILE* out) {
    if (std::fwrite(text.data(), 1, text.size(), out) != text.size() || std::fflush(out) != 0)
      throw_output_error("cannot write", path, errno);
  });
  set_.add(*file);
  files_.push_back(std::move(file));
}

void StagedFiles::png(const std::filesystem::path& path, const RgbaImage& image) {
  auto file = std::make_unique<AtomicFile>(path);
  write_temporary(*file, [&](std::FILE* out) { write_png(out, path, image); });
  set_.add(*file);
  files_.push_back(std::move(file));
}

void StagedFiles::adopt(const std::filesystem::path& path, const std::filesystem::path& made) {
  auto file = std::make_unique<AtomicFile>(path);
  std::error_code ec;
  std::filesystem::rename(made, file->temp_path(), ec);
  if (ec) throw_output_error("cannot write", path, ec.message());
  set_.add(*file);
  files_.push_back(std::move(file));
}

void StagedFiles::commit() { set_.commit(); }

}  // namespace bookspin::output
