#include "products/explorer.hpp"

#include <iomanip>
#include <set>
#include <sstream>
#include <vector>

#include "cache/manifest_head.hpp"
#include "common/errors.hpp"
#include "common/text_file.hpp"
#include "output/atomic_output.hpp"
#include "output/data_url.hpp"
#include "output/finite_number.hpp"
#include "output/output_dir.hpp"
#include "output/png_writer.hpp"
#include "output/sha256.hpp"
#include "physics/presets.hpp"
#include "render/face_images.hpp"
#include "scene/canonical.hpp"

namespace bookspin::products {

namespace {

/// Numbers in shortest round-trip form, checked finite (output::finite_text): the page's
/// doubles are the same as bookspin's.
template <typename Matrix>
void json_numbers(std::ostream& out, const Matrix& m, std::string_view what) {
  out << '[';
  for (Eigen::Index i = 0; i < m.size(); ++i)
    out << (i ? "," : "") << output::finite_text(static_cast<double>(m.data()[i]), what);
  out << ']';
}

std::string number(double value, std::string_view what) { return output::finite_text(value, what); }

void method(std::ostream& out, const physics::ModelConfig& m, const char* suffix) {
  out << "\"model" << suffix << "\":" << scene::json_string(std::string(physics::to_string(m.kind)))
      << ",\"integrator" << suffix
      << "\":" << scene::json_string(std::string(physics::to_string(m.integrator)))
      << ",\"normalize" << suffix << "\":" << (m.normalize ? "true" : "false");
}

/// `text` safe inside a <script> element: "</" cannot close it early.
std::string script_safe(std::string text) {
  for (auto at = text.find("</"); at != std::string::npos; at = text.find("</", at + 3))
    text.replace(at, 2, "<\\/");
  return text;
}

/// The models the page can run: every tile but the other engines' (the page binds src/physics
/// alone, docs/engines.md), or the scene's model; the exact motion where none is left.
std::vector<physics::ModelConfig> page_models(const scene::Scene& s) {
  std::vector<physics::ModelConfig> models;
  if (s.compare.empty()) models.push_back(s.model);
  for (const scene::CompareTile& tile : s.compare) models.push_back(tile.model);
  std::erase_if(models, [](const physics::ModelConfig& m) { return physics::is_engine(m.kind); });
  if (models.empty()) models.push_back({physics::ModelKind::exact, physics::Integrator::euler});
  return models;
}

std::string read_shell(const std::filesystem::path& shell) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(shell, ec))
    throw InputError(shell.string() + ": the explorer page's shell is missing (web/build.sh)");
  return read_text_file(shell, "the explorer page's shell");
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

std::string explorer_scene_json(const scene::Scene& s) {
  std::ostringstream out;
  const std::vector<physics::ModelConfig> models = page_models(s);
  const physics::ModelConfig& first = models.front();
  out << "{\"name\":" << scene::json_string(s.name) << ",\"title\":" << scene::json_string(s.title)
      << ",\"description\":" << scene::json_string(s.description) << ",\"state\":{"
      << "\"body\":" << scene::json_string(std::string(physics::to_string(s.body.shape))) << ',';
  method(out, first, "");
  out << ",\"damping\":" << (first.damping ? "true" : "false")
      << ",\"k\":" << number(first.spring_constant, "explorer page: model.spring_constant")
      << ",\"cells\":" << first.lattice_cells
      << ",\"dt\":" << number(s.dt, "explorer page: time.dt") << ",\"axis\":\"custom\",\"w\":";
  json_numbers(out, s.initial.omega0_body, "explorer page: initial.angular_velocity");
  out << ",\"jiggle\":" << number(s.initial.jiggle, "explorer page: initial.jiggle")
      << ",\"seed\":" << s.initial.seed
      << ",\"speed\":" << number(s.dt * s.steps_per_frame * s.render.fps, "explorer page: speed")
      << ",\"showL\":" << (s.render.show_angular_momentum ? "true" : "false")
      << ",\"showAxes\":" << (s.render.show_body_axes ? "true" : "false");
  if (models.size() >= 2) {
    // The page compares two methods: the first tile with the last (e.g. Euler and exact).
    out << ",\"compare\":true,";
    method(out, models.back(), "2");
  }
  out << "},\"book\":{\"size\":";
  json_numbers(out, s.body.cage.size, "explorer page: book.size");
  out << ",\"mass\":" << number(s.body.cage.mass, "explorer page: book.mass") << '}';
  if (s.body.shape != physics::BodyShape::book) {
    const physics::Body& b = s.body;
    out << ",\"body\":{\"shape\":" << scene::json_string(std::string(physics::to_string(b.shape)))
        << ",\"mass\":" << number(b.cage.mass, "explorer page: body.mass") << ",\"moments\":";
    json_numbers(out, b.moments, "explorer page: body moments");
    out << ",\"cage\":";
    json_numbers(out, b.cage.size, "explorer page: body cage");
    out << ",\"volume\":" << number(b.volume, "explorer page: body volume") << ",\"vertices\":";
    json_numbers(out, b.vertices, "explorer page: body vertices");
    out << ",\"triangles\":";
    json_numbers(out, b.triangles, "explorer page: body triangles");
    out << ",\"colours\":";
    json_numbers(out, b.face_colours, "explorer page: body colours");
    out << ",\"smooth\":" << (b.smooth ? "true" : "false") << '}';
  }
  out << '}';
  return out.str();
}

ExplorerPageResult write_explorer_page(const ExplorerPageRequest& request) {
  std::set<std::string> names;
  for (const scene::Scene& s : request.scenes) {
    if (!names.insert(s.name).second)
      throw InputError(s.source.string() + ": scene.name: '" + s.name +
                       "' is the name of another scene given to the explorer");
  }
  std::string page = read_shell(request.shell);
  const auto at = page.find(kExplorerDataMarker);
  if (at == std::string::npos)
    throw InputError(request.shell.string() + ": not an explorer shell (no " +
                     std::string(kExplorerDataMarker) + " marker; web/build.sh makes one)");

  std::ostringstream data;
  data << "<script>window.BOOKSPIN_SCENES=[";
  for (std::size_t i = 0; i < request.scenes.size(); ++i) {
    stop_if_asked(request.stop_signal, "explore scenes");
    data << (i ? ",\n" : "\n") << script_safe(explorer_scene_json(request.scenes[i]));
  }
  data << "];\nwindow.BOOKSPIN_BOOK_ART={";
  const char* faces[] = {"front", "back", "spine", "pages"};  // FaceImage order
  for (int f = 0; f < 4; ++f) {
    stop_if_asked(request.stop_signal, "explore scenes");
    const RgbaImage image = render::generate_face_image(static_cast<render::FaceImage>(f));
    data << (f ? "," : "") << '"' << faces[f] << "\":\""
         << output::data_url("image/png", output::encode_png(image, 6)) << '"';
  }
  data << "};</script>";
  page.replace(at, std::string(kExplorerDataMarker).size(), data.str());

  const std::string engines_marker = kExplorerEnginesMarker;
  const auto engines_at = page.find(engines_marker);
  if (!request.engines.empty()) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(request.engines, ec))
      throw InputError(request.engines.string() +
                       ": the explorer's JavaScript engines are missing (web/build.sh writes "
                       "them beside the shell)");
    if (engines_at == std::string::npos)
      throw InputError(request.shell.string() + ": this shell has no place for the engines (no " +
                       engines_marker + " marker; web/build.sh makes one)");
    page.replace(engines_at, engines_marker.size(),
                 "<script>" +
                     script_safe(read_text_file(request.engines, "the explorer's engines")) +
                     "</script>");
  } else if (engines_at != std::string::npos) {
    page.erase(engines_at, engines_marker.size());
  }

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

