// Every message reaches the window: the scene reader's warnings show on
// the message line and stay in the scene panel while the scene is open.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "app/viewer/test_scenes.h"
#include "support/files.h"
#include "support/paths.h"
#include "viewer/ui/viewer_app.h"

namespace meshtrace::viewer {
namespace {

namespace fs = std::filesystem;

// The viewer's test scene with its up vector along the view direction.
fs::path sceneWithUpAlongTheView(const std::string& name) {
  const fs::path dir = test::copyOfViewerTestScenes(name);
  std::string text = test::readFileBytes(dir / "viewer_test.sce");
  const std::string camera = "camera 0 2.2 5.5  0 0.55 0  0 1 0";
  text.replace(text.find(camera), camera.size(), "camera 0 2.2 5.5  0 0.55 0  0 -1.65 -5.5");
  test::writeFile(dir / "viewer_test.sce", text);
  return dir / "viewer_test.sce";
}

TEST(SceneWarnings, ShowOnTheMessageLineAndStayWithTheScene) {
  const fs::path scene = sceneWithUpAlongTheView("viewer_warnings");
  ViewerOptions o;
  o.noDefaultDirs = true;
  o.threads = 1;
  o.scene = scene.string();
  ViewerApp app(o, "viewer");
  for (int i = 0; i < 6000 && app.state().scenes.pipeline->busy(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  app.poll();
  const ViewerState& state = app.state();
  ASSERT_TRUE(state.session.loaded()) << state.session.error();
  ASSERT_EQ(state.session.warnings().size(), 1u);
  test::expectMentions(state.session.warnings()[0], {"viewer_test.sce:3", "parallel"});
  test::expectMentions(state.message, {"warning", "viewer_test.sce:3", "parallel"});
  EXPECT_TRUE(state.messageIsWarning);
  EXPECT_FALSE(state.messageIsError);
}

}  // namespace
}  // namespace meshtrace::viewer
