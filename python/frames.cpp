// bookspin.frames: a scene's clip frame by frame, as numpy images, the very frames `bookspin
// render` encodes: the clip stage's FrameLoop (clip/clip.hpp), the one loop render_clip() feeds
// its sinks from, run on a thread of its own (its GL context stays on that thread) one frame
// ahead of the caller, through a queue of one frame: constant memory, whatever the length.
#include <atomic>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <exception>
#include <memory>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "clip/bounded_queue.hpp"
#include "clip/clip.hpp"
#include "common/errors.hpp"

namespace bookspin::python {

namespace {

const char* kDoc = R"(frames(scene, overrides=None) -> bookspin.Frames

The frames of a scene's clip, one at a time: an iterator of (t, image), where
  t      float, the frame's time in the scene's time units (the diagnostics CSV's t column:
         frame k is at k * time.steps_per_frame * time.dt, also after a divergence)
  image  numpy uint8 array of shape (H, W, 3), RGB, top row first, H = render.height,
         W = render.width
for every frame of the clip (time.frames of them, frame 0 the start), exactly the frames
`bookspin render` encodes and writes as PNGs (OUT/<name>/frames/frame_00000.png, ...): the
same loop makes them, decorated as the scene asks (caption, render.panel, render.sphere,
render.poinsot; a comparison scene's tiles side by side). Nothing is written.

The frames are made on a thread of the module's own, one frame ahead of the caller, and each
is handed over as it is asked for: memory stays that of a few frames however long the clip.
Leaving the loop early (break, del, close()) stops that thread; Ctrl-C while a frame is
awaited raises KeyboardInterrupt within a fraction of a second. The GIL is released while
a frame is awaited.

Arguments:
  scene      a path (str or os.PathLike) to a TOML scene, or the TOML text itself (as
             bookspin.simulate takes it)
  overrides  a dict {"time.frames": 30, "render.width": 320, ...}, each applied as
             `--set KEY=VALUE` (the value spelled in TOML)

Raises bookspin.Error with the command line's one line for a bad scene or override, at the
call; RuntimeError from the iteration when the machine has no usable EGL/OpenGL.

  for t, image in bookspin.frames("scenes/fig09-matrix-unstable-x.toml",
                                  {"time.frames": 30, "render.width": 320,
                                   "render.height": 180}):
      image.shape   # (180, 320, 3))";

const char* kFramesDoc =
    R"(The iterator bookspin.frames returns: next() gives (t, image), t in time units,
image a uint8 array (H, W, 3); close() stops it early (as leaving it does).)";

/// One frame handed from the loop's thread to Python.
struct FrameItem {
  double t = 0.0;
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  ///< height × width × 3
};

/// `image`'s pixels without alpha (the frames are opaque, as their PNGs are RGB).
void rgb_of(const RgbaImage& image, std::vector<std::uint8_t>& rgb) {
  const std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
  rgb.resize(pixels * 3);
  const std::uint8_t* from = image.pixels.data();
  std::uint8_t* to = rgb.data();
  for (std::size_t i = 0; i < pixels; ++i, from += 4, to += 3) std::memcpy(to, from, 3);
}

/// bookspin.Frames: the loop's thread, started at the first next(), and the queue of one frame
/// between it and Python.
class Frames {
 public:
  explicit Frames(scene::Scene scene) : scene_(std::move(scene)) {}
  /// Stops the loop's thread (it needs no GIL: this waits at most for the frame it is making).
  ~Frames() { stop(); }
  Frames(const Frames&) = delete;
  Frames& operator=(const Frames&) = delete;

  py::tuple next() {
    if (busy_) throw py::value_error("bookspin.Frames: already executing");
    if (finished_) throw py::stop_iteration();
    busy_ = true;
    struct Idle {
      bool& busy;
      ~Idle() { busy = false; }
    } idle{busy_};
    if (!loop_.joinable()) loop_ = std::thread([this] { produce(); });
    std::optional<FrameItem> item;
    {
      const StopPoll poll = python_stop();
      py::gil_scoped_release release;
      while (!(item = queue_.pop_for(std::chrono::milliseconds(20)))) {
        if (queue_.closed()) break;  // the last frame was taken, or the loop failed
        if (const int signal = stop_signal(poll, "frames")) {
          finish();
          throw Interrupted(signal);
        }
      }
      if (!item) finish();
    }
    if (!item) {
      if (error_) std::rethrow_exception(std::exchange(error_, nullptr));
      throw py::stop_iteration();
    }
    py::array_t<std::uint8_t> image(std::vector<py::ssize_t>{item->height, item->width, 3});
    std::memcpy(image.mutable_data(), item->rgb.data(), item->rgb.size());
    return py::make_tuple(item->t, std::move(image));
  }

  /// Stops the loop early; later next() calls raise StopIteration.
  void close() {
    py::gil_scoped_release release;
    finish();
  }

 private:
  /// The loop's thread: every frame into the queue, until the last, an error, or stop().
  void produce() {
    try {
      clip::FrameLoop loop(scene_);
      const StopPoll stopping = [this](std::string_view) { return stopping_.load() ? SIGINT : 0; };
      std::optional<RgbaImage> spare;  // the frame before, to read the next one back into
      const clip::SpareFrames spares = [&spare] { return std::exchange(spare, std::nullopt); };
      while (auto frame = loop.next(stopping, spares)) {
        FrameItem item{frame->t, frame->image.width, frame->image.height, {}};
        rgb_of(frame->image, item.rgb);
        spare = std::move(frame->image);
        if (!queue_.push(std::move(item))) break;  // closed: the caller stopped
      }
    } catch (const Interrupted&) {
      // stop(): the caller left
    } catch (...) {
      error_ = std::current_exception();  // seen by next() once the queue is closed
    }
    queue_.close();
  }

  /// Stops the loop's thread and waits for it.
  void stop() {
    stopping_ = true;
    queue_.close();
    if (loop_.joinable()) loop_.join();
  }

  void finish() {
    stop();
    finished_ = true;
  }

  scene::Scene scene_;
  clip::BoundedQueue<FrameItem> queue_{1};
  std::atomic<bool> stopping_{false};
  std::exception_ptr error_;  ///< the loop's error, written before the queue is closed
  std::thread loop_;
  bool finished_ = false;  ///< no more frames: the last was taken, or stopped
  bool busy_ = false;      ///< inside next() (the GIL is released there)
};

std::unique_ptr<Frames> frames(const py::object& scene_input, const py::object& overrides) {
  scene::Scene scene = scene_arg(scene_input, overrides);
  for (const std::string& warning : scene.warnings) warn(warning);
  return std::make_unique<Frames>(std::move(scene));
}

}  // namespace

void add_frames(py::module_& m) {
  py::class_<Frames>(m, "Frames", kFramesDoc)
      .def("__iter__", [](py::object self) { return self; })
      .def("__next__", &Frames::next)
      .def("close", &Frames::close,
           "Stops the frames early; later next() calls raise StopIteration.");
  m.def("frames", &frames, py::arg("scene"), py::arg("overrides") = py::none(), kDoc);
}

}  // namespace bookspin::python
