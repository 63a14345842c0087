#include "cli/run_guarded.hpp"

#include <exception>
#include <iostream>
#include <string>

#include "common/errors.hpp"
#include "common/stop.hpp"
#include "physics/exact_solution.hpp"
#include "render/render_error.hpp"
#include "scene/toml_reader.hpp"
#include "video/video.hpp"

namespace bookspin::cli {

namespace {

int report(const char* kind, const std::string& message, int code) {
  std::cerr << "bookspin: " << kind << ": " << scene::escape_controls(message) << '\n';
  return code;
}

}  // namespace

int run_guarded(const std::function<int()>& command) {
  try {
    return command();
  } catch (const Interrupted& stop) {
    std::cerr << "\nbookspin: interrupted; nothing written\n";
    return 128 + stop.signal();
  } catch (const InputError& e) {
    return report("error", e.what(), kExitUsage);
  } catch (const physics::ExactHorizonError& e) {
    // A time asked of the exact motion past its horizon (docs/physics.md §8, "How far in
    // time"): the input's, said as the physics says it, where no door named the key first.
    return report("error", e.what(), kExitUsage);
  } catch (const OutputError& e) {
    return report("error", e.what(), kExitFailure);
  } catch (const render::RenderError& e) {
    return report("error", e.what(), kExitFailure);
  } catch (const video::EncoderError& e) {
    return report("error", e.what(), kExitFailure);
  } catch (const std::exception& e) {
    return report("internal error", e.what(), kExitInternal);
  } catch (...) {
    return report("internal error", "unknown exception", kExitInternal);
  }
}

}  // namespace bookspin::cli
