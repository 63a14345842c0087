#include "products/explorer.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <set>
#include <vector>

#include "cache/make_cached.hpp"
#include "cache/manifest_head.hpp"
#include "common/errors.hpp"
#include "common/json_writer.hpp"
#include "common/sha256.hpp"
#include "common/text_file.hpp"
#include "output/atomic_output.hpp"
#include "output/data_url.hpp"
#include "output/output_dir.hpp"
#include "output/png_writer.hpp"
#include "output/sha256.hpp"
#include "physics/presets.hpp"
#include "render/face_images.hpp"

namespace bookspin::products {

namespace {

/// `image` at half its width and height (odd sides rounded up), each pixel the mean of the
/// 2×2 it covers: the page's book art. At 1024×1584 its cover's PNG was 1.5 MB and the page's
/// HTML 6.2 MB, whose parse held back the first frame; the view draws the book a few hundred
/// pixels tall, so half the pixels lose nothing seen (mipmaps shrink it further).
RgbaImage half_size(const RgbaImage& image) {
  RgbaImage half((image.width + 1) / 2, (image.height + 1) / 2);
  for (int y = 0; y < half.height; ++y)
    for (int x = 0; x < half.width; ++x)
      for (int c = 0; c < 4; ++c) {
        int sum = 0, count = 0;
        for (int dy = 0; dy < 2; ++dy)
          for (int dx = 0; dx < 2; ++dx)
            if (2 * y + dy < image.height && 2 * x + dx < image.width) {
              sum += image.row(2 * y + dy)[4 * (2 * x + dx) + c];
              ++count;
            }
        half.row(y)[4 * x + c] = static_cast<std::uint8_t>((sum + count / 2) / count);
      }
  return half;
}

/// `text` safe inside a <script> element: "</" cannot close it early.
std::string script_safe(std::string text) {
  for (auto at = text.find("</"); at != std::string::npos; at = text.find("</", at + 3))
    text.replace(at, 2, "<\\/");
  return text;
}

/// The page's shell (web/build.sh) and the engines' bundle that fills its engines marker.
struct Shell {
  std::string page;                            ///< the shell's bytes
  std::size_t data_at = std::string::npos;     ///< where kExplorerDataMarker stands
  std::size_t engines_at = std::string::npos;  ///< where kExplorerEnginesMarker stands, if it does
  std::string engines;                         ///< the engines' bundle; empty: none asked for
};

/// request.shell and request.engines read and checked. Throws InputError naming the file (see
/// write_explorer_page).
Shell read_shell(const ExplorerPageRequest& request) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(request.shell, ec))
    throw InputError(request.shell.string() +
                     ": the explorer page's shell is missing (web/build.sh)");
  Shell shell;
  shell.page = read_text_file(request.shell, "the explorer page's shell");
  shell.data_at = shell.page.find(kExplorerDataMarker);
  if (shell.data_at == std::string::npos)
    throw InputError(request.shell.string() + ": not an explorer shell (no " +
                     std::string(kExplorerDataMarker) + " marker; web/build.sh makes one)");
  shell.engines_at = shell.page.find(kExplorerEnginesMarker);
  if (request.engines.empty()) return shell;
  if (!std::filesystem::is_regular_file(request.engines, ec))
    throw InputError(request.engines.string() +
                     ": the explorer's JavaScript engines are missing (web/build.sh writes "
                     "them beside the shell)");
  if (shell.engines_at == std::string::npos)
    throw InputError(request.shell.string() + ": this shell has no place for the engines (no " +
                     std::string(kExplorerEnginesMarker) + " marker; web/build.sh makes one)");
  shell.engines = read_text_file(request.engines, "the explorer's engines");
  return shell;
}

}  // namespace

std::filesystem::path explorer_page_path(const std::filesystem::path& out_dir) {
  return out_dir / "explorer.html";
}

std::filesystem::path explorer_engines_beside(const std::filesystem::path& shell) {
  return shell.parent_path() / kExplorerEnginesName;
}

std::filesystem::path default_explorer_shell() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return (ec ? std::filesystem::path(".") : exe.parent_path()) / "web" / kExplorerShellName;
}

