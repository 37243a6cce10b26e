// raytrace --all --shard I/N: four shares run side by side with GNU
// parallel write what one run writes; a Slurm array task's index picks the
// same share; a malformed share is refused.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/cli.h"
#include "support/files.h"
#include "support/paths.h"

namespace meshtrace {
namespace {

// Seven scenes that render to different images (their backgrounds differ).
std::filesystem::path sevenScenes() {
  const auto dir = test::folderWithGoodScene();
  const std::string good = test::readFileBytes(dir / "good.sce");
  std::filesystem::remove(dir / "good.sce");
  std::filesystem::create_directories(dir / "scenes");
  const char* const backgrounds[] = {"0.0", "0.1", "0.2", "0.3", "0.4", "0.5", "0.6"};
  for (int i = 0; i < 7; ++i) {
    std::string name = "s";  // built in steps: GCC 12 warns wrongly about "s" + string
    name += std::to_string(i);
    name += ".sce";
    test::writeFile(dir / "scenes" / name,
                    std::string("background ") + backgrounds[i] + " 0.2 0.3\n" + good);
  }
  std::filesystem::copy_file(dir / "tri.off", dir / "scenes" / "tri.off");
  return dir;
}

// Every file of `dir`, name and bytes.
std::vector<std::pair<std::string, std::string>> contents(const std::filesystem::path& dir) {
  std::vector<std::pair<std::string, std::string>> out;
  for (const std::string& name : test::listFolder(dir))
    out.emplace_back(name, test::readFileBytes(dir / name));
  return out;
}

TEST(RaytraceShard, FourSharesThroughGnuParallelWriteWhatOneRunWrites) {
  const auto dir = sevenScenes();
  const auto scenes = (dir / "scenes").string();
  const auto one =
      test::runTool(test::raytraceTool(), {"--all", scenes, (dir / "one").string()}, dir);
  ASSERT_TRUE(one.exited && one.exitCode == 0) << test::describe(one);
  const auto shards =
      test::runTool("/usr/bin/parallel",
                    {"--halt", "now,fail=1", test::raytraceTool().string(), "--shard", "{}/4",
                     "--all", scenes, (dir / "shards").string(), ":::", "0", "1", "2", "3"},
                    dir, 120.0);
  ASSERT_TRUE(shards.exited && shards.exitCode == 0) << test::describe(shards);
  const auto expected = contents(dir / "one");
  ASSERT_EQ(expected.size(), 7u);
  EXPECT_TRUE(contents(dir / "shards") == expected);
  // Each share rendered its own scenes: 2, 2, 2 and 1 of the 7.
  EXPECT_NE(shards.out.find("(share 3/4 of 7 scenes)"), std::string::npos) << shards.out;
}

TEST(RaytraceShard, ASlurmArrayTaskRunsItsShare) {
  const auto dir = sevenScenes();
  const auto scenes = (dir / "scenes").string();
  const auto r = test::runTool(
      "/usr/bin/env",
      {"SLURM_ARRAY_TASK_ID=11", "SLURM_ARRAY_TASK_MIN=10", "SLURM_ARRAY_TASK_COUNT=3",
       test::raytraceTool().string(), "--all", scenes, (dir / "out").string()},
      dir);
  ASSERT_TRUE(r.exited && r.exitCode == 0) << test::describe(r);
  // Share 1/3: the scenes at indices 1 and 4 of s0..s6.
  EXPECT_EQ(test::listFolder(dir / "out"), (std::vector<std::string>{"s1.png", "s4.png"}));
}

TEST(RaytraceShard, RefusesAMalformedShare) {
  const auto dir = sevenScenes();
  for (const char* bad : {"4/4", "1/0", "x/2", "1", "-1/2"}) {
    const auto r = test::runTool(
        test::raytraceTool(),
        {"--shard", bad, "--all", (dir / "scenes").string(), (dir / "out").string()}, dir);
    EXPECT_TRUE(r.exited && r.exitCode == 2) << bad << test::describe(r);
    EXPECT_NE(r.err.find("--shard"), std::string::npos) << r.err;
  }
}

}  // namespace
}  // namespace meshtrace
