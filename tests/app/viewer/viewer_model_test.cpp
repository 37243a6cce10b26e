// The viewer's model: what it does without a window.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>

#include "meshtrace/io/scene_parser.h"
#include "meshtrace/render/render.h"
#include "support/bad_inputs.h"
#include "support/files.h"
#include "support/paths.h"
#include "viewer/model/ab_compare.h"
#include "viewer/model/camera_control.h"
#include "viewer/model/geometry_load.h"
#include "viewer/model/heat_scales.h"
#include "viewer/model/image_viewport.h"
#include "viewer/model/options.h"
#include "viewer/model/projection.h"
#include "viewer/model/ray_tree.h"
#include "viewer/model/render_progress.h"
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
  const std::string out =
      rewriteMeshes(text, {Shading::Phong, Shading::Flat}, {true, true}, "/s", "/s");
  EXPECT_EQ(out,
            "# mesh a.off FLAT in a comment stays\ncamera 0 0 5 0 0 0 0 1 0 45 8 6\n"
            "mesh a.off PHONG 1 1 1 1 1 1 1 1 1 1 0   # first\n"
            "sphere 0 0 0 1  0 0 0 0 0 0 0 0 0 1 0\nmesh PHONG.off\tFLAT 1 1 1 1 1 1 1 1 1 1 0\n");
  EXPECT_THROW(rewriteMeshes(text, {Shading::Flat}, {true}, "/s", "/s"), std::runtime_error);
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

  // Saved elsewhere (the mesh paths follow): the snapshot tests list the
  // test scenes' folder while this runs beside them.
  const fs::path out = test::scratchDir() / "viewer_test-saved.sce";
  session.saveMeshes(out, Existing::Refuse);
  const Scene saved = loadScene(out);
  ASSERT_EQ(saved.meshes.size(), 1u) << "the hidden box is a comment";
  EXPECT_EQ(saved.meshes[0].shading(), Shading::Flat);

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

TEST(ImageViewport, FromOneToOneOnEveryPixelCanBeHoveredAndZoomKeepsThePointUnderTheMouse) {
  // A 1024-pixel square image in a smaller area: fitted it is scaled down;
  // at 1:1 and closer, moving the mouse a screen pixel at a time meets
  // every column in turn, none skipped, and panning reaches all of them.
  const ScreenRect area{100.0f, 50.0f, 600.0f, 500.0f};
  ImageViewport v;
  v.layout(area, 1024, 1024);
  EXPECT_LT(v.zoom(), 1.0);
  for (double zoom : {1.0, 3.0, 24.0}) {
    v.zoomTo(zoom, 0.0, 512.0);
    v.layout(area, 1024, 1024);
    std::vector<bool> seen(1024, false);
    for (int pass = 0;
         pass < 4000 && !std::all_of(seen.begin(), seen.end(), [](bool b) { return b; }); ++pass) {
      int last = -1;
      for (float sx = area.x; sx < area.x + area.width; sx += 1.0f) {
        const auto p = v.pixelAt(sx, area.y + 250.0f);
        if (!p) continue;
        if (last >= 0) {
          ASSERT_LE(p->first - last, 1) << "zoom " << zoom << " skips a column";
        }
        last = p->first;
        seen[static_cast<std::size_t>(p->first)] = true;
      }
      v.panBy(-area.width / 2, 0.0f);
      v.layout(area, 1024, 1024);
    }
    EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](bool b) { return b; })) << zoom;
    // A pixel's centre on screen is inside that pixel.
    v.zoomTo(zoom, 300.0, 700.0);
    v.layout(area, 1024, 1024);
    const auto [sx, sy] = v.toScreen(300.5, 700.5);
    EXPECT_EQ(v.pixelAt(sx, sy), std::make_pair(300, 700));
  }
  const auto before = v.pixelAt(222.0f, 333.0f);
  v.zoomAt(2.0, 222.0f, 333.0f);
  v.layout(area, 1024, 1024);
  EXPECT_EQ(v.pixelAt(222.0f, 333.0f), before);
  EXPECT_DOUBLE_EQ(v.zoom(), 48.0);
}

TEST(HeatScales, PercentileByNearestRankAndNothingForNoValues) {
  std::vector<float> values;
  for (int i = 100; i >= 1; --i) values.push_back(float(i));
  EXPECT_EQ(percentile(values, 0.02), 2.0);
  EXPECT_EQ(percentile(values, 0.98), 98.0);
  EXPECT_EQ(percentile(values, 0.0), 1.0);
  EXPECT_EQ(percentile(values, 1.0), 100.0);
  std::vector<float> none;
  EXPECT_TRUE(std::isnan(percentile(none, 0.5)));
}