ExplorerPageResult write_explorer_page(const ExplorerPageRequest& request) {
  std::set<std::string> names;
  for (const scene::Scene& s : request.scenes) {
    if (!names.insert(s.name).second)
      throw InputError(s.source.string() + ": scene.name: '" + s.name +
                       "' is the name of another scene given to the explorer");
  }
  Shell shell = read_shell(request);  // checked before any work

  // The page's data, as a plain value: every scene, then the book's faces.
  if (!request.scene_data) throw InternalError("explorer page: no maker of the scenes' page data");
  JsonArray scenes;
  for (const scene::Scene& scene : request.scenes) scenes.push_back({request.scene_data(scene)});
  JsonObject book_art;
  const char* faces[] = {"front", "back", "spine", "pages"};  // FaceImage order
  for (int f = 0; f < 4; ++f) {
    stop_if_asked(request.stop_signal, "explore scenes");
    const RgbaImage image =
        half_size(render::generate_face_image(static_cast<render::FaceImage>(f)));
    book_art.push_back({faces[f], {output::data_url("image/png", output::encode_png(image, 6))}});
  }

  // The data goes into the shell as JSON, handed to the writer once per script variable.
  const std::string data = "<script>window.BOOKSPIN_SCENES=" +
                           script_safe(json_text({std::move(scenes)}, "explorer page scene",
                                                 JsonLayout::element_per_line)) +
                           ";\nwindow.BOOKSPIN_BOOK_ART=" +
                           script_safe(json_text({std::move(book_art)}, "explorer page book art")) +
                           ";</script>";
  // Both markers were found in the shell itself (never in the data): the later is replaced
  // first, so that the earlier one's place stands.
  std::string page = std::move(shell.page);
  const std::string engines_marker = kExplorerEnginesMarker;
  const auto fill_engines = [&] {
    if (shell.engines_at == std::string::npos) return;
    page.replace(shell.engines_at, engines_marker.size(),
                 shell.engines.empty() ? std::string()
                                       : "<script>" + script_safe(shell.engines) + "</script>");
  };
  if (shell.engines_at != std::string::npos && shell.engines_at > shell.data_at) fill_engines();
  page.replace(shell.data_at, std::string(kExplorerDataMarker).size(), data);
  if (shell.engines_at != std::string::npos && shell.engines_at < shell.data_at) fill_engines();

  ExplorerPageResult result;
  result.path = explorer_page_path(request.out_dir);
  stop_if_asked(request.stop_signal, "explore write");
  output::prepare_output_dir(request.out_dir);
  output::write_text_file(result.path, page);
  result.bytes = page.size();
  return result;
}

std::filesystem::path explorer_manifest_path(const std::filesystem::path& out_dir) {
  return out_dir / "explorer-manifest.json";
}

namespace {

/// The head of the page's manifest after its command: the SHA-256 of the shell, of the
/// engines' bundle when given, and of every scene's head (the program, the resolved scene and
/// its input files).
JsonObject explorer_head(const ExplorerPageRequest& request) {
  std::string scenes;
  for (const scene::Scene& scene : request.scenes)
    scenes += cache::manifest_head("explore", JsonObject{}, scene);
  const auto sha256 = [](const std::optional<std::string>& hash) -> JsonValue {
    return {"sha256:" + hash.value_or("unreadable")};
  };
  JsonObject members{{"shell", sha256(output::sha256_file(request.shell))}};
  if (!request.engines.empty())
    members.push_back({"engines", sha256(output::sha256_file(request.engines))});
  members.push_back({"scenes", sha256(sha256_text(scenes))});
  return members;
}

}  // namespace

ExplorerOutcome make_explorer_page(const ExplorerPageRequest& request) {
  ExplorerOutcome done;
  done.result.path = explorer_page_path(request.out_dir);
  const cache::CachedOutputs cached{"explorer.html",
                                    explorer_manifest_path(request.out_dir),
                                    "explore",
                                    explorer_head(request),
                                    request.out_dir,
                                    nullptr,
                                    /*all_or_nothing=*/true};  // one page, whole or not at all
  done.outcome = cache::make_cached(cached, request.freshness, [&] {
    done.result = write_explorer_page(request);
    return cache::Made{{done.result.path}};
  });
  return done;
}

}  // namespace bookspin::products
