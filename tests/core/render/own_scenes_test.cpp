// Our own scenes/ against our stored renders in expected_results/, and
// those stored renders against a second renderer that shares no code with
// the one that made them (support/spec_renderer.h), itself checked against
// the course's reference images.
#include <gtest/gtest.h>

#include <cstdio>
#include <set>

#include "meshtrace/geometry/mesh.h"
#include "meshtrace/io/scene_parser.h"
#include "meshtrace/render/render.h"
#include "support/image_agreement.h"
#include "support/paths.h"
#include "support/spec_renderer.h"

namespace meshtrace {
namespace {

std::vector<std::filesystem::path> ownScenes() {
  std::vector<std::filesystem::path> scenes;
  for (const auto& e : std::filesystem::recursive_directory_iterator(test::sourceDir() / "scenes"))
    if (e.path().extension() == ".sce") scenes.push_back(e.path());
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}

class OwnScenes : public ::testing::TestWithParam<std::filesystem::path> {};

Image8 expectedResult(const std::filesystem::path& scene) {
  return readImage(test::sourceDir() / "expected_results" / (scene.stem().string() + ".png"));
}

// The renderer is deterministic, so a fresh render is the stored one byte
// for byte (measured: no pixel differs). A difference means the images
// changed: look at them, and store the new ones with
// scripts/update_expected.sh once they pass the check below.
TEST_P(OwnScenes, RenderMatchesExpectedResult) {
  const std::filesystem::path& file = GetParam();
  const Image8 ours = quantize(render(loadScene(file), {}));
  const Image8 expected = expectedResult(file);
  ASSERT_EQ(ours.width, expected.width);
  ASSERT_EQ(ours.height, expected.height);
  const std::size_t differ = test::pixelsDiffering(ours, expected);
  std::printf("[ figures  ] %-18s pixels differing from the stored render: %zu\n",
              file.stem().string().c_str(), differ);
  EXPECT_EQ(differ, 0u);
}

// The stored renders against the second renderer, which follows the same
// page by other means: only rounding decisions may differ, on at most a
// handful of pixels (measured: one pixel, by one level, on knot and on
// mirror_hall).
TEST_P(OwnScenes, ExpectedResultAgreesWithASecondRenderer) {
  const std::filesystem::path& file = GetParam();
  const Image8 second = test::renderBySpec(loadScene(file));
  const Image8 expected = expectedResult(file);
  ASSERT_EQ(second.width, expected.width);
  ASSERT_EQ(second.height, expected.height);
  const std::size_t differ = test::pixelsDiffering(second, expected);
  std::printf(
      "[ figures  ] %-18s pixels differing from the second renderer: %zu, by more than "
      "32: %zu\n",
      file.stem().string().c_str(), differ, test::pixelsDiffering(second, expected, 32));
  EXPECT_LE(differ, test::kHandfulOfPixels);
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

// The second renderer is itself held to the scene format's page: on the
// course's scenes it matches the reference images within JPEG noise.
TEST(SecondRenderer, MatchesTheCourseReferenceImagesWithinJpegNoise) {
  MESHTRACE_REQUIRE_SEED();
  int scenes = 0;
  for (const auto& dir : std::filesystem::directory_iterator(test::seedDir() / "scenes")) {
    const std::string name = dir.path().filename().string();
    const auto reference = test::seedDir() / "expected_results" / (name + ".jpg");
    if (!std::filesystem::exists(reference)) continue;
    ++scenes;
    test::expectWithinJpegNoise(test::renderBySpec(loadScene(dir.path() / (name + ".sce"))),
                                reference, "second renderer: " + name);
  }
  EXPECT_EQ(scenes, 10);
}

}  // namespace
}  // namespace meshtrace
