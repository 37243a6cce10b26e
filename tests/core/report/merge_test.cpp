// mergeReports: the shares of a run, each written by writeReport, merge
// into the files one run writes; shares that overlap, leave a share out,
// belong to another run or are damaged are refused with the file named.
#include "meshtrace/report/merge.h"

#include <gtest/gtest.h>

#include "meshtrace/report/report.h"
#include "support/files.h"
#include "support/paths.h"

namespace meshtrace {
namespace {

// A measured scene as measureScene would return it, its numbers made up
// (with more digits than the CSV keeps) so that no rendering is needed.
SceneReport madeUpScene(const std::string& name, double seed) {
  SceneReport s;
  s.scene = "scenes/" + name + "/" + name + ".sce";
  s.reference = name + ".png (our expected image)";
  s.converged = "our render with 256 samples/pixel";
  s.jpegNoiseRmse = 0.123456789 * seed;
  s.samplesSlope = -0.51234567 * seed;
  s.leftOut = {"no reflection rays: depth is 0", "a reason, with a comma and \"quotes\""};
  const std::vector<ReportConfig> configs = {
      {"progressive", "coarse 1/4", TraceOptions{}, 4, 1},
      {"samples", "4 samples/pixel", TraceOptions{}, 1, 4},
      {"samples", "16 samples/pixel", TraceOptions{}, 1, 16},
      {"accel", "watertight double none", TraceOptions{AccelMethod::None}, 1, 1}};
  for (std::size_t i = 0; i < configs.size(); ++i) {
    ReportRow r{configs[i]};
    r.seconds = 0.0123456789 * (i + 1) * seed;
    r.rmse = 1.23456789 * (i + 1) * seed;
    r.psnr = 30.123456 + i;
    r.hitDiffers = 0.001234567 * i;
    r.maxNormalDegrees = 0.5 * i;
    r.against = configs[i].group == "samples" ? "converged" : "reference";
    s.rows.push_back(r);
  }
  return s;
}

const std::vector<SceneReport> kRun = {madeUpScene("a", 1), madeUpScene("b", 2),
                                       madeUpScene("c", 3)};

ReportShare shareOf(std::size_t index, std::size_t count) {
  ReportShare share{Shard{index, count}, {}};
  for (const SceneReport& s : kRun) share.scenes.push_back(s.scene);
  return share;
}

// Writes share `index` of `count` of kRun into dir/share<index> and returns it.
std::filesystem::path writeShare(const std::filesystem::path& dir, std::size_t index,
                                 std::size_t count) {
  std::vector<SceneReport> mine;
  for (std::size_t i = 0; i < kRun.size(); ++i)
    if (i % count == index) mine.push_back(kRun[i]);
  const auto out = dir / ("share" + std::to_string(index));
  writeReport(out, mine, "stability of share " + std::to_string(index), shareOf(index, count));
  return out;
}

std::string mergeError(const std::filesystem::path& out,
                       const std::vector<std::filesystem::path>& shares) {
  try {
    mergeReports(out, shares);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(ReportMerge, FourSharesMergeIntoTheFilesOfOneRun) {
  const auto dir = test::scratchDir();
  writeReport(dir / "one", kRun, "stability of share 0");
  std::vector<std::filesystem::path> shares;
  for (std::size_t i = 0; i < 4; ++i) shares.push_back(writeShare(dir, i, 4));
  mergeReports(dir / "merged", shares);
  // The data, the report and the plots' scripts: byte for byte.
  for (const char* name : {"report.csv", "scenes.csv", "share.txt", "stability.md", "report.md",
                           "plot_a.gp", "plot_b.gp", "plot_c.gp"})
    EXPECT_EQ(test::readFileBytes(dir / "merged" / name), test::readFileBytes(dir / "one" / name))
        << name;
  EXPECT_EQ(test::listFolder(dir / "merged"), test::listFolder(dir / "one"));
}

TEST(ReportMerge, RefusesOverlappingShares) {
  const auto dir = test::scratchDir();
  const auto s0 = writeShare(dir, 0, 2), s1 = writeShare(dir, 1, 2);
  const std::string error = mergeError(dir / "merged", {s0, s1, s1});
  EXPECT_NE(error.find("overlapping shares"), std::string::npos) << error;
  EXPECT_NE(error.find("share 1/2"), std::string::npos) << error;
  EXPECT_FALSE(std::filesystem::exists(dir / "merged"));
}

TEST(ReportMerge, RefusesAMissingShareNamingItsScenes) {
  const auto dir = test::scratchDir();
  const auto s0 = writeShare(dir, 0, 3), s2 = writeShare(dir, 2, 3);
  const std::string error = mergeError(dir / "merged", {s2, s0});
  EXPECT_NE(error.find("incomplete: no folder holds share 1/3 (scenes/b/b.sce)"), std::string::npos)
      << error;
  EXPECT_FALSE(std::filesystem::exists(dir / "merged"));
}

TEST(ReportMerge, RefusesSharesOfAnotherRun) {
  const auto dir = test::scratchDir();
  const auto s0 = writeShare(dir, 0, 2);
  writeReport(dir / "other", {kRun[1]}, "stability", ReportShare{Shard{1, 2}, {"x.sce", "y.sce"}});
  const std::string error = mergeError(dir / "merged", {s0, dir / "other"});
  EXPECT_NE(error.find("other/share.txt"), std::string::npos) << error;
  EXPECT_NE(error.find("not of the same run"), std::string::npos) << error;
}

// A share whose files lack a scene it owns (its run stopped) or hold one
// it does not own is refused: the merge would otherwise drop or double it.
TEST(ReportMerge, RefusesAShareWhoseScenesAreNotItsShare) {
  const auto dir = test::scratchDir();
  const auto s0 = writeShare(dir, 0, 2);
  writeReport(dir / "short", {}, "stability", shareOf(1, 2));
  std::string error = mergeError(dir / "merged", {s0, dir / "short"});
  EXPECT_NE(error.find("short/scenes.csv"), std::string::npos) << error;
  EXPECT_NE(error.find("lacks scenes/b/b.sce"), std::string::npos) << error;
  writeReport(dir / "wrong", {kRun[0]}, "stability", shareOf(1, 2));
  error = mergeError(dir / "merged", {s0, dir / "wrong"});
  EXPECT_NE(error.find("holds scenes/a/a.sce, which is not in share 1/2"), std::string::npos)
      << error;
}

TEST(ReportMerge, RefusesADamagedShareNamingTheFileAndLine) {
  const auto dir = test::scratchDir();
  const auto s0 = writeShare(dir, 0, 2), s1 = writeShare(dir, 1, 2);
  const std::string csv = test::readFileBytes(s1 / "report.csv");
  // Line 3, the second row of scene b: its rmse (the 10th field) not a number.
  std::string damaged = csv;
  std::size_t at = damaged.find('\n', damaged.find('\n') + 1) + 1;
  for (int comma = 0; comma < 9; ++comma) at = damaged.find(',', at) + 1;
  damaged.insert(at, "x");
  test::writeFile(s1 / "report.csv", damaged);
  std::string error = mergeError(dir / "merged", {s0, s1});
  EXPECT_NE(error.find("report.csv:3: rmse is 'x4.9383', not a number"), std::string::npos)
      << error;
  // A quote never closed, after the header and four rows: the line it opened on.
  test::writeFile(s1 / "report.csv", csv + "b,\"samples,1\n");
  error = mergeError(dir / "merged", {s0, s1});
  EXPECT_NE(error.find("report.csv:6: a quoted field is never closed"), std::string::npos) << error;
  // A row with a field too many; a file that is not the report's at all.
  test::writeFile(s1 / "report.csv",
                  csv + "b,samples,1,bvh,watertight,double,1,1,1,1,1,1,1,x,y,z\n");
  error = mergeError(dir / "merged", {s0, s1});
  EXPECT_NE(error.find("report.csv:6: 16 fields where the header has 15"), std::string::npos)
      << error;
  test::writeFile(s1 / "report.csv", csv);
  test::writeFile(s1 / "scenes.csv", std::string("\x89PNG\r\n\x1a\n,\"\"\n", 12));
  error = mergeError(dir / "merged", {s0, s1});
  EXPECT_NE(error.find("scenes.csv:1: the header is not the report's"), std::string::npos) << error;
  std::filesystem::remove(s1 / "share.txt");
  error = mergeError(dir / "merged", {s0, s1});
  EXPECT_NE(error.find("share.txt"), std::string::npos) << error;
  EXPECT_FALSE(std::filesystem::exists(dir / "merged"));
}

}  // namespace
}  // namespace meshtrace
