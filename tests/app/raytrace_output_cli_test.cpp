// raytrace's outputs written whole or not at all, as root too: read-only
// folders and full disks (mounted for the run), a file size limit, a
// signal in the middle of the write, a symlink at the output's name, the
// longest legal name, and --report's files replaced together (and no folder
// left behind by a report that failed).
#include <gtest/gtest.h>
#include <signal.h>

#include "meshtrace/io/image.h"
#include "support/cli.h"
#include "support/files.h"
#include "support/mounts.h"
#include "support/paths.h"
#include "support/scene_snippets.h"

namespace meshtrace {
namespace {

using test::expectRefusedBeforeRendering;
using test::folderWithGoodScene;
using test::raytraceTool;
using test::renderArgs;

// Root writes through file permissions, so the folder is made read-only by
// a read-only mount, which stops root too.
TEST(RaytraceOutput, RefusesAReadOnlyFolderLeavingTheOldFile) {
  const auto dir = folderWithGoodScene();
  std::filesystem::create_directory(dir / "ro");
  test::writeFile(dir / "ro" / "out.png", test::kOldOutput);
  std::string refused;
  const auto r = test::runToolWithMounts(raytraceTool(), renderArgs(dir, "ro/out.png"), dir,
                                         test::readOnlyFolder(dir / "ro"), refused);
  MESHTRACE_SKIP_IF_MOUNTS_REFUSED(r, refused);
  EXPECT_TRUE(r->exited && r->exitCode == 1) << test::describe(*r);
  test::expectMentions(r->err, {"error", "out.png", "read-only"});
  expectRefusedBeforeRendering(*r);
  EXPECT_EQ(test::readFileBytes(dir / "ro" / "out.png"), test::kOldOutput);
  EXPECT_EQ(test::listFolder(dir / "ro"), std::vector<std::string>{"out.png"});
}

// A disk that fills up during the write: the error is seen, the old file
// stays and the temporary goes.
TEST(RaytraceOutput, AFullDiskLeavesTheOldOutputAndNoTemporary) {
  const auto dir = folderWithGoodScene();
  test::writeFile(dir / "good.sce",
                  "camera 0 0 5  0 0 0  0 1 0  45  400 300\n" + test::kSphereLine);
  std::filesystem::create_directory(dir / "full");
  std::filesystem::create_directory(dir / "after");
  test::writeFile(dir / "full" / "out.ppm", test::kOldOutput);
  std::string refused;
  // 64 KiB: room for the old file, not for the new one's 360 kB.
  const auto r =
      test::runToolWithMounts(raytraceTool(), renderArgs(dir, "full/out.ppm"), dir,
                              test::smallTmpfs(dir / "full", 64 << 10, dir / "after"), refused);
  MESHTRACE_SKIP_IF_MOUNTS_REFUSED(r, refused);
  EXPECT_TRUE(r->exited && r->exitCode == 1) << test::describe(*r);
  test::expectMentions(r->err, {"error", "out.ppm", "No space left"});
  EXPECT_EQ(test::readFileBytes(dir / "after" / "out.ppm"), test::kOldOutput);
  EXPECT_EQ(test::listFolder(dir / "after"), std::vector<std::string>{"out.ppm"});
}

// `ulimit -f` in the user's shell: SIGXFSZ at its default action, which
// would kill a tool that did not handle it.
TEST(RaytraceOutput, AFileSizeLimitLeavesTheOldOutputAndNoTemporary) {
  const auto dir = folderWithGoodScene();
  test::writeFile(dir / "good.sce",
                  "camera 0 0 5  0 0 0  0 1 0  45  200 150\n" + test::kSphereLine);
  test::writeFile(dir / "out.ppm", test::kOldOutput);
  // Room for what the tool prints (the limit holds for its stdout and
  // stderr files too), not for the 90 kB image.
  const auto r =
      test::runTool(raytraceTool(), renderArgs(dir, "out.ppm"), dir, {.fileSize = 16384});
  EXPECT_TRUE(r.exited && r.exitCode == 1) << test::describe(r);
  test::expectMentions(r.err, {"error", "out.ppm", "file size limit"});
  EXPECT_EQ(test::readFileBytes(dir / "out.ppm"), test::kOldOutput);
  EXPECT_EQ(test::listFolder(dir), (std::vector<std::string>{"good.sce", "out.ppm", "tri.off"}));
}

// SIGINT or SIGTERM sent the moment the temporary appears: the tool ends by
// that signal, the temporary goes with it and the old output stays.
void expectSignalDuringTheWriteLeavesTheOldOutput(int signal) {
  const auto dir = test::scratchDir();
  // 12 MB of PPM: the write takes milliseconds, far longer than the
  // signal's way from the test to the tool.
  test::writeFile(dir / "big.sce", "camera 0 0 5  0 0 0  0 1 0  45  2048 2048\n");
  std::filesystem::create_directory(dir / "out");
  test::writeFile(dir / "out" / "big.ppm", test::kOldOutput);
  const auto r = test::runTool(raytraceTool(),
                               {(dir / "big.sce").string(), (dir / "out" / "big.ppm").string()},
                               dir, {.signalOnTemporary = signal, .watch = dir / "out"});
  ASSERT_TRUE(r.signalSent) << "no temporary seen: " << test::describe(r);
  EXPECT_FALSE(r.exited) << "the tool finished before the signal came: " << test::describe(r);
  EXPECT_EQ(r.signal, signal) << test::describe(r);
  EXPECT_EQ(test::readFileBytes(dir / "out" / "big.ppm"), test::kOldOutput);
  EXPECT_EQ(test::listFolder(dir / "out"), std::vector<std::string>{"big.ppm"});
}

TEST(RaytraceOutput, SigintDuringTheWriteLeavesTheOldOutputAndNoTemporary) {
  expectSignalDuringTheWriteLeavesTheOldOutput(SIGINT);
}

TEST(RaytraceOutput, SigtermDuringTheWriteLeavesTheOldOutputAndNoTemporary) {
  expectSignalDuringTheWriteLeavesTheOldOutput(SIGTERM);
}

// A symlink at the output's name is replaced by the image; the file it
// pointed to is never written.
TEST(RaytraceOutput, ReplacesASymlinkedOutputWithoutWritingItsTarget) {
  const auto dir = folderWithGoodScene();
  test::writeFile(dir / "precious", test::kOldOutput);
  std::filesystem::create_symlink("precious", dir / "out.png");
  test::expectSuccess(raytraceTool(), renderArgs(dir, "out.png"), dir);
  EXPECT_EQ(test::readFileBytes(dir / "precious"), test::kOldOutput);
  EXPECT_FALSE(std::filesystem::is_symlink(dir / "out.png"));
  EXPECT_EQ(readImage(dir / "out.png").width, 8);
}

TEST(RaytraceOutput, WritesAnOutputNamedWithTheLongestLegalName) {
  const auto dir = folderWithGoodScene();
  const std::string name = std::string(251, 'n') + ".png";  // 255 bytes
  test::expectSuccess(raytraceTool(), renderArgs(dir, name), dir);
  EXPECT_EQ(readImage(dir / name).width, 8);
  const auto r = test::expectRefusal(raytraceTool(), renderArgs(dir, "n" + name), dir,
                                     {"256 bytes", "255"}, dir / ("n" + name));
  expectRefusedBeforeRendering(r);
}

// --report DIR with a tiny sphere scene: writes report.md, report.csv and
// the scene's plot.
std::vector<std::string> reportArgs(const std::filesystem::path& dir,
                                    const std::filesystem::path& reportDir) {
  test::writeFile(dir / "tiny.sce", test::kCameraLine + "light 0 0 10 1 1 1\n" + test::kSphereLine);
  return {"--threads", "2", "--report", reportDir.string(), (dir / "tiny.sce").string()};
}

TEST(RaytraceOutput, ReportReplacesEveryFileAndLeavesNoTemporary) {
  const auto dir = test::scratchDir();
  std::filesystem::create_directory(dir / "report");
  for (const char* name : {"report.md", "report.csv", "plot_tiny.png"})
    test::writeFile(dir / "report" / name, test::kOldOutput);
  const auto r = test::expectSuccess(raytraceTool(), reportArgs(dir, dir / "report"), dir);
  test::expectMentions(r.out, {"wrote", "report.md"});
  EXPECT_EQ(test::listFolder(dir / "report"),
            (std::vector<std::string>{"plot_tiny.gp", "plot_tiny.png", "report.csv", "report.md",
                                      "scenes.csv", "share.txt", "stability.md"}));
  EXPECT_EQ(readImage(dir / "report" / "plot_tiny.png").width, 1100);
  test::expectMentions(test::readFileBytes(dir / "report" / "report.md"),
                       {"# Error against run time", "## tiny", "## Stability suite"});
  test::expectMentions(test::readFileBytes(dir / "report" / "report.csv"),
                       {"scene,group,config", "tiny,progressive"});
}

// The report's files are all written before any replaces its old version:
// a disk that fills up leaves the old report whole.
TEST(RaytraceOutput, ReportIntoAFullDiskKeepsTheOldReport) {
  const auto dir = test::scratchDir();
  std::filesystem::create_directory(dir / "report");
  std::filesystem::create_directory(dir / "after");
  test::writeFile(dir / "report" / "report.md", test::kOldOutput);
  test::writeFile(dir / "report" / "report.csv", test::kOldOutput);
  std::string refused;
  // Two pages: the old files fill them.
  const auto r =
      test::runToolWithMounts(raytraceTool(), reportArgs(dir, dir / "report"), dir,
                              test::smallTmpfs(dir / "report", 8192, dir / "after"), refused);
  MESHTRACE_SKIP_IF_MOUNTS_REFUSED(r, refused);
  EXPECT_TRUE(r->exited && r->exitCode == 1) << test::describe(*r);
  test::expectMentions(r->err, {"error", "No space left"});
  EXPECT_EQ(r->out.find("wrote"), std::string::npos) << test::describe(*r);
  EXPECT_EQ(test::readFileBytes(dir / "after" / "report.md"), test::kOldOutput);
  EXPECT_EQ(test::readFileBytes(dir / "after" / "report.csv"), test::kOldOutput);
  EXPECT_EQ(test::listFolder(dir / "after"), (std::vector<std::string>{"report.csv", "report.md"}));
}

// Refused before the measurements, which take a while.
TEST(RaytraceOutput, ReportRefusesAReadOnlyFolderBeforeMeasuring) {
  const auto dir = test::scratchDir();
  std::filesystem::create_directory(dir / "report");
  std::string refused;
  const auto r = test::runToolWithMounts(raytraceTool(), reportArgs(dir, dir / "report"), dir,
                                         test::readOnlyFolder(dir / "report"), refused);
  MESHTRACE_SKIP_IF_MOUNTS_REFUSED(r, refused);
  EXPECT_TRUE(r->exited && r->exitCode == 1) << test::describe(*r);
  test::expectMentions(r->err, {"error", "report", "read-only"});
  EXPECT_EQ(r->out.find("measured"), std::string::npos) << test::describe(*r);
  EXPECT_TRUE(test::listFolder(dir / "report").empty());
}

// A run that fails before writing its report leaves no folder it made (a
// scene that does not load; the folders a/b both new), and an empty
// folder that was there stays.
TEST(RaytraceOutput, AFailedReportLeavesNoFolderItMade) {
  const auto dir = test::scratchDir();
  test::writeFile(dir / "broken.sce", "bogus\n");
  for (const auto& reportDir : {dir / "a" / "b", dir / "there"}) {
    SCOPED_TRACE(reportDir.string());
    if (reportDir.filename() == "there") std::filesystem::create_directory(reportDir);
    const auto r = test::runTool(
        raytraceTool(), {"--report", reportDir.string(), (dir / "broken.sce").string()}, dir);
    EXPECT_TRUE(r.exited && r.exitCode == 1) << test::describe(r);
    test::expectMentions(r.err, {"broken.sce:1"});
  }
  EXPECT_EQ(test::listFolder(dir), (std::vector<std::string>{"broken.sce", "there"}));
  EXPECT_TRUE(test::listFolder(dir / "there").empty());
}

}  // namespace
}  // namespace meshtrace
