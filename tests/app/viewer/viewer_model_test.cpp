// The viewer's model: what it does without a window.
#include <gtest/gtest.h>

#include <fstream>

#include "meshtrace/io/scene_parser.h"
#include "meshtrace/render/render.h"
#include "support/bad_inputs.h"
#include "support/files.h"
#include "support/paths.h"
#include "viewer/model/camera_control.h"
#include "viewer/model/geometry_load.h"
#include "viewer/model/options.h"
#include "viewer/model/projection.h"
#include "viewer/model/reference_lookup.h"
#include "viewer/model/render_scene.h"
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

// The render scene of the session's current request, made as the
// background work makes it.
std::shared_ptr<RenderScene> renderSceneOf(const SceneSession& session, std::uint64_t id = 1) {
  return makeRenderScene(
      session.request(TraceOptions{}, id), [](std::string) {}, [] { return false; });
}

TEST(Session, ShadingVisibilityResetAndSave) {
  SceneSession session;
  session.beginOpening(testScene());
  EXPECT_TRUE(session.opening());
  EXPECT_FALSE(session.loaded());
  const LoadedScene loaded = loadGeometry(testScene());
  session.adopt(loaded);
  EXPECT_FALSE(session.opening());
  ASSERT_EQ(session.meshes().size(), 2u);
  EXPECT_EQ(session.meshes()[0].name, "ball");
  EXPECT_EQ(session.meshes()[0].shading, Shading::Phong);
  EXPECT_EQ(session.meshes()[0].triangles, 80u);
  EXPECT_EQ(loaded.scene->meshes[0].shading(), Shading::Flat) << "read FLAT, PHONG later";
  EXPECT_TRUE(loaded.scene->meshes[0].vertexNormals().empty());
  const auto all = renderSceneOf(session);
  ASSERT_EQ(all->prepared->scene().meshes.size(), 2u);
  EXPECT_TRUE(all->prepared->built());
  EXPECT_EQ(all->prepared->scene().meshes[0].shading(), Shading::Phong);
  EXPECT_FALSE(all->prepared->scene().meshes[0].vertexNormals().empty());
  EXPECT_TRUE(all->allVisible);
  session.adoptBase(*all);
  EXPECT_EQ(renderSceneOf(session)->prepared->sharedScene(), all->prepared->sharedScene())
      << "the file's modes on the adopted base: nothing copied";

  const std::uint64_t r0 = session.meshRevision();
  session.setShading(0, Shading::Flat);
  session.setVisible(1, false);
  EXPECT_GT(session.meshRevision(), r0);
  EXPECT_TRUE(session.meshesChanged());
  const auto some = renderSceneOf(session, 2);
  EXPECT_EQ(some->request, 2u);
  ASSERT_EQ(some->prepared->scene().meshes.size(), 1u);
  EXPECT_EQ(some->prepared->scene().meshes[0].shading(), Shading::Flat);
  EXPECT_EQ(some->sceneMesh, std::vector<std::uint32_t>{0});
  EXPECT_FALSE(some->allVisible);
  EXPECT_EQ(all->prepared->scene().meshes[0].shading(), Shading::Phong)
      << "the old render scene never changes";

  const fs::path out = testScene().parent_path() / "viewer_test-saved-by-test.sce";
  session.saveModes(out);
  const Scene saved = loadScene(out);
  fs::remove(out);
  EXPECT_EQ(saved.meshes[0].shading(), Shading::Flat);
  EXPECT_EQ(saved.meshes[1].shading(), Shading::Flat);

  session.resetMeshes();
  EXPECT_FALSE(session.meshesChanged());
  EXPECT_EQ(renderSceneOf(session)->prepared->scene().meshes.size(), 2u);
}

TEST(GeometryLoad, RefusesBadInputWithLoadScenesOwnMessage) {
  // Read in two stages, a scene must fail exactly as loadScene fails.
  for (const test::BadInput& input : test::badInputs()) {
    const auto dir = test::scratchDir() / input.name;
    fs::create_directories(dir);
    if (!input.scene.empty()) test::writeFile(dir / "bad.sce", input.scene);
    if (!input.mesh.empty()) test::writeFile(dir / "mesh.off", input.mesh);
    fs::create_directories(dir / "folder.off");
    std::string expected, got;
    try {
      loadScene(dir / "bad.sce");
    } catch (const std::exception& e) {
      expected = e.what();
    }
    try {
      loadGeometry(dir / "bad.sce");
    } catch (const std::exception& e) {
      got = e.what();
    }
    EXPECT_FALSE(got.empty()) << input.name;
    EXPECT_EQ(got, expected) << input.name;
  }
}

TEST(GeometryLoad, TheRenderSceneOfTheFilesModesRendersAsLoadSceneDoes) {
  std::vector<fs::path> scenes{testScene(),
                               test::sourceDir() / "scenes/shading_modes/shading_phong.sce"};
  for (const fs::path& file : scenes) {
    SceneSession session;
    session.adopt(loadGeometry(file));
    const auto staged = renderSceneOf(session);
    const Scene direct = loadScene(file);
    const Image8 a = quantize(render(staged->prepared->scene(), {}));
    const Image8 b = quantize(render(direct, {}));
    EXPECT_EQ(a.rgb, b.rgb) << file;
  }
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

TEST(Projection, PointsOnAPixelsRayLandOnThePixelAndABoxTakesItsExtent) {
  CameraSpec spec;
  spec.eye = Vec3(0.5, 0.2, 5.0);
  spec.center = Vec3(0.0);
  spec.up = Vec3(0.0, 1.0, 0.0);
  spec.fovyDegrees = 40.0;
  spec.width = 64;
  spec.height = 48;
  const Camera camera(spec);
  const Projection projection(camera);
  // The camera's own rays are the independent truth: a point on pixel
  // (x, y)'s ray projects back to (x, y), whatever its distance.
  for (const auto& [x, y] : {std::pair{0.0, 0.0}, {63.0, 47.0}, {10.5, 30.25}, {-5.0, 60.0}})
    for (double t : {0.5, 3.0, 40.0}) {
      const Ray ray = camera.primaryRay(x, y);
      const auto q = projection.project(ray.origin + t * ray.direction);
      ASSERT_TRUE(q);
      EXPECT_NEAR(q->x, x, 1e-9);
      EXPECT_NEAR(q->y, y, 1e-9);
    }
  const Ray behind = camera.primaryRay(20.0, 20.0);
  EXPECT_FALSE(projection.project(behind.origin - behind.direction));
  // A box whose corners lie on the rays of pixels (10, 10) and (30, 20),
  // in one plane facing the camera: 20 pixels wide, 10 high.
  const Vec3 toCenter = glm::normalize(spec.center - spec.eye);
  const auto onPlane = [&](double x, double y) {
    const Ray r = camera.primaryRay(x, y);
    return r.origin + (4.0 / glm::dot(r.direction, toCenter)) * r.direction;
  };
  Aabb box;
  box.extend(onPlane(10.0, 10.0));
  box.extend(onPlane(30.0, 20.0));
  // Axis-aligned, the box is not quite the plane's rectangle: its extent
  // lies between the rectangle's and a little more.
  EXPECT_GE(imageExtent(projection, box), 20.0 - 1e-9);
  EXPECT_LT(imageExtent(projection, box), 24.0);
  Aabb aroundEye;
  aroundEye.extend(spec.eye - Vec3(1.0));
  aroundEye.extend(spec.eye + Vec3(1.0));
  EXPECT_EQ(imageExtent(projection, aroundEye), INFINITY);
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
