// Progressive rendering: coarse to fine, exact where it ends, cancellable.
#include <gtest/gtest.h>

#include "meshtrace/geometry/mesh_generators.h"
#include "meshtrace/io/mesh_writer.h"
#include "meshtrace/io/scene_parser.h"
#include "meshtrace/render/integrator.h"
#include "meshtrace/render/progressive.h"
#include "meshtrace/render/render.h"
#include "support/paths.h"

namespace meshtrace {
namespace {

std::shared_ptr<Scene> progressiveScene(int width, int height) {
  const auto dir = test::scratchDir();
  writeOff(makeTorus(Vec3(0.0, 0.6, 0.0), 1.0, 0.35, 24, 12), dir / "torus.off");
  const std::string text = "camera 0 2 5  0 0.4 0  0 1 0  45  " + std::to_string(width) + " " +
                           std::to_string(height) +
                           "\ndepth 1\nambience 0.2 0.2 0.2\nlight 3 4 3  0.9 0.9 0.9\n"
                           "mesh torus.off PHONG 0.1 0.1 0.1  0.7 0.4 0.2  0.5 0.5 0.5  30 0\n"
                           "plane 0 0 0  0 1 0  0.1 0.1 0.1  0.5 0.5 0.5  0 0 0  1 0.3\n";
  return std::make_shared<Scene>(parseScene(text, dir / "progressive.sce"));
}

std::vector<std::uint8_t> rgbOf(const ProgressiveFrame& f) {
  std::vector<std::uint8_t> rgb;
  for (std::size_t i = 0; i < f.rgba.size(); i += 4)
    rgb.insert(rgb.end(), &f.rgba[i], &f.rgba[i + 3]);
  return rgb;
}

// Renders `scene` to the end with two workers and returns the frame.
ProgressiveFrame renderToEnd(ProgressiveRenderer& renderer, const std::shared_ptr<Scene>& scene,
                             const ProgressiveSettings& settings,
                             std::vector<int>* changed = nullptr) {
  renderer.start(std::make_shared<PreparedScene>(scene, TraceOptions{}), scene->camera, settings);
  EXPECT_TRUE(renderer.waitUntilFinished(60000));
  ProgressiveFrame frame;
  const std::vector<int> tiles = renderer.update(frame);
  if (changed) *changed = tiles;
  return frame;
}

TEST(Progressive, ExactImageEqualsRender) {
  // 70x45 is not a multiple of the tile size: edge tiles are partial.
  const auto scene = progressiveScene(70, 45);
  ProgressiveRenderer renderer(2);
  ProgressiveSettings settings;
  settings.firstStep = 16;
  std::vector<int> changed;
  ProgressiveFrame frame = renderToEnd(renderer, scene, settings, &changed);
  EXPECT_EQ(changed.size(), std::size_t(frame.tilesX * frame.tilesY));
  EXPECT_EQ(rgbOf(frame), quantize(render(*scene, {})).rgb);
  const ProgressiveStatus s = renderer.status();
  EXPECT_TRUE(s.finished && s.exactDone && s.coarseDone);
  EXPECT_EQ(s.passCount, 5);  // 16, 8, 4, 2, 1
  EXPECT_EQ(s.samplesPerPixel, 1);
  EXPECT_DOUBLE_EQ(s.exactFraction, 1.0);
  EXPECT_EQ(s.counters.primaryRays, 70u * 45u);  // each pixel traced once over all passes
  EXPECT_GE(s.exactMs, s.firstCoarseMs);
  // Nothing changed since: no tiles to copy.
  EXPECT_TRUE(renderer.update(frame).empty());
}

TEST(Progressive, ExtraSamplesAverageJitteredRays) {
  const auto scene = progressiveScene(32, 24);
  ProgressiveRenderer renderer(2);
  ProgressiveSettings settings;
  settings.firstStep = 8;
  settings.extraSamples = 3;
  const ProgressiveFrame frame = renderToEnd(renderer, scene, settings);
  EXPECT_EQ(renderer.status().samplesPerPixel, 4);
  // Pixel (5, 7): the average of the exact ray and three jittered ones.
  const SceneIntersector intersector(*scene, TraceOptions{});
  const Integrator integrator(intersector);
  Counters c;
  const int x = 5, y = 7, row = 24 - 1 - y;
  Color sum = integrator.pixel(x, y, c);
  for (int k = 1; k <= 3; ++k) {
    double dx, dy;
    sampleOffset(k, dx, dy);
    EXPECT_LT(std::abs(dx), 0.5);
    EXPECT_LT(std::abs(dy), 0.5);
    sum += integrator.pixel(x + dx, y + dy, c);
  }
  const Color mean = sum / 4.0;
  for (int k = 0; k < 3; ++k) EXPECT_EQ(frame.rgba[(row * 32 + x) * 4 + k], toByte(mean[k]));
}

TEST(Progressive, AntiAliasingKeepsEachTilesExactColoursBeside) {
  const auto scene = progressiveScene(40, 30);
  ProgressiveRenderer renderer(2);
  ProgressiveSettings settings;
  settings.firstStep = 8;
  settings.extraSamples = 2;
  const ProgressiveFrame frame = renderToEnd(renderer, scene, settings);
  ASSERT_EQ(frame.exactRgba.size(), frame.rgba.size());
  ProgressiveFrame exact = frame;
  exact.rgba.assign(frame.exactRgba.begin(), frame.exactRgba.end());
  EXPECT_EQ(rgbOf(exact), quantize(render(*scene, {})).rgb);
  EXPECT_NE(rgbOf(frame), rgbOf(exact)) << "the anti-aliased colours differ at edges";

  settings.extraSamples = 0;
  EXPECT_TRUE(renderToEnd(renderer, scene, settings).exactRgba.empty())
      << "without anti-aliasing the colours are the exact ones";
}

TEST(Progressive, ProbesMatchProbePixelAndCoarseTilesStandForBlocks) {
  const auto scene = progressiveScene(40, 30);
  ProgressiveRenderer renderer(2);
  ProgressiveSettings settings;
  settings.firstStep = 8;
  settings.color = false;
  settings.probes = true;
  ProgressiveFrame frame = renderToEnd(renderer, scene, settings);
  const SceneIntersector intersector(*scene, TraceOptions{});
  for (int t = 0; t < frame.tilesX * frame.tilesY; ++t) EXPECT_EQ(frame.tileStep[t], 1);
  for (int row = 0; row < 30; row += 3)
    for (int col = 0; col < 40; col += 3) {
      const PixelProbe expected = probePixel(intersector, scene->camera, col, 30 - 1 - row);
      const PixelProbe* p = frame.probeAt(col, row);
      ASSERT_NE(p, nullptr);
      EXPECT_EQ(p->object, expected.object);
      EXPECT_EQ(p->triangle, expected.triangle);
      EXPECT_EQ(p->depth, expected.depth);
      EXPECT_EQ(p->cost, expected.cost);
    }
  // A tile at step 4 stands for pixel (5, 6) with its block's corner (4, 4).
  frame.tileStep[0] = 4;
  EXPECT_EQ(frame.probeAt(5, 6), &frame.probes[4 * 40 + 4]);
}

TEST(Progressive, RestartCancelsAndRendersTheNewCamera) {
  const auto scene = progressiveScene(64, 48);
  const auto prepared = std::make_shared<PreparedScene>(scene, TraceOptions{});
  ProgressiveRenderer renderer(2);
  ProgressiveSettings settings;
  settings.extraSamples = 50;  // long enough to be cancelled in flight
  const std::uint64_t first = renderer.start(prepared, scene->camera, settings);
  CameraSpec moved = scene->camera.spec();
  moved.eye = Vec3(1.0, 2.5, 4.0);
  settings.extraSamples = 0;
  const std::uint64_t second = renderer.start(prepared, Camera(moved), settings);
  EXPECT_GT(second, first);
  ASSERT_TRUE(renderer.waitUntilFinished(60000));
  EXPECT_EQ(renderer.status().job, second);
  ProgressiveFrame frame;
  renderer.update(frame);
  EXPECT_EQ(frame.job, second);
  Scene movedScene = *scene;
  movedScene.camera = Camera(moved);
  EXPECT_EQ(rgbOf(frame), quantize(render(movedScene, {})).rgb);
}

TEST(Progressive, CancelLeavesNoJob) {
  const auto scene = progressiveScene(16, 16);
  ProgressiveRenderer renderer(1);
  renderer.start(std::make_shared<PreparedScene>(scene, TraceOptions{}), scene->camera, {});
  renderer.cancel();
  EXPECT_EQ(renderer.status().job, 0u);
  EXPECT_TRUE(renderer.waitUntilFinished(10));
}

}  // namespace
}  // namespace meshtrace
