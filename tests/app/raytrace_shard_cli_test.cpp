// raytrace --all and --report with --shard I/N: four shares run side by
// side with GNU parallel write what one run writes (--report's once
// merged); a Slurm array task's index picks the same share; a malformed
// share, and a merge of shares that overlap or leave one out, are refused,
// leaving no folder behind.
#include <gtest/gtest.h>

#include <algorithm>
#include <sstream>
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

// report.csv without its seconds column (9th): run times differ between runs.
std::string rowsWithoutTimes(const std::filesystem::path& csv) {
  std::string out, line;
  std::istringstream in(test::readFileBytes(csv));
  while (std::getline(in, line)) {
    std::size_t start = 0;
    for (int comma = 0; comma < 8; ++comma) start = line.find(',', start) + 1;
    out += line.substr(0, start) + line.substr(line.find(',', start) + 1) + "\n";
  }
  return out;
}

TEST(RaytraceShard, FourReportSharesThroughGnuParallelMergeIntoOneRunsRows) {
  const auto dir = sevenScenes();
  std::vector<std::string> scenes;
  for (const char* name : {"s3.sce", "s0.sce", "s4.sce", "s1.sce", "s2.sce"})
    scenes.push_back((dir / "scenes" / name).string());
  std::vector<std::string> args = {"--quiet", "--threads", "1", "--report", (dir / "one").string()};
  args.insert(args.end(), scenes.begin(), scenes.end());
  const auto one = test::runTool(test::raytraceTool(), args, dir, 120.0);
  ASSERT_TRUE(one.exited && one.exitCode == 0) << test::describe(one);
  args = {
      "--halt", "now,fail=1", test::raytraceTool().string(), "--quiet", "--threads", "1", "--shard",
      "{}/4",   "--report",   (dir / "share{}").string()};
  args.insert(args.end(), scenes.begin(), scenes.end());
  for (const char* i : {":::", "0", "1", "2", "3"}) args.push_back(i);
  const auto shares = test::runTool("/usr/bin/parallel", args, dir, 240.0);
  ASSERT_TRUE(shares.exited && shares.exitCode == 0) << test::describe(shares);
  // Share 0/4 measured s0 and s4 of the sorted five.
  EXPECT_EQ(test::readFileBytes(dir / "share0" / "scenes.csv").find(",s1,"), std::string::npos);
  const auto merged = test::runTool(
      test::raytraceTool(),
      {"--report-merge", (dir / "merged").string(), (dir / "share2").string(),
       (dir / "share0").string(), (dir / "share3").string(), (dir / "share1").string()},
      dir);
  ASSERT_TRUE(merged.exited && merged.exitCode == 0) << test::describe(merged);
  const std::string rows = rowsWithoutTimes(dir / "one" / "report.csv");
  EXPECT_EQ(std::count(rows.begin(), rows.end(), '\n'), 1 + 5 * 15);  // 15 configurations each
  EXPECT_EQ(rowsWithoutTimes(dir / "merged" / "report.csv"), rows);
  EXPECT_EQ(test::listFolder(dir / "merged"), test::listFolder(dir / "one"));
  test::expectMentions(test::readFileBytes(dir / "merged" / "report.md"),
                       {"## s0", "## s4", "## Stability suite"});
  // The stability suite is the same for every share: only share 0 measures it.
  const std::string suite = test::readFileBytes(dir / "share0" / "stability.md");
  test::expectMentions(suite, {"Mrays/s"});
  EXPECT_EQ(test::readFileBytes(dir / "merged" / "stability.md"), suite);
  for (const char* other : {"share1", "share2", "share3"})
    test::expectMentions(test::readFileBytes(dir / other / "stability.md"),
                         {"Measured by share 0/4"});

  // Share 1 twice, then without share 3: refused, the output left alone.
  for (const std::vector<std::string>& given :
       {std::vector<std::string>{"share0", "share1", "share2", "share3", "share1"},
        std::vector<std::string>{"share0", "share1", "share2"}}) {
    std::vector<std::string> mergeArgs = {"--report-merge", (dir / "merged").string()};
    for (const std::string& g : given) mergeArgs.push_back((dir / g).string());
    const auto refused = test::runTool(test::raytraceTool(), mergeArgs, dir);
    EXPECT_TRUE(refused.exited && refused.exitCode == 1) << test::describe(refused);
    test::expectMentions(
        refused.err,
        {"error: --report-merge", given.size() == 5 ? "overlapping shares" : "incomplete",
         given.size() == 5 ? "share 1/4"
                           : "share 3/4 (" + (dir / "scenes" / "s3.sce").string() + ")"});
  }
  EXPECT_EQ(rowsWithoutTimes(dir / "merged" / "report.csv"), rows);
}

// A refused merge leaves no folder behind where there was none.
TEST(RaytraceShard, ARefusedMergeLeavesNoFolder) {
  const auto dir = test::scratchDir();
  std::filesystem::create_directory(dir / "share0");
  const auto r = test::runTool(
      test::raytraceTool(),
      {"--report-merge", (dir / "merged").string(), (dir / "share0").string()}, dir);
  EXPECT_TRUE(r.exited && r.exitCode == 1) << test::describe(r);
  test::expectMentions(r.err, {"error: --report-merge", "share.txt"});
  EXPECT_EQ(test::listFolder(dir), std::vector<std::string>{"share0"});
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
