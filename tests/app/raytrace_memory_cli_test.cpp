// Memory as a checked resource in the tools: a scene's needs are planned
// before they are allocated and refused beyond --max-memory, naming the
// phase; under any address-space limit the tools end with a clean error,
// never an abort.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <set>
#include <string>

#include "support/cli.h"
#include "support/files.h"
#include "support/paths.h"
#include "support/scene_snippets.h"

namespace meshtrace {
namespace {

using test::debugAabbTool;
using test::folderWithGoodScene;
using test::raytraceTool;
using test::renderArgs;

constexpr rlim_t kMiB = rlim_t{1} << 20;

// Our knot mesh (106,496 triangles) seen in a tiny image: the mesh and its
// BVH are what the run needs.
std::filesystem::path knotScene(const std::filesystem::path& dir, int width = 4, int height = 3) {
  return test::writeFile(dir / "knot.sce",
                         "camera 0 2.4 7  0 1.2 0  0 1 0  38  " + std::to_string(width) + " " +
                             std::to_string(height) + "\nlight 0 5 5  1 1 1\nmesh " +
                             (test::sourceDir() / "scenes" / "knot" / "knot.off").string() +
                             " FLAT " + test::kMaterial + "\n");
}

std::vector<std::string> withArgs(std::vector<std::string> options,
                                  const std::filesystem::path& scene,
                                  const std::filesystem::path& out) {
  options.push_back(scene.string());
  options.push_back(out.string());
  return options;
}

// The bytes --stats prints after `label` in megabytes ("the BVH's build
// 15 MB"), or -1 where the output does not have it.
double statsBytes(const std::string& out, const std::string& label) {
  const std::size_t at = out.find(label);
  if (at == std::string::npos) return -1.0;
  double mb = 0.0;
  std::sscanf(out.c_str() + at + label.size(), "%lf MB", &mb);
  return mb * 1048576.0;
}

// "memory planned: ... (the BVH's build 15 MB, ...)": the build's plan.
double plannedBuildBytes(const std::string& out) { return statsBytes(out, "the BVH's build "); }

// Each phase refuses before it allocates: the mesh arrays while they load
// (about 5 MB), the BVH before it is built (planned at 15 MB).
TEST(RaytraceMemory, RefusesBeyondMaxMemoryNamingThePhase) {
  const auto dir = test::scratchDir();
  const auto scene = knotScene(dir);
  const auto out = dir / "out.png";
  const auto load =
      test::expectRefusal(raytraceTool(), withArgs({"--max-memory", "2M"}, scene, out), dir,
                          {"knot.sce", "cannot load", "knot.off", "--max-memory"}, out);
  EXPECT_EQ(load.out.find("loaded"), std::string::npos) << test::describe(load);
  const auto build =
      test::expectRefusal(raytraceTool(), withArgs({"--max-memory", "10M"}, scene, out), dir,
                          {"cannot build the BVH of 106496 triangles", "10 MB"}, out);
  EXPECT_EQ(build.out.find("built"), std::string::npos) << test::describe(build);
  test::expectSuccess(raytraceTool(), withArgs({"--max-memory", "64M"}, scene, out), dir);
}

TEST(RaytraceMemory, RefusesAMaxMemoryThatIsNoSize) {
  const auto dir = test::scratchDir();
  const auto r = test::runTool(
      raytraceTool(), withArgs({"--max-memory", "lots"}, knotScene(dir), dir / "o.png"), dir);
  EXPECT_TRUE(r.exited && r.exitCode == 2) << test::describe(r);
  test::expectMentions(r.err, {"--max-memory", "'lots'", "not a size"});
}

// The tool's own peak resident memory, as its --stats prints it (the
// kernel's count; a parent's rusage of a forked child would also hold the
// test process's memory at the fork).
double peakResidentBytes(const std::string& out) {
  return statsBytes(out, "peak resident memory so far: ");
}

// The plan of the BVH's build covers what the build adds to the run's
// resident memory (measured against brute force, which builds nothing),
// and is not a wild overestimate of it.
TEST(RaytraceMemory, TheBvhPlanCoversWhatTheBuildTakes) {
  if (test::kBuiltWithAsan)
    GTEST_SKIP() << "AddressSanitizer's redzones and quarantine change resident memory: the "
                    "plan is measured in the build without it";
  const auto dir = test::scratchDir();
  const auto scene = knotScene(dir);
  const auto none = test::expectSuccess(
      raytraceTool(), withArgs({"--stats", "--accel", "none"}, scene, dir / "a.png"), dir);
  const auto bvh =
      test::expectSuccess(raytraceTool(), withArgs({"--stats"}, scene, dir / "b.png"), dir);
  const double planned = plannedBuildBytes(bvh.out);
  ASSERT_GT(peakResidentBytes(none.out), 0.0) << none.out;
  ASSERT_GT(peakResidentBytes(bvh.out), 0.0) << bvh.out;
  const double taken = peakResidentBytes(bvh.out) - peakResidentBytes(none.out);
  ASSERT_GT(planned, 0.0) << bvh.out;
  EXPECT_GT(taken, 0.0);
  EXPECT_LE(taken, planned) << "the build took more than planned";
  EXPECT_LE(planned, 3.0 * taken) << "the plan is far above what the build takes";
}

// The phase that fails and how the run ends, for each limit below.
struct LimitedRun {
  rlim_t addressSpace;
  test::ToolResult result;
};

// Whatever the address-space limit, with the default memory limit (planned
// from what the address space leaves) or with the plan switched off
// (--max-memory 1T, so that allocations fail for real): an exit, not a
// signal, and when it fails, a message about memory. Both the load and
// the build fail at some limit, and a generous one renders.
TEST(RaytraceMemory, NeverAbortsUnderAnAddressSpaceLimit) {
  MESHTRACE_SKIP_ADDRESS_LIMITS_UNDER_ASAN();
  const auto dir = test::scratchDir();
  const auto scene = knotScene(dir);
  for (const bool plan : {true, false}) {
    std::set<std::string> failedIn;
    bool rendered = false;
    // From 24 MB: below about 22 MB the tool's libraries (OpenEXR and
    // OpenMesh among them) leave too little to read the scene file at all,
    // before any plan could refuse it.
    for (const rlim_t mb : {24, 32, 40, 48, 56, 64, 80, 96, 128, 160, 256}) {
      std::vector<std::string> options;
      if (!plan) options = {"--max-memory", "1T"};
      const auto r = test::runTool(raytraceTool(), withArgs(options, scene, dir / "out.png"), dir,
                                   {.addressSpace = mb * kMiB});
      SCOPED_TRACE(std::to_string(mb) + " MB of address space, " +
                   (plan ? "planned" : "not planned") + ": " + test::describe(r));
      ASSERT_TRUE(r.exited) << "killed by a signal";
      if (r.exitCode == 0) {
        rendered = true;
        continue;
      }
      EXPECT_EQ(r.exitCode, 1);
      EXPECT_NE(r.err.find("memory"), std::string::npos);
      EXPECT_NE(r.err.find(plan ? "over the limit" : "not enough memory"), std::string::npos);
      for (const char* phase : {"load", "build", "render", "write"})
        if (r.err.find(std::string(plan ? "cannot " : "memory to ") + phase) != std::string::npos)
          failedIn.insert(phase);
    }
    EXPECT_TRUE(rendered) << "no limit was generous enough";
    EXPECT_TRUE(failedIn.count("load")) << (plan ? "planned" : "not planned");
    EXPECT_TRUE(failedIn.count("build")) << "no limit the mesh fits in but the BVH does not";
  }
}

// 16384 x 2048 pixels need 864 MB from the render to the 8-bit copy.
TEST(RaytraceMemory, AWideImageUnder900MegabytesEndsCleanly) {
  MESHTRACE_SKIP_ADDRESS_LIMITS_UNDER_ASAN();
  const auto dir = test::scratchDir();
  const auto scene = test::writeFile(
      dir / "wide.sce", "camera 0 0 5  0 0 0  0 1 0  45  16384 2048\n" + test::kSphereLine);
  const auto planned = test::runTool(raytraceTool(), withArgs({}, scene, dir / "out.png"), dir,
                                     {.addressSpace = 900 * kMiB});
  EXPECT_TRUE(planned.exited && planned.exitCode == 1) << test::describe(planned);
  test::expectMentions(planned.err, {"cannot render the image of 16384x2048 pixels", "864 MB"});
  EXPECT_EQ(planned.out.find("rendered"), std::string::npos) << test::describe(planned);

  const auto failed =
      test::runTool(raytraceTool(), withArgs({"--max-memory", "1T"}, scene, dir / "out.png"), dir,
                    {.addressSpace = 600 * kMiB});
  EXPECT_TRUE(failed.exited && failed.exitCode == 1) << test::describe(failed);
  test::expectMentions(failed.err, {"not enough memory to render the image of 16384x2048 pixels"});
  EXPECT_TRUE(test::listFolder(dir) == std::vector<std::string>{"wide.sce"});
}

TEST(DebugAabbMemory, AWideImageUnder900MegabytesEndsCleanly) {
  MESHTRACE_SKIP_ADDRESS_LIMITS_UNDER_ASAN();
  const auto dir = test::scratchDir();
  test::writeFile(dir / "tri.off", test::kTriangleOff);
  const auto scene = test::writeFile(dir / "wide.sce",
                                     "camera 0 0 5  0 0 0  0 1 0  45  16384 2048\n"
                                     "mesh tri.off FLAT " +
                                         test::kMaterial + "\n");
  for (const bool plan : {true, false}) {
    std::vector<std::string> options;
    if (!plan) options = {"--max-memory", "1T"};
    const auto r = test::runTool(debugAabbTool(), withArgs(options, scene, dir / "out.png"), dir,
                                 {.addressSpace = 900 * kMiB});
    EXPECT_TRUE(r.exited && r.exitCode == 1) << test::describe(r);
    test::expectMentions(r.err, {"render the box counts of 16384x2048 pixels"});
  }
}

// Files are checked as they stream: the tool finds the mistake on line 2
// of a 250 MB scene within an address space of 64 MB (which the tiny
// scene's whole run fits in), where reading the file first took 3.3 GB.
TEST(RaytraceMemory, FindsAMistakeEarlyInAHugeSceneInLittleMemory) {
  MESHTRACE_SKIP_ADDRESS_LIMITS_UNDER_ASAN();
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
TEST(RaytraceMemory, ReadsPastAHundredMegabyteLineInLittleMemory) {
  MESHTRACE_SKIP_ADDRESS_LIMITS_UNDER_ASAN();
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

// One face of 50 million corners over 3 vertices, cut into 50 million
// triangles (5.8 GB with their BVH): a polygon lists each vertex once, so
// the face is refused at its line, and the 100 MB line costs its own size.
TEST(RaytraceMemory, RefusesAFaceOfMoreCornersThanVertices) {
  MESHTRACE_SKIP_ADDRESS_LIMITS_UNDER_ASAN();
  const auto dir = test::scratchDir();
  {
    std::FILE* f = std::fopen((dir / "face.off").c_str(), "wb");
    ASSERT_TRUE(f);
    std::fputs("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n50000000", f);
    const std::string block = [] {
      std::string b;
      for (int i = 0; i < 1000000; ++i) b += " 0 1";
      return b;
    }();
    for (int i = 0; i < 25; ++i) std::fwrite(block.data(), 1, block.size(), f);
    std::fputs("\n", f);
    ASSERT_EQ(std::fclose(f), 0);
  }
  const auto scene = test::writeFile(
      dir / "face.sce", test::kCameraLine + "mesh face.off FLAT " + test::kMaterial + "\n");
  const auto r = test::runTool(raytraceTool(), withArgs({}, scene, dir / "out.png"), dir,
                               {.addressSpace = 512 * kMiB});
  std::filesystem::remove(dir / "face.off");
  EXPECT_TRUE(r.exited && r.exitCode == 1) << test::describe(r);
  test::expectMentions(r.err, {"face.off:6", "face 0", "50000000 corners", "3 vertices"});
}

}  // namespace
}  // namespace meshtrace
