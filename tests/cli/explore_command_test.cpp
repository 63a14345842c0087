// `bookspin explore SCENE… -o OUT`: the scenes written into the explorer page's shell
// (docs/explorer.md). These tests use a small shell of their own, so they need neither
// emscripten nor a browser; tests/browser/explorer_test.py runs the real page.
#include <gtest/gtest.h>

#include <fstream>
#include <regex>

#include "support/cli_runner.hpp"
#include "support/scratch.hpp"

namespace bookspin::cli {
namespace {

using namespace bookspin::test;
namespace fs = std::filesystem;

const char* kShell =
    "<!doctype html><html><body>\n<!--BOOKSPIN_DATA-->\n<script>app()</script>\n</body></html>\n";

fs::path write_shell(const fs::path& dir, const std::string& text = kShell) {
  const fs::path shell = dir / "shell.html";
  std::ofstream(shell) << text;
  return shell;
}

/// The entry of scene `name` in the page's BOOKSPIN_SCENES (its JSON object, one line).
std::string scene_entry(const std::string& page, const std::string& name) {
  const auto at = page.find("{\"name\":\"" + name + "\"");
  if (at == std::string::npos) return "";
  return page.substr(at, page.find('\n', at) - at);
}

std::vector<double> numbers_after(const std::string& text, const std::string& key) {
  std::smatch m;
  std::vector<double> out;
  if (!std::regex_search(text, m, std::regex("\"" + key + "\":\\[([^\\]]*)\\]"))) return out;
  std::istringstream list(m[1].str());
  for (std::string item; std::getline(list, item, ',');) out.push_back(std::stod(item));
  return out;
}

TEST(ExploreCommand, WritesEveryScenesSettingsAndTheMeshBodyIntoTheShell) {
  const fs::path dir = fresh_dir("explore/page");
  const fs::path shell = write_shell(dir);
  const CliResult r =
      run_bookspin("explore " + scene_path("fig09-matrix-unstable-x") + " " +
                   scene_path("major-axis-rule") + " " + scene_path("t-handle-dzhanibekov") +
                   " --shell " + shell.string() + " -o " + (dir / "out").string());
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_NE(r.output.find("3 scenes"), std::string::npos) << r.output;
  const std::string page = read_file(dir / "out" / "explorer.html");
  // The shell is kept around the data, which replaces the marker.
  EXPECT_EQ(page.find("<!--BOOKSPIN_DATA-->"), std::string::npos);
  EXPECT_EQ(page.rfind("<!doctype html><html><body>\n<script>window.BOOKSPIN_SCENES=[", 0), 0u);
  EXPECT_NE(page.find("</script>\n<script>app()</script>\n</body></html>\n"), std::string::npos);

  // fig09: the paper's book and spin (the original program's ω0 about x, scenes/fig09-…).
  const std::string book = scene_entry(page, "fig09-matrix-unstable-x");
  ASSERT_FALSE(book.empty());
  EXPECT_NE(book.find("\"body\":\"book\",\"model\":\"rigid-matrix\",\"integrator\":\"euler\""),
            std::string::npos)
      << book;
  EXPECT_EQ(numbers_after(book, "w"), (std::vector<double>{0.114819, 0.0, 0.0}));
  EXPECT_EQ(book.find("\"body\":{"), std::string::npos) << "the book is built by the page";

  // The long box 2.0 × 1.2 × 0.3 of mass 1: moments m(b² + c²)/12 … in ascending order, the
  // spin of 6 about the smallest axis (x), the lattice of 8 cells, the two tiles compared.
  const std::string box = scene_entry(page, "major-axis-rule");
  ASSERT_FALSE(box.empty());
  const std::vector<double> moments = numbers_after(box, "moments");
  ASSERT_EQ(moments.size(), 3u) << box.substr(0, 400);
  EXPECT_NEAR(moments[0], (1.2 * 1.2 + 0.3 * 0.3) / 12, 1e-7);
  EXPECT_NEAR(moments[1], (2.0 * 2.0 + 0.3 * 0.3) / 12, 1e-7);
  EXPECT_NEAR(moments[2], (2.0 * 2.0 + 1.2 * 1.2) / 12, 1e-7);
  EXPECT_EQ(numbers_after(box, "w"), (std::vector<double>{6.0, 0.0, 0.0}));
  // The mesh file's coordinates arrive as float32 (assimp): ~1e-7 relative.
  const std::vector<double> cage = numbers_after(box, "cage");
  ASSERT_EQ(cage.size(), 3u);
  EXPECT_NEAR(cage[0], 2.0, 2e-7);
  EXPECT_NEAR(cage[1], 1.2, 2e-7);
  EXPECT_NEAR(cage[2], 0.3, 2e-7);
  const std::vector<double> vertices = numbers_after(box, "vertices");
  const std::vector<double> triangles = numbers_after(box, "triangles");
  EXPECT_EQ(vertices.size(), 3u * 8u);    // the box's 8 corners
  EXPECT_EQ(triangles.size(), 3u * 12u);  // 12 triangles
  EXPECT_EQ(numbers_after(box, "colours").size(), 3u * 12u);
  for (const double v : vertices) {
    const double a = std::abs(v);
    EXPECT_TRUE(std::abs(a - 1.0) < 1e-7 || std::abs(a - 0.6) < 1e-7 || std::abs(a - 0.15) < 1e-7)
        << v;
  }
  EXPECT_NE(box.find("\"model\":\"particle\",\"integrator\":\"velocity-verlet\""),
            std::string::npos);
  EXPECT_NE(box.find("\"cells\":8"), std::string::npos);
  EXPECT_NE(
      box.find("\"compare\":true,\"model2\":\"rigid-quaternion\",\"integrator2\":\"splitting\""),
      std::string::npos);
  EXPECT_NE(box.find("\"shape\":\"mesh\""), std::string::npos);

  // The T-handle: its body given whole, the preset's shape named.
  const std::string t_handle = scene_entry(page, "t-handle-dzhanibekov");
  EXPECT_NE(t_handle.find("\"body\":{\"shape\":\"t-handle\""), std::string::npos);

  // The book's four faces as PNG data: URLs.
  for (const char* face : {"front", "back", "spine", "pages"})
    EXPECT_NE(page.find(std::string("\"") + face + "\":\"data:image/png;base64,iVBORw0KGgo"),
              std::string::npos)
        << face;
}

/// A fresh folder with the test shell and a one-line scene titled `title` (DIR/s.toml), and
/// the command that writes its page to DIR/out/explorer.html.
struct OnePage {
  fs::path dir, scene, page;
  std::string args;
  OnePage(const std::string& name, const std::string& title)
      : dir(fresh_dir(name)), scene(dir / "s.toml"), page(dir / "out" / "explorer.html") {
    const fs::path shell = write_shell(dir);
    std::ofstream(scene) << "[scene]\ntitle = \"" << title << "\"\n";
    args = "explore " + scene.string() + " --shell " + shell.string() + " -o " +
           (dir / "out").string();
  }
};

// Nothing to do, nothing done: run again with the same shell and scenes, the page keeps its
// bytes and its modification time; a comment is no change; a changed scene or shell rewrites it.
TEST(ExploreCommand, UnchangedInputsLeaveThePageAloneAndAChangeRewritesIt) {
  const OnePage one("explore/cached", "first title");
  const fs::path &dir = one.dir, &scene = one.scene, &page = one.page;
  const std::string& args = one.args;
  ASSERT_EQ(run_bookspin(args).status, 0);
  const std::string bytes = read_file(page);
  const auto written = fs::last_write_time(page);
  const auto same = [&](const std::string& why) {
    const CliResult r = run_bookspin(args);
    EXPECT_EQ(r.status, 0) << r.output;
    EXPECT_NE(r.output.find("up to date"), std::string::npos) << why << "\n" << r.output;
    EXPECT_EQ(read_file(page), bytes) << why;
    EXPECT_EQ(fs::last_write_time(page), written) << why;
  };
  same("nothing changed");
  std::ofstream(scene, std::ios::app) << "# a comment only\n";
  same("a comment");

  std::ofstream(scene) << "[scene]\ntitle = \"second title\"\n";
  CliResult r = run_bookspin(args);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.find("up to date"), std::string::npos) << r.output;
  EXPECT_NE(read_file(page).find("second title"), std::string::npos);

