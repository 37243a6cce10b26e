// Progress lines: raytrace --all shows what it is rendering, how far it is
// and the time left on a terminal (a pseudo-terminal made by script(1)),
// and nothing of it when stderr is a file or with --quiet.
#include <gtest/gtest.h>

#include <string>

#include "support/cli.h"
#include "support/files.h"

namespace meshtrace {
namespace {

// A folder of two scenes, and the `raytrace --all` command line over it.
struct TwoScenes {
  std::filesystem::path dir = test::folderWithGoodScene();
  TwoScenes() { test::writeFile(dir / "second.sce", test::readFileBytes(dir / "good.sce")); }
  std::string command(const std::string& options) const {
    return test::raytraceTool().string() + " " + options + " --all " + dir.string() + " " +
           (dir / "out").string();
  }
};

TEST(RaytraceProgress, ShowsEachSceneAndTheTimeLeftOnATerminal) {
  const TwoScenes scenes;
  const auto r = test::runOnTerminal(scenes.command(""), scenes.dir);
  ASSERT_TRUE(r.exited && r.exitCode == 0) << test::describe(r);
  EXPECT_NE(r.out.find("scene 1/2 (good.sce)\r"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("scene 2/2 (second.sce), "), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" left"), std::string::npos) << r.out;
}

TEST(RaytraceProgress, IsQuietWithQuietOnATerminal) {
  const TwoScenes scenes;
  const auto r = test::runOnTerminal(scenes.command("--quiet"), scenes.dir);
  ASSERT_TRUE(r.exited && r.exitCode == 0) << test::describe(r);
  EXPECT_NE(r.out.find("wrote"), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("scene 1/2"), std::string::npos) << r.out;
}

TEST(RaytraceProgress, IsQuietWhenNotATerminal) {
  const TwoScenes scenes;
  const auto r =
      test::runTool(test::raytraceTool(),
                    {"--all", scenes.dir.string(), (scenes.dir / "out").string()}, scenes.dir);
  ASSERT_TRUE(r.exited && r.exitCode == 0) << test::describe(r);
  EXPECT_EQ(r.err.find("scene 1/2"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\r'), std::string::npos) << r.err;
}

}  // namespace
}  // namespace meshtrace
