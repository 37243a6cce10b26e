// A bare mesh opens as raytrace renders it: in the scene made for it
// (mesh_scene.h), said so in the scene panel, and saved as that scene
// beside the mesh under the rules of every save.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "meshtrace/io/mesh_scene.h"
#include "meshtrace/io/scene_parser.h"
#include "support/files.h"
#include "support/paths.h"
#include "viewer/model/camera_control.h"
#include "viewer/platform/drop.h"
#include "viewer/ui/panels.h"

namespace meshtrace::viewer {
namespace {

namespace fs = std::filesystem;

// The viewer's test ball alone in a fresh folder of its own.
fs::path bareBall(const std::string& name) {
  const fs::path dir = test::scratchDir() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::copy_file(test::sourceDir() / "tests/app/viewer/scenes/ball.off", dir / "ball.off");
  return dir / "ball.off";
}

// The mesh dropped on a viewer with nothing else open, once it has loaded.
void dropAndSettle(ViewerApp& app, const fs::path& file) {
  const std::string path = file.string();
  const char* paths[] = {path.c_str()};
  dropPaths(app, 1, paths);
  for (int i = 0; i < 6000 && app.state().scenes.pipeline->busy(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  app.poll();
}

ViewerOptions bareOptions() {
  ViewerOptions o;
  o.noDefaultDirs = true;
  o.threads = 1;
  return o;
}

std::string sceneMadeFor(const fs::path& mesh) {
  MemoryBudget budget(defaultMemoryLimit());
  return meshSceneText(mesh, budget);
}

TEST(BareMesh, OpensInTheSceneRaytraceMakesForIt) {
  const fs::path mesh = bareBall("viewer_bare_open");
  ViewerApp app(bareOptions(), "viewer");
  dropAndSettle(app, mesh);
  const SceneSession& session = app.state().session;
  ASSERT_TRUE(session.loaded()) << session.error();
  EXPECT_TRUE(session.generated());
  MemoryBudget budget(defaultMemoryLimit());
  const Scene raytraced = loadMeshAsScene(mesh, budget);
  EXPECT_TRUE(sameCamera(session.camera(), raytraced.camera.spec()))
      << cameraLine(session.camera()) << "\n"
      << cameraLine(raytraced.camera.spec());
  EXPECT_EQ(session.scene().planes.size(), 1u) << "the floor";
  EXPECT_EQ(session.scene().lights.size(), 1u);
  ASSERT_EQ(session.meshes().size(), 1u);
  EXPECT_EQ(session.meshes()[0].fileShading, Shading::Phong);
  EXPECT_EQ(session.meshes()[0].triangles, raytraced.meshes[0].triangles().size());
  EXPECT_EQ(app.state().sceneSavePath, (mesh.parent_path() / "ball.sce").string());
}

TEST(BareMesh, SavesItsSceneBesideTheMeshAndNeverReplacesOne) {
  const fs::path mesh = bareBall("viewer_bare_save");
  ViewerApp app(bareOptions(), "viewer");
  dropAndSettle(app, mesh);
  ViewerState& state = app.state();
  ASSERT_TRUE(state.session.loaded()) << state.session.error();
  const fs::path target = mesh.parent_path() / "ball.sce";
  save(state, app.display(), SaveKind::Scene, Existing::Refuse);
  EXPECT_EQ(test::readFileBytes(target), sceneMadeFor(mesh));
  test::expectMentions(state.message, {"saved the scene to", target.string()});
  EXPECT_TRUE(sameCamera(loadScene(target).camera.spec(), state.session.camera()));

  // The same path again: asked, not replaced.
  state.session.setVisible(0, false);
  save(state, app.display(), SaveKind::Scene, Existing::Refuse);
  ASSERT_TRUE(state.overwrite.has_value());
  EXPECT_EQ(state.overwrite->path, target);
  EXPECT_EQ(test::readFileBytes(target), sceneMadeFor(mesh));
  save(state, app.display(), SaveKind::Scene, Existing::Replace);
  EXPECT_TRUE(loadScene(target).meshes.empty()) << "the hidden mesh is a comment";
  EXPECT_NE(test::readFileBytes(target).find("# hidden in the viewer: mesh ball.off"),
            std::string::npos);

  // Opened again with its scene there, a new name is proposed.
  dropAndSettle(app, mesh);
  EXPECT_EQ(app.state().sceneSavePath, (mesh.parent_path() / "ball-2.sce").string());
}

}  // namespace
}  // namespace meshtrace::viewer
