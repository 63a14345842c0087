// bookspin.render: a scene's clip, the files `bookspin render SCENE -o OUT` writes, made by the
// clip product (products::make_clip) with the GIL released, a tqdm bar showing its frames.
#include <algorithm>
#include <string>

#include "bindings.hpp"
#include "common/errors.hpp"
#include "products/clip.hpp"

namespace bookspin::python {

namespace {

const char* kDoc = R"(render(scene, out, overrides=None, png=False, progress=True) -> str

Renders a scene's clip into the folder `out`, as `bookspin render SCENE -o OUT` does (with
png=False as `--no-png`), and returns the MP4's path, OUT/<scene name>.mp4. It writes the same
files, through the same product (docs/outputs.md):
  OUT/<name>.mp4             the H.264 video (and .webm, .gif as render.formats asks: then the
                             first of them is returned where there is no MP4)
  OUT/<name>/frames/         with png=True: frame_00000.png, ... one per frame, 8-bit RGB,
                             render.width x render.height, the frames bookspin.frames yields
  OUT/<name>/diagnostics.csv the diagnostics CSV (a comparison: diagnostics-<tile>.csv each)
  OUT/<name>/manifest.json   the manifest; a clip it says is up to date with this scene and
                             these options is not rendered again, as on the command line
Every output is written under a temporary name and put in place only when the whole clip is
done: an error or Ctrl-C leaves no temporary and no partial file.

Arguments:
  scene      a path (str or os.PathLike) to a TOML scene, or the TOML text itself (as
             bookspin.simulate takes it); a comparison scene ([[compare]]) renders its tiles
  out        the output folder (str or os.PathLike), made if missing
  overrides  a dict {"time.frames": 120, "render.width": 640, ...}, each applied as
             `--set KEY=VALUE` (the value spelled in TOML)
  png        also write the PNG frames (the command line's default; --no-png is png=False)
  progress   show a progress bar of the frames (tqdm.auto: a widget in a notebook, a bar on
             stderr in a terminal) where Debian's python3-tqdm is installed; False: none

Warnings (the MP4 made by libx264 rather than render.codec's encoder, a simulation that
diverged) are issued as UserWarning with the command line's words. Raises bookspin.Error with
the command line's one line for a bad scene or override; OSError `cannot write "PATH":
reason` when an output cannot be written; RuntimeError when the machine lacks what the run
needs (EGL, an encoder); KeyboardInterrupt on Ctrl-C, within a frame. The GIL is released
while it renders.)";

std::string render(const py::object& scene_input, const py::object& out,
                   const py::object& overrides, bool png, bool progress) {
  bool ok = false;
  const std::string out_dir = path_arg(out, ok, "out");
  if (!ok)
    throw InputError("out: expected a folder's path (str or os.PathLike), got " +
                     std::string(py::str(py::type::handle_of(out).attr("__name__"))));
  products::ClipJob job;
  job.scene = scene_arg(scene_input, overrides);
  for (const std::string& warning : job.scene.warnings) warn(warning);
  job.out_dir = out_dir;
  job.write_png = png;
  const products::ClipLayout layout = products::clip_layout(job.out_dir, job.scene);
  const std::vector<std::string>& formats = job.scene.render.formats;
  const auto mp4 = std::find(formats.begin(), formats.end(), "mp4");
  const std::string video =
      layout.videos.at(mp4 == formats.end() ? 0 : mp4 - formats.begin()).string();

  ProgressBar bar(progress, job.scene.frames, job.scene.name, "frame");
  job.on_progress = [&bar](int done) { bar.update(done); };
  job.stop_signal = python_stop();
  products::ClipOutcome done;
  {
    py::gil_scoped_release release;
    done = products::make_clip(job);
  }
  // As the command line words them: a clip found up to date repeats its render's warnings.
  const char* when = done.outcome == cache::Outcome::up_to_date ? " (when it was rendered)" : "";
  for (const std::string& warning : done.warnings) warn(warning + when);
  return video;
}

}  // namespace

void add_render(py::module_& m) {
  m.def("render", &render, py::arg("scene"), py::arg("out"), py::arg("overrides") = py::none(),
        py::arg("png") = false, py::arg("progress") = true, kDoc);
}

}  // namespace bookspin::python