TEST(RayTree, PrimaryHitReflectionAndShadowRaysOneBlockedWithItsBlockerNamed) {
  // A mirror at z = 0 faced by the camera (pixel (1, 1) of a 2x2 image
  // looks at its centre); a light above and behind the camera with a
  // sphere on the way to it, one to the side with nothing between. The
  // expected points are worked out here from the camera's ray.
  const Scene scene = parseScene(
      "camera 0 0 5  0 0 0  0 1 0  45  2 2\ndepth 1\n"
      "light 0 3 3  1 1 1\nlight 3 0 3  1 1 1\n"
      "plane 0 0 0  0 0 1  0.1 0.1 0.1  0.5 0.5 0.5  0 0 0  1 0.5\n"
      "sphere 0 1.5 1.5 0.3  0.1 0.1 0.1  0.5 0.5 0.5  0 0 0  1 0\n",
      "ray_tree.sce");
  const Camera camera(scene.camera);
  const SceneIntersector intersector(scene, TraceOptions{});
  const PixelInspection in = inspectPixel(intersector, camera, 1.0, 1.0);
  const auto describe = [](const PrimitiveRef& ref) {
    return ref.kind == ObjectKind::Sphere ? std::string("the sphere") : std::string("the mirror");
  };
  const std::vector<RaySegment> tree = rayTree(in, scene, 100.0, describe);
  const auto near = [](const Vec3& a, const Vec3& b) { return glm::length(a - b) < 1e-6; };
  const auto find = [&](RayKind kind, int level) -> const RaySegment* {
    for (const RaySegment& s : tree)
      if (s.kind == kind && s.level == level) return &s;
    return nullptr;
  };
  const Ray ray = camera.primaryRay(1.0, 1.0);
  const Vec3 hit = ray.origin + (-ray.origin.z / ray.direction.z) * ray.direction;
  const RaySegment* primary = find(RayKind::Primary, 0);
  ASSERT_TRUE(primary);
  EXPECT_TRUE(near(primary->from, Vec3(0, 0, 5)));
  EXPECT_TRUE(near(primary->to, hit));
  // The shadow ray toward (0, 3, 3) enters the sphere where
  // |hit + t d - c| = r first.
  const Vec3 d = glm::normalize(Vec3(0, 3, 3) - hit);
  const Vec3 oc = hit - Vec3(0, 1.5, 1.5);
  const double halfB = glm::dot(oc, d);
  const double entry = -halfB - std::sqrt(halfB * halfB - (glm::dot(oc, oc) - 0.09));
  const RaySegment* blocked = find(RayKind::Blocked, 0);
  ASSERT_TRUE(blocked);
  EXPECT_TRUE(near(blocked->from, hit));
  EXPECT_TRUE(near(blocked->to, hit + entry * d));
  EXPECT_NE(blocked->label.find("the sphere"), std::string::npos) << blocked->label;
  const RaySegment* past = find(RayKind::PastBlocker, 0);
  ASSERT_TRUE(past);
  EXPECT_TRUE(near(past->to, Vec3(0, 3, 3)));
  const RaySegment* lit = find(RayKind::Lit, 0);
  ASSERT_TRUE(lit);
  EXPECT_TRUE(near(lit->from, hit));
  EXPECT_TRUE(near(lit->to, Vec3(3, 0, 3)));
  // The mirror reflects the ray about its normal; it then meets nothing.
  const RaySegment* reflection = find(RayKind::Reflection, 1);
  ASSERT_TRUE(reflection) << "no reflection segment";
  EXPECT_TRUE(near(reflection->from, hit));
  const Vec3 mirrored(ray.direction.x, ray.direction.y, -ray.direction.z);
  EXPECT_NEAR(glm::dot(glm::normalize(reflection->to - reflection->from), mirrored), 1.0, 1e-9);
  EXPECT_EQ(reflection->label, "miss");
}

TEST(AbCompare, FiguresAndTheDifferenceImageFromTheChannels) {
  // Two pixels; B differs from A by 3 in one channel: MSE 9 / 6 channels.
  const Image8 a{2, 1, {0, 0, 0, 10, 20, 30}};
  const Image8 b{2, 1, {0, 0, 0, 10, 20, 33}};
  const AbComparison c = compareWithB(7, a, b);
  EXPECT_EQ(c.job, 7u);
  EXPECT_NEAR(c.difference.rmse, std::sqrt(1.5), 1e-12);
  EXPECT_NEAR(c.difference.psnr, 20.0 * std::log10(255.0 / std::sqrt(1.5)), 1e-9);
  EXPECT_EQ(c.difference.maxDifference, 3);
  EXPECT_EQ(c.differenceRgba,
            (std::vector<std::uint8_t>{0, 0, 0, 255, 0, 0, 3 * kAbDifferenceGain, 255}));
}

