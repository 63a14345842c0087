// Every input of a cached product in its up-to-date check (docs/outputs.md, "Manifests and
// up-to-date checks"). The list below names each input a clip, a plot, an accuracy report or
// a glTF export reads: every scene key
// (scenes/README.md, "Keys", and the [[compare]] keys), each texture file, the mesh file and
// what it pulls in (an OBJ's .mtl, a glTF's .bin), the mesh's geometry and face colours, the
// job's options and the program. Each is changed in turn, and the product's manifest head
// (the one make_cached compares) must then make the product again; changing nothing must not.
// The list is checked against what the product declares: every member of its manifest head's
// scene and inputs, and every documented key, needs an entry, so an input added without one
// fails here.
#include <gtest/gtest.h>

#include <cctype>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "analysis/accuracy.hpp"
#include "cache/make_cached.hpp"
#include "products/accuracy.hpp"
#include "products/clip.hpp"
#include "products/gltf.hpp"
#include "products/plot.hpp"
#include "scene/scene.hpp"
#include "support/cli_runner.hpp"
#include "support/mesh_files.hpp"

namespace bookspin::products {
namespace {

namespace fs = std::filesystem;
using namespace bookspin::test;  // scratch folders, file readers, mesh writers

const fs::path kGolden = fs::path(BOOKSPIN_SOURCE_DIR) / "tests" / "golden";

/// The scenes an input is changed in: the book with its four textures, a mesh body read from an
/// OBJ with a .mtl (two colours), a mesh body read from a glTF with its buffer in a .bin file.
enum class Base { book, obj, gltf };

/// One input: what is changed, before (`before`: --set overrides of both runs) and after (`set`:
/// more overrides; `edit`: files changed in the scene's folder; `clip`, `plot`, `accuracy`: an
/// option of that product's job, an input of that product alone).
struct Input {
  std::string name;
  Base base = Base::book;
  std::vector<std::string> before = {};
  std::vector<std::string> set = {};
  std::function<void(const fs::path& dir)> edit = {};
  std::function<void(ClipJob&)> clip = {};
  std::function<void(PlotJob&)> plot = {};
  std::function<void(AccuracyJob&)> accuracy = {};
  bool is_option() const { return clip || plot || accuracy; }
  /// An option of `product`'s job ("clip", "plot", "accuracy"; the export has none of its own).
  bool is_option_of(const std::string& product) const {
    return product == "clip"   ? bool(clip)
           : product == "plot" ? bool(plot)
                               : product == "accuracy" && bool(accuracy);
  }
};

/// The OBJ box with its two parts coloured by `box.mtl`.
void write_obj(const fs::path& dir, const Point& size) {
  std::ofstream obj(dir / "box.obj");
  obj << "mtllib box.mtl\n";
  for (int i = 0; i < 8; ++i) {
    const Point p = box_corner(i, size);
    obj << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << '\n';
  }
  const auto quads = box_quads();
  for (std::size_t f = 0; f < quads.size(); ++f) {
    if (f == 0 || f == 3) obj << "usemtl " << (f == 0 ? "cover" : "pages") << '\n';
    obj << 'f';
    for (int k : quads[f]) obj << ' ' << k + 1;
    obj << '\n';
  }
}

void write_mtl(const fs::path& dir, const std::string& cover_kd) {
  std::ofstream(dir / "box.mtl") << "newmtl cover\nKd " << cover_kd
                                 << "\nnewmtl pages\nKd 0.9 0.9 0.8\n";
}

void write_gltf(const fs::path& dir, const Point& size) {
  const std::string buffer = box_gltf_buffer(size);
  std::ofstream(dir / "box.gltf") << box_gltf_json(size, {0, 0, 0}, buffer.size(), "box.bin");
  write_bytes(dir / "box.bin", buffer);
}

void copy_golden(const std::string& golden, const fs::path& to) {
  fs::copy_file(kGolden / golden, to, fs::copy_options::overwrite_existing);
}

/// Writes the three scenes and every file they read into `dir`.
void write_sandbox(const fs::path& dir) {
  copy_golden("face-front-from-plus-z.png", dir / "front.png");
  copy_golden("face-back-from-minus-z.png", dir / "back.png");
  copy_golden("face-spine-from-plus-x.png", dir / "spine.png");
  copy_golden("face-pages-from-minus-x.png", dir / "pages.png");
  copy_golden("face-front-from-plus-z.png", dir / "other.png");
  std::ofstream(dir / "book.toml") << "[render]\ntexture_front = \"front.png\"\n"
                                      "texture_back = \"back.png\"\ntexture_spine = \"spine.png\"\n"
                                      "texture_pages = \"pages.png\"\n";
  write_obj(dir, {1.0f, 2.0f, 3.0f});
  write_mtl(dir, "0.8 0.1 0.1");
  fs::copy_file(dir / "box.obj", dir / "copy.obj");
  std::ofstream(dir / "measured.csv") << "t,wx,wy,wz\n0,1,2,3\n";  // measured.omega
  std::ofstream(dir / "obj.toml") << "[model]\nkind = \"rigid-matrix\"\n[body]\nshape = \"mesh\"\n"
                                     "mesh = \"box.obj\"\n";
  write_gltf(dir, {1.0f, 2.0f, 3.0f});
  std::ofstream(dir / "gltf.toml") << "[model]\nkind = \"rigid-matrix\"\n[body]\nshape = "
                                      "\"mesh\"\nmesh = \"box.gltf\"\n";
}

const char* scene_file(Base base) {
  return base == Base::book ? "book.toml" : base == Base::obj ? "obj.toml" : "gltf.toml";
}

/// The texture `file` given other pixels: those of the golden `from`.
std::function<void(const fs::path&)> new_pixels(const std::string& file, const std::string& from) {
  return [file, from](const fs::path& dir) { copy_golden(from, dir / file); };
}

/// Every input, by name. Names of scene keys are the keys themselves; "compare." names a key
/// of a [[compare]] entry; "file:" a file's bytes; "job:" an option of the job; "program" the
/// build.
std::vector<Input> inputs() {
  const std::string twist = "initial.angular_velocity=[0.1, 0.01, 0.0]";
  const std::string handle = "body.shape=\"t-handle\"";
  const std::string rigid = "model.kind=\"rigid-matrix\"";
  const std::string axis = "initial.spin_axis=\"largest\"";
  const std::string compare =
      "compare=[{label = \"a\", model = {kind = \"particle\"}}, {label = \"b\", model = {kind = "
      "\"rigid-matrix\", normalize = true}}]";
  const auto tile = [&compare](const std::string& from, const std::string& to) {
    std::string changed = compare;
    changed.replace(changed.rfind(from), from.size(), to);
    return std::vector<std::string>{changed};
  };
  std::vector<Input> list{
      {"scene.name", Base::book, {}, {"scene.name=\"other\""}},
      {"scene.title", Base::book, {}, {"scene.title=\"Another title\""}},
      {"scene.description", Base::book, {}, {"scene.description=\"What it shows\""}},
      {"model.kind", Base::book, {}, {rigid}},
      {"model.integrator", Base::book, {}, {"model.integrator=\"velocity-verlet\""}},
      {"model.normalize", Base::book, {}, {"model.normalize=true"}},
      {"model.normalize_every", Base::book, {"model.normalize=true"}, {"model.normalize_every=3"}},
      {"model.damping", Base::book, {}, {"model.damping=false"}},
      {"model.spring_constant", Base::book, {}, {"model.spring_constant=20.0"}},
      {"model.lattice_cells", Base::book, {handle}, {"model.lattice_cells=8"}},
      {"model.drag",
       Base::book,
       {rigid, "model.drag=\"linear\"", "model.drag_rate=0.2"},
       {"model.drag=\"quadratic\""}},
      {"model.drag_rate",
       Base::book,
       {rigid, "model.drag=\"linear\"", "model.drag_rate=0.2"},
       {"model.drag_rate=0.3"}},
      {"body.shape", Base::book, {}, {handle}},
      {"body.mesh", Base::obj, {}, {"body.mesh=\"copy.obj\""}},
      {"body.mass", Base::book, {handle}, {"body.mass=2.0"}},
      {"body.scale", Base::book, {handle}, {"body.scale=2.0"}},
      {"book.size", Base::book, {}, {"book.size=[1.0, 2.0, 0.25]"}},
      {"book.mass", Base::book, {}, {"book.mass=3.0"}},
      {"initial.angular_velocity", Base::book, {}, {twist}},
      {"initial.spin_axis",
       Base::book,
       {axis, "initial.spin_rate=0.2"},
       {"initial.spin_axis=\"smallest\""}},
      {"initial.spin_rate", Base::book, {axis, "initial.spin_rate=0.2"}, {"initial.spin_rate=0.3"}},
      {"initial.jiggle", Base::book, {}, {"initial.jiggle=0.01"}},
      {"initial.seed", Base::book, {"initial.jiggle=0.01"}, {"initial.seed=7"}},
      {"time.dt", Base::book, {}, {"time.dt=0.01"}},
      {"time.steps_per_frame", Base::book, {}, {"time.steps_per_frame=2"}},
      {"time.frames", Base::book, {}, {"time.frames=5"}},
      {"time.duration", Base::book, {}, {"time.duration=1.0"}},
      {"time.unit", Base::book, {}, {"time.unit=\"s\""}},
      {"render.width", Base::book, {}, {"render.width=640"}},
      {"render.height", Base::book, {}, {"render.height=360"}},
      {"render.fps", Base::book, {}, {"render.fps=24"}},
      {"render.fov_y", Base::book, {}, {"render.fov_y=40.0"}},
      {"render.camera_direction", Base::book, {}, {"render.camera_direction=[1.0, 1.0, 1.0]"}},
      {"render.camera_distance", Base::book, {}, {"render.camera_distance=10.0"}},
      {"render.show_angular_momentum", Base::book, {}, {"render.show_angular_momentum=true"}},
      {"render.show_body_axes", Base::book, {}, {"render.show_body_axes=true"}},
      {"render.texture_front", Base::book, {}, {"render.texture_front=\"other.png\""}},
      {"render.texture_back", Base::book, {}, {"render.texture_back=\"other.png\""}},
      {"render.texture_spine", Base::book, {}, {"render.texture_spine=\"other.png\""}},
      {"render.texture_pages", Base::book, {}, {"render.texture_pages=\"other.png\""}},
      {"render.codec", Base::book, {}, {"render.codec=\"h264_nvenc\""}},
      {"render.crf", Base::book, {}, {"render.crf=20"}},
      {"render.preset", Base::book, {}, {"render.preset=\"fast\""}},
      {"render.png_compression", Base::book, {}, {"render.png_compression=3"}},
      {"render.formats", Base::book, {}, {"render.formats=[\"mp4\", \"gif\"]"}},
      {"render.gif_width", Base::book, {}, {"render.gif_width=320"}},
      {"render.gif_fps", Base::book, {}, {"render.gif_fps=10"}},
      {"render.webm_crf", Base::book, {}, {"render.webm_crf=30"}},
      {"render.anisotropy", Base::book, {}, {"render.anisotropy=2"}},
      {"render.msaa", Base::book, {}, {"render.msaa=2"}},
      {"render.panel", Base::book, {}, {"render.panel=true"}},
      {"render.sphere", Base::book, {}, {"render.sphere=true"}},
      {"render.poinsot", Base::book, {}, {"render.poinsot=true"}},
      {"render.caption_twist", Base::book, {twist}, {"render.caption_twist=true"}},
      {"measured.omega", Base::book, {}, {"measured.omega=\"measured.csv\""}},
      {"compare", Base::book, {}, {compare}},
      {"compare.label", Base::book, {compare}, tile("\"b\"", "\"c\"")},
      {"compare.model.kind",
       Base::book,
       {compare},
       tile("\"rigid-matrix\"", "\"rigid-quaternion\"")},
      {"compare.model.integrator",
       Base::book,
       {compare},
       tile("normalize", "integrator = \"rk4\", normalize")},
      {"compare.model.normalize",
       Base::book,
       {compare},
       tile("normalize = true", "normalize = false")},
      {"compare.model.normalize_every",
       Base::book,
       {compare},
       tile("normalize = true", "normalize = true, normalize_every = 4")},
      {"compare.model.damping",
       Base::book,
       {compare},
       tile("\"particle\"", "\"particle\", damping = false")},
      {"compare.model.spring_constant",
       Base::book,
       {compare},
       tile("\"particle\"", "\"particle\", spring_constant = 5.0")},
      {"compare.model.drag",
       Base::book,
       {compare},
       tile("normalize = true", "normalize = true, drag = \"linear\", drag_rate = 0.2")},
      {"compare.model.drag_rate",
       Base::book,
       {compare, "model.kind=\"exact\"", "model.drag=\"linear\"", "model.drag_rate=0.2"},
       tile("normalize = true", "normalize = true, drag_rate = 0.4")},
      {"compare.model.lattice_cells",
       Base::book,
       {handle, compare},
       tile("\"particle\"", "\"particle\", lattice_cells = 6")},
  };
  // The files a scene reads, by their bytes.
  for (const char* face : {"front", "back", "spine", "pages"}) {
    const std::string other =
        face == std::string("front") ? "face-back-from-minus-z.png" : "face-front-from-plus-z.png";
    list.push_back({std::string("file:render.texture_") + face,
                    Base::book,
                    {},
                    {},
                    new_pixels(std::string(face) + ".png", other)});
  }
  list.push_back({"file:body.mesh geometry", Base::obj, {}, {}, [](const fs::path& dir) {
                    write_obj(dir, {1.0f, 2.0f, 3.5f});
                  }});
  // The .mtl the OBJ pulls in: the same geometry, the cover part recoloured.
  list.push_back({"file:body.mesh .mtl face colours", Base::obj, {}, {}, [](const fs::path& dir) {
                    write_mtl(dir, "0.1 0.1 0.8");
                  }});
  // The .bin the glTF pulls in: the .gltf unchanged, the box inside it longer.
  list.push_back({"file:body.mesh .bin geometry", Base::gltf, {}, {}, [](const fs::path& dir) {
                    write_bytes(dir / "box.bin", box_gltf_buffer({1.0f, 2.0f, 3.5f}));
                  }});
  // The measured ω's samples (measured.omega): the explorer draws them.
  list.push_back({"file:measured.omega",
                  Base::book,
                  {"measured.omega=\"measured.csv\""},
                  {},
                  [](const fs::path& dir) {
                    std::ofstream(dir / "measured.csv") << "t,wx,wy,wz\n0,1,2,3.5\n";
                  }});
  // Each product's own options.
  list.push_back({"job:png", Base::book, {}, {}, {}, [](ClipJob& job) { job.write_png = false; }});
  list.push_back({"job:png_compression", Base::book, {}, {}, {}, [](ClipJob& job) {
                    job.png_compression = 6;
                  }});
  list.push_back({"job:width", Base::book, {}, {}, {}, {}, [](PlotJob& job) { job.width = 800; }});
  list.push_back(
      {"job:height", Base::book, {}, {}, {}, {}, [](PlotJob& job) { job.height = 500; }});
  list.push_back({"job:flips", Base::book, {}, {}, {}, {}, {}, [](AccuracyJob& job) {
                    job.request.flips = 3.0;
                  }});
  list.push_back({"job:dt", Base::book, {}, {}, {}, {}, {}, [](AccuracyJob& job) {
                    job.request.dts = {0.01, 0.02};
                  }});
  list.push_back({"job:methods", Base::book, {}, {}, {}, {}, {}, [](AccuracyJob& job) {
                    job.request.methods = analysis::parse_methods("rigid");
                  }});
  return list;
}

/// A product's manifest head for `input`'s scene, before or after the change.
using HeadOf = std::function<std::string(const scene::Scene&, const Input&, bool after)>;

std::string clip_head(const scene::Scene& scene, const Input& input, bool after) {
  ClipJob job;
  job.scene = scene;
  job.out_dir = "out";
  if (after && input.clip) input.clip(job);
  return clip_manifest_head(job);
}

std::string plot_head(const scene::Scene& scene, const Input& input, bool after) {
  PlotJob job;
  job.scene = scene;
  job.out_dir = "out";
  if (after && input.plot) input.plot(job);
  return plot_manifest_head(job);
}

std::string accuracy_head(const scene::Scene& scene, const Input& input, bool after) {
  AccuracyJob job;
  job.request.scene = scene;
  job.request.dts = {0.01};
  job.out_dir = "out";
  if (after && input.accuracy) input.accuracy(job);
  return accuracy_manifest_head(job);
}

std::string gltf_head(const scene::Scene& scene, const Input&, bool) {
  GltfJob job;
  job.scene = scene;
  job.out_dir = "out";
  return gltf_manifest_head(job);
}

scene::Scene scene_of(const fs::path& dir, const Input& input, bool after) {
  std::vector<std::string> overrides = input.before;
  if (after) overrides.insert(overrides.end(), input.set.begin(), input.set.end());
  return scene::parse_scene(dir / scene_file(input.base), overrides);
}

/// The check-make-record of every cached product (cache::make_cached) with a head that holds
/// `head` (a product's), and a make that writes one file: made, or up to date.
cache::Outcome run(const fs::path& dir, const std::string& head) {
  const cache::CachedOutputs cached{"made", dir / "manifest.json", "test", {{"head", {head}}}, dir};
  return cache::make_cached(cached, {}, [&dir] {
    std::ofstream(dir / "made.txt") << "made";
    return cache::Made{{dir / "made.txt"}};
  });
}

/// Folder-safe form of an input's name.
std::string folder_name(std::string name) {
  for (char& c : name)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '-';
  return name;
}

void expect_each_input_makes_again(const std::string& product, const HeadOf& head_of) {
  for (const Input& input : inputs()) {
    if (input.is_option() && !input.is_option_of(product)) continue;  // another product's
    SCOPED_TRACE(product + ": " + input.name);
    const fs::path dir = fresh_dir("products/inputs/" + product + "/" + folder_name(input.name));
    write_sandbox(dir);
    ASSERT_EQ(run(dir, head_of(scene_of(dir, input, false), input, false)), cache::Outcome::made);
    // Nothing changed: read again, the same head, nothing made.
    EXPECT_EQ(run(dir, head_of(scene_of(dir, input, false), input, false)),
              cache::Outcome::up_to_date);
    if (input.edit) input.edit(dir);
    EXPECT_EQ(run(dir, head_of(scene_of(dir, input, true), input, true)), cache::Outcome::made);
  }
}

TEST(ProductInputs, EachInputChangedMakesTheClipAgainAndNothingChangedDoesNot) {
  expect_each_input_makes_again("clip", clip_head);
}

TEST(ProductInputs, EachInputChangedMakesThePlotAgainAndNothingChangedDoesNot) {
  expect_each_input_makes_again("plot", plot_head);
}

TEST(ProductInputs, EachInputChangedMakesTheAccuracyReportAgainAndNothingChangedDoesNot) {
  expect_each_input_makes_again("accuracy", accuracy_head);
}

TEST(ProductInputs, EachInputChangedMakesTheGltfExportAgainAndNothingChangedDoesNot) {
  expect_each_input_makes_again("gltf", gltf_head);
}

// The program: a manifest written by another build (its build id) is stale.
TEST(ProductInputs, AnotherBuildOfTheProgramMakesAgain) {
  const fs::path dir = fresh_dir("products/inputs/program");
  write_sandbox(dir);
  const Input book{"program", Base::book};
  const std::string head = clip_head(scene_of(dir, book, false), book, false);
  ASSERT_EQ(run(dir, head), cache::Outcome::made);
  ASSERT_EQ(run(dir, head), cache::Outcome::up_to_date);
  const std::string marker = "\"build_id\": \"sha256:";
  ASSERT_NE(head.find(marker), std::string::npos) << head;
  std::string manifest = read_file(dir / "manifest.json");
  const auto at = manifest.find(marker) + marker.size();
  manifest[at] = manifest[at] == '0' ? '1' : '0';
  std::ofstream(dir / "manifest.json", std::ios::binary) << manifest;
  EXPECT_EQ(run(dir, head), cache::Outcome::made);
}

/// The names in backquotes in the first cell of each row of the Markdown table under the line
/// that starts with `header` in `text`.
std::vector<std::string> first_cells(const std::string& text, const std::string& header) {
  std::vector<std::string> names;
  const auto start = text.find(header);
  if (start == std::string::npos) return names;
  std::istringstream rows(text.substr(start));
  std::string row;
  std::getline(rows, row);  // the header
  std::getline(rows, row);  // |---|
  while (std::getline(rows, row) && row.rfind("|", 0) == 0) {
    const std::string cell = row.substr(1, row.find('|', 1) - 1);
    static const std::regex quoted("`([^`]+)`");
    for (auto it = std::sregex_iterator(cell.begin(), cell.end(), quoted);
         it != std::sregex_iterator(); ++it)
      names.push_back((*it)[1]);
  }
  return names;
}

/// The member names of the JSON object opened by the line `opening` in `head`, at `indent`.
std::vector<std::string> members(const std::string& head, const std::string& opening, int indent) {
  std::vector<std::string> names;
  const auto start = head.find(opening);
  if (start == std::string::npos) return names;
  std::istringstream lines(head.substr(start + opening.size()));
  const std::regex member("^ {" + std::to_string(indent) + "}\"([^\"]+)\": ");
  for (std::string line; std::getline(lines, line);) {
    if (line.find_first_not_of(' ') < static_cast<std::size_t>(indent)) break;  // the object ends
    std::smatch m;
    if (std::regex_search(line, m, member)) names.push_back(m[1]);
  }
  return names;
}

// Every input the products declare has its entry above: the documented scene keys, the
// members of the manifest head (the resolved scene, the input files, the options), so that a
// new key, file or option with no entry fails here until the list changes it too.
TEST(ProductInputs, TheListNamesEveryDeclaredInput) {
  std::set<std::string> listed{"program"};
  for (const Input& input : inputs()) listed.insert(input.name);
  const auto has_entry = [&listed](const std::string& name) {
    for (const std::string& entry : listed)
      if (entry == name || entry.rfind(name + " ", 0) == 0) return true;
    return false;
  };
  // Documented keys (scenes/README.md, "Keys"; a [[compare]] entry's keys).
  const std::string readme = read_file(fs::path(BOOKSPIN_SOURCE_DIR) / "scenes" / "README.md");
  const std::vector<std::string> keys = first_cells(readme, "| key | type | default |");
  EXPECT_GT(keys.size(), 50u);
  for (const std::string& key : keys) EXPECT_TRUE(has_entry(key)) << key;
  const std::vector<std::string> tile_keys = first_cells(readme, "| key (in each `[[compare]]`)");
  EXPECT_GT(tile_keys.size(), 5u);
  for (const std::string& key : tile_keys) EXPECT_TRUE(has_entry("compare." + key)) << key;
  // What the heads of a clip, a plot, an accuracy report and an export hold, for a mesh comparison
  // and the textured book. Members derived from others are changed through them.
  const std::map<std::string, std::string> derived{
      {"manifest", ""},               // the format's version: not an input
      {"command", ""},                // the product itself
      {"bookspin", "program"},        // version and build id
      {"options", ""},                // its members are checked below
      {"job:format", ""},             // the export's format: glb, the one so far, not a choice
      {"scene", ""},                  // ditto
      {"inputs", ""},                 // ditto
      {"body.moments", "body.mass"},  // mass, scale and the mesh's geometry
      {"body.volume", "body.scale"},  // scale and the mesh's geometry
      {"body.surface", "file:body.mesh geometry"},            // vertex and triangle counts, smooth
      {"body_surface", "file:body.mesh .mtl face colours"}};  // geometry and face colours
  const fs::path dir = fresh_dir("products/inputs/declared");
  write_sandbox(dir);
  const Input mesh_compare{
      "", Base::obj, {"compare=[{label = \"a\", model = {kind = \"exact\"}}]"}};
  const Input book{"", Base::book};
  std::set<std::string> seen;
  for (const Input* input : {&mesh_compare, &book}) {
    const scene::Scene s = scene_of(dir, *input, false);
    for (const std::string& head : {clip_head(s, *input, false), plot_head(s, *input, false),
                                    accuracy_head(s, *input, false), gltf_head(s, *input, false)}) {
      for (const std::string& m : members(head, "", 2)) seen.insert(m);
      for (const std::string& m : members(head, "  \"scene\": {\n", 4)) {
        static const std::regex tile("^compare\\[[0-9]+\\]\\.");
        seen.insert(std::regex_replace(m, tile, "compare."));
      }
      for (const std::string& m : members(head, "  \"inputs\": {\n", 4)) seen.insert("file:" + m);
      for (const std::string& m : members(head, "  \"options\": {\n", 4)) seen.insert("job:" + m);
    }
  }
  EXPECT_GT(seen.size(), 60u);
  for (const std::string& name : seen) {
    const auto d = derived.find(name);
    if (d != derived.end()) {
      if (!d->second.empty()) {
        EXPECT_TRUE(has_entry(d->second)) << name << " → " << d->second;
      }
      continue;
    }
    EXPECT_TRUE(has_entry(name)) << name << " is in a manifest head but not in the list";
  }
}

}  // namespace
}  // namespace bookspin::products
