// The shortcut table: no key does two things, every entry can be found in
// a menu, and every entry's command does something.
#include <gtest/gtest.h>

#include <set>

#include "viewer/model/shortcuts.h"
#include "viewer/ui/panels.h"
#include "viewer/ui/viewer_app.h"

namespace meshtrace::viewer {
namespace {

TEST(Shortcuts, NoKeyIsBoundTwiceAndEveryEntryIsInAMenuWithAKey) {
  std::vector<std::pair<Chord, std::string>> seen;
  const std::set<std::string> menus{"File", "View", "Render", "Help"};
  for (const Shortcut& s : shortcuts()) {
    EXPECT_FALSE(s.label.empty());
    EXPECT_TRUE(menus.count(s.menu)) << s.label << " in menu '" << s.menu << "'";
    EXPECT_FALSE(s.keys.empty()) << s.label;
    for (const Chord& c : s.keys) {
      for (const auto& [other, label] : seen)
        EXPECT_FALSE(other == c) << chordLabel(c) << " is bound to '" << label << "' and '"
                                 << s.label << "'";
      seen.emplace_back(c, s.label);
    }
  }
  EXPECT_EQ(chordLabel({"S", true, true}), "Ctrl+Shift+S");
}

TEST(Shortcuts, EveryCommandHasAnEntryAndEveryEntryAnAction) {
  std::set<Command> commands;
  for (const Shortcut& s : shortcuts()) commands.insert(s.command);
  EXPECT_EQ(commands.size(), static_cast<std::size_t>(Command::Help) + 1)
      << "a command no key or menu reaches";

  ViewerOptions o;
  o.noDefaultDirs = true;
  o.threads = 1;
  ViewerApp app(o, "viewer");
  ViewerState& state = app.state();
  for (const Shortcut& s : shortcuts()) EXPECT_TRUE(runCommand(state, app.display(), s)) << s.label;

  const auto run = [&](Command command, int view = 0) {
    for (const Shortcut& s : shortcuts())
      if (s.command == command && s.view == view) return runCommand(state, app.display(), s);
    return false;
  };
  ASSERT_TRUE(run(Command::ShowView, static_cast<int>(View::Depth)));
  EXPECT_EQ(state.view, View::Depth);
  state.helpOpen = false;
  run(Command::Help);
  EXPECT_TRUE(state.helpOpen);
  run(Command::Unpin);
  EXPECT_FALSE(state.helpOpen) << "Esc closes the help first";
  state.extraSamples = 0;
  run(Command::MoreSamples);
  run(Command::MoreSamples);
  EXPECT_EQ(state.extraSamples, 2);
  run(Command::FewerSamples);
  EXPECT_EQ(state.extraSamples, 1);
  EXPECT_TRUE(state.quitRequested) << "Quit ran in the loop above";
  EXPECT_TRUE(app.display().paused()) << "and Pause";
  run(Command::PauseResume);
  EXPECT_FALSE(app.display().paused());
}

}  // namespace
}  // namespace meshtrace::viewer
