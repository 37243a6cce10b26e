#pragma once
// What the viewer remembers between runs: the scenes opened last. Kept in
// $XDG_CONFIG_HOME/meshtrace/viewer.txt (~/.config when it is unset), one
// "recent PATH" line each, newest first; lines it does not know are skipped,
// so an older viewer reads a newer file.
#include <filesystem>
#include <vector>

namespace meshtrace::viewer {

struct ViewerSettings {
  std::vector<std::filesystem::path> recent;  // newest first, at most kMaxRecent
  static constexpr std::size_t kMaxRecent = 10;
};

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
