// What the viewer remembers between runs: the settings file's place under
// $XDG_CONFIG_HOME, the recent scenes, and an app that keeps its settings.
#include <gtest/gtest.h>
#include <stdlib.h>

#include <chrono>
#include <thread>

#include "support/files.h"
#include "support/paths.h"
#include "viewer/model/settings.h"
#include "viewer/ui/viewer_app.h"

namespace meshtrace::viewer {
namespace {

namespace fs = std::filesystem;

TEST(Settings, LiveUnderXdgConfigHomeAndKeepTheRecentScenesNewestFirst) {
  const fs::path config = test::scratchDir() / "config";
  const char* old = std::getenv("XDG_CONFIG_HOME");
  const std::string before = old ? old : "";
  ::setenv("XDG_CONFIG_HOME", config.c_str(), 1);
  const fs::path file = settingsFile();
  if (old)
    ::setenv("XDG_CONFIG_HOME", before.c_str(), 1);
  else
    ::unsetenv("XDG_CONFIG_HOME");
  EXPECT_EQ(file, config / "meshtrace" / "viewer.txt");

  ViewerSettings s;
  for (int i = 0; i < 12; ++i) addRecent(s, "/s/" + std::to_string(i) + ".sce");
  addRecent(s, "/s/5.sce");
  ASSERT_EQ(s.recent.size(), ViewerSettings::kMaxRecent);
  EXPECT_EQ(s.recent[0], "/s/5.sce");
  EXPECT_EQ(s.recent[1], "/s/11.sce");
  EXPECT_EQ(std::count(s.recent.begin(), s.recent.end(), fs::path("/s/5.sce")), 1);

  saveSettings(s, file);
  EXPECT_EQ(loadSettings(file).recent, s.recent);
  test::writeFile(file, "from a newer viewer\nrecent /a.sce\nrecent /b.sce\n");
  EXPECT_EQ(loadSettings(file).recent, (std::vector<fs::path>{"/a.sce", "/b.sce"}));
  EXPECT_TRUE(loadSettings(config / "missing.txt").recent.empty());
}

TEST(Settings, ThePanelsWidthsAndVisibilityRoundTripAndLeaveTheImageTheLargest) {
  ViewerSettings s;
  const PanelWidths defaults = panelWidths(1280, s);
  EXPECT_GT(1280 - defaults.left - defaults.right, std::max(defaults.left, defaults.right))
      << "at 1280 wide the image is the largest";
  s.left = {250, false};
  s.right = {520, true};
  s.panes = {180, 210};
  const fs::path file = test::scratchDir() / "viewer.txt";
  saveSettings(s, file);
  const ViewerSettings back = loadSettings(file);
  EXPECT_EQ(back.left, s.left);
  EXPECT_EQ(back.right, s.right);
  EXPECT_EQ(back.panes, s.panes);
  EXPECT_EQ(panelWidths(1280, back).left, 0.0f) << "hidden";
  EXPECT_EQ(panelWidths(1280, back).right, 520.0f);
  s.left.shown = true;
  s.right.width = 2000;
  const PanelWidths squeezed = panelWidths(900, s);
  EXPECT_FLOAT_EQ(900 - squeezed.left - squeezed.right, 0.4f * 900) << "40% stays the image's";
  s.right.width = 10;
  EXPECT_EQ(panelWidths(1280, s).right, kMinPanel);
}

TEST(Settings, CameraBookmarksArePerSceneNamedOnceAndKept) {
  ViewerSettings s;
  setBookmark(s, "/s/a.sce", "front", "camera 0 0 5 0 0 0 0 1 0 45 8 6");
  setBookmark(s, "/s/b.sce", "front", "camera 1 0 5 0 0 0 0 1 0 45 8 6");
  setBookmark(s, "/s/a.sce", "top\tview", "camera 0 5 0 0 0 0 0 0 1 45 8 6");
  setBookmark(s, "/s/a.sce", "front", "camera 0 0 9 0 0 0 0 1 0 45 8 6");
  const std::vector<CameraBookmark> a = bookmarksOf(s, "/s/a.sce");
  ASSERT_EQ(a.size(), 2u);
  EXPECT_EQ(a[0].name, "front");
  EXPECT_EQ(a[0].cameraLine, "camera 0 0 9 0 0 0 0 1 0 45 8 6") << "the name's camera replaced";
  EXPECT_EQ(a[1].name, "top view") << "a tab would break the file's line";

  const fs::path file = test::scratchDir() / "viewer.txt";
  saveSettings(s, file);
  EXPECT_EQ(loadSettings(file).bookmarks, s.bookmarks);
  removeBookmark(s, "/s/a.sce", "front");
  EXPECT_EQ(bookmarksOf(s, "/s/a.sce").size(), 1u);
  EXPECT_EQ(bookmarksOf(s, "/s/b.sce").size(), 1u) << "another scene's of that name stays";
}

TEST(Settings, AnAppThatKeepsThemRemembersEachSceneItOpens) {
  const fs::path file = test::scratchDir() / "viewer.txt";
  const fs::path scene = test::sourceDir() / "tests/app/viewer/scenes/viewer_test.sce";
  ViewerOptions o;
  o.noDefaultDirs = true;
  o.threads = 1;
  o.scene = scene.string();
  {
    ViewerApp app(o, "viewer");
    app.useSettings(file);
    for (int i = 0; i < 6000 && app.state().scenes.pipeline->busy(); ++i)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    app.poll();
    ASSERT_TRUE(app.state().session.loaded());
  }
  EXPECT_EQ(loadSettings(file).recent, std::vector<fs::path>{scene.lexically_normal()});
}

}  // namespace
}  // namespace meshtrace::viewer
