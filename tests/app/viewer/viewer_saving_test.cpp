// Saving from the viewer: hidden meshes kept as comments, a scene moved to
// another folder still finds its meshes, no file replaced unless told, and
// no path proposed where the user may not or should not write.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include "app/viewer/test_scenes.h"
#include "meshtrace/io/scene_parser.h"
#include "support/files.h"
#include "support/paths.h"
#include "viewer/model/geometry_load.h"
#include "viewer/model/save_target.h"
#include "viewer/model/scene_writer.h"
#include "viewer/model/session.h"

namespace meshtrace::viewer {
namespace {

namespace fs = std::filesystem;

fs::path testScenes() { return test::viewerTestScenes(); }

// A fresh folder of its own for each test.
fs::path freshDir(const std::string& name) {
  const fs::path dir = test::scratchDir() / ("viewer_saving_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

TEST(SceneWriter, AHiddenMeshBecomesCommentLinesOnLinesOfTheirOwn) {
  const std::string text =
      "camera 0 0 5 0 0 0 0 1 0 45 8 6\n"
      "mesh a.off FLAT 1 1 1 1 1 1 1 1 1 1 0   # first\n"
      "mesh b.off PHONG 1 1 1\n  1 1 1 1 1 1 1 0 sphere 0 0 0 1  0 0 0 0 0 0 0 0 0 1 0\n";
  const std::string out =
      rewriteMeshes(text, {Shading::Phong, Shading::Flat}, {false, false}, "/s", "/s");
  EXPECT_EQ(out,
            "camera 0 0 5 0 0 0 0 1 0 45 8 6\n"
            "# hidden in the viewer: mesh a.off PHONG 1 1 1 1 1 1 1 1 1 1 0   # first\n"
            "# hidden in the viewer: mesh b.off FLAT 1 1 1\n#     1 1 1 1 1 1 1 0\n"
            " sphere 0 0 0 1  0 0 0 0 0 0 0 0 0 1 0\n");
  const Scene scene = parseScene(out, "/s/x.sce");
  EXPECT_TRUE(scene.meshes.empty());
  EXPECT_EQ(scene.spheres.size(), 1u) << "the sphere after the hidden mesh stays";
}

TEST(SceneWriter, ASceneSavedElsewhereStillFindsItsMeshes) {
  const fs::path dir = freshDir("moved");
  SceneSession session;
  session.beginOpening(testScenes() / "viewer_test.sce");
  session.adopt(loadGeometry(testScenes() / "viewer_test.sce"));
  session.setShading(1, Shading::Phong);
  const fs::path out = dir / "sub" / "moved.sce";
  fs::create_directories(out.parent_path());
  session.saveMeshes(out, Existing::Refuse);
  const Scene saved = loadScene(out);
  ASSERT_EQ(saved.meshes.size(), 2u);
  EXPECT_EQ(saved.meshes[1].shading(), Shading::Phong);
  EXPECT_EQ(fs::canonical(saved.meshes[0].file()), fs::canonical(testScenes() / "ball.off"));
}

// A path a scene file cannot hold (white space, '#') is refused, not
// written to be misread as other words.
TEST(SceneWriter, RefusesAMeshPathASceneFileCannotHold) {
  const std::string text =
      "camera 0 0 5 0 0 0 0 1 0 45 8 6\nmesh a.off FLAT 1 1 1 1 1 1 1 1 1 1 0\n";
  EXPECT_THROW(rewriteMeshes(text, {Shading::Flat}, {true}, "/my scenes", "/elsewhere"),
               std::runtime_error);
  EXPECT_THROW(rewriteMeshes(text, {Shading::Flat}, {true}, "/s#1", "/elsewhere"),
               std::runtime_error);
  // Beside its meshes the path is kept as written.
  EXPECT_NO_THROW(rewriteMeshes(text, {Shading::Flat}, {true}, "/my scenes", "/my scenes"));
}

TEST(SceneWriter, RefusesToReplaceAFileUnlessTold) {
  const fs::path dir = freshDir("refuse");
  fs::copy(testScenes(), dir, fs::copy_options::recursive);
  const fs::path scene = dir / "viewer_test.sce";
  const std::string original = test::readFileBytes(scene);
  SceneSession session;
  session.beginOpening(scene);
  session.adopt(loadGeometry(scene));
  session.setShading(0, Shading::Flat);
  try {
    session.saveMeshes(scene, Existing::Refuse);
    ADD_FAILURE() << "replaced the scene it was not told to replace";
  } catch (const FileExists& e) {
    EXPECT_EQ(e.path, scene);
    test::expectMentions(e.what(), {scene.string(), "exists"});
  }
  EXPECT_EQ(test::readFileBytes(scene), original);
  session.saveMeshes(scene, Existing::Replace);
  EXPECT_NE(test::readFileBytes(scene), original);
  EXPECT_EQ(loadScene(scene).meshes[0].shading(), Shading::Flat);
  EXPECT_EQ(test::listFolder(dir).size(), test::listFolder(testScenes()).size())
      << "no temporary left";
}

TEST(SaveTarget, NeverProposesReadOnlyOrCourseFolders) {
  const fs::path dir = freshDir("folders");
  const fs::path readOnly = dir / "read-only", course = dir / "shared" / "seed" / "scenes",
                 mine = dir / "mine";
  for (const fs::path& d : {readOnly, course, mine}) fs::create_directories(d);
  ::chmod(readOnly.c_str(), 0555);
  EXPECT_FALSE(isWritableFolder(readOnly));
  EXPECT_TRUE(isCourseData(course));
  EXPECT_TRUE(isCourseData(course / "x.sce"));
  EXPECT_FALSE(isCourseData(mine));
  EXPECT_EQ(chooseSaveFolder({readOnly, course, dir / "missing", mine}, "/fallback"), mine);
  EXPECT_EQ(chooseSaveFolder({readOnly, course}, "/fallback"), "/fallback");
  ::chmod(readOnly.c_str(), 0755);

  EXPECT_EQ(freeName(mine, "a-render", ".png"), mine / "a-render.png");
  test::writeFile(mine / "a-render.png", "x");
  test::writeFile(mine / "a-render-2.png", "x");
  EXPECT_EQ(freeName(mine, "a-render", ".png"), mine / "a-render-3.png");
  EXPECT_THROW(refuseExisting(mine / "a-render.png", Existing::Refuse), FileExists);
  EXPECT_NO_THROW(refuseExisting(mine / "a-render.png", Existing::Replace));
  EXPECT_NO_THROW(refuseExisting(mine / "new.png", Existing::Refuse));
}

}  // namespace
}  // namespace meshtrace::viewer