ExplorerOutcome make_explorer_page(const ExplorerPageRequest& request) {
  std::string scenes;
  for (const scene::Scene& scene : request.scenes)
    scenes += cache::manifest_head("explore", "", scene);
  const std::string head =
      "  \"manifest\": 1,\n  \"command\": \"explore\",\n  \"shell\": \"sha256:" +
      output::sha256_file(request.shell).value_or("unreadable") + "\",\n" +
      (request.engines.empty()
           ? std::string()
           : "  \"engines\": \"sha256:" +
                 output::sha256_file(request.engines).value_or("unreadable") + "\",\n") +
      "  \"scenes\": \"sha256:" + output::sha256_text(scenes) + "\",\n";
  ExplorerOutcome done;
  done.result.path = explorer_page_path(request.out_dir);
  int signal = 0;
  done.outcome = cache::run_cached(
      {explorer_manifest_path(request.out_dir), head, request.out_dir, false, false, [&] {
         return unless_interrupted(signal, [&] {
           done.result = write_explorer_page(request);
           return cache::JobOutputs{
               "", {done.result.path.lexically_relative(request.out_dir).generic_string()}};
         });
       }});
  if (signal != 0) throw Interrupted(signal);  // the earlier page and manifest untouched
  return done;
}

}  // namespace bookspin::products
