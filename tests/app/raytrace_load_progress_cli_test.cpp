// Progress lines while a large mesh loads: on a terminal (a pseudo-terminal
// made by script(1)) raytrace names the mesh and how much of it is read;
// nothing of it with --quiet, when its output is not a terminal, or for a
// small mesh; within --all's scene line; and an error in a large mesh
// starts on a line of its own.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "meshtrace/geometry/mesh_generators.h"
#include "meshtrace/io/mesh_writer.h"
#include "support/cli.h"
#include "support/files.h"
#include "support/paths.h"
#include "support/scene_snippets.h"

namespace meshtrace {
namespace {

// A scene of one torus knot of 480k triangles, 8.7 MB as a binary PLY of
// float coordinates: just above the size from which loads show a line,
// and quick to write, read and render at 8x6 pixels.
struct LargeMeshScene {
  std::filesystem::path dir = test::scratchDir();
  std::filesystem::path mesh = dir / "knot.ply";
  std::filesystem::path scene = dir / "knot.sce";
  LargeMeshScene() {
    writeBinaryPly(makeTorusKnot(Vec3(0.0), 1.0, 2, 3, 0.3, 2400, 100), mesh,
                   PlyCoordinates::Float);
    test::writeFile(scene, test::kCameraLine + "light 0 0 10 1 1 1\nmesh knot.ply PHONG " +
                               test::kMaterial + "\n");
  }
  std::string command(const std::string& options,
                      const std::filesystem::path& tool = test::raytraceTool()) const {
    return tool.string() + " " + options + " " + scene.string() + " " + (dir / "out.png").string();
  }
};

TEST(RaytraceLoadProgress, NamesTheMeshAndTheShareReadOnATerminal) {
  const LargeMeshScene large;
  const auto r = test::runOnTerminal(large.command(""), large.dir);
  ASSERT_TRUE(r.exited && r.exitCode == 0) << test::describe(r);
  const std::size_t line = r.out.find("loading knot.ply: ");
  ASSERT_NE(line, std::string::npos) << r.out;
  EXPECT_NE(r.out.find("% (", line), std::string::npos) << r.out;
  EXPECT_NE(r.out.find(" of 8.7 MB)", line), std::string::npos) << r.out;
  // Wiped before "loaded ...", which starts at the line's beginning.
  const std::size_t loaded = r.out.find("loaded ");
  ASSERT_NE(loaded, std::string::npos) << r.out;
  EXPECT_LT(line, loaded);
  EXPECT_EQ(r.out[loaded - 1], '\r') << r.out;
}

TEST(RaytraceLoadProgress, IsQuietWithQuietOnATerminal) {
  const LargeMeshScene large;
  const auto r = test::runOnTerminal(large.command("--quiet"), large.dir);
  ASSERT_TRUE(r.exited && r.exitCode == 0) << test::describe(r);
  EXPECT_NE(r.out.find("loaded "), std::string::npos) << r.out;
  EXPECT_EQ(r.out.find("loading"), std::string::npos) << r.out;
}

// debug_aabb loads scenes the same way, and takes --quiet too.
TEST(RaytraceLoadProgress, DebugAabbShowsTheLineAndIsQuietWithQuiet) {
  const LargeMeshScene large;
  const auto shown = test::runOnTerminal(large.command("", test::debugAabbTool()), large.dir);
  ASSERT_TRUE(shown.exited && shown.exitCode == 0) << test::describe(shown);
  EXPECT_NE(shown.out.find("loading knot.ply: "), std::string::npos) << shown.out;
  const auto quiet =
      test::runOnTerminal(large.command("--quiet", test::debugAabbTool()), large.dir);
  ASSERT_TRUE(quiet.exited && quiet.exitCode == 0) << test::describe(quiet);
  EXPECT_NE(quiet.out.find("loaded "), std::string::npos) << quiet.out;
  EXPECT_EQ(quiet.out.find("loading"), std::string::npos) << quiet.out;
}

// With --all, the mesh's line is drawn after the scene's, which it would
// otherwise hide while the mesh loads.
TEST(RaytraceLoadProgress, NestsInTheSceneLineOfAll) {
  const LargeMeshScene large;
  const auto r = test::runOnTerminal(test::raytraceTool().string() + " --all " +
                                         large.dir.string() + " " + (large.dir / "out").string(),
                                     large.dir);
  ASSERT_TRUE(r.exited && r.exitCode == 0) << test::describe(r);
  EXPECT_NE(r.out.find("\rscene 1/1 (knot.sce) | loading knot.ply: "), std::string::npos) << r.out;
}

// A line wider than the terminal would wrap, and the next redraw would
// start on the wrapped part: every drawn line is cut one column short of
// the width.
TEST(RaytraceLoadProgress, CutsTheLineToTheTerminalsWidth) {
  const LargeMeshScene large;
  const auto r = test::runOnTerminal("stty cols 30; " + test::raytraceTool().string() +
                                         " --all " + large.dir.string() + " " +
                                         (large.dir / "out").string(),
                                     large.dir);
  ASSERT_TRUE(r.exited && r.exitCode == 0) << test::describe(r);
  const std::size_t load = r.out.find("\rscene 1/1 (knot.sce) | lo");
  ASSERT_NE(load, std::string::npos) << r.out;
  EXPECT_EQ(r.out.find('\r', load + 1), load + 1 + 29) << r.out;
}

TEST(RaytraceLoadProgress, IsQuietWhenNotATerminal) {
  const LargeMeshScene large;
  const auto r = test::runTool(test::raytraceTool(),
                               {large.scene.string(), (large.dir / "out.png").string()}, large.dir);
  ASSERT_TRUE(r.exited && r.exitCode == 0) << test::describe(r);
  EXPECT_EQ(r.err.find("loading"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find('\r'), std::string::npos) << r.err;
}

TEST(RaytraceLoadProgress, ShowsNoLineForASmallMesh) {
  const std::filesystem::path dir = test::folderWithGoodScene();
  const auto r =
      test::runOnTerminal(test::raytraceTool().string() + " " + (dir / "good.sce").string() + " " +
                              (dir / "out.png").string(),
                          dir);
  ASSERT_TRUE(r.exited && r.exitCode == 0) << test::describe(r);
  EXPECT_EQ(r.out.find("loading"), std::string::npos) << r.out;
}

TEST(RaytraceLoadProgress, WipesTheLineBeforeAnErrorInTheMesh) {
  const LargeMeshScene large;
  // The last face's last corner out of range: the error comes once the
  // whole file is read.
  std::string bytes = test::readFileBytes(large.mesh);
  bytes.replace(bytes.size() - 4, 4, "\xff\xff\xff\x7f");
  test::writeFile(large.mesh, bytes);
  const auto r = test::runOnTerminal(large.command(""), large.dir);
  ASSERT_TRUE(r.exited && r.exitCode == 1) << test::describe(r);
  const std::size_t line = r.out.find("loading knot.ply: ");
  ASSERT_NE(line, std::string::npos) << r.out;
  const std::size_t error = r.out.find("error: ");
  ASSERT_NE(error, std::string::npos) << r.out;
  EXPECT_LT(line, error);
  // The error follows a run of spaces over the line and a carriage return.
  ASSERT_EQ(r.out[error - 1], '\r') << r.out;
  const std::size_t wipe = r.out.rfind('\r', error - 2);
  ASSERT_NE(wipe, std::string::npos) << r.out;
  EXPECT_EQ(r.out.find_first_not_of(' ', wipe + 1), error - 1) << r.out;
  test::expectMentions(r.out.substr(error), {"knot.ply", "face 479999"});
}

}  // namespace
}  // namespace meshtrace
