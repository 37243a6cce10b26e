// A bare mesh file is a scene: raytrace frames it (camera, light, floor,
// PHONG) and --print-scene writes the same scene as .sce.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "app/formats/mesh_files.h"
#include "meshtrace/geometry/mesh_generators.h"
#include "meshtrace/io/image.h"
#include "meshtrace/io/mesh_scene.h"
#include "meshtrace/io/scene_parser.h"
#include "support/cli.h"
#include "support/files.h"
#include "support/paths.h"

namespace meshtrace {
namespace {

// Whether `ray` meets `box` (slab test).
bool meets(const Ray& ray, const Aabb& box) {
  double near = 0.0, far = kInfinity;
  for (int k = 0; k < 3; ++k) {
    const double t0 = (box.min[k] - ray.origin[k]) / ray.direction[k];
    const double t1 = (box.max[k] - ray.origin[k]) / ray.direction[k];
    near = std::max(near, std::min(t0, t1));
    far = std::min(far, std::max(t0, t1));
  }
  return near <= far;
}

// A long, flat and off-centre box, the hardest to frame among simple ones.
const Aabb kBox = [] {
  Aabb box;
  box.extend(Vec3(-30.0, 2.0, 5.0));
  box.extend(Vec3(10.0, 6.0, 9.0));
  return box;
}();

TEST(MeshScene, FramesTheWholeBoxWithItsCentreInView) {
  const auto dir = test::scratchDir();
  const MeshData spanning = {{kBox.min, kBox.max, Vec3(kBox.min.x, kBox.max.y, kBox.max.z)},
                             {{0, 1, 2}}};
  test::writeMeshFile(spanning, test::MeshFormat::Off, dir / "box.off");
  const Scene scene = parseScene(meshSceneText(kBox, "box.off"), dir / "box.sce");
  const Camera& camera = scene.camera;
  const int w = camera.width(), h = camera.height();
  // No ray through the image's border meets the box: all of it is inside.
  for (int x = 0; x < w; ++x)
    for (int y : {0, h - 1}) ASSERT_FALSE(meets(camera.primaryRay(x + 0.5, y + 0.5), kBox)) << x;
  for (int y = 0; y < h; ++y)
    for (int x : {0, w - 1}) ASSERT_FALSE(meets(camera.primaryRay(x + 0.5, y + 0.5), kBox)) << y;
  EXPECT_TRUE(meets(camera.primaryRay(w / 2.0, h / 2.0), kBox));
  // Lit, and standing on a floor at the bottom of the box.
  ASSERT_EQ(scene.lights.size(), 1u);
  ASSERT_EQ(scene.planes.size(), 1u);
  EXPECT_EQ(scene.planes[0].point.y, kBox.min.y);
  EXPECT_GT(scene.lights[0].position.y, kBox.max.y);
}

class BareMeshCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = test::scratchDir();
    test::writeMeshFile(test::onFloatGrid(makeTorus(Vec3(0.5, 0.4, -0.2), 1.0, 0.35, 24, 12)),
                        test::MeshFormat::PlyBinary, dir_ / "torus.ply");
  }
  std::string path(const char* name) const { return (dir_ / name).string(); }
  std::filesystem::path dir_;
};

TEST_F(BareMeshCli, RendersTheMeshFramedAndPrintsTheSameSceneAsText) {
  const auto bare =
      test::runTool(test::raytraceTool(), {path("torus.ply"), path("bare.png")}, dir_);
  ASSERT_TRUE(bare.exited && bare.exitCode == 0) << test::describe(bare);
  const auto printed =
      test::runTool(test::raytraceTool(), {"--print-scene", path("torus.ply")}, dir_);
  ASSERT_TRUE(printed.exited && printed.exitCode == 0) << test::describe(printed);
  EXPECT_NE(printed.out.find("mesh torus.ply PHONG"), std::string::npos) << printed.out;
  test::writeFile(dir_ / "torus.sce", printed.out);
  const auto saved =
      test::runTool(test::raytraceTool(), {path("torus.sce"), path("saved.png")}, dir_);
  ASSERT_TRUE(saved.exited && saved.exitCode == 0) << test::describe(saved);
  const Image8 image = readImage(dir_ / "bare.png");
  EXPECT_EQ(image.width, 800);
  EXPECT_TRUE(image.rgb == readImage(dir_ / "saved.png").rgb);
  // The torus is lit: part of the image is brighter than the floor gets.
  const auto brightest = *std::max_element(image.rgb.begin(), image.rgb.end());
  EXPECT_GT(brightest, 200);
}

TEST_F(BareMeshCli, PrintSceneRefusesWhatIsNotAMesh) {
  test::writeFile(dir_ / "bad.obj", "v 0 0 0\nf 1 2 3\n");
  test::expectRefusal(test::raytraceTool(), {"--print-scene", path("bad.obj")}, dir_,
                      {"bad.obj:2", "face 0", "'2'"}, {});
  test::writeFile(dir_ / "a.sce", "camera 0 0 5 0 0 0 0 1 0 40 8 6\n");
  test::expectRefusal(test::raytraceTool(), {"--print-scene", path("a.sce")}, dir_,
                      {"a.sce", "not a mesh file"}, {});
}

// A scene file has no quoting, so a mesh whose name holds white space or
// '#' cannot be named by the scene a bare mesh becomes: refused by name,
// with the old output kept, rather than misread as other words.
TEST_F(BareMeshCli, AMeshWhoseNameASceneCannotHoldIsRefusedByName) {
  for (const char* name : {"my torus.ply", "tab\ttorus.ply", "a#b.ply"}) {
    std::filesystem::copy_file(dir_ / "torus.ply", dir_ / name);
    const auto out = test::writeFile(dir_ / "out.png", test::kOldOutput);
    test::expectRefusal(test::raytraceTool(), {path(name), out.string()}, dir_,
                        {name, "cannot name this file", "rename"}, out);
    test::expectRefusal(test::raytraceTool(), {"--print-scene", path(name)}, dir_,
                        {name, "cannot name this file"}, {});
    std::filesystem::remove(dir_ / name);
  }
}

}  // namespace
}  // namespace meshtrace
