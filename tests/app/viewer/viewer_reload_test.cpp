// Live reload: a watched file's change is seen once; a reload keeps what
// the user changed where it still applies; a broken file keeps the last
// good scene and shows the error with its file and line.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "app/viewer/test_scenes.h"
#include "support/files.h"
#include "support/paths.h"
#include "viewer/model/file_watch.h"
#include "viewer/model/geometry_load.h"
#include "viewer/model/session.h"
#include "viewer/ui/panels.h"
#include "viewer/ui/viewer_app.h"

namespace meshtrace::viewer {
namespace {

namespace fs = std::filesystem;

// A copy of the test scenes to edit.
fs::path editableScenes(const std::string& name) {
  return test::copyOfViewerTestScenes("viewer_reload_" + name);
}

// Replaces the first `from` in the file with `to`.
void edit(const fs::path& file, const std::string& from, const std::string& to) {
  std::string text = test::readFileBytes(file);
  const std::size_t at = text.find(from);
  ASSERT_NE(at, std::string::npos) << from;
  text.replace(at, from.size(), to);
  test::writeFile(file, text);
}

TEST(FileWatch, ReportsEachChangeOnceAndAFileThatDisappears) {
  const fs::path dir = editableScenes("watch");
  FileWatch watch;
  watch.watch({dir / "viewer_test.sce", dir / "ball.off", dir / "ball.off"});
  EXPECT_EQ(watch.files().size(), 2u) << "a file named twice is watched once";
  EXPECT_TRUE(watch.changed().empty());
  edit(dir / "ball.off", "OFF", "OFF\n# edited");
  EXPECT_EQ(watch.changed(), std::vector<fs::path>{dir / "ball.off"});
  EXPECT_TRUE(watch.changed().empty()) << "reported once";
  fs::remove(dir / "viewer_test.sce");
  EXPECT_EQ(watch.changed(), std::vector<fs::path>{dir / "viewer_test.sce"});
}

TEST(Session, AReloadKeepsTheMovedCameraAndEachMeshsSwitchesByName) {
  const fs::path dir = editableScenes("session");
  const fs::path scene = dir / "viewer_test.sce";
  SceneSession session;
  session.beginOpening(scene);
  session.adopt(loadGeometry(scene));
  CameraSpec moved = session.camera();
  moved.eye = Vec3(1.0, 2.0, 3.0);
  session.setCamera(moved);
  session.setShading(0, Shading::Flat);
  session.setVisible(1, false);
  // The file's image size changes; the box goes; a new mesh named as the
  // ball comes first.
  edit(scene, "240 160", "200 100");
  edit(scene, "mesh box.off", "mesh ball.off");
  session.adoptReload(loadGeometry(scene));
  EXPECT_EQ(session.camera().eye, moved.eye);
  EXPECT_EQ(session.camera().width, 200);
  EXPECT_EQ(session.camera().height, 100);
  ASSERT_EQ(session.meshes().size(), 2u);
  EXPECT_EQ(session.meshes()[0].shading, Shading::Flat) << "the ball's switch is kept";
  EXPECT_TRUE(session.meshes()[0].visible);
  EXPECT_EQ(session.meshes()[1].name, "ball #2");
  EXPECT_TRUE(session.meshes()[1].visible) << "the hidden box is gone; nothing else is hidden";

  // A camera the user did not move follows the file.
  SceneSession still;
  still.beginOpening(scene);
  still.adopt(loadGeometry(scene));
  edit(scene, "camera 0 2.2 5.5", "camera 0 3 5.5");
  still.adoptReload(loadGeometry(scene));
  EXPECT_EQ(still.camera().eye, Vec3(0.0, 3.0, 5.5));
}

void settle(ViewerApp& app) {
  for (int i = 0; i < 6000 && app.state().scenes.pipeline->busy(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  app.poll();
}

TEST(LiveReload, AnEditReloadsKeepingTheViewAndABrokenEditKeepsTheLastGoodScene) {
  const fs::path dir = editableScenes("app");
  const fs::path scene = dir / "viewer_test.sce";
  ViewerOptions o;
  o.noDefaultDirs = true;
  o.threads = 1;
  o.scene = scene.string();
  ViewerApp app(o, "viewer");
  settle(app);
  ViewerState& state = app.state();
  ASSERT_TRUE(state.session.loaded()) << state.session.error();
  CameraSpec moved = state.session.camera();
  moved.eye = Vec3(1.0, 2.0, 4.0);
  state.session.setCamera(moved);
  state.session.setVisible(1, false);
  state.pinned = PixelRef{10, 20};
  state.view = View::Normals;
  settle(app);
  checkWatchedFiles(state);
  EXPECT_FALSE(state.reload.pending) << "nothing changed";

  edit(scene, "sphere 0.2 0.35 1.4  0.35", "sphere 0.2 0.35 1.4  0.5");
  checkWatchedFiles(state);
  EXPECT_TRUE(state.reload.pending);
  settle(app);
  ASSERT_TRUE(state.session.loaded());
  EXPECT_FALSE(state.reload.pending);
  EXPECT_EQ(state.session.scene().spheres.at(0).radius, 0.5);
  EXPECT_EQ(state.session.camera().eye, moved.eye);
  EXPECT_FALSE(state.session.meshes()[1].visible);
  EXPECT_EQ(state.pinned, (PixelRef{10, 20}));
  EXPECT_EQ(state.view, View::Normals);
  EXPECT_NE(state.message.find("reloaded"), std::string::npos) << state.message;
  settle(app);
  ASSERT_TRUE(state.scenes.render);
  EXPECT_EQ(state.scenes.render->sceneMesh, std::vector<std::uint32_t>{0})
      << "the box stays hidden";

  const auto good = state.scenes.render;
  edit(scene, "depth 1", "depth 1\nsphere 1 2");  // line 5 lacks numbers; line 6 shows it
  checkWatchedFiles(state);
  settle(app);
  EXPECT_TRUE(state.session.loaded()) << "the last good scene is kept";
  EXPECT_EQ(state.scenes.render, good) << "and its image";
  EXPECT_EQ(state.session.scene().spheres.at(0).radius, 0.5);
  test::expectMentions(state.session.reloadError(), {"viewer_test.sce:6", "(line 5)"});
  EXPECT_TRUE(state.messageIsError);

  edit(scene, "depth 1\nsphere 1 2", "depth 1");
  checkWatchedFiles(state);
  settle(app);
  EXPECT_TRUE(state.session.reloadError().empty());
  EXPECT_EQ(state.session.camera().eye, moved.eye) << "kept through the broken edit";
  EXPECT_FALSE(state.session.meshes()[1].visible);
}

}  // namespace
}  // namespace meshtrace::viewer
