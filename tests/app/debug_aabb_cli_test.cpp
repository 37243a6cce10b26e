// The debug_aabb tool: the box-count image, and clean refusals of bad input.
#include <gtest/gtest.h>

#include "meshtrace/io/image.h"
#include "support/cli.h"
#include "support/files.h"
#include "support/mounts.h"
#include "support/paths.h"
#include "support/scene_snippets.h"

namespace meshtrace {
namespace {

using test::debugAabbTool;

class DebugAabbBadInput : public ::testing::TestWithParam<test::BadInput> {};

TEST_P(DebugAabbBadInput, ExitsWithAnErrorNamingTheFileAndLeavesTheOutput) {
  test::expectRefusesBadInput(debugAabbTool(), GetParam());
}

INSTANTIATE_TEST_SUITE_P(Cases, DebugAabbBadInput, ::testing::ValuesIn(test::badInputs()),
                         [](const auto& info) { return info.param.name; });

// Writes scene.sce with `meshLines` after the standard camera, and tri.off.
std::filesystem::path sceneWithMeshes(const std::filesystem::path& dir,
                                      const std::string& meshLines) {
  test::writeFile(dir / "tri.off", test::kTriangleOff);
  return test::writeFile(dir / "scene.sce", test::kCameraLine + meshLines);
}

TEST(DebugAabbCli, MarksThePixelsWhoseRayMeetsTheMeshBox) {
  const auto dir = test::scratchDir();
  const auto scene = sceneWithMeshes(dir, "mesh tri.off FLAT " + test::kMaterial + "\n");
  test::expectSuccess(debugAabbTool(), {scene.string(), (dir / "out.png").string()}, dir);
  const Image8 image = readImage(dir / "out.png");
  ASSERT_EQ(image.width, 8);
  ASSERT_EQ(image.height, 6);
  EXPECT_EQ(image.channel(4, 3, 0), 255) << "the centre looks at the mesh";
  EXPECT_EQ(image.channel(4, 3, 1), 0);
  EXPECT_EQ(image.channel(0, 0, 0), 0) << "the corner looks past it";
}

// A mesh without vertices has an empty box, which no ray may meet.
TEST(DebugAabbCli, AMeshWithNoVerticesMeetsNoRay) {
  const auto dir = test::scratchDir();
  test::writeFile(dir / "none.off", "OFF\n0 0 0\n");
  const auto scene = sceneWithMeshes(dir, "mesh none.off FLAT " + test::kMaterial + "\n");
  test::expectSuccess(debugAabbTool(), {scene.string(), (dir / "out.png").string()}, dir);
  const Image8 image = readImage(dir / "out.png");
  EXPECT_EQ(image.rgb, std::vector<std::uint8_t>(8 * 6 * 3, 0));
}

TEST(DebugAabbCli, RefusesAnUnwritableOutputLeavingTheOldFile) {
  const auto dir = test::scratchDir();
  const auto scene = sceneWithMeshes(dir, "mesh tri.off FLAT " + test::kMaterial + "\n");
  test::writeFile(dir / "out.tga", test::kOldOutput);
  test::expectRefusal(debugAabbTool(), {scene.string(), (dir / "out.tga").string()}, dir,
                      {"out.tga"}, dir / "out.tga");
  test::expectRefusal(debugAabbTool(), {scene.string(), (dir / "nowhere" / "out.png").string()},
                      dir, {"out.png"}, dir / "nowhere" / "out.png");
}

// As root too: the folder is a read-only mount.
TEST(DebugAabbCli, AllIntoAReadOnlyFolderWritesNothingAndFails) {
  const auto dir = test::scratchDir();
  std::filesystem::create_directories(dir / "scenes");
  std::filesystem::create_directories(dir / "results");
  sceneWithMeshes(dir / "scenes", "mesh tri.off FLAT " + test::kMaterial + "\n");
  test::writeFile(dir / "results" / "debug_aabb_scene.png", test::kOldOutput);
  std::string refused;
  const auto r = test::runToolWithMounts(
      debugAabbTool(), {"--all", (dir / "scenes").string(), (dir / "results").string()}, dir,
      test::readOnlyFolder(dir / "results"), refused);
  MESHTRACE_SKIP_IF_MOUNTS_REFUSED(r, refused);
  EXPECT_TRUE(r->exited && r->exitCode == 1) << test::describe(*r);
  test::expectMentions(r->err, {"error", "debug_aabb_scene.png", "read-only"});
  EXPECT_EQ(test::readFileBytes(dir / "results" / "debug_aabb_scene.png"), test::kOldOutput);
  EXPECT_EQ(test::listFolder(dir / "results"), std::vector<std::string>{"debug_aabb_scene.png"});
}

TEST(DebugAabbCli, AllSkipsScenesWithoutMeshesAndNamesBadOnes) {
  const auto dir = test::scratchDir();
  std::filesystem::create_directory(dir / "scenes");
  sceneWithMeshes(dir / "scenes", "mesh tri.off FLAT " + test::kMaterial + "\n");
  test::writeFile(dir / "scenes" / "spheres.sce", test::kCameraLine + test::kSphereLine);
  test::writeFile(dir / "scenes" / "broken.sce", test::kCameraLine + "mesh tri.off FLAT 1 2\n");
  const test::ToolResult r = test::runTool(
      debugAabbTool(), {"--all", (dir / "scenes").string(), (dir / "results").string()}, dir);
  ASSERT_TRUE(r.exited) << test::describe(r);
  EXPECT_EQ(r.exitCode, 1) << test::describe(r);
  test::expectMentions(r.err, {"broken.sce:2", "incomplete"});
  EXPECT_EQ(test::listFolder(dir / "results"), std::vector<std::string>{"debug_aabb_scene.png"});
}

}  // namespace
}  // namespace meshtrace
