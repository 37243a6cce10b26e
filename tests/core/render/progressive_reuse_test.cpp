// Progressive rendering across jobs: storage handed from one job to the
// next and a viewer's frame kept between jobs still give the exact images;
// each pass reports itself once; paused workers wait and come back.
#include <gtest/gtest.h>

#include <algorithm>
#include <mutex>

#include "meshtrace/io/image.h"
#include "meshtrace/io/scene_parser.h"
#include "meshtrace/render/inspect.h"
#include "meshtrace/render/progressive.h"
#include "meshtrace/render/render.h"
#include "support/paths.h"

namespace meshtrace {
namespace {

std::shared_ptr<Scene> spheresOnAFloor() {
  return std::make_shared<Scene>(
      parseScene("camera 0 1.5 5  0 0.5 0  0 1 0  45  50 38\ndepth 2\nambience 0.2 0.2 0.2\n"
                 "light 3 4 3  0.9 0.9 0.9\n"
                 "sphere -0.6 0.5 0  0.5  0.1 0.1 0.1  0.7 0.3 0.2  0.5 0.5 0.5  30 0.3\n"
                 "sphere 0.7 0.4 0.5  0.4  0.1 0.1 0.1  0.2 0.4 0.8  0.5 0.5 0.5  30 0\n"
                 "plane 0 0 0  0 1 0  0.1 0.1 0.1  0.5 0.5 0.5  0 0 0  1 0.2\n",
                 test::scratchDir() / "spheres.sce"));
}

Camera movedCamera(const Scene& scene, double x) {
  CameraSpec c = scene.camera.spec();
  c.eye = Vec3(x, 2.0, 4.5);
  return Camera(c);
}

std::vector<std::uint8_t> rgbOf(const ProgressiveFrame& f) {
  std::vector<std::uint8_t> rgb;
  for (std::size_t i = 0; i < f.rgba.size(); i += 4)
    rgb.insert(rgb.end(), &f.rgba[i], &f.rgba[i + 3]);
  return rgb;
}

std::vector<std::uint8_t> renderThrough(const Scene& scene, const Camera& camera) {
  Scene moved = scene;
  moved.camera = camera;
  return quantize(render(moved, {})).rgb;
}

// Two workers rendering one scene at first step 8.
class ProgressiveReuse : public ::testing::Test {
 protected:
  // Renders through `camera` to the end and brings `frame` up to date.
  void renderToEnd(const Camera& camera, const ProgressiveSettings& settings,
                   ProgressiveFrame& frame) {
    renderer.start(prepared, camera, settings);
    ASSERT_TRUE(renderer.waitUntilFinished(60000));
    renderer.update(frame);
  }

  std::shared_ptr<Scene> scene = spheresOnAFloor();
  std::shared_ptr<PreparedScene> prepared = std::make_shared<PreparedScene>(scene, TraceOptions{});
  ProgressiveRenderer renderer{2};
  ProgressiveSettings colour{.firstStep = 8};
};

TEST_F(ProgressiveReuse, ConsecutiveJobsAndAKeptFrameGiveTheExactImages) {
  ProgressiveFrame frame;  // one frame for every job, as a viewer keeps it
  for (double x : {0.0, 1.5, -2.0, 0.5}) {
    const Camera camera = movedCamera(*scene, x);
    renderToEnd(camera, colour, frame);
    EXPECT_EQ(rgbOf(frame), renderThrough(*scene, camera)) << "eye x " << x;
  }
}

TEST_F(ProgressiveReuse, ProbesAfterAColourJobAreThoseOfTheNewCamera) {
  ProgressiveFrame frame;
  renderToEnd(scene->camera, colour, frame);
  ProgressiveSettings probes = colour;
  probes.color = false;
  probes.probes = true;
  const Camera camera = movedCamera(*scene, 1.0);
  renderToEnd(camera, probes, frame);
  const SceneIntersector intersector(*scene, TraceOptions{});
  for (int row = 0; row < frame.height; ++row)
    for (int col = 0; col < frame.width; ++col) {
      const PixelProbe expected =
          probePixel(intersector, camera, col, flippedRow(row, frame.height));
      const PixelProbe* p = frame.probeAt(col, row);
      ASSERT_NE(p, nullptr);
      EXPECT_EQ(p->object, expected.object) << col << "," << row;
      EXPECT_EQ(p->depth, expected.depth) << col << "," << row;
    }
}

TEST_F(ProgressiveReuse, EachPassReportsOnceAndSaysWhatItCompleted) {
  std::mutex mutex;
  std::vector<PassFinished> reported;
  ProgressiveRenderer reporting(2, {}, [&](const PassFinished& p) {
    std::lock_guard<std::mutex> lock(mutex);
    reported.push_back(p);
  });
  ProgressiveSettings settings = colour;  // passes at steps 8, 4, 2, 1, then two AA passes
  settings.extraSamples = 2;
  reporting.start(prepared, scene->camera, settings);
  ASSERT_TRUE(reporting.waitUntilFinished(60000));
  std::lock_guard<std::mutex> lock(mutex);
  ASSERT_EQ(reported.size(), 6u);
  std::sort(reported.begin(), reported.end(),
            [](const PassFinished& a, const PassFinished& b) { return a.pass < b.pass; });
  for (int pass = 0; pass < 6; ++pass) {
    EXPECT_EQ(reported[pass].pass, pass);
    EXPECT_EQ(reported[pass].coarse, pass == 0);
    EXPECT_EQ(reported[pass].exact, pass == 3);
    EXPECT_EQ(reported[pass].last, pass == 5);
  }
}

TEST_F(ProgressiveReuse, PausedWorkersWaitAndResumeAndCancellingThemDoesNotHang) {
  auto paused = std::make_unique<ProgressiveRenderer>(2);
  paused->pauseWorkers(2);
  paused->start(prepared, scene->camera, {});
  EXPECT_FALSE(paused->waitUntilFinished(100)) << "every worker paused: no progress";
  EXPECT_EQ(paused->status().passesDone, 0);
  paused->pauseWorkers(1);  // one worker carries on alone
  ASSERT_TRUE(paused->waitUntilFinished(60000));
  ProgressiveFrame frame;
  paused->update(frame);
  EXPECT_EQ(rgbOf(frame), renderThrough(*scene, scene->camera));

  paused->pauseWorkers(2);
  paused->start(prepared, movedCamera(*scene, 1.0), {});
  paused->start(prepared, movedCamera(*scene, 2.0), {});  // cancels a paused job
  paused.reset();  // and stopping with paused workers returns
}

}  // namespace
}  // namespace meshtrace
