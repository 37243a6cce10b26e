#pragma once
// What the viewer remembers between runs: the scenes opened last, the side
// panels' widths and whether they are shown, and the heights the scene list
// and the inspector's pane were dragged to. Kept in $XDG_CONFIG_HOME/meshtrace/viewer.txt
// (~/.config when it is unset), a "recent PATH" line per scene, newest
// first, "left-panel WIDTH SHOWN", "right-panel WIDTH SHOWN",
// "scene-list-height HEIGHT" and "inspector-height HEIGHT"; lines it does
// not know are skipped, so an older viewer reads a newer file.
#include <filesystem>
#include <string>
#include <vector>

namespace meshtrace::viewer {

struct SidePanel {
  float width = 0.0f;  // window pixels; 0: the default for the window's width
  bool shown = true;
  bool operator==(const SidePanel&) const = default;
};

// A camera saved under a name for one scene ("bookmark SCENE<TAB>NAME<TAB>camera ...").
struct CameraBookmark {
  std::filesystem::path scene;
  std::string name;
  std::string cameraLine;  // as camera_control.h writes and reads it
  bool operator==(const CameraBookmark&) const = default;
};

// The heights the scene list and the inspector's pane were dragged to, in
// window pixels; 0: not dragged (pane_heights.h).
struct PaneHeights {
  float sceneList = 0.0f, inspector = 0.0f;
  bool operator==(const PaneHeights&) const = default;
};

struct ViewerSettings {
  std::vector<std::filesystem::path> recent;  // newest first, at most kMaxRecent
  static constexpr std::size_t kMaxRecent = 10;
  SidePanel left, right;
  PaneHeights panes;
  std::vector<CameraBookmark> bookmarks;  // in the order they were made
};

// Saves `camera` as `name` for `scene` (absolute), replacing one of that name.
void setBookmark(ViewerSettings& settings, const std::filesystem::path& scene,
                 const std::string& name, const std::string& cameraLine);
// The bookmarks of `scene`, in order.
std::vector<CameraBookmark> bookmarksOf(const ViewerSettings& settings,
                                        const std::filesystem::path& scene);
void removeBookmark(ViewerSettings& settings, const std::filesystem::path& scene,
                    const std::string& name);

// The side panels' widths in a window `width` pixels wide: the widths
// chosen, or defaults (about a fifth and a third), 0 for a hidden one; each
// at least kMinPanel, and together leaving the image at least 40% of the
// window, so that it stays the largest thing on screen.
struct PanelWidths {
  float left, right;
};
inline constexpr float kMinPanel = 160.0f;
PanelWidths panelWidths(float width, const ViewerSettings& settings);

// The settings file's path; empty when neither $XDG_CONFIG_HOME nor $HOME is set.
std::filesystem::path settingsFile();

// Empty settings for a missing or unreadable file.
ViewerSettings loadSettings(const std::filesystem::path& file);
// Written whole or not at all (output_file.h), its folder made if missing.
// Throws std::runtime_error naming the file.
void saveSettings(const ViewerSettings& settings, const std::filesystem::path& file);

// Puts `scene` first in the recent list (absolute), once.
void addRecent(ViewerSettings& settings, const std::filesystem::path& scene);

}  // namespace meshtrace::viewer