  write_shell(dir, std::string(kShell) + "<!-- another shell -->\n");
  r = run_bookspin(args);
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.find("up to date"), std::string::npos) << r.output;
  EXPECT_NE(read_file(page).find("another shell"), std::string::npos);
}

// A page corrupted at the same size stays "up to date" on sizes; --verify hashes it and writes
// it again, --force writes it whatever the manifest says (docs/outputs.md).
TEST(ExploreCommand, VerifySeesASameSizeCorruptionAndForceRewrites) {
  const OnePage one("explore/verify", "a title");
  const fs::path& page = one.page;
  const std::string& args = one.args;
  ASSERT_EQ(run_bookspin(args).status, 0);
  const std::string bytes = read_file(page);
  std::string corrupted = bytes;
  corrupted[corrupted.find("a title")] = 'A';
  std::ofstream(page, std::ios::binary) << corrupted;
  CliResult r = run_bookspin(args);
  EXPECT_NE(r.output.find("up to date"), std::string::npos) << r.output;
  EXPECT_EQ(read_file(page), corrupted);
  r = run_bookspin(args + " --verify");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.find("up to date"), std::string::npos) << r.output;
  EXPECT_EQ(read_file(page), bytes);
  r = run_bookspin(args + " --verify");
  EXPECT_NE(r.output.find("up to date"), std::string::npos) << r.output;
  const auto written = fs::last_write_time(page);
  r = run_bookspin(args + " --force");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.find("up to date"), std::string::npos) << r.output;
  EXPECT_EQ(read_file(page), bytes);
  EXPECT_GE(fs::last_write_time(page), written);
}

