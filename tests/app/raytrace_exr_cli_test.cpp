// raytrace SCENE OUT.exr: one multi-layer OpenEXR file, read back here and
// checked at pixels whose values are known from the scene's geometry.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <set>
#include <string>

#include "meshtrace/io/exr.h"
#include "meshtrace/io/image.h"
#include "meshtrace/render/layers.h"
#include "support/cli.h"
#include "support/files.h"
#include "support/paths.h"

namespace meshtrace {
namespace {

constexpr int kMidX = 5, kMidRow = 4;

// The value of channel `name` at (x, row), as a double.
double at(const ExrImage& image, const std::string& name, int x, int row) {
  const ExrChannel* c = image.find(name);
  EXPECT_NE(c, nullptr) << "no channel " << name;
  if (!c) return std::nan("");
  const std::size_t i = static_cast<std::size_t>(row) * image.width + x;
  return c->floats.empty() ? static_cast<double>(c->uints[i]) : c->floats[i];
}

// Renders `scene` (10x10 pixels: camera rays go through pixel corners, so
// pixel (5, row 4), at y 5 from the bottom, has the view's axis)
// to out.exr and out.png and reads the EXR back.
ExrImage renderExr(const std::filesystem::path& dir, const std::string& scene) {
  test::writeFile(dir / "s.sce", scene);
  for (const char* out : {"out.exr", "out.png"}) {
    const auto r =
        test::runTool(test::raytraceTool(), {(dir / "s.sce").string(), (dir / out).string()}, dir);
    EXPECT_TRUE(r.exited && r.exitCode == 0) << test::describe(r);
  }
  return readExr(dir / "out.exr");
}

TEST(RaytraceExr, HasEveryLayerAndTheSphereAtTheMiddlePixel) {
  const auto dir = test::scratchDir();
  const ExrImage image = renderExr(
      dir,
      "camera 0 0 5  0 0 0  0 1 0  30  10 10\nbackground 0.1 0.2 0.3\nambience 0.2 0.2 0.2\n"
      "light 0 0 10  1 1 1\nsphere 0 0 0  1  0.1 0.1 0.1  0.5 0.5 0.5  0 0 0  1 0\n");
  ASSERT_EQ(image.width, 10);
  ASSERT_EQ(image.height, 10);
  std::set<std::string> names;
  for (const ExrChannel& c : image.channels) names.insert(c.name);
  EXPECT_EQ(names, (std::set<std::string>{"R", "G", "B", "Z", "N.X", "N.Y", "N.Z", "P.X", "P.Y",
                                          "P.Z", "objectId", "triangleId", "barycentric.B",
                                          "barycentric.C", "traversalCost"}));
  // The middle ray meets the sphere at (0, 0, 1), 4 from the eye, facing it.
  EXPECT_NEAR(at(image, "Z", kMidX, kMidRow), 4.0, 1e-5);
  EXPECT_NEAR(at(image, "N.Z", kMidX, kMidRow), 1.0, 1e-6);
  EXPECT_NEAR(at(image, "N.X", kMidX, kMidRow), 0.0, 1e-6);
  EXPECT_NEAR(at(image, "P.Z", kMidX, kMidRow), 1.0, 1e-5);
  EXPECT_NEAR(at(image, "P.Y", kMidX, kMidRow), 0.0, 1e-6);
  EXPECT_EQ(at(image, "objectId", kMidX, kMidRow), 0.0);
  EXPECT_EQ(at(image, "triangleId", kMidX, kMidRow), double{kNoHitId});  // a sphere has none
  EXPECT_GT(at(image, "traversalCost", kMidX, kMidRow), 0.0);
  // Lit head-on: ambient 0.1 * 0.2 + diffuse 0.5 * 1, before quantisation.
  EXPECT_NEAR(at(image, "R", kMidX, kMidRow), 0.02 + 0.5, 1e-6);
  // A corner sees the background, at infinity.
  EXPECT_TRUE(std::isinf(at(image, "Z", 0, 0)));
  EXPECT_EQ(at(image, "objectId", 0, 0), double{kNoHitId});
  EXPECT_NEAR(at(image, "B", 0, 0), 0.3, 1e-7);
  // The colour channels quantise to the PNG's bytes.
  const Image8 png = readImage(dir / "out.png");
  for (int row = 0; row < 10; ++row)
    for (int x = 0; x < 10; ++x)
      for (int c = 0; c < 3; ++c)
        ASSERT_EQ(toByte(at(image, std::string(1, "RGB"[c]), x, row)), png.channel(x, row, c));
}

TEST(RaytraceExr, GivesTheTriangleAndBarycentricsOfAMeshHit) {
  const auto dir = test::scratchDir();
  test::writeFile(dir / "tri.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  const ExrImage image =
      renderExr(dir,
                "camera 0.25 0.25 5  0.25 0.25 0  0 1 0  10  10 10\nlight 0 0 10  1 1 1\n"
                "sphere 5 5 -5  0.5  0 0 0  1 1 1  0 0 0  1 0\n"
                "mesh tri.off FLAT  0 0 0  1 1 1  0 0 0  1 0\n");
  // The middle ray goes down the z axis through (0.25, 0.25, 0): a quarter
  // of the way to B = (1, 0, 0) and a quarter to C = (0, 1, 0).
  EXPECT_EQ(at(image, "objectId", kMidX, kMidRow), 1.0);  // after the sphere
  EXPECT_EQ(at(image, "triangleId", kMidX, kMidRow), 0.0);
  EXPECT_NEAR(at(image, "barycentric.B", kMidX, kMidRow), 0.25, 1e-6);
  EXPECT_NEAR(at(image, "barycentric.C", kMidX, kMidRow), 0.25, 1e-6);
  EXPECT_NEAR(at(image, "Z", kMidX, kMidRow), 5.0, 1e-5);
  EXPECT_NEAR(at(image, "P.X", kMidX, kMidRow), 0.25, 1e-6);
  EXPECT_NEAR(std::abs(at(image, "N.Z", kMidX, kMidRow)), 1.0, 1e-6);
}

TEST(RaytraceExr, AnUnwritableExrLeavesTheOldFile) {
  const auto dir = test::scratchDir();
  const auto scene = test::folderWithGoodScene();
  test::writeFile(dir / "out.exr", test::kOldOutput);
  const auto r =
      test::runTool(test::raytraceTool(),
                    {(scene / "good.sce").string(), (dir / "missing" / "out.exr").string()}, dir);
  EXPECT_TRUE(r.exited && r.exitCode == 1) << test::describe(r);
  EXPECT_EQ(test::readFileBytes(dir / "out.exr"), test::kOldOutput);
}

}  // namespace
}  // namespace meshtrace
