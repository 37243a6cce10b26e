// A headless run never hides a failure: a scene that does not load, a
// command line naming a mesh, pixel, reference, view, panel or BVH depth
// the scene lacks end with a message and a non-zero exit, and the output
// (an earlier snapshot, say) is left as it was.
#include <gtest/gtest.h>

#include <regex>

#include "support/bad_inputs.h"
#include "support/cli.h"
#include "support/files.h"
#include "support/paths.h"

namespace meshtrace {
namespace {

namespace fs = std::filesystem;

fs::path viewerTool() { return MESHTRACE_VIEWER; }

std::vector<std::string> headless(const fs::path& dir, std::vector<std::string> args) {
  std::vector<std::string> all{
      "--headless", "--no-default-dirs",        "--threads",  "2",
      "--snapshot", (dir / "out.png").string(), "--describe", (dir / "out.txt").string()};
  all.insert(all.end(), args.begin(), args.end());
  return all;
}

class ViewerBadInput : public ::testing::TestWithParam<test::BadInput> {};

TEST_P(ViewerBadInput, ExitsWithTheErrorAndLeavesTheOutput) {
  const test::BadInput& input = GetParam();
  const auto dir = test::scratchDir();
  if (!input.scene.empty()) test::writeFile(dir / "bad.sce", input.scene);
  if (!input.mesh.empty()) test::writeFile(dir / "mesh.off", input.mesh);
  fs::create_directory(dir / "folder.off");
  test::writeFile(dir / "out.png", test::kOldOutput);
  test::expectRefusal(viewerTool(), headless(dir, {(dir / "bad.sce").string()}), dir,
                      input.mentions, dir / "out.png");
}

INSTANTIATE_TEST_SUITE_P(Cases, ViewerBadInput, ::testing::ValuesIn(test::badInputs()),
                         [](const auto& info) { return info.param.name; });

// Scenes a headless run once turned into a picture of the error with exit
// 0: a scene that is not there, a depth of 1e9 (or a whole number as
// large), a mesh that is /dev/zero (endless, of no size to read).
class ViewerBrokenScene : public ::testing::TestWithParam<test::BadInput> {};

TEST_P(ViewerBrokenScene, ExitsNonZeroNamingTheFileAndLeavesTheOutput) {
  const test::BadInput& input = GetParam();
  const auto dir = test::scratchDir();
  if (!input.scene.empty()) test::writeFile(dir / "bad.sce", input.scene);
  test::writeFile(dir / "out.png", test::kOldOutput);
  test::expectRefusal(viewerTool(), headless(dir, {(dir / "bad.sce").string()}), dir,
                      input.mentions, dir / "out.png");
}

const std::string kSmallCamera = "camera 0 0 5  0 0 0  0 1 0  45 32 24\n";
const std::string kGrey = " 0.1 0.1 0.1  0.5 0.5 0.5  0 0 0  1 0\n";

INSTANTIATE_TEST_SUITE_P(
    Cases, ViewerBrokenScene,
    ::testing::Values(test::BadInput{"Missing", "", "", {"bad.sce", "not found"}},
                      test::BadInput{"DepthOf1e9",
                                     kSmallCamera + "depth 1e9\nsphere 0 0 0 1" + kGrey,
                                     "",
                                     {"bad.sce:2", "1e9"}},
                      test::BadInput{"DepthOfABillion",
                                     kSmallCamera + "depth 1000000000\nsphere 0 0 0 1" + kGrey,
                                     "",
                                     {"bad.sce:2", "1000000000"}},
                      test::BadInput{"MeshOfDevZero",
                                     kSmallCamera + "mesh /dev/zero FLAT" + kGrey,
                                     "",
                                     {"bad.sce:2", "/dev/zero"}}),
    [](const auto& info) { return info.param.name; });

// The test scene in a scratch folder beside an existing out.png.
fs::path sceneCopy() {
  const auto dir = test::scratchDir();
  for (const char* f : {"viewer_test.sce", "ball.off", "box.off"})
    fs::copy_file(test::sourceDir() / "tests/app/viewer/scenes" / f, dir / f);
  test::writeFile(dir / "out.png", test::kOldOutput);
  return dir;
}

struct Refusal {
  std::string name;
  std::vector<std::string> args;
  std::vector<std::string> mentions;
  int exitCode = 1;  // 2: the command line itself is wrong
};

class ViewerRefusal : public ::testing::TestWithParam<Refusal> {};

TEST_P(ViewerRefusal, SaysWhatTheSceneLacksAndLeavesTheOutput) {
  const Refusal& r = GetParam();
  const auto dir = sceneCopy();
  std::vector<std::string> args = r.args;
  args.push_back((dir / "viewer_test.sce").string());
  if (r.exitCode == 1) {
    test::expectRefusal(viewerTool(), headless(dir, args), dir, r.mentions, dir / "out.png");
    return;
  }
  const test::ToolResult result = test::runTool(viewerTool(), headless(dir, args), dir);
  EXPECT_TRUE(result.exited && result.exitCode == r.exitCode) << test::describe(result);
  for (const std::string& m : r.mentions)
    EXPECT_NE(result.err.find(m), std::string::npos) << m << "\n" << test::describe(result);
  EXPECT_EQ(test::readFileBytes(dir / "out.png"), test::kOldOutput);
  EXPECT_FALSE(fs::exists(dir / "out.txt"));
}

INSTANTIATE_TEST_SUITE_P(
    Options, ViewerRefusal,
    ::testing::Values(
        Refusal{"NoSuchMeshToShade", {"--shading", "nope=FLAT"}, {"nope", "ball, box"}},
        Refusal{"NoSuchMeshToHide", {"--hide", "7"}, {"--hide", "'7'"}},
        Refusal{"PinPastTheRightEdge", {"--pin", "240,5"}, {"--pin 240,5", "240x160"}},
        Refusal{"PinAboveTheTop", {"--pin", "5,160"}, {"--pin 5,160", "y 0..159"}},
        Refusal{"PinLeftOfTheImage", {"--pin", "-1,3"}, {"--pin -1,3"}},
        Refusal{"NoSuchReference", {"--reference", "missing.png"}, {"--reference", "missing.png"}},
        Refusal{"BvhDepthPastTheDeepestNode",
                {"--draw", "cut", "--bvh-depth", "40"},
                {"--bvh-depth 40", "deepest"}},
        Refusal{"NoSuchView", {"--view", "nope"}, {"view 'nope'"}, 2},
        Refusal{"NoSuchOverlay", {"--overlay", "nope"}, {"overlay 'nope'"}, 2},
        Refusal{"NoSuchPanel", {"--open", "nope"}, {"panel 'nope'", "compare"}, 2},
        Refusal{"NothingToDrawByThatName", {"--draw", "nope"}, {"'nope'"}, 2},
        Refusal{"NoSuchTriangleTest", {"--triangle", "nope"}, {"nope"}, 2},
        Refusal{"ZoomOutOfRange", {"--zoom", "100"}, {"--zoom"}, 2}),
    [](const auto& info) { return info.param.name; });

TEST(ViewerHeadless, WritesTheSnapshotWhenAllIsWell) {
  const auto dir = sceneCopy();
  test::expectSuccess(viewerTool(),
                      headless(dir, {"--pin", "88,109", (dir / "viewer_test.sce").string()}), dir);
  EXPECT_NE(test::readFileBytes(dir / "out.png"), test::kOldOutput);
  EXPECT_NE(test::readFileBytes(dir / "out.txt").find("pixel (88, 109) pinned"), std::string::npos);
}

TEST(ViewerHeadless, ShowsTheScenesWarningsInTheWindow) {
  const auto dir = sceneCopy();
  std::string text = test::readFileBytes(dir / "viewer_test.sce");
  const std::string up = "0 1 0  45";
  text.replace(text.find(up), up.size(), "0 -1.65 -5.5  45");  // up along the view
  test::writeFile(dir / "viewer_test.sce", text);
  test::expectSuccess(viewerTool(), headless(dir, {(dir / "viewer_test.sce").string()}), dir);
  const std::string shown = test::readFileBytes(dir / "out.txt");
  std::size_t count = 0;
  for (std::size_t at = shown.find("parallel to the view"); at != std::string::npos;
       at = shown.find("parallel to the view", at + 1))
    ++count;
  EXPECT_EQ(count, 2u) << "in the scene panel and on the message line:\n" << shown;
}

// A cube as ASCII PLY: a format read through OpenMesh, as users bring.
const std::string kCubePly =
    "ply\nformat ascii 1.0\nelement vertex 8\nproperty float x\nproperty float y\n"
    "property float z\nelement face 12\nproperty list uchar int vertex_indices\nend_header\n"
    "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
    "3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n"
    "3 2 3 7\n3 2 7 6\n3 1 2 6\n3 1 6 5\n3 0 4 7\n3 0 7 3\n";

TEST(ViewerHeadless, OpensABareMeshFramedAsRaytraceFramesIt) {
  const auto dir = test::scratchDir();
  test::writeFile(dir / "cube.ply", kCubePly);
  test::writeFile(dir / "out.png", test::kOldOutput);
  test::expectSuccess(viewerTool(), headless(dir, {(dir / "cube.ply").string()}), dir);
  EXPECT_NE(test::readFileBytes(dir / "out.png"), test::kOldOutput);
  const std::string shown = test::readFileBytes(dir / "out.txt");
  test::expectMentions(shown, {"generated scene for cube.ply", "1 planes", "1 lights", "12 / 8"});
  EXPECT_FALSE(fs::exists(dir / "cube.sce")) << "nothing saved unless asked";
}

TEST(ViewerHeadless, ABadBareMeshExitsNamingTheFileAndLeavesTheOutput) {
  const auto dir = test::scratchDir();
  std::string bad = kCubePly;
  bad.replace(bad.find("3 0 2 1"), 7, "3 0 2 99");
  test::writeFile(dir / "bad.ply", bad);
  test::writeFile(dir / "out.png", test::kOldOutput);
  test::expectRefusal(viewerTool(), headless(dir, {(dir / "bad.ply").string()}), dir, {"bad.ply"},
                      dir / "out.png");
}

TEST(ViewerVersion, IsTheProjectsVersionFromTheTopLevelCMakeLists) {
  // The one place the version is written: project(meshtrace VERSION x.y.z ...).
  const std::string cmake = test::readFileBytes(test::sourceDir() / "CMakeLists.txt");
  std::smatch m;
  ASSERT_TRUE(
      std::regex_search(cmake, m, std::regex(R"(project\(meshtrace\s+VERSION\s+([0-9.]+))")))
      << "the top-level project() states the version";
  const auto dir = test::scratchDir();
  const test::ToolResult result = test::runTool(viewerTool(), {"--version"}, dir);
  ASSERT_TRUE(result.exited && result.exitCode == 0) << test::describe(result);
  // Help > About shows the same line (versionLine()).
  EXPECT_EQ(result.out, "meshtrace viewer " + m[1].str() + "\n");
}

}  // namespace
}  // namespace meshtrace
