// raytrace --report on a tiny purpose-made scene: every configuration is
// measured, the files are written, and the reference render agrees with
// itself.
#include "meshtrace/report/report.h"

#include <gtest/gtest.h>

#include <fstream>

#include "meshtrace/report/stability.h"
#include "support/paths.h"

namespace meshtrace {
namespace {

Scene tinyScene() {
  Scene s;
  s.file = test::scratchDir() / "tiny.sce";  // no expected image beside it
  s.camera = Camera(CameraSpec{{0, 1, 5}, {0, 0, 0}, {0, 1, 0}, 45.0, 24, 16});
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
  EXPECT_EQ(plot.width, 640);
  EXPECT_TRUE(std::filesystem::exists(dir / "report.md"));
}

}  // namespace
}  // namespace meshtrace
