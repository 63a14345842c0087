// `bookspin gallery`: OUT/index.html over the clips, frames and plots already under OUT.
#include <iostream>

#include "cache/freshness.hpp"
#include "cli/commands.hpp"
#include "cli/interrupt.hpp"
#include "products/gallery.hpp"

namespace bookspin::cli {

int gallery_command(const GalleryOptions& options) {
  products::GalleryJob job;
  job.out_dir = options.out_dir;
  job.scene_paths = options.scene_paths;
  job.freshness = {options.force, false, remake_note};
  job.stop_signal = stop_poll();
  const products::GalleryOutcome done = products::make_gallery(job);
  const std::string page = products::gallery_layout(job.out_dir).page.string();
  if (done.outcome == cache::Outcome::up_to_date) {
    std::cout << "up to date: " << std::filesystem::path(page).filename().string() << std::endl;
    return kExitOk;
  }
  std::cout << "wrote " << page << " (" << done.entries << " clips)\n";
  return kExitOk;
}

}  // namespace bookspin::cli
