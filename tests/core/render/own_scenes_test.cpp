// Fresh renders of our own scenes/ against our stored renders in
// expected_results/. The renderer is deterministic, so only pixels where a
// rounding decision flips (silhouettes, shared edges) may differ, and only
// when the compiler or its flags change.
#include <gtest/gtest.h>

#include <cstdio>
#include <set>

#include "meshtrace/geometry/mesh.h"
#include "meshtrace/io/scene_parser.h"
#include "meshtrace/render/render.h"
#include "meshtrace/report/image_compare.h"
#include "support/paths.h"

namespace meshtrace {
namespace {

constexpr double kMaxRmse = 0.25;
constexpr double kMaxFractionOver32 = 0.0005;

std::vector<std::filesystem::path> ownScenes() {
  std::vector<std::filesystem::path> scenes;
  for (const auto& e : std::filesystem::recursive_directory_iterator(test::sourceDir() / "scenes"))
    if (e.path().extension() == ".sce") scenes.push_back(e.path());
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

class OwnScenes : public ::testing::TestWithParam<std::filesystem::path> {};

TEST_P(OwnScenes, RenderMatchesExpectedResult) {
  const std::filesystem::path& file = GetParam();
  const Scene scene = loadScene(file);
  const auto expected = test::sourceDir() / "expected_results" / (file.stem().string() + ".png");
  ASSERT_TRUE(std::filesystem::exists(expected)) << "no stored render for " << file;
  const ImageDifference d = compareImages(quantize(render(scene, {})), readImage(expected));
  std::printf("[ figures  ] %-18s RMSE %.3f  pixels off >32: %.4f%%  max %d\n",
              file.stem().string().c_str(), d.rmse, 100.0 * d.fractionOver32, d.maxDifference);
  EXPECT_LE(d.rmse, kMaxRmse);
  EXPECT_LE(d.fractionOver32, kMaxFractionOver32);
}

INSTANTIATE_TEST_SUITE_P(Scenes, OwnScenes, ::testing::ValuesIn(ownScenes()),
                         [](const auto& info) { return info.param.stem().string(); });

// What the scenes must cover together: every entity, both shading modes,
// several lights, mirrors, one mesh shaded both ways, and a large mesh.
TEST(OwnScenesCoverage, UseEveryEntityBothShadingModesAndALargeMesh) {
  std::size_t spheres = 0, planes = 0, cylinders = 0, meshes = 0, maxLights = 0, maxTriangles = 0;
  bool mirror = false;
  std::set<std::pair<std::filesystem::path, Shading>> meshModes;
  const auto scenes = ownScenes();
  for (const auto& file : scenes) {
    const Scene s = loadScene(file);
    spheres += s.spheres.size();
    planes += s.planes.size();
    cylinders += s.cylinders.size();
    meshes += s.meshes.size();
    maxLights = std::max(maxLights, s.lights.size());
    mirror |= s.hasMirrors() && s.depth > 0;
    for (const Mesh& m : s.meshes) {
      meshModes.insert({std::filesystem::canonical(m.file()), m.shading()});
      maxTriangles = std::max(maxTriangles, m.triangles().size());
    }
  }
  bool sameMeshBothWays = false;
  for (const auto& [path, mode] : meshModes)
    sameMeshBothWays |= mode == Shading::Flat && meshModes.count({path, Shading::Phong});
  EXPECT_GE(scenes.size(), 6u);
  EXPECT_GT(spheres, 0u);
  EXPECT_GT(planes, 0u);
  EXPECT_GT(cylinders, 0u);
  EXPECT_GT(meshes, 0u);
  EXPECT_GE(maxLights, 2u);
  EXPECT_TRUE(mirror);
  EXPECT_TRUE(sameMeshBothWays);
  EXPECT_GT(maxTriangles, 100000u);
}

}  // namespace
}  // namespace meshtrace
