// The viewer saves the render's layers as raytrace does: one EXR of the
// same channels and values for the scene on screen, written by "Save
// layers" or by "Save render" to a .exr name. (Through a moved camera:
// render_test.cpp's RenderLayers test.)
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <thread>

#include "app/viewer/test_scenes.h"
#include "meshtrace/io/exr.h"
#include "meshtrace/render/layers.h"
#include "support/cli.h"
#include "support/files.h"
#include "support/paths.h"
#include "viewer/ui/panels.h"
#include "viewer/ui/viewer_app.h"

namespace meshtrace::viewer {
namespace {

namespace fs = std::filesystem;

// The viewer's test scene in a fresh folder of its own.
fs::path sceneCopy(const std::string& name) {
  return test::copyOfViewerTestScenes(name) / "viewer_test.sce";
}

// Until the scene on screen is the one built for the session's camera.
void settle(ViewerApp& app) {
  for (int i = 0; i < 6000; ++i) {
    app.poll();
    const auto& scene = app.display().renderScene();
    if (!app.state().scenes.pipeline->busy() && scene && !scene->preview) return;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
}

ExrImage raytraceExr(const fs::path& scene, const fs::path& out) {
  const auto r =
      test::runTool(test::raytraceTool(), {scene.string(), out.string()}, scene.parent_path());
  EXPECT_TRUE(r.exited && r.exitCode == 0) << test::describe(r);
  return readExr(out);
}

double at(const ExrImage& image, const std::string& name, int x, int row) {
  const ExrChannel* c = image.find(name);
  if (!c) return std::nan("");
  const std::size_t i = static_cast<std::size_t>(row) * image.width + x;
  return c->floats.empty() ? static_cast<double>(c->uints[i]) : c->floats[i];
}

// Every channel of `a` is in `b`, in the same order, with the same values.
void expectSameLayers(const ExrImage& a, const ExrImage& b) {
  ASSERT_EQ(a.width, b.width);
  ASSERT_EQ(a.height, b.height);
  ASSERT_EQ(a.channels.size(), b.channels.size());
  for (std::size_t c = 0; c < a.channels.size(); ++c) {
    const ExrChannel &x = a.channels[c], &y = b.channels[c];
    EXPECT_EQ(x.name, y.name);
    EXPECT_TRUE(x.floats == y.floats && x.uints == y.uints) << "channel " << x.name;
  }
}

// Saves and waits for the save, which renders in the background, to end.
void saveAndWait(ViewerApp& app, SaveKind kind) {
  ViewerState& state = app.state();
  save(state, app.display(), kind, Existing::Refuse);
  for (int i = 0; i < 6000 && state.layersSave->busy(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  collectLayersSave(state);
}

ViewerOptions bareOptions() {
  ViewerOptions o;
  o.noDefaultDirs = true;
  o.threads = 1;
  return o;
}

TEST(SaveLayers, WritesTheExrRaytraceWritesForTheSceneOnScreen) {
  const fs::path scene = sceneCopy("viewer_layers");
  const fs::path dir = scene.parent_path();
  ViewerOptions o = bareOptions();
  o.scene = scene.string();
  ViewerApp app(o, "viewer");
  settle(app);
  ViewerState& state = app.state();
  ASSERT_TRUE(state.session.loaded()) << state.session.error();
  state.layersPath = (dir / "viewer.exr").string();
  save(state, app.display(), SaveKind::Layers, Existing::Refuse);
  // The layers are a render of their own: the frame that asked goes on.
  test::expectMentions(state.message, {"saving the layers to"});
  for (int i = 0; i < 6000 && state.layersSave->busy(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  collectLayersSave(state);
  test::expectMentions(state.message, {"saved the layers to", (dir / "viewer.exr").string()});
  EXPECT_FALSE(state.messageIsError);

  const ExrImage viewer = readExr(dir / "viewer.exr");
  const ExrImage raytraced = raytraceExr(scene, dir / "raytrace.exr");
  expectSameLayers(viewer, raytraced);
  for (const char* name : {"R", "G", "B", "Z", "N.X", "N.Y", "N.Z", "P.X", "P.Y", "P.Z", "objectId",
                           "triangleId", "barycentric.B", "barycentric.C", "traversalCost"})
    EXPECT_NE(viewer.find(name), nullptr) << name;
  // The top-left corner sees the background; the bottom-left, the floor
  // (the plane y = 0, facing up); left of the middle, the red ball (a mesh).
  EXPECT_TRUE(std::isinf(at(viewer, "Z", 0, 0)));
  EXPECT_EQ(at(viewer, "objectId", 0, 0), kNoHitId);
  EXPECT_EQ(at(viewer, "triangleId", 20, 150), kNoHitId);
  EXPECT_NEAR(at(viewer, "P.Y", 20, 150), 0.0, 1e-5);
  EXPECT_NEAR(at(viewer, "N.Y", 20, 150), 1.0, 1e-6);
  EXPECT_LT(at(viewer, "Z", 20, 150), 10.0);
  EXPECT_NE(at(viewer, "triangleId", 95, 70), kNoHitId);
  EXPECT_GT(at(viewer, "R", 95, 70), 2 * at(viewer, "B", 95, 70)) << "the ball is red";

  // "Save render" to a .exr name writes the same file.
  state.savePath = (dir / "render.exr").string();
  saveAndWait(app, SaveKind::Render);
  expectSameLayers(readExr(dir / "render.exr"), raytraced);

  // Never over an existing file without asking.
  const std::string before = test::readFileBytes(dir / "viewer.exr");
  save(state, app.display(), SaveKind::Layers, Existing::Refuse);
  ASSERT_TRUE(state.overwrite.has_value());
  EXPECT_EQ(test::readFileBytes(dir / "viewer.exr"), before);
}

}  // namespace
}  // namespace meshtrace::viewer
