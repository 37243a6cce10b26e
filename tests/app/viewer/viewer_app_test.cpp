// The viewer app without a display: what a drop on the window, the folder
// browser and the camera's Copy button do, and the frame statistics.
#include "viewer/ui/viewer_app.h"

#include <gtest/gtest.h>
#include <imgui.h>

#include <chrono>
#include <fstream>
#include <thread>

#include "app/viewer/test_scenes.h"
#include "meshtrace/io/scene_parser.h"
#include "support/paths.h"
#include "viewer/model/camera_control.h"
#include "viewer/model/folder_browser.h"
#include "viewer/model/frame_stats.h"
#include "viewer/platform/drop.h"
#include "viewer/ui/panels.h"

namespace meshtrace::viewer {
namespace {

namespace fs = std::filesystem;

fs::path testScenes() { return test::viewerTestScenes(); }

ViewerOptions bareOptions() {
  ViewerOptions o;
  o.noDefaultDirs = true;
  o.threads = 1;
  return o;
}

// Until the background work (opening a scene, making its render scene)
// has ended, as frames would wait for it.
void settle(ViewerApp& app) {
  for (int i = 0; i < 6000 && app.state().scenes.pipeline->busy(); ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  app.poll();
}

// GLFW hands the drop callback C strings; the same function serves it here.
void drop(ViewerApp& app, const std::vector<std::string>& paths) {
  std::vector<const char*> c;
  for (const std::string& p : paths) c.push_back(p.c_str());
  dropPaths(app, static_cast<int>(c.size()), c.data());
  settle(app);
}

TEST(Drop, OpensASceneAndAddsAFolder) {
  ViewerApp app(bareOptions(), "viewer");
  drop(app, {(testScenes() / "viewer_test.sce").string()});
  EXPECT_TRUE(app.state().session.loaded()) << app.state().session.error();
  EXPECT_EQ(app.state().session.file().filename(), "viewer_test.sce");
  EXPECT_TRUE(app.state().message.empty()) << app.state().message;

  const auto dir = test::scratchDir();
  fs::copy_file(testScenes() / "viewer_test.sce", dir / "copy.sce");
  drop(app, {dir.string()});
  ASSERT_EQ(app.state().folders.size(), 1u);
  EXPECT_EQ(app.state().folders[0].scenes, std::vector<fs::path>{fs::canonical(dir) / "copy.sce"});
  drop(app, {dir.string()});
  EXPECT_EQ(app.state().folders.size(), 1u) << "a folder dropped twice is listed once";
}

// `viewer --no-default-dirs copy.sce` from the scene's folder: the folder
// listed is that one, not "not a folder: " (the empty parent of a bare
// file name).
TEST(StartFolders, ASceneNamedWithoutAFolderListsTheCurrentOne) {
  const auto dir = test::scratchDir();
  fs::copy_file(testScenes() / "viewer_test.sce", dir / "copy.sce");
  for (const char* mesh : {"ball.off", "box.off"}) fs::copy_file(testScenes() / mesh, dir / mesh);
  fs::current_path(dir);
  ViewerOptions o = bareOptions();
  o.scene = "copy.sce";
  ViewerApp app(o, "viewer");
  settle(app);
  ASSERT_EQ(app.state().folders.size(), 1u);
  EXPECT_TRUE(app.state().folders[0].error.empty()) << app.state().folders[0].error;
  EXPECT_EQ(app.state().folders[0].scenes, std::vector<fs::path>{fs::canonical(dir) / "copy.sce"});
}

TEST(Drop, RefusesAFileThatIsNotAScene) {
  ViewerApp app(bareOptions(), "viewer");
  drop(app, {(testScenes() / "viewer_test.sce").string()});
  drop(app, {(testScenes() / "viewer_test.txt").string()});
  EXPECT_TRUE(app.state().messageIsError);
  EXPECT_NE(app.state().message.find("not a .sce file, a mesh file or a folder"), std::string::npos)
      << app.state().message;
  EXPECT_NE(app.state().message.find("viewer_test.txt"), std::string::npos);
  EXPECT_EQ(app.state().session.file().filename(), "viewer_test.sce") << "the scene stays open";
  EXPECT_TRUE(app.state().session.loaded());
}

TEST(Drop, ABrokenSceneShowsItsErrorAndTheNextDropStillWorks) {
  ViewerApp app(bareOptions(), "viewer");
  // Several files at once open in turn: the broken one is shown last.
  drop(app, {(testScenes() / "viewer_test.sce").string(), (testScenes() / "broken.sce").string()});
  EXPECT_FALSE(app.state().session.loaded());
  EXPECT_NE(app.state().session.error().find("broken.sce:5"), std::string::npos)
      << app.state().session.error();
  EXPECT_TRUE(app.idle()) << "nothing renders for a scene that did not load";
  drop(app, {(testScenes() / "no-such-scene.sce").string()});
  EXPECT_FALSE(app.state().session.loaded());
  EXPECT_NE(app.state().session.error().find("no-such-scene.sce"), std::string::npos);
  drop(app, {(testScenes() / "viewer_test.sce").string()});
  EXPECT_TRUE(app.state().session.loaded());
  EXPECT_TRUE(app.state().session.error().empty());
}

TEST(FolderBrowser, ListsSubfoldersAndMovesThroughThem) {
  const auto dir = test::scratchDir();
  fs::create_directories(dir / "b" / "inner");
  fs::create_directories(dir / "a");
  fs::create_directories(dir / ".hidden");
  std::ofstream(dir / "file.sce") << "";
  FolderBrowser browser(dir);
  EXPECT_EQ(browser.folder(), fs::canonical(dir));
  std::vector<std::string> labels;
  for (const BrowserEntry& e : browser.entries()) labels.push_back(e.label);
  EXPECT_EQ(labels, (std::vector<std::string>{"..", "a/", "b/"}))
      << "parent first, then the subfolders sorted; no files, no hidden folders";
  browser.enter(2);
  EXPECT_EQ(browser.folder(), fs::canonical(dir / "b"));
  ASSERT_EQ(browser.entries().size(), 2u);
  EXPECT_EQ(browser.entries()[1].label, "inner/");
  browser.enter(0);
  EXPECT_EQ(browser.folder(), fs::canonical(dir)) << "'..' goes back up";
  browser.enter(99);
  EXPECT_EQ(browser.folder(), fs::canonical(dir)) << "out of range: no move";
  browser.moveTo(dir / "no-such-folder");
  EXPECT_EQ(browser.entries().size(), 1u) << "a missing folder lists only '..'";
}

TEST(FolderBrowser, TheRootHasNoParentEntry) {
  FolderBrowser browser(fs::path("/"));
  ASSERT_FALSE(browser.entries().empty());
  EXPECT_NE(browser.entries()[0].label, "..");
}

// ImGui's own clipboard gives null while empty.
std::string clipboard() {
  const char* text = ImGui::GetClipboardText();
  return text ? text : "";
}

TEST(CameraCopy, PutsTheCameraLineOfTheMovedCameraOnTheClipboard) {
  ImGui::CreateContext();  // no backend: ImGui keeps its own clipboard
  ViewerApp app(bareOptions(), "viewer");
  ViewerState& state = app.state();
  copyCameraLine(state);
  EXPECT_EQ(clipboard(), "") << "no scene: nothing copied";
  drop(app, {(testScenes() / "viewer_test.sce").string()});
  state.session.setCamera(orbit(state.session.camera(), 40.0, 10.0));
  copyCameraLine(state);
  const std::string copied = clipboard();
  EXPECT_EQ(copied.rfind("camera ", 0), 0u) << copied;
  EXPECT_EQ(state.message, "copied: " + copied);
  EXPECT_FALSE(state.messageIsError);
  // Pasted into a scene file, the line gives back the moved camera exactly.
  const Scene pasted = parseScene(copied + "\n", testScenes() / "pasted.sce");
  EXPECT_EQ(pasted.camera.spec().eye, state.session.camera().eye);
  EXPECT_EQ(pasted.camera.spec().center, state.session.camera().center);
  EXPECT_EQ(pasted.camera.spec().up, state.session.camera().up);
  EXPECT_EQ(pasted.camera.spec().width, state.session.camera().width);
  ImGui::DestroyContext();
}

TEST(FrameStats, NothingUntilAFrameAndThenTheLongestAndThe99thPercentile) {
  FrameStats stats;
  EXPECT_EQ(formatMs(stats.longest()), "-") << "a render that ended before any frame";
  EXPECT_EQ(formatMs(stats.percentile(99.0)), "-");
  for (int i = 1; i <= 200; ++i) stats.add(i * 0.5);  // 0.5 .. 100 ms
  EXPECT_EQ(stats.longest(), 100.0);
  EXPECT_EQ(stats.percentile(99.0), 99.0);  // the 198th of 200
  EXPECT_EQ(stats.percentile(50.0), 50.0);
  EXPECT_EQ(formatMs(stats.longest()), "100.0 ms");
  stats.clear();
  EXPECT_FALSE(stats.longest());
}

TEST(FrameStats, ARenderThatEndsBeforeTheFirstFrameShowsNoLongestFrame) {
  ViewerOptions options = bareOptions();
  options.scene = (testScenes() / "viewer_test.sce").string();
  ViewerApp app(options, "viewer");
  settle(app);
  ASSERT_TRUE(app.display().waitUntilFinished(60000));
  // The first frame comes after the render: it was not drawn while rendering.
  EXPECT_FALSE(app.frameDone(12.0));
  EXPECT_EQ(app.state().timing.renderingFrames.count(), 0u);
  EXPECT_EQ(formatMs(app.state().timing.renderingFrames.longest()), "-");
}

}  // namespace
}  // namespace meshtrace::viewer