TEST(SceneCatalog, ListsScenesBelowAFolder) {
  const SceneFolder f = scanFolder(test::sourceDir() / "tests/app/viewer/scenes", "tests");
  EXPECT_TRUE(f.error.empty());
  ASSERT_GE(f.scenes.size(), 2u);
  EXPECT_EQ(sceneLabel(f, f.scenes[0]), "broken.sce");
  EXPECT_FALSE(scanFolder(test::sourceDir() / "no-such-folder", "x").error.empty());
}

TEST(SceneCatalog, DefaultFoldersComeInOneOrderWhereverTheViewerStartsTitledByFolder) {
  const fs::path dir = fs::weakly_canonical(test::scratchDir());
  const fs::path checkout = dir / "course" / "meshtrace", elsewhere = dir / "work";
  for (const fs::path& d : {checkout / "scenes", checkout / "build/bin",
                            dir / "course/shared/seed/scenes", elsewhere / "scenes"})
    fs::create_directories(d);
  const fs::path exe = checkout / "build/bin/viewer";
  using Roots = std::vector<std::pair<fs::path, std::string>>;
  const Roots fromCheckout = defaultSceneRoots(exe, checkout);
  EXPECT_EQ(fromCheckout, (Roots{{checkout / "scenes", "meshtrace/scenes"},
                                 {dir / "course/shared/seed/scenes", "seed/scenes"}}));
  const Roots fromElsewhere = defaultSceneRoots(exe, elsewhere);
  ASSERT_EQ(fromElsewhere.size(), 3u);
  EXPECT_EQ(Roots(fromElsewhere.begin(), fromElsewhere.begin() + 2), fromCheckout)
      << "the checkout's folders first, wherever the viewer starts";
  EXPECT_EQ(fromElsewhere[2],
            (std::pair<fs::path, std::string>{elsewhere / "scenes", "work/scenes"}))
      << "another scenes/ folder is titled by its own folder";
}

TEST(CameraControl, APastedCameraLineReadsAsTheSceneReaderReadsIt) {
  CameraSpec c;
  c.eye = Vec3(0.1, 2.25, -5.0);
  c.center = Vec3(0.0, 0.5, 0.0);
  c.fovyDegrees = 37.5;
  c.width = 320;
  c.height = 200;
  const CameraSpec back = parseCameraLine("  " + cameraLine(c) + "  # copied\n");
  EXPECT_TRUE(sameCamera(back, c)) << cameraLine(back);
  for (const char* bad :
       {"", "camera 0 0 5 0 0 0 0 1 0 45 320", "sphere 0 0 0 1",
        "camera 0 0 5 0 0 0 0 1 0 45 320 200 7", "camera 0 0 5 0 0 5 0 1 0 45 8 6"})
    EXPECT_THROW(parseCameraLine(bad), std::exception) << bad;
}

TEST(RenderProgress, TheTimeLeftFollowsThePaceOfTheAntiAliasingPasses) {
  ProgressiveStatus s;
  s.passCount = 8;
  s.passesDone = 4;
  s.passMs = {10, 20, 30, -1, -1, -1, -1, -1};
  s.exactMs = 30;
  EXPECT_FALSE(aaTimeLeftMs(s)) << "before the exact image";
  s.exactDone = true;
  EXPECT_FALSE(aaTimeLeftMs(s)) << "no pass after the exact image yet";
  s.passMs[3] = 130;  // one AA pass, 100 after the exact image; four to go
  ASSERT_TRUE(aaTimeLeftMs(s));
  EXPECT_DOUBLE_EQ(*aaTimeLeftMs(s), 400.0);
  s.passesDone = 6;
  s.passMs[4] = 230;
  s.passMs[5] = 430;  // three AA passes in 400, two to go
  EXPECT_DOUBLE_EQ(*aaTimeLeftMs(s), 2 * 400.0 / 3);
  s.finished = true;
  EXPECT_FALSE(aaTimeLeftMs(s));
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
  EXPECT_TRUE(o->sizeGiven) << "--size is taken as given, not fitted to the screen";
  EXPECT_EQ(o->overlay, Overlay::BoxHits);
  EXPECT_EQ(o->view, View::Normals);
  ASSERT_TRUE(o->pin);
  EXPECT_EQ(o->pin->second, 4);
  ASSERT_EQ(o->shading.size(), 1u);
  EXPECT_EQ(o->shading[0].second, Shading::Flat);
}

}  // namespace
}  // namespace meshtrace::viewer
