// The raytrace tool as a user runs it: renders, refuses bad input cleanly
// and never leaves a broken or half-written output file.
#include <gtest/gtest.h>

#include "meshtrace/io/image.h"
#include "support/cli.h"
#include "support/files.h"
#include "support/paths.h"
#include "support/scene_snippets.h"

namespace meshtrace {
namespace {

using test::expectRefusedBeforeRendering;
using test::folderWithGoodScene;
using test::raytraceTool;
using test::renderArgs;

class RaytraceBadInput : public ::testing::TestWithParam<test::BadInput> {};

TEST_P(RaytraceBadInput, ExitsWithAnErrorNamingTheFileAndLeavesTheOutput) {
  test::expectRefusesBadInput(raytraceTool(), GetParam());
}

INSTANTIATE_TEST_SUITE_P(Cases, RaytraceBadInput, ::testing::ValuesIn(test::badInputs()),
                         [](const auto& info) { return info.param.name; });

TEST(RaytraceCli, RendersEachImageTypeAtTheSceneSize) {
  const auto dir = folderWithGoodScene();
  for (const char* name : {"out.png", "out.bmp", "out.ppm", "out.jpg"}) {
    test::expectSuccess(raytraceTool(), renderArgs(dir, name), dir);
    const Image8 image = readImage(dir / name);
    EXPECT_EQ(image.width, 8) << name;
    EXPECT_EQ(image.height, 6) << name;
  }
}

TEST(RaytraceCli, ReportsWhatItLoadedAndHowLongItTook) {
  const auto dir = folderWithGoodScene();
  const test::ToolResult r = test::expectSuccess(raytraceTool(), renderArgs(dir, "out.png"), dir);
  test::expectMentions(r.out, {"2 objects", "1 triangles", "ms", "rendered 8x6", "wrote"});
}

TEST(RaytraceCli, ReplacesAnExistingOutputWithTheNewImage) {
  const auto dir = folderWithGoodScene();
  test::writeFile(dir / "out.png", test::kOldOutput);
  test::expectSuccess(raytraceTool(), renderArgs(dir, "out.png"), dir);
  EXPECT_EQ(readImage(dir / "out.png").width, 8);
  EXPECT_EQ(test::listFolder(dir), (std::vector<std::string>{"good.sce", "out.png", "tri.off"}));
}

TEST(RaytraceCli, GivesTheSameImageForOneAndTwoThreads) {
  const auto dir = folderWithGoodScene();
  auto args1 = renderArgs(dir, "one.ppm");
  auto args2 = renderArgs(dir, "two.ppm");
  args1.insert(args1.begin(), {"--threads", "1"});
  args2.insert(args2.begin(), {"--threads", "2"});
  test::expectSuccess(raytraceTool(), args1, dir);
  test::expectSuccess(raytraceTool(), args2, dir);
  EXPECT_TRUE(test::readFileBytes(dir / "one.ppm") == test::readFileBytes(dir / "two.ppm"));
}

TEST(RaytraceCli, WarnsButRendersWhenUpIsParallelToTheView) {
  const auto dir = test::scratchDir();
  test::writeFile(dir / "up.sce",
                  "# from above\ncamera 0 5 0  0 0 0  0 1 0  45  8 6\n" + test::kSphereLine);
  const test::ToolResult r =
      test::runTool(raytraceTool(), {(dir / "up.sce").string(), (dir / "out.png").string()}, dir);
  ASSERT_TRUE(r.exited) << test::describe(r);
  EXPECT_EQ(r.exitCode, 0) << test::describe(r);
  test::expectMentions(r.err, {"warning", "up.sce:2", "parallel"});
  EXPECT_EQ(readImage(dir / "out.png").width, 8);
}

TEST(RaytraceCli, RefusesAnOutputInAMissingFolder) {
  const auto dir = folderWithGoodScene();
  const auto r = test::expectRefusal(raytraceTool(), renderArgs(dir, "missing/out.png"), dir,
                                     {"out.png", "missing"}, dir / "missing" / "out.png");
  expectRefusedBeforeRendering(r);
}

TEST(RaytraceCli, RefusesAnOutputPathThatIsAFolder) {
  const auto dir = folderWithGoodScene();
  std::filesystem::create_directory(dir / "out.png");
  const auto r = test::expectRefusal(raytraceTool(), renderArgs(dir, "out.png"), dir,
                                     {"out.png", "folder"}, dir / "out.png");
  expectRefusedBeforeRendering(r);
  EXPECT_TRUE(std::filesystem::is_directory(dir / "out.png"));
}

TEST(RaytraceCli, RefusesAnOutputBelowARegularFile) {
  const auto dir = folderWithGoodScene();
  test::writeFile(dir / "file", "x");
  const auto r = test::expectRefusal(raytraceTool(), renderArgs(dir, "file/out.png"), dir,
                                     {"out.png", "not a folder"}, dir / "file");
  expectRefusedBeforeRendering(r);
}

TEST(RaytraceCli, RefusesAnUnknownImageTypeLeavingTheOldFile) {
  const auto dir = folderWithGoodScene();
  test::writeFile(dir / "out.gif", test::kOldOutput);
  const auto r = test::expectRefusal(raytraceTool(), renderArgs(dir, "out.gif"), dir,
                                     {"out.gif", "image type"}, dir / "out.gif");
  expectRefusedBeforeRendering(r);
}

TEST(RaytraceCli, AllRendersTheGoodScenesAndNamesTheBadOnes) {
  const auto dir = folderWithGoodScene();
  std::filesystem::create_directories(dir / "scenes" / "sub");
  std::filesystem::copy_file(dir / "good.sce", dir / "scenes" / "good.sce");
  std::filesystem::copy_file(dir / "tri.off", dir / "scenes" / "tri.off");
  test::writeFile(dir / "scenes" / "sub" / "broken.sce", test::kCameraLine + "depth x\n");
  const test::ToolResult r = test::runTool(
      raytraceTool(), {"--all", (dir / "scenes").string(), (dir / "results").string()}, dir);
  ASSERT_TRUE(r.exited) << test::describe(r);
  EXPECT_EQ(r.exitCode, 1) << "one scene failed";
  test::expectMentions(r.err, {"broken.sce:2", "depth"});
  EXPECT_EQ(test::listFolder(dir / "results"), std::vector<std::string>{"good.png"});
}

TEST(RaytraceCli, AllSaysASymlinkLoopIsOne) {
  const auto dir = test::scratchDir();
  std::filesystem::create_directory_symlink(dir / "loop", dir / "loop");
  const auto r = test::expectRefusal(raytraceTool(),
                                     {"--all", (dir / "loop").string(), (dir / "results").string()},
                                     dir, {"loop", "symbolic links"}, dir / "results");
  EXPECT_EQ(r.err.find("not a folder"), std::string::npos) << test::describe(r);
}

TEST(RaytraceCli, RefusesBadCommandLines) {
  const auto dir = folderWithGoodScene();
  for (const std::vector<std::string>& args : {std::vector<std::string>{},
                                               {"only-one.sce"},
                                               {"--accel", "octree", "a.sce", "b.png"},
                                               {"--threads", "-3", "a.sce", "b.png"}}) {
    const test::ToolResult r = test::runTool(raytraceTool(), args, dir);
    ASSERT_TRUE(r.exited) << test::describe(r);
    EXPECT_NE(r.exitCode, 0) << test::describe(r);
  }
}

}  // namespace
}  // namespace meshtrace
