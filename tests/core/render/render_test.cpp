// Whole-image rendering: independent of the thread count, each pixel what
// it is alone, y = 0 the bottom row, and the bounding-box debug image.
#include "meshtrace/render/render.h"

#include <gtest/gtest.h>

#include <cmath>

#include "meshtrace/io/scene_parser.h"
#include "meshtrace/render/integrator.h"
#include "meshtrace/render/layers.h"
#include "support/files.h"
#include "support/meshes.h"
#include "support/paths.h"
#include "support/scene_snippets.h"

namespace meshtrace {
namespace {

// A scene with every kind of object, two lights and a mirror, so that every
// code path contributes to the pixels.
Scene busyScene() {
  const auto dir = test::scratchDir();
  test::writeFile(dir / "tri.off", test::kTriangleOff);
  return loadScene(test::writeFile(
      dir / "busy.sce",
      "camera 0 1 6  0 0 0  0 1 0  50  37 23\n"
      "depth 2\nbackground 0.1 0.2 0.3\nambience 0.2 0.2 0.2\n"
      "light 3 5 5  0.8 0.8 0.8\nlight -4 2 3  0.4 0.2 0.2\n"
      "sphere 1 0 0  0.8  0.1 0.1 0.1  0.7 0.2 0.2  0.5 0.5 0.5  30 0.3\n"
      "plane 0 -1 0  0 1 0  0.1 0.1 0.1  0.5 0.5 0.5  0 0 0  1 0.5\n"
      "cylinder -1.5 0 0  0.4  0 1 0  1.5  0.1 0.1 0.1  0.2 0.6 0.2  0.3 0.3 0.3  10 0\n"
      "mesh tri.off PHONG  0.1 0.1 0.1  0.2 0.2 0.7  0.3 0.3 0.3  10 0.2\n"));
}

TEST(Render, GivesTheSameImageForOneAndTwoThreads) {
  const Scene scene = busyScene();
  RenderOptions one, two;
  one.threads = 1;
  two.threads = 2;
  const Image a = render(scene, one);
  const Image b = render(scene, two);
  ASSERT_EQ(a.pixels.size(), 37u * 23u);
  EXPECT_TRUE(a.pixels == b.pixels) << "pixels must not depend on the thread count";
  int distinct = 0;  // the scene is not trivially uniform
  for (const Color& c : a.pixels) distinct += c != a.pixels[0];
  EXPECT_GT(distinct, 100);
}

TEST(Render, CountsTheSameWorkForOneAndTwoThreads) {
  const Scene scene = busyScene();
  RenderOptions one, two;
  one.threads = 1;
  two.threads = 2;
  Counters c1, c2;
  render(scene, one, &c1);
  render(scene, two, &c2);
  EXPECT_EQ(c1.primaryRays, 37u * 23u);
  EXPECT_EQ(c1.describe(), c2.describe());
}

// Shadow rays test the last blocker toward their light (LastBlockers), which
// a render task carries from pixel to pixel: the tasks' tiles, and so the
// work counted, must not depend on the thread count or the workers' timing.
TEST(Render, CountsTheSameWorkForOneAndTwoThreadsWhereBlockersCarryOver) {
  const Scene scene = test::hallScene(240, 180);
  RenderOptions one, two;
  one.threads = 1;
  two.threads = 2;
  Counters c1, c2, again;
  const Image a = render(scene, one, &c1);
  const Image b = render(scene, two, &c2);
  render(scene, two, &again);
  EXPECT_TRUE(a.pixels == b.pixels);
  EXPECT_GT(c1.lastBlockerHits, c1.shadowRays / 10);
  EXPECT_EQ(c1.describe(), c2.describe());
  EXPECT_EQ(c2.describe(), again.describe());
}

// The image traces its rays in 2x2 packets (odd edges pixel by pixel):
// primary rays, each light's shadow rays and each level's mirror reflections.
// Each pixel must still be the colour brute force gives it alone, and the
// image must cast the rays that pixel by pixel would.
void expectEachPixelAsAlone(const Scene& scene) {
  Counters packets;
  const Image image = render(scene, {}, &packets);
  const SceneIntersector brute(scene, {.accel = AccelMethod::None});
  const Integrator integrator(brute);
  Counters alone;
  int differing = 0;
  for (int row = 0; row < image.height; ++row)
    for (int x = 0; x < image.width; ++x)
      differing += integrator.pixel(x, flippedRow(row, image.height), alone) != image.at(x, row);
  EXPECT_EQ(differing, 0);
  EXPECT_EQ(packets.primaryRays, alone.primaryRays);
  EXPECT_EQ(packets.shadowRays, alone.shadowRays);
  EXPECT_EQ(packets.reflectionRays, alone.reflectionRays);
  EXPECT_GT(alone.reflectionRays, alone.primaryRays / 4);  // the mirrors take part
}

TEST(Render, GivesEachPixelTheColourItHasAlone) { expectEachPixelAsAlone(busyScene()); }

// Beyond kMaxPacketLights lights, a packet's shading goes on ray by ray.
TEST(Render, GivesEachPixelItsColourAloneWithMoreLightsThanAPacketTakes) {
  Scene scene = busyScene();
  while (scene.lights.size() <= kMaxPacketLights) {
    const double k = static_cast<double>(scene.lights.size());
    scene.lights.push_back({{std::sin(k) * 5.0, 4.0, std::cos(k) * 5.0}, Color(0.02)});
  }
  expectEachPixelAsAlone(scene);
}

TEST(Render, StoresTheBottomRowLast) {
  // A red sphere fills the upper part of the view only.
  Scene scene = parseScene(
      "camera 0 0 5  0 0 0  0 1 0  45  9 9\nambience 1 1 1\n"
      "sphere 0 3 0  1.9  1 0 0  0 0 0  0 0 0  1 0\n",
      "top.sce");
  const Image image = render(scene, {});
  EXPECT_EQ(image.at(4, 0), Color(1, 0, 0)) << "the top storage row sees the sphere";
  EXPECT_EQ(image.at(4, 8), Color(0.0)) << "the bottom row sees the background";
}

TEST(Render, MissesGiveTheBackground) {
  const Scene scene = parseScene(test::kCameraLine + "background 0.25 0.5 0.75\n", "empty.sce");
  const Image image = render(scene, {});
  for (const Color& c : image.pixels) EXPECT_EQ(c, Color(0.25, 0.5, 0.75));
}

TEST(RenderLayers, ThroughAnotherCameraAreThoseOfTheSceneSeenFromIt) {
  const Scene scene = busyScene();
  // Another view and size: the viewer's camera, once moved.
  CameraSpec moved = scene.camera.spec();
  moved.eye = Vec3(2.0, 2.5, 5.0);
  moved.width = 29;
  moved.height = 31;
  Scene fromThere = scene;
  fromThere.camera = Camera(moved);
  const SceneIntersector here(scene, {}), there(fromThere, {});
  const ExrImage through = renderLayers(here, Camera(moved), 1);
  const ExrImage seen = renderLayers(there, 1);
  ASSERT_EQ(through.width, 29);
  ASSERT_EQ(through.height, 31);
  ASSERT_EQ(through.channels.size(), seen.channels.size());
  for (std::size_t c = 0; c < seen.channels.size(); ++c) {
    EXPECT_EQ(through.channels[c].name, seen.channels[c].name);
    EXPECT_TRUE(through.channels[c].floats == seen.channels[c].floats &&
                through.channels[c].uints == seen.channels[c].uints)
        << seen.channels[c].name;
  }
}

TEST(DebugAabb, CountsTheBoxesEachPrimaryRayMeets) {
  const auto dir = test::scratchDir();
  test::writeFile(dir / "tri.off", test::kTriangleOff);
  // Two copies of the same mesh: rays through it meet two boxes, the rest none.
  const Scene scene = loadScene(
      test::writeFile(dir / "two.sce", test::kCameraLine + "mesh tri.off FLAT " + test::kMaterial +
                                           "\n" + "mesh tri.off PHONG " + test::kMaterial + "\n"));
  const BoxHitCounts counts = countBoxHits(scene, 1);
  EXPECT_EQ(counts.maxCount, 2);
  EXPECT_EQ(counts.counts[3 * 8 + 4], 2) << "the centre pixel looks at the mesh";
  EXPECT_EQ(counts.counts[0], 0) << "the corner pixel looks past it";
  const Image image = debugAabbImage(counts);
  EXPECT_EQ(image.at(4, 3), Color(1, 0, 0));
  EXPECT_EQ(image.at(0, 0), Color(0.0));
}

TEST(DebugAabb, ABoxAroundTheEyeCountsForEveryPixel) {
  const auto dir = test::scratchDir();
  test::writeFile(dir / "big.off", "OFF\n3 1 0\n-10 -10 -10\n10 10 10\n10 -10 10\n3 0 1 2\n");
  const Scene scene = loadScene(test::writeFile(
      dir / "in.sce", test::kCameraLine + "mesh big.off FLAT " + test::kMaterial + "\n"));
  const BoxHitCounts counts = countBoxHits(scene);
  for (int n : counts.counts) EXPECT_EQ(n, 1);
}

TEST(DebugAabb, ImageIsBlackWhenNoBoxIsMet) {
  BoxHitCounts counts;
  counts.width = 2;
  counts.height = 1;
  counts.counts = {0, 0};
  const Image image = debugAabbImage(counts);
  EXPECT_EQ(image.pixels, (std::vector<Color>{Color(0.0), Color(0.0)}));
}

}  // namespace
}  // namespace meshtrace
