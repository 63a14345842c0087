// The progress bar of a long call (docs/python.md): tqdm's, where it is installed (Debian's
// python3-tqdm), `tqdm.auto` choosing a notebook's widget or a terminal's bar on stderr.
#include <csignal>

#include "bindings.hpp"

namespace bookspin::python {

ProgressBar::ProgressBar(bool show, int total, std::string description, std::string unit)
    : show_(show), total_(total), description_(std::move(description)), unit_(std::move(unit)) {}

ProgressBar::~ProgressBar() {
  if (!bar_) return;
  py::gil_scoped_acquire gil;
  try {
    bar_.attr("close")();
  } catch (py::error_already_set&) {
    // A bar that cannot close is left as it is.
  }
  bar_.release().dec_ref();
}

void ProgressBar::update(int done) {
  if (!show_) return;
  using Clock = std::chrono::steady_clock;
  const Clock::time_point now = Clock::now();
  if (done < total_ && now - last_ < std::chrono::milliseconds(100)) return;
  last_ = now;
  py::gil_scoped_acquire gil;
  try {
    if (!bar_) {
      bar_ = py::module_::import("tqdm.auto")
                 .attr("tqdm")(py::arg("total") = total_, py::arg("desc") = description_,
                               py::arg("unit") = unit_);
    }
    bar_.attr("update")(done - shown_);
    shown_ = done;
  } catch (py::error_already_set& e) {
    // Ctrl-C while tqdm's Python code ran: the call stops as it would at its own poll.
    if (e.matches(PyExc_KeyboardInterrupt)) throw Interrupted(SIGINT);
    show_ = false;  // no tqdm, or a tqdm that fails: no bar
    if (bar_) bar_.release().dec_ref();
  }
}

}  // namespace bookspin::python
