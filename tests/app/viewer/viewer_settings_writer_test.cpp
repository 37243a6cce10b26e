// The settings file is written off the UI thread, in the order asked, and
// nothing asked for is lost when the window closes.
#include <gtest/gtest.h>

#include <string>

#include "support/files.h"
#include "support/paths.h"
#include "viewer/model/settings_writer.h"

namespace meshtrace::viewer {
namespace {

namespace fs = std::filesystem;

// Settings told apart by their one recent scene.
ViewerSettings request(int n) {
  ViewerSettings s;
  s.recent.push_back("/scene" + std::to_string(n) + ".sce");
  return s;
}

TEST(SettingsWriter, TheLastRequestIsWhatTheFileHoldsOnceFlushed) {
  const fs::path file = test::scratchDir() / "config" / "viewer.txt";
  SettingsWriter writer;
  for (int i = 1; i <= 20; ++i) writer.save(request(i), file);
  writer.flush();
  EXPECT_EQ(loadSettings(file).recent, request(20).recent);
  EXPECT_EQ(writer.takeError(), "");
}

TEST(SettingsWriter, WhatIsWaitingWhenItGoesIsWritten) {
  const fs::path file = test::scratchDir() / "viewer.txt";
  {
    SettingsWriter writer;
    writer.save(request(1), file);
    writer.save(request(3), file);
  }
  EXPECT_EQ(loadSettings(file).recent, request(3).recent);
}

TEST(SettingsWriter, AFailedWriteIsReportedOnce) {
  // A folder cannot be made under a regular file.
  const fs::path blocker = test::writeFile(test::scratchDir() / "not-a-folder", "x");
  SettingsWriter writer;
  writer.save(request(1), blocker / "viewer.txt");
  writer.flush();
  EXPECT_NE(writer.takeError(), "");
  EXPECT_EQ(writer.takeError(), "") << "reported once";
}

}  // namespace
}  // namespace meshtrace::viewer
