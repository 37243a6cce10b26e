// The raytrace tool as a user runs it: renders, refuses bad input cleanly
// and never leaves a broken or half-written output file.
#include <gtest/gtest.h>
#include <signal.h>

#include <fstream>

#include "meshtrace/io/image.h"
#include "support/cli.h"
#include "support/files.h"
#include "support/mounts.h"
#include "support/paths.h"
#include "support/scene_snippets.h"

namespace meshtrace {
namespace {

using test::raytraceTool;

class RaytraceBadInput : public ::testing::TestWithParam<test::BadInput> {};

TEST_P(RaytraceBadInput, ExitsWithAnErrorNamingTheFileAndLeavesTheOutput) {
  test::expectRefusesBadInput(raytraceTool(), GetParam());
}

INSTANTIATE_TEST_SUITE_P(Cases, RaytraceBadInput, ::testing::ValuesIn(test::badInputs()),
                         [](const auto& info) { return info.param.name; });

// A scratch folder holding good.sce (a sphere and a mesh) and its mesh.
std::filesystem::path folderWithGoodScene() {
  const auto dir = test::scratchDir();
  test::writeFile(dir / "tri.off", test::kTriangleOff);
  test::writeFile(dir / "good.sce", test::kCameraLine + "light 0 0 10 1 1 1\n" + test::kSphereLine +
                                        "mesh tri.off PHONG " + test::kMaterial + "\n");
  return dir;
}

std::vector<std::string> renderArgs(const std::filesystem::path& dir, const std::string& out) {
  return {(dir / "good.sce").string(), (dir / out).string()};
}

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

// An output that cannot be written is refused before the scene is loaded
// and rendered, not after a long render.
void expectRefusedBeforeRendering(const test::ToolResult& r) {
  EXPECT_EQ(r.out.find("loaded"), std::string::npos) << test::describe(r);
  EXPECT_EQ(r.out.find("rendered"), std::string::npos) << test::describe(r);
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

// Root writes through file permissions, so the folder is made read-only by
// a read-only mount, which stops root too.
TEST(RaytraceCli, RefusesAReadOnlyFolderLeavingTheOldFile) {
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
TEST(RaytraceCli, AFullDiskLeavesTheOldOutputAndNoTemporary) {
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
TEST(RaytraceCli, AFileSizeLimitLeavesTheOldOutputAndNoTemporary) {
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

TEST(RaytraceCli, SigintDuringTheWriteLeavesTheOldOutputAndNoTemporary) {
  expectSignalDuringTheWriteLeavesTheOldOutput(SIGINT);
}

TEST(RaytraceCli, SigtermDuringTheWriteLeavesTheOldOutputAndNoTemporary) {
  expectSignalDuringTheWriteLeavesTheOldOutput(SIGTERM);
}

// A symlink at the output's name is replaced by the image; the file it
// pointed to is never written.
TEST(RaytraceCli, ReplacesASymlinkedOutputWithoutWritingItsTarget) {
  const auto dir = folderWithGoodScene();
  test::writeFile(dir / "precious", test::kOldOutput);
  std::filesystem::create_symlink("precious", dir / "out.png");
  test::expectSuccess(raytraceTool(), renderArgs(dir, "out.png"), dir);
  EXPECT_EQ(test::readFileBytes(dir / "precious"), test::kOldOutput);
  EXPECT_FALSE(std::filesystem::is_symlink(dir / "out.png"));
  EXPECT_EQ(readImage(dir / "out.png").width, 8);
}

TEST(RaytraceCli, WritesAnOutputNamedWithTheLongestLegalName) {
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

TEST(RaytraceCli, ReportReplacesEveryFileAndLeavesNoTemporary) {
  const auto dir = test::scratchDir();
  std::filesystem::create_directory(dir / "report");
  for (const char* name : {"report.md", "report.csv", "plot_tiny.png"})
    test::writeFile(dir / "report" / name, test::kOldOutput);
  const auto r = test::expectSuccess(raytraceTool(), reportArgs(dir, dir / "report"), dir);
  test::expectMentions(r.out, {"wrote", "report.md"});
  EXPECT_EQ(test::listFolder(dir / "report"),
            (std::vector<std::string>{"plot_tiny.png", "report.csv", "report.md"}));
  EXPECT_EQ(readImage(dir / "report" / "plot_tiny.png").width, 640);
  test::expectMentions(test::readFileBytes(dir / "report" / "report.md"),
                       {"# Error against run time", "## tiny", "## Stability suite"});
  test::expectMentions(test::readFileBytes(dir / "report" / "report.csv"),
                       {"scene,group,config", "tiny,progressive"});
}

// The report's files are all written before any replaces its old version:
// a disk that fills up leaves the old report whole.
TEST(RaytraceCli, ReportIntoAFullDiskKeepsTheOldReport) {
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
TEST(RaytraceCli, ReportRefusesAReadOnlyFolderBeforeMeasuring) {
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

// Files are checked as they stream: the tool finds the mistake on line 2
// of a 250 MB scene within an address space of 64 MB (which the tiny
// scene's whole run fits in), where reading the file first took 3.3 GB.
TEST(RaytraceCli, FindsAMistakeEarlyInAHugeSceneInLittleMemory) {
  const auto dir = folderWithGoodScene();
  constexpr rlim_t kAddressSpace = rlim_t{64} << 20;
  test::expectSuccess(raytraceTool(), renderArgs(dir, "out.png"), dir);
  const auto fits = test::runTool(raytraceTool(), renderArgs(dir, "out.png"), dir,
                                  {.addressSpace = kAddressSpace});
  ASSERT_TRUE(fits.exited && fits.exitCode == 0)
      << "the tiny scene must fit: " << test::describe(fits);

  const auto huge = test::writeFile(dir / "huge.sce", test::kCameraLine + "bogus 1 2 3\n");
  std::filesystem::resize_file(huge, 250'000'000);  // the rest never gets read
  const auto r = test::runTool(raytraceTool(), {huge.string(), (dir / "out.png").string()}, dir,
                               {.addressSpace = kAddressSpace});
  std::filesystem::remove(huge);
  EXPECT_TRUE(r.exited && r.exitCode == 1) << test::describe(r);
  test::expectMentions(r.err, {"huge.sce:2", "unknown keyword 'bogus'"});
}

// A line of 100 MB (a comment) costs no more memory than a short one.
TEST(RaytraceCli, ReadsPastAHundredMegabyteLineInLittleMemory) {
  const auto dir = folderWithGoodScene();
  const auto file = dir / "long.sce";
  {
    std::ofstream out(file, std::ios::binary);
    out << test::kCameraLine << "# " << std::string(100'000'000, 'x') << "\nbogus\n";
    ASSERT_TRUE(out.flush());
  }
  const auto r = test::runTool(raytraceTool(), {file.string(), (dir / "out.png").string()}, dir,
                               {.addressSpace = rlim_t{64} << 20});
  std::filesystem::remove(file);
  EXPECT_TRUE(r.exited && r.exitCode == 1) << test::describe(r);
  test::expectMentions(r.err, {"long.sce:3", "unknown keyword 'bogus'"});
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
