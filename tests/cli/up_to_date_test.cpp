// Up-to-date skipping of `bookspin render`, `plot`, `gallery`, `sweep`, `accuracy` and `export`
// through their manifests (src/output/manifest.hpp): what makes a run skip and what makes it render
// again.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "support/cli_runner.hpp"

namespace bookspin::cli {
namespace {

using namespace bookspin::test;  // the shared runner (tests/support)

namespace fs = std::filesystem;

constexpr const char* kScene = R"toml(# A tiny scene for the manifest tests.
[scene]
name = "tiny"

[model]
kind = "rigid-matrix"
normalize = true

[time]
frames = 4
steps_per_frame = 3

[render]
width = 64
height = 48
preset = "ultrafast"
)toml";

/// OUT with its own copy of the tiny scene (OUT/scene/tiny.toml; outputs under OUT/out).
struct Sandbox {
  fs::path root, scene, out;
  explicit Sandbox(const std::string& name)
      : root(fresh_dir(name)), scene(root / "scene" / "tiny.toml"), out(root / "out") {
    fs::create_directories(scene.parent_path());
    write(kScene);
  }
  void write(const std::string& text) const { std::ofstream(scene, std::ios::binary) << text; }
  CliResult render(const std::string& extra = "") const {
    return run_bookspin("render " + scene.string() + " --jobs 1 -o " + out.string() + extra);
  }
  fs::path mp4() const { return out / "tiny.mp4"; }
};

bool rendered(const CliResult& r) {
  return r.status == 0 && r.output.find("rendered: tiny") != std::string::npos &&
         r.output.find("up to date") == std::string::npos;
}
bool skipped(const CliResult& r) {
  return r.status == 0 && r.output.find("up to date: tiny") != std::string::npos &&
         r.output.find("rendered:") == std::string::npos;
}

std::string replace(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

TEST(Manifest, SecondRunSkipsAndLeavesTheOutputsAlone) {
  const Sandbox box("manifest_skip");
  ASSERT_TRUE(rendered(box.render())) << box.render().output;
  ASSERT_TRUE(fs::is_regular_file(box.out / "tiny" / "manifest.json"));
  const std::string mp4 = read_file(box.mp4());
  const auto written = fs::last_write_time(box.mp4());
  const CliResult again = box.render();
  EXPECT_TRUE(skipped(again)) << again.output;
  EXPECT_EQ(fs::last_write_time(box.mp4()), written);
  EXPECT_EQ(read_file(box.mp4()), mp4);
  // Another path to the same file is the same scene.
  const CliResult other =
      run_bookspin("render " + (box.root / "scene" / ".." / "scene" / "tiny.toml").string() +
                   " --jobs 2 -o " + box.out.string());
  EXPECT_TRUE(skipped(other)) << other.output;
}

TEST(Manifest, ManifestListsEveryOutputWithItsSizeAndHash) {
  const Sandbox box("manifest_contents");
  ASSERT_TRUE(rendered(box.render()));
  const std::string m = read_file(box.out / "tiny" / "manifest.json");
  for (const char* file : {"\"tiny.mp4\"", "\"tiny/frames/frame_00000.png\"",
                           "\"tiny/frames/frame_00003.png\"", "\"tiny/diagnostics.csv\""})
    EXPECT_NE(m.find(std::string("{\"path\": ") + file), std::string::npos) << file << '\n' << m;
  EXPECT_NE(m.find("\"size\": " + std::to_string(fs::file_size(box.mp4()))), std::string::npos);
  EXPECT_NE(m.find("\"time.frames\": 4,"), std::string::npos) << m;
  EXPECT_NE(m.find("\"render.crf\": 16,"), std::string::npos) << m;  // a default, resolved
  EXPECT_NE(m.find("\"build_id\": \"sha256:"), std::string::npos) << m;
  // The manifest's hash of the MP4 is the MP4's (sha256sum, coreutils).
  std::string sum;
  run_shell("sha256sum " + box.mp4().string(), sum);
  EXPECT_NE(m.find("\"sha256\": \"" + sum.substr(0, 64) + "\"}"), std::string::npos) << m;
}

TEST(Manifest, ChangedValueRendersAgainCommentOnlyEditDoesNot) {
  const Sandbox box("manifest_edit");
  ASSERT_TRUE(rendered(box.render()));
  // Comments, blank lines, key order within a table, a default spelled out, a number
  // written another way: the same scene.
  std::string text = replace(kScene, "# A tiny scene", "# An edited comment\n\n# on a tiny scene");
  text = replace(text, "normalize = true", "normalize = true   # SVD");
  text = replace(text, "frames = 4\nsteps_per_frame = 3", "steps_per_frame = 3\nframes = 4");
  text += "[book]\nmass = 8.000\n";  // the default, spelled out
  box.write(text);
  const CliResult comment = box.render();
  EXPECT_TRUE(skipped(comment)) << comment.output;
  box.write(replace(text, "mass = 8.000", "mass = 8.001"));
  const CliResult value = box.render();
  EXPECT_TRUE(rendered(value)) << value.output;
  EXPECT_NE(value.output.find("changed"), std::string::npos) << value.output;  // says why
  // An override is a changed value too, and so are the output options.
  EXPECT_TRUE(rendered(box.render(" --set render.crf=20")));
  EXPECT_TRUE(skipped(box.render(" --set render.crf=20")));
  EXPECT_TRUE(rendered(box.render(" --set render.crf=20 --frames 3")));
  EXPECT_TRUE(rendered(box.render(" --set render.crf=20 --frames 3 --png-compression 6")));
  EXPECT_TRUE(rendered(box.render(" --set render.crf=20 --frames 3 --png-compression 6 --no-png")));
}

TEST(Manifest, MissingTruncatedOrEditedOutputRendersAgain) {
  const Sandbox box("manifest_outputs");
  ASSERT_TRUE(rendered(box.render()));
  const fs::path frame = box.out / "tiny" / "frames" / "frame_00002.png";
  fs::remove(frame);
  EXPECT_TRUE(rendered(box.render()));
  EXPECT_TRUE(fs::is_regular_file(frame));

  fs::resize_file(box.mp4(), fs::file_size(box.mp4()) / 2);
  const CliResult truncated = box.render();
  EXPECT_TRUE(rendered(truncated)) << truncated.output;
  EXPECT_NE(truncated.output.find("bytes, the manifest says"), std::string::npos)
      << truncated.output;

  // Same size, other bytes: only --verify (hashes) sees it.
  const fs::path csv = box.out / "tiny" / "diagnostics.csv";
  std::string text = read_file(csv);
  text[text.size() - 2] = text[text.size() - 2] == '1' ? '2' : '1';
  std::ofstream(csv, std::ios::binary) << text;
  EXPECT_TRUE(skipped(box.render()));
  const CliResult verified = box.render(" --verify");
  EXPECT_TRUE(rendered(verified)) << verified.output;
  EXPECT_TRUE(skipped(box.render(" --verify")));
}

TEST(Manifest, ForceOtherBuildOrBrokenManifestRendersAgain) {
  const Sandbox box("manifest_force");
  ASSERT_TRUE(rendered(box.render()));
  EXPECT_TRUE(rendered(box.render(" --force")));
  // A different binary: the build id in the manifest is not this program's.
  const fs::path manifest = box.out / "tiny" / "manifest.json";
  std::string text = read_file(manifest);
  const auto at = text.find("\"build_id\": \"sha256:") + 20;
  text[at] = text[at] == '0' ? '1' : '0';
  std::ofstream(manifest, std::ios::binary) << text;
  EXPECT_TRUE(rendered(box.render()));
  EXPECT_TRUE(skipped(box.render()));
  // A manifest cut short is no manifest.
  text = read_file(manifest);
  std::ofstream(manifest, std::ios::binary) << text.substr(0, text.size() - 10);
  EXPECT_TRUE(rendered(box.render()));
  fs::remove(manifest);
  EXPECT_TRUE(rendered(box.render()));
}

// A cover's texture and the page edges' alike (a manifest that left the pages out once went
// unnoticed): a changed file renders again.
TEST(Manifest, ChangedTextureRendersAgain) {
  const fs::path golden = fs::path(BOOKSPIN_SOURCE_DIR) / "tests" / "golden";
  for (const std::string face : {"front", "pages"}) {
    SCOPED_TRACE(face);
    const Sandbox box("manifest_texture_" + face);
    const fs::path file = box.scene.parent_path() / (face + ".png");
    fs::copy_file(golden / "face-front-from-plus-z.png", file);
    box.write(
        replace(kScene, "[render]\n", "[render]\ntexture_" + face + " = \"" + face + ".png\"\n"));
    ASSERT_TRUE(rendered(box.render()));
    EXPECT_TRUE(skipped(box.render()));
    fs::copy_file(golden / "face-back-from-minus-z.png", file,
                  fs::copy_options::overwrite_existing);
    const CliResult r = box.render();
    EXPECT_TRUE(rendered(r)) << r.output;
  }
}

/// A closed box, `x` × 2 × 3, as OBJ text (outward winding).
std::string box_obj(double x) {
  const std::string a = std::to_string(x);
  return "v 0 0 0\nv " + a + " 0 0\nv " + a + " 2 0\nv 0 2 0\nv 0 0 3\nv " + a + " 0 3\nv " + a +
         " 2 3\nv 0 2 3\n"
         "f 1 4 3\nf 1 3 2\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\n"
         "f 4 8 7\nf 4 7 3\nf 1 5 8\nf 1 8 4\nf 2 3 7\nf 2 7 6\n";
}

TEST(Manifest, ChangedMeshRendersAgain) {
  const Sandbox box("manifest_mesh");
  const fs::path obj = box.scene.parent_path() / "box.obj";
  std::ofstream(obj) << box_obj(1.0);
  box.write(std::string(kScene) + "[body]\nshape = \"mesh\"\nmesh = \"box.obj\"\n");
  const CliResult first = box.render();
  ASSERT_TRUE(rendered(first)) << first.output;
  const std::string m = read_file(box.out / "tiny" / "manifest.json");
  EXPECT_NE(m.find("\"body.mesh\": \"sha256:"), std::string::npos) << m;
  EXPECT_NE(m.find("\"body.mesh\": \"box.obj\""), std::string::npos) << m;
  EXPECT_TRUE(skipped(box.render()));
  std::ofstream(obj) << box_obj(1.5);
  const CliResult changed = box.render();
  EXPECT_TRUE(rendered(changed)) << changed.output;
}

// An OBJ recoloured through its .mtl file: the .obj's bytes and the geometry are the same,
// the body's face colours are not, so the clip renders again.
TEST(Manifest, MeshRecolouredThroughItsMtlRendersAgain) {
  const Sandbox box("manifest_mtl");
  const fs::path obj = box.scene.parent_path() / "box.obj";
  const fs::path mtl = box.scene.parent_path() / "box.mtl";
  std::ofstream(obj) << "mtllib box.mtl\nusemtl paint\n" << box_obj(1.0);
  std::ofstream(mtl) << "newmtl paint\nKd 0.8 0.1 0.1\n";
  box.write(std::string(kScene) + "[body]\nshape = \"mesh\"\nmesh = \"box.obj\"\n");
  ASSERT_TRUE(rendered(box.render()));
  EXPECT_TRUE(skipped(box.render()));
  std::ofstream(mtl) << "newmtl paint\nKd 0.1 0.1 0.8\n";
  const CliResult r = box.render();
  EXPECT_TRUE(rendered(r)) << r.output;
}

TEST(Manifest, FailedRunKeepsTheEarlierOutputsAndManifest) {
  const Sandbox box("manifest_failed");
  ASSERT_TRUE(rendered(box.render()));
  // The output directory's frames path taken by a file: the render fails before anything is
  // put in place (docs/outputs.md, "One run's outputs, all or nothing"), so the MP4, the CSV
  // and the manifest keep their bytes. The frames it lists are gone (removed here), so once
  // the path is free the next run renders again instead of trusting it. (An interrupted
  // render keeps it too: tests/cli/interrupt_test.cpp finds the earlier clip untouched.)
  const fs::path manifest = box.out / "tiny" / "manifest.json";
  const std::string manifest_bytes = read_file(manifest), mp4 = read_file(box.mp4()),
                    csv = read_file(box.out / "tiny" / "diagnostics.csv");
  fs::remove_all(box.out / "tiny" / "frames");
  std::ofstream(box.out / "tiny" / "frames") << "not a directory";
  EXPECT_NE(box.render(" --force").status, 0);
  EXPECT_EQ(read_file(manifest), manifest_bytes);
  EXPECT_EQ(read_file(box.mp4()), mp4);
  EXPECT_EQ(read_file(box.out / "tiny" / "diagnostics.csv"), csv);
  fs::remove(box.out / "tiny" / "frames");
  EXPECT_TRUE(rendered(box.render()));
}

TEST(Manifest, PlotAndGallerySkipWhenUpToDate) {
  const Sandbox box("manifest_plot_gallery");
  const auto plot = [&box](const std::string& width) {
    return "plot " + box.scene.string() + " --width " + width + " --height 400 -o " +
           box.out.string();
  };
  const CliResult first = run_bookspin(plot("640"));
  ASSERT_EQ(first.status, 0) << first.output;
  EXPECT_NE(first.output.find("wrote"), std::string::npos);
  const CliResult second = run_bookspin(plot("640"));
  EXPECT_NE(second.output.find("up to date: tiny-plot"), std::string::npos) << second.output;
  EXPECT_NE(run_bookspin(plot("660")).output.find("wrote"), std::string::npos);
  EXPECT_NE(run_bookspin(plot("660")).output.find("up to date"), std::string::npos);
  EXPECT_NE(run_bookspin(plot("660") + " --force").output.find("wrote"), std::string::npos);

  const std::string gallery = "gallery " + box.out.string() + " " + box.scene.string();
  EXPECT_NE(run_bookspin(gallery).output.find("wrote"), std::string::npos);
  const std::string page = read_file(box.out / "index.html");
  EXPECT_NE(run_bookspin(gallery).output.find("up to date: index.html"), std::string::npos);
  EXPECT_EQ(read_file(box.out / "index.html"), page);
  ASSERT_TRUE(rendered(box.render()));  // the page now shows the clip: written again
  EXPECT_NE(run_bookspin(gallery).output.find("wrote"), std::string::npos);
  EXPECT_NE(read_file(box.out / "index.html").find("tiny.mp4"), std::string::npos);
}

TEST(Manifest, WholeSweepSkipsWhenUpToDate) {
  const Sandbox box("manifest_sweep");
  const auto sweep = [&box](const std::string& measures) {
    return run_bookspin("sweep " + box.scene.string() +
                        " --vary 'initial.jiggle=0:0.001:2' --measure " + measures + " -j 1 -o " +
                        box.out.string());
  };
  const CliResult first = sweep("energy_drift");
  ASSERT_EQ(first.status, 0) << first.output;
  EXPECT_NE(first.output.find("wrote"), std::string::npos) << first.output;
  const CliResult second = sweep("energy_drift");
  EXPECT_NE(second.output.find("up to date: tiny-sweep"), std::string::npos) << second.output;
  EXPECT_NE(sweep("energy_drift,diverged_at").output.find("wrote"), std::string::npos);
  fs::remove(box.out / "tiny-sweep.png");
  EXPECT_NE(sweep("energy_drift,diverged_at").output.find("wrote"), std::string::npos);
  EXPECT_TRUE(fs::is_regular_file(box.out / "tiny-sweep.png"));
}

/// `bookspin export --gltf` of the sandbox's scene with `options`.
CliResult export_gltf(const Sandbox& box, const std::string& options) {
  return run_bookspin("export " + box.scene.string() + " --gltf " + options + " -o " +
                      box.out.string());
}

/// An export that made the .glb, and one that found it up to date.
bool made(const CliResult& r) {
  return r.status == 0 && r.output.find("exported: ") != std::string::npos &&
         r.output.find("up to date") == std::string::npos;
}
bool skipped_glb(const CliResult& r) {
  return r.status == 0 && r.output.find("up to date: tiny.glb") != std::string::npos &&
         r.output.find("exported:") == std::string::npos;
}

TEST(Manifest, GltfExportSkipsWhenUpToDateAndTheGalleryLinksOnlyAListedGlb) {
  const Sandbox box("manifest_gltf");
  const auto exported = [&box](const std::string& options) { return export_gltf(box, options); };
  ASSERT_TRUE(made(exported("")));
  const fs::path glb = box.out / "tiny.glb";
  const std::string bytes = read_file(glb);
  const CliResult second = exported("");
  EXPECT_TRUE(skipped_glb(second)) << second.output;
  EXPECT_EQ(read_file(glb), bytes);
  box.write(std::string(kScene) + "# a comment only\n");
  EXPECT_TRUE(skipped_glb(exported("")));
  EXPECT_TRUE(made(exported("--frames 3")));  // the scene's time.frames changed
  EXPECT_TRUE(skipped_glb(exported("--frames 3")));
  EXPECT_TRUE(made(exported("--frames 3 --force")));
  fs::remove(glb);
  EXPECT_TRUE(made(exported("--frames 3")));
  // The gallery links the .glb while its manifest lists it, and not once the manifest is gone.
  const std::string gallery = "gallery " + box.out.string() + " " + box.scene.string();
  ASSERT_EQ(run_bookspin(gallery).status, 0);
  EXPECT_NE(read_file(box.out / "index.html").find("tiny.glb"), std::string::npos);
  fs::remove(box.out / "tiny" / "gltf-manifest.json");
  ASSERT_EQ(run_bookspin(gallery + " --force").status, 0);
  EXPECT_EQ(read_file(box.out / "index.html").find("tiny.glb"), std::string::npos);
}

// Same size, other bytes: a plain export trusts the .glb's size in its manifest and says up to
// date; --verify hashes it, finds it changed and exports it again, byte for byte the first
// export; then --verify finds it as its manifest says.
TEST(Manifest, GltfExportVerifyRemakesAGlbChangedAtTheSameSize) {
  const Sandbox box("manifest_gltf_verify");
  const auto exported = [&box](const std::string& options) { return export_gltf(box, options); };
  ASSERT_TRUE(made(exported("")));
  const fs::path glb = box.out / "tiny.glb";
  const std::string bytes = read_file(glb);
  ASSERT_GT(bytes.size(), 100u);
  std::string changed = bytes;
  changed[changed.size() - 5] = static_cast<char>(~changed[changed.size() - 5]);
  std::ofstream(glb, std::ios::binary) << changed;
  ASSERT_EQ(fs::file_size(glb), bytes.size());
  const CliResult plain = exported("");
  EXPECT_TRUE(skipped_glb(plain)) << plain.output;
  EXPECT_TRUE(read_file(glb) == changed) << "a plain run rewrote the .glb";  // not printed: MBs
  const CliResult verified = exported("--verify");
  EXPECT_TRUE(made(verified)) << verified.output;
  EXPECT_TRUE(read_file(glb) == bytes) << "--verify did not export the .glb again";
  const CliResult again = exported("--verify");
  EXPECT_TRUE(skipped_glb(again)) << again.output;
}

TEST(Manifest, AccuracyReportSkipsWhenUpToDateAndRemeasuresOnAnyOptionChange) {
  const Sandbox box("manifest_accuracy");
  const auto accuracy = [&box](const std::string& options) {
    return run_bookspin("accuracy " + box.scene.string() +
                        " --set initial.jiggle=0.001 --flips 1 " + options + " -o " +
                        box.out.string());
  };
  const std::string options = "--dt 1 0.5 --methods rigid-quaternion:rk4,mujoco:euler";
  const CliResult first = accuracy(options);
  ASSERT_EQ(first.status, 0) << first.output;
  EXPECT_NE(first.output.find("wrote " + (box.out / "tiny-energy-vs-dt.png").string()),
            std::string::npos)
      << first.output;
  const std::string csv = read_file(box.out / "tiny-accuracy.csv");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 1 + 2 * 2) << csv;  // 2 methods × 2 dt
  const CliResult second = accuracy(options);
  EXPECT_NE(second.output.find("up to date: tiny-accuracy"), std::string::npos) << second.output;
  EXPECT_EQ(second.output.find("rigid-quaternion rk4"), std::string::npos);  // not measured
  EXPECT_EQ(read_file(box.out / "tiny-accuracy.csv"), csv);
  for (const std::string changed : {"--dt 1 0.25 --methods rigid-quaternion:rk4,mujoco:euler",
                                    "--dt 1 0.5 --methods rigid-quaternion:rk4",
                                    "--dt 1 0.5 --methods rigid-quaternion:rk4,mujoco:euler "
                                    "--force"}) {
    SCOPED_TRACE(changed);
    EXPECT_NE(accuracy(changed).output.find("wrote"), std::string::npos);
  }
  fs::remove(box.out / "tiny-energy-vs-dt.png");
  EXPECT_NE(accuracy("--dt 1 0.5 --methods rigid-quaternion:rk4").output.find("wrote"),
            std::string::npos);
  EXPECT_TRUE(fs::is_regular_file(box.out / "tiny-energy-vs-dt.png"));
}

}  // namespace
}  // namespace bookspin::cli
