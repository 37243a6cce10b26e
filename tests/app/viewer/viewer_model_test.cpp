// The viewer's model: what it does without a window.
#include <gtest/gtest.h>

#include <fstream>

#include "meshtrace/io/scene_parser.h"
#include "support/paths.h"
#include "viewer/model/camera_control.h"
#include "viewer/model/options.h"
#include "viewer/model/reference_lookup.h"
#include "viewer/model/scene_catalog.h"
#include "viewer/model/scene_writer.h"
#include "viewer/model/session.h"
#include "viewer/model/views.h"

namespace meshtrace::viewer {
namespace {

namespace fs = std::filesystem;

fs::path testScene() { return test::sourceDir() / "tests/app/viewer/scenes/viewer_test.sce"; }

TEST(SceneWriter, ChangesOnlyTheShadingWords) {
  const std::string text =
      "# mesh a.off FLAT in a comment stays\ncamera 0 0 5 0 0 0 0 1 0 45 8 6\n"
      "mesh a.off FLAT 1 1 1 1 1 1 1 1 1 1 0   # first\n"
      "sphere 0 0 0 1  0 0 0 0 0 0 0 0 0 1 0\nmesh PHONG.off\tPHONG 1 1 1 1 1 1 1 1 1 1 0\n";
  const std::string out = rewriteMeshModes(text, {Shading::Phong, Shading::Flat});
  EXPECT_EQ(out,
            "# mesh a.off FLAT in a comment stays\ncamera 0 0 5 0 0 0 0 1 0 45 8 6\n"
            "mesh a.off PHONG 1 1 1 1 1 1 1 1 1 1 0   # first\n"
            "sphere 0 0 0 1  0 0 0 0 0 0 0 0 0 1 0\nmesh PHONG.off\tFLAT 1 1 1 1 1 1 1 1 1 1 0\n");
  EXPECT_THROW(rewriteMeshModes(text, {Shading::Flat}), std::runtime_error);
}

TEST(Session, ShadingVisibilityResetAndSave) {
  SceneSession session;
  ASSERT_TRUE(session.load(testScene())) << session.error();
  ASSERT_EQ(session.meshes().size(), 2u);
  EXPECT_EQ(session.meshes()[0].name, "ball");
  EXPECT_EQ(session.meshes()[0].shading, Shading::Phong);
  const std::uint64_t r0 = session.revision();
  const auto all = session.prepared(TraceOptions{});
  EXPECT_EQ(all->scene().meshes.size(), 2u);
  EXPECT_EQ(session.prepared(TraceOptions{}), all) << "unchanged scene: reused";

  session.setShading(0, Shading::Flat);
  session.setVisible(1, false);
  EXPECT_GT(session.revision(), r0);
  EXPECT_TRUE(session.meshesChanged());
  const auto some = session.prepared(TraceOptions{});
  ASSERT_EQ(some->scene().meshes.size(), 1u);
  EXPECT_EQ(some->scene().meshes[0].shading(), Shading::Flat);
  EXPECT_EQ(session.sceneMesh(0), 0u);
  EXPECT_EQ(all->scene().meshes[0].shading(), Shading::Phong)
      << "the old render scene never changes";

  const fs::path out = testScene().parent_path() / "viewer_test-saved-by-test.sce";
  session.saveModes(out);
  const Scene saved = loadScene(out);
  fs::remove(out);
  EXPECT_EQ(saved.meshes[0].shading(), Shading::Flat);
  EXPECT_EQ(saved.meshes[1].shading(), Shading::Flat);

  session.resetMeshes();
  EXPECT_FALSE(session.meshesChanged());
  EXPECT_EQ(session.prepared(TraceOptions{})->scene().meshes.size(), 2u);
}

TEST(Session, BadSceneGivesTheErrorWithFileAndLine) {
  SceneSession session;
  EXPECT_FALSE(session.load(test::sourceDir() / "tests/app/viewer/scenes/broken.sce"));
  EXPECT_FALSE(session.loaded());
  EXPECT_NE(session.error().find("broken.sce:5"), std::string::npos) << session.error();
  EXPECT_EQ(session.prepared(TraceOptions{}), nullptr);
  EXPECT_FALSE(session.load(test::sourceDir() / "no/such/scene.sce"));
  EXPECT_FALSE(session.error().empty());
}

TEST(CameraControl, OrbitKeepsDistancePanMovesBothZoomApproaches) {
  CameraSpec c;
  c.eye = Vec3(0, 1, 5);
  c.center = Vec3(0, 1, 0);
  c.width = 200;
  c.height = 100;
  const CameraSpec o = orbit(c, 180.0, 0.0);  // 90 degrees around up
  EXPECT_NEAR(glm::length(o.eye - o.center), 5.0, 1e-12);
  EXPECT_NEAR(o.eye.y, 1.0, 1e-12);
  EXPECT_NEAR(std::abs(o.eye.x), 5.0, 1e-9);
  const CameraSpec p = pan(c, 10.0, 0.0);
  EXPECT_NEAR(glm::length((p.eye - c.eye) - (p.center - c.center)), 0.0, 1e-12);
  EXPECT_GT(glm::length(p.center - c.center), 0.0);
  const CameraSpec z = zoom(c, 1.0);
  EXPECT_NEAR(glm::length(z.eye - z.center), 4.5, 1e-12);
  // Orbiting straight up stops short of the pole.
  const CameraSpec up = orbit(c, 0.0, 10000.0);
  EXPECT_LT(std::abs(glm::dot(glm::normalize(up.eye - up.center), Vec3(0, 1, 0))), 0.996);
}

TEST(CameraControl, CameraLineParsesBackToTheSameCamera) {
  CameraSpec c;
  c.eye = Vec3(0.1, 2.0 / 3.0, -5);
  c.center = Vec3(1e-7, 0, 0);
  c.up = Vec3(0, 1, 0);
  c.fovyDegrees = 47.5;
  c.width = 320;
  c.height = 240;
  const std::string line = cameraLine(c);
  EXPECT_EQ(line.rfind("camera 0.1 0.6666666666666666 -5 1e-07 0 0 0 1 0 47.5 320 240", 0), 0u)
      << line;
  const Scene s = parseScene(line + "\n", "camera.sce");
  EXPECT_EQ(s.camera.spec().eye, c.eye);
  EXPECT_EQ(s.camera.spec().center, c.center);
  EXPECT_EQ(s.camera.spec().fovyDegrees, c.fovyDegrees);
}

TEST(SceneCatalog, ListsScenesBelowAFolder) {
  const SceneFolder f = scanFolder(test::sourceDir() / "tests/app/viewer/scenes", "tests");
  EXPECT_TRUE(f.error.empty());
  ASSERT_GE(f.scenes.size(), 2u);
  EXPECT_EQ(sceneLabel(f, f.scenes[0]), "broken.sce");
  EXPECT_FALSE(scanFolder(test::sourceDir() / "no-such-folder", "x").error.empty());
}

TEST(ReferenceLookup, FindsExpectedResultsBesideTheSceneFolders) {
  const auto dir = test::scratchDir();
  fs::create_directories(dir / "scenes/demo");
  fs::create_directories(dir / "expected_results");
  std::ofstream(dir / "scenes/demo/demo.sce") << "";
  EXPECT_FALSE(findReference(dir / "scenes/demo/demo.sce"));
  std::ofstream(dir / "expected_results/demo.jpg") << "x";
  EXPECT_EQ(findReference(dir / "scenes/demo/demo.sce"), dir / "expected_results/demo.jpg");
}

TEST(Views, NamesRoundTripAndFalseColoursFollowTheProbe) {
  for (int i = 0; i < kViewCount; ++i)
    EXPECT_EQ(parseView(name(static_cast<View>(i))), static_cast<View>(i));
  for (int i = 0; i < kOverlayCount; ++i)
    EXPECT_EQ(parseOverlay(name(static_cast<Overlay>(i))), static_cast<Overlay>(i));
  EXPECT_FALSE(parseView("bogus"));
  PixelProbe miss;
  FalseColorScales s;
  EXPECT_EQ(falseColor(View::Normals, miss, s), Color(kMissGrey));
  PixelProbe hit;
  hit.object = 2;
  hit.depth = 3.0f;
  hit.normal[2] = 1.0f;
  hit.boxHits = 2;
  s.boxMax = 4;
  EXPECT_EQ(falseColor(View::Normals, hit, s), Color(0.5, 0.5, 1.0));
  EXPECT_DOUBLE_EQ(overlayValue(Overlay::BoxHits, hit, s), 0.5);
  EXPECT_TRUE(needsProbes(View::Depth));
  EXPECT_FALSE(needsProbes(View::Color));
}

TEST(Options, ParsesTheHeadlessSnapshotCommandLine) {
  std::vector<std::string> args{"viewer",    "--headless", "--snapshot", "out.png", "--size",
                                "800x600",   "--overlay",  "boxes",      "--pin",   "3,4",
                                "--shading", "ball=FLAT",  "--view",     "normals", "scene.sce"};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  int code = -1;
  const auto o = parseOptions(static_cast<int>(argv.size()), argv.data(), code);
  ASSERT_TRUE(o);
  EXPECT_EQ(o->scene, "scene.sce");
  EXPECT_EQ(o->width, 800);
  EXPECT_EQ(o->overlay, Overlay::BoxHits);
  EXPECT_EQ(o->view, View::Normals);
  ASSERT_TRUE(o->pin);
  EXPECT_EQ(o->pin->second, 4);
  ASSERT_EQ(o->shading.size(), 1u);
  EXPECT_EQ(o->shading[0].second, Shading::Flat);
}

}  // namespace
}  // namespace meshtrace::viewer