TEST(ExploreCommand, TextThatWouldCloseTheScriptIsEscaped) {
  const fs::path dir = fresh_dir("explore/escape");
  const fs::path scene = dir / "sneaky.toml";
  std::ofstream(scene) << "[scene]\ntitle = \"a </script><script>alert(1)</script> b\"\n";
  const CliResult r = run_bookspin("explore " + scene.string() + " --shell " +
                                   write_shell(dir).string() + " -o " + dir.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string page = read_file(dir / "explorer.html");
  EXPECT_NE(page.find("a <\\/script><script>alert(1)<\\/script> b"), std::string::npos);
  EXPECT_EQ(page.find("alert(1)</script>"), std::string::npos);
}

TEST(ExploreCommand, BadInputsAreOneLineExitTwoAndWriteNothing) {
  const fs::path dir = fresh_dir("explore/bad");
  const fs::path shell = write_shell(dir);
  const fs::path no_marker = dir / "plain.html";
  std::ofstream(no_marker) << "<html></html>\n";
  const fs::path bad_scene = dir / "bad.toml";
  std::ofstream(bad_scene) << "[time]\ndt = -1\n";
  const std::string out = " -o " + (dir / "out").string();
  const std::string fig09 = scene_path("fig09-matrix-unstable-x");
  struct Case {
    std::string args;
    std::string says;
  };
  const Case cases[] = {
      {fig09 + " --shell " + (dir / "missing.html").string(),
       "missing.html: the explorer page's shell is missing"},
      {fig09 + " --shell " + no_marker.string(), "plain.html: not an explorer shell"},
      {bad_scene.string() + " --shell " + shell.string(), "bad.toml"},
      {fig09 + " " + fig09 + " --shell " + shell.string(), "is the name of another scene"},
      {"--shell " + shell.string(), "SCENE is required"},
  };
  for (const Case& c : cases) {
    const CliResult r = run_bookspin("explore " + c.args + out);
    EXPECT_EQ(r.status, 2) << c.args << "\n" << r.output;
    EXPECT_NE(r.output.find(c.says), std::string::npos) << c.args << "\n" << r.output;
    EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
    EXPECT_FALSE(fs::exists(dir / "out" / "explorer.html")) << c.args;
  }
}

TEST(ExploreCommand, WithoutTheBuiltShellSaysHowToBuildItAndExitsOne) {
  // A copy of the program in a folder with no web/explorer-shell.html beside it.
  const fs::path dir = fresh_dir("explore/unbuilt");
  fs::copy_file(BOOKSPIN_EXE, dir / "bookspin");
  CliResult r = run_program(
      "", (dir / "bookspin").string(),
      "explore " + scene_path("fig09-matrix-unstable-x") + " -o " + (dir / "out").string());
  EXPECT_EQ(r.status, 1) << r.output;
  EXPECT_NE(r.output.find("bookspin: error: the explorer page's program is not built: no " +
                          (dir / "web" / "explorer-shell.html").string()),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("web/build.sh"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir / "out"));
  // With the shell in place it works.
  fs::create_directories(dir / "web");
  write_shell(dir / "web");
  fs::rename(dir / "web" / "shell.html", dir / "web" / "explorer-shell.html");
  r = run_program(
      "", (dir / "bookspin").string(),
      "explore " + scene_path("fig09-matrix-unstable-x") + " -o " + (dir / "out").string());
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(fs::exists(dir / "out" / "explorer.html"));
}

TEST(ExploreCommand, EnginesGoInOnlyWithTheFlagAndCountInTheUpToDateCheck) {
  // A shell with the engines' marker, and the engines' bundle beside it (web/build.sh).
  const fs::path dir = fresh_dir("explore/engines");
  const fs::path shell = write_shell(
      dir,
      "<html>\n<!--BOOKSPIN_DATA-->\n<!--BOOKSPIN_ENGINES-->\n<script>app()</script>\n</html>\n");
  const fs::path engines = dir / "explorer-engines.js";
  std::ofstream(engines) << "window.BOOKSPIN_ENGINES=['first'];";
  const fs::path page = dir / "out" / "explorer.html";
  const std::string args = "explore " + scene_path("fig09-matrix-unstable-x") + " --shell " +
                           shell.string() + " -o " + (dir / "out").string();

  CliResult r = run_bookspin(args);
  ASSERT_EQ(r.status, 0) << r.output;
  std::string text = read_file(page);
  EXPECT_EQ(text.find("BOOKSPIN_ENGINES"), std::string::npos) << "no engines without the flag";
  EXPECT_NE(text.find("</script>\n\n<script>app()</script>"), std::string::npos);

  r = run_bookspin(args + " --engines");
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(r.output.find("up to date"), std::string::npos) << r.output;
  text = read_file(page);
  EXPECT_NE(text.find("\n<script>window.BOOKSPIN_ENGINES=['first'];</script>\n<script>app()"),
            std::string::npos)
      << text.substr(text.size() - 200);
  EXPECT_NE(run_bookspin(args + " --engines").output.find("up to date"), std::string::npos);
  std::ofstream(engines) << "window.BOOKSPIN_ENGINES=['second'];";
  r = run_bookspin(args + " --engines");
  EXPECT_EQ(r.output.find("up to date"), std::string::npos) << "a changed bundle rewrites the page";
  EXPECT_NE(read_file(page).find("['second']"), std::string::npos);
  r = run_bookspin(args);
  EXPECT_EQ(r.output.find("up to date"), std::string::npos) << "without the flag again";
  EXPECT_EQ(read_file(page).find("BOOKSPIN_ENGINES"), std::string::npos);

  // The bundle missing, or a shell with no place for it: exit 2 naming the file, nothing written.
  fs::remove_all(dir / "out");
  fs::remove(engines);
  r = run_bookspin(args + " --engines");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find(engines.string() + ": the explorer's JavaScript engines are missing"),
            std::string::npos)
      << r.output;
  fs::create_directories(dir / "old");
  const fs::path old_shell = write_shell(dir / "old", kShell);
  std::ofstream(dir / "old" / "explorer-engines.js") << "window.BOOKSPIN_ENGINES=[];";
  r = run_bookspin("explore " + scene_path("fig09-matrix-unstable-x") + " --shell " +
                   old_shell.string() + " --engines -o " + (dir / "out").string());
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("has no place for the engines"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(page));
}

}  // namespace
}  // namespace bookspin::cli
