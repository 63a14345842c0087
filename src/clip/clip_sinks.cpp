#include "clip/clip_sinks.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <stdexcept>

#include "output/diagnostics_csv.hpp"
#include "output/output_dir.hpp"
#include "output/png_writer.hpp"

namespace bookspin::clip {

namespace {

bool wants(const SinkOptions& options, const char* format) {
  for (const std::string& wanted : options.formats)
    if (wanted == format) return true;
  return false;
}

/// `paths`, once the clip's output folder is checked (output::prepare_output_dir) and the folder
/// of every video `options` asks for is made: before any sink opens a file.
const ClipPaths& with_folders(const ClipPaths& paths, const SinkOptions& options) {
  std::vector<std::filesystem::path> folders;
  for (const auto& [format, file] :
       {std::pair{"mp4", &paths.mp4}, std::pair{"webm", &paths.webm}, std::pair{"gif", &paths.gif}})
    if (wants(options, format)) folders.push_back(file->parent_path());
  output::prepare_output_dir(paths.mp4.parent_path());
  for (const auto& folder : folders) {
    std::error_code ec;
    output::make_directories(folder, ec);
    if (ec) throw_output_error("cannot create directory", folder, ec.value());
  }
  return paths;
}

}  // namespace

std::string frame_file_name(int index) {
  char name[32];
  std::snprintf(name, sizeof name, "frame_%05d.png", index);
  return name;
}

ClipSinks::ClipSinks(const ClipPaths& paths, const SinkOptions& options,
                     const std::vector<std::filesystem::path>& tile_csvs)
    : paths_(with_folders(paths, options)),
      options_(options),
      csv_(paths.csv),
      png_queue_(2 * static_cast<std::size_t>(std::max(1, options.png_workers))) {
  if (options_.formats.empty()) throw std::invalid_argument("ClipSinks: no video format");
  for (const auto& path : tile_csvs)
    tile_csvs_.push_back(std::make_unique<output::DiagnosticsCsvFile>(path));
  const video::EncoderSettings& e = options_.encoder;
  // Each video in its own member, opened before any thread starts; the threads share out
  // the cores the encoders would otherwise each take for themselves.
  if (wants(options_, "mp4")) {
    mp4_.emplace(paths.mp4, e);
    videos_.push_back(std::make_unique<Video>());
    videos_.back()->add_frame = [this](const RgbaImage& f) { mp4_->add_frame(f); };
    videos_.back()->finish = [this](output::OutputSet& set) { mp4_->finish(&set, options_.stop); };
  }
  if (wants(options_, "webm")) {
    webm_.emplace(paths.webm,
                  video::WebmSettings{e.width, e.height, e.fps, options_.webm_crf, e.threads});
    videos_.push_back(std::make_unique<Video>());
    videos_.back()->add_frame = [this](const RgbaImage& f) { webm_->add_frame(f); };
    videos_.back()->finish = [this](output::OutputSet& set) { webm_->finish(&set, options_.stop); };
  }
  if (wants(options_, "gif")) {
    gif_.emplace(paths.gif, video::GifSettings{e.width, e.height, e.fps, options_.gif_width,
                                               options_.gif_fps});
    videos_.push_back(std::make_unique<Video>());
    videos_.back()->add_frame = [this](const RgbaImage& f) { gif_->add_frame(f); };
    videos_.back()->finish = [this](output::OutputSet& set) { gif_->finish(&set, options_.stop); };
  }
  if (videos_.empty()) throw std::invalid_argument("ClipSinks: unknown video format");
  if (options_.write_png) frames_.emplace(paths.frames_dir);
  for (auto& video : videos_) workers_.emplace_back([this, v = video.get()] { encode_loop(*v); });
  if (options_.write_png) {
    for (int i = 0; i < std::max(1, options_.png_workers); ++i)
      workers_.emplace_back([this] { png_loop(); });
  }
}

ClipSinks::~ClipSinks() { stop_workers(); }

const std::string& ClipSinks::encoder_message() const {
  static const std::string none;
  return mp4_ ? mp4_->fallback_message() : none;
}

const std::string& ClipSinks::mp4_encoder() const {
  static const std::string none;
  return mp4_ ? mp4_->codec_name() : none;
}

void ClipSinks::stop_workers() {
  for (auto& video : videos_) video->queue.close();
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
  for (auto& video : videos_) video->queue.close();
  png_queue_.close();
}

void ClipSinks::rethrow_if_failed() {
  std::lock_guard lock(error_mutex_);
  if (error_) std::rethrow_exception(error_);
}

void ClipSinks::encode_loop(Video& video) {
  try {
    while (auto frame = video.queue.pop()) video.add_frame(**frame);
  } catch (...) {
    record_error();
  }
}

void ClipSinks::png_loop() {
  try {
    while (auto item = png_queue_.pop()) {
      output::write_png(frames_->temp_path() / frame_file_name(item->first), *item->second,
                        options_.png_compression);
    }
  } catch (...) {
    record_error();
  }
}

void ClipSinks::add(int index, RgbaImage image, std::span<const physics::Diagnostics> rows) {
  if (rows.size() != 1 + tile_csvs_.size())
    throw std::invalid_argument("ClipSinks::add: one row per diagnostics CSV");
  rethrow_if_failed();
  csv_.add(index, rows[0]);
  for (std::size_t i = 0; i < tile_csvs_.size(); ++i) tile_csvs_[i]->add(index, rows[1 + i]);
  // Shared by the encoder and the PNG queue; whoever lets go last hands the buffer back.
  Frame frame(new RgbaImage(std::move(image)), [this](const RgbaImage* done) { recycle(done); });
  bool queued = true;
  for (auto& video : videos_) queued = queued && video->queue.push(frame);
  queued = queued && (!options_.write_png || png_queue_.push({index, std::move(frame)}));
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

void ClipSinks::finish(output::OutputSet& set) {
  stop_workers();
  rethrow_if_failed();
  // A failed CSV write stops here, before the videos are finalized.
  csv_.close();
  for (auto& csv : tile_csvs_) csv->close();
  for (auto& video : videos_) video->finish(set);
  if (frames_) set.add(*frames_);
  csv_.finish(set);
  for (auto& csv : tile_csvs_) csv->finish(set);
}

}  // namespace bookspin::clip
