#include "output/clip_sinks.hpp"

#include <cerrno>
#include <cstdio>

#include "output/diagnostics_csv.hpp"
#include "output/output_dir.hpp"
#include "output/png_writer.hpp"

namespace bookspin::output {

namespace {

std::filesystem::path frame_file(const std::filesystem::path& dir, int index) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d.png", index);
  return dir / name;
}

std::filesystem::path make_parent(const std::filesystem::path& file) {
  std::error_code ec;
  make_directories(file.parent_path(), ec);
  if (ec) throw_output_error("cannot create directory", file.parent_path(), ec.value());
  return file;
}

}  // namespace

ClipSinks::ClipSinks(const ClipPaths& paths, const SinkOptions& options)
    : paths_(paths),
      options_(options),
      encoder_(make_parent(paths.mp4), options.encoder),
      csv_(paths.csv),
      encode_queue_(4),
      png_queue_(2 * static_cast<std::size_t>(std::max(1, options.png_workers))) {
  if (options_.write_png) frames_.emplace(paths.frames_dir);
  workers_.emplace_back([this] { encode_loop(); });
  if (options_.write_png) {
    for (int i = 0; i < std::max(1, options_.png_workers); ++i)
      workers_.emplace_back([this] { png_loop(); });
  }
}

ClipSinks::~ClipSinks() { stop_workers(); }

void ClipSinks::stop_workers() {
  encode_queue_.close();
  png_queue_.close();
  for (auto& worker : workers_)
    if (worker.joinable()) worker.join();
  workers_.clear();
}

void ClipSinks::record_error() {
  {
    std::lock_guard lock(error_mutex_);
    if (!error_) error_ = std::current_exception();
  }
  encode_queue_.close();
  png_queue_.close();
}

void ClipSinks::rethrow_if_failed() {
  std::lock_guard lock(error_mutex_);
  if (error_) std::rethrow_exception(error_);
}

void ClipSinks::encode_loop() {
  try {
    while (auto frame = encode_queue_.pop()) encoder_.add_frame(**frame);
  } catch (...) {
    record_error();
  }
}

void ClipSinks::png_loop() {
  try {
    while (auto item = png_queue_.pop()) {
      output::write_png(frame_file(frames_->temp_path(), item->first), *item->second,
                        options_.png_compression);
    }
  } catch (...) {
    record_error();
  }
}

void ClipSinks::add(int index, RgbaImage image, const physics::Diagnostics& diagnostics) {
  rethrow_if_failed();
  csv_.add(index, diagnostics);
  // Shared by the encoder and the PNG queue; whoever lets go last hands the buffer back.
  Frame frame(new RgbaImage(std::move(image)), [this](const RgbaImage* done) { recycle(done); });
  const bool queued = encode_queue_.push(frame) &&
                      (!options_.write_png || png_queue_.push({index, std::move(frame)}));
  if (!queued) rethrow_if_failed();
}

// A few spares cover the frames in flight; beyond that a buffer is simply freed.
constexpr std::size_t kMaxSpares = 4;

void ClipSinks::recycle(const RgbaImage* image) {
  std::unique_ptr<RgbaImage> owned(const_cast<RgbaImage*>(image));  // the frame's sole owner now
  std::lock_guard lock(spare_mutex_);
  if (spares_.size() < kMaxSpares) spares_.push_back(std::move(*owned));
}

std::optional<RgbaImage> ClipSinks::spare_frame() {
  std::lock_guard lock(spare_mutex_);
  if (spares_.empty()) return std::nullopt;
  RgbaImage image = std::move(spares_.back());
  spares_.pop_back();
  return image;
}

void ClipSinks::finish() {
  stop_workers();
  rethrow_if_failed();
  csv_.close();  // a failed CSV write stops here, before the MP4 is put in place
  encoder_.finish();
  if (frames_) frames_->commit();
  csv_.commit();
}

}  // namespace bookspin::output
