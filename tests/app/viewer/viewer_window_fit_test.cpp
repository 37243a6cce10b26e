// The default window fits the screen it opens on: a 1280x800 window on a
// 1280x720 screen (no window manager to shrink it) is made 1280x720; a
// panel and a window frame leave their room; a larger screen keeps the
// size asked for.
#include <gtest/gtest.h>

#include "viewer/model/options.h"
#include "viewer/model/window_fit.h"

namespace meshtrace::viewer {
namespace {

void expectArea(const ScreenArea& a, int x, int y, int width, int height) {
  EXPECT_EQ(a.x, x);
  EXPECT_EQ(a.y, y);
  EXPECT_EQ(a.width, width);
  EXPECT_EQ(a.height, height);
}

TEST(WindowFit, TheDefaultSizeShrinksToAScreenLowerThanIt) {
  const ViewerOptions defaults;
  expectArea(fitWindow(defaults.width, defaults.height, {0, 0, 1280, 720}, {}), 0, 0, 1280, 720);
}

TEST(WindowFit, ALargerScreenKeepsTheSizeAskedFor) {
  expectArea(fitWindow(1280, 800, {0, 0, 1920, 1080}, {}), 0, 0, 1280, 800);
}

TEST(WindowFit, PanelsAndTheWindowFrameLeaveTheirRoom) {
  // A 28-pixel panel at the top of a 1366x768 screen, a frame with a
  // 30-pixel title bar and 2-pixel borders.
  const ScreenArea area{0, 28, 1366, 740};
  expectArea(fitWindow(1280, 800, area, {2, 30, 2, 2}), 2, 58, 1280, 708);
  // A second monitor to the right: the window stays on it.
  expectArea(fitWindow(1280, 800, {1920, 0, 1024, 768}, {}), 1920, 0, 1024, 768);
}

TEST(WindowFit, NoMonitorKnownLeavesTheSizeAsAsked) {
  expectArea(fitWindow(1280, 800, {}, {}), 0, 0, 1280, 800);
}

}  // namespace
}  // namespace meshtrace::viewer
