// raytrace --report on a tiny purpose-made scene: every configuration is
// measured, the files are written, and the reference render agrees with
// itself.
#include "meshtrace/report/report.h"

#include <gtest/gtest.h>

#include <fstream>

#include "meshtrace/io/scene_parser.h"
#include "meshtrace/report/stability.h"
#include "support/paths.h"

namespace meshtrace {
namespace {

Scene tinyScene(int width = 24, int height = 16) {
  Scene s;
  s.file = test::scratchDir() / "tiny.sce";  // no expected image beside it
  s.camera = Camera(CameraSpec{{0, 1, 5}, {0, 0, 0}, {0, 1, 0}, 45.0, width, height});
  s.lights.push_back({{3, 4, 5}, Color(1.0)});
  s.spheres.push_back({{-0.8, 0, 0}, 0.6, {Color(0.2), Color(0.6), Color(0.3), 20.0, 0.0}});
  MeshData box = makeClosedGridBox(1);
  box.triangles.resize(2);  // one square face: too few triangles for a BVH
  for (Vec3& v : box.vertices) v = 0.5 * v + Vec3(0.8, 0.0, 0.0);
  s.meshes.emplace_back("box.off", std::move(box), Shading::Flat, Material{});
  return s;
}

TEST(Report, MeasuresEveryConfigurationAndWritesFiles) {
  const Scene scene = tinyScene();
  const SceneReport r = measureScene(scene, 1);
  std::vector<std::string> leftOut;
  EXPECT_EQ(r.rows.size(), reportConfigs(scene, leftOut).size());
  EXPECT_NE(r.reference.find("64 samples"), std::string::npos);
  bool bvhLeftOut = false;
  for (const std::string& s : r.leftOut) bvhLeftOut |= s.rfind("no BVH for box.off", 0) == 0;
  EXPECT_TRUE(bvhLeftOut);
  for (const ReportRow& row : r.rows) {
    // Each configuration was timed: some time passed, and not an absurd
    // amount for 384 pixels.
    EXPECT_GT(row.seconds, 0.0) << row.config.name;
    EXPECT_LT(row.seconds, 60.0) << row.config.name;
    EXPECT_TRUE(std::isfinite(row.rmse)) << row.config.name;
    // The exact image traces the same primary hits as the brute-force reference.
    if (row.config.name == "exact (default)") {
      EXPECT_EQ(row.hitDiffers, 0.0);
    }
    if (row.config.step == 1) {
      EXPECT_LE(row.maxNormalDegrees, 1e-6) << row.config.name;
    }
  }
  const auto dir = test::scratchDir();
  writeReport(dir, {r}, "stability table");
  std::ifstream csv(dir / "report.csv");
  std::size_t lines = 0;
  for (std::string line; std::getline(csv, line);) ++lines;
  EXPECT_EQ(lines, r.rows.size() + 1);
  const Image8 plot = readImage(dir / "plot_tiny.png");
  EXPECT_EQ(plot.width, 1100);
  EXPECT_TRUE(std::filesystem::exists(dir / "plot_tiny.gp"));
  EXPECT_TRUE(std::filesystem::exists(dir / "report.md"));
}

// The samples sweep is scored against a converged render, so its error
// falls as samples rise (against the 1-sample exact image, 16 samples
// looked worse than 4); the pixel-exact configurations keep the reference.
TEST(Report, SamplesErrorFallsAgainstAConvergedRender) {
  // Large enough for the error to be an average over many edge pixels.
  const SceneReport r = measureScene(tinyScene(120, 80), 0);
  EXPECT_NE(r.converged.find("256 samples"), std::string::npos) << r.converged;
  std::vector<double> sweep;
  for (const ReportRow& row : r.rows) {
    EXPECT_EQ(row.against, row.config.group == "samples" ? "converged" : "reference")
        << row.config.name;
    if (row.config.group == "samples") sweep.push_back(row.rmse);
  }
  ASSERT_EQ(sweep.size(), 4u);  // 1, 4, 16, 64 samples
  for (std::size_t i = 1; i < sweep.size(); ++i) EXPECT_LT(sweep[i], sweep[i - 1]) << i;
  EXPECT_LT(r.samplesSlope, -0.3);
  EXPECT_GT(r.samplesSlope, -1.5);
}

// Our scenes/ are scored against their renders stored in the checkout's
// expected_results/, not against a 64-sample render of their own.
TEST(Report, OurScenesAreScoredAgainstTheirStoredRenders) {
  std::size_t scenes = 0;
  for (const auto& e :
       std::filesystem::recursive_directory_iterator(test::sourceDir() / "scenes")) {
    if (e.path().extension() != ".sce") continue;
    ++scenes;
    const Scene scene = loadScene(e.path());
    EXPECT_EQ(findReferenceImage(scene).lexically_normal(),
              test::sourceDir() / "expected_results" / (e.path().stem().string() + ".png"))
        << e.path();
  }
  EXPECT_GE(scenes, 6u);
}

// A stored render is the reference, the report says which file it is, and
// the exact configuration, which rendered it, matches it exactly.
TEST(Report, AStoredRenderIsTheReferenceAndTheReportNamesIt) {
  const auto dir = test::scratchDir();
  Scene scene = tinyScene();
  scene.file = dir / "scenes" / "tiny" / "tiny.sce";
  std::filesystem::create_directories(dir / "expected_results");
  const auto stored = dir / "expected_results" / "tiny.png";
  writeImage(quantize(renderConfig(scene, {"progressive", "exact", TraceOptions{}, 1, 1})), stored);
  const SceneReport r = measureScene(scene, 1);
  EXPECT_EQ(r.reference.rfind(stored.lexically_normal().string() + " (a stored render)", 0), 0u)
      << r.reference;
  bool sawExact = false;
  for (const ReportRow& row : r.rows)
    if (row.config.name == "exact (default)") {
      sawExact = true;
      EXPECT_EQ(row.rmse, 0.0);
    }
  EXPECT_TRUE(sawExact);
  writeReport(dir / "report", {r}, "stability table");
  std::ifstream in(dir / "report" / "report.md");
  const std::string md((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(md.find("Scored against: " + r.reference), std::string::npos) << md;
  EXPECT_NE(md.find("| tiny | " + r.reference + " |"), std::string::npos) << md;
}

}  // namespace
}  // namespace meshtrace
