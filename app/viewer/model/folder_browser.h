#pragma once
// The folder browser behind the scene list: a folder, the entries offered
// in it ("..", then its subfolders), and moving through them. The listing
// is read when the folder changes, not on every frame that shows it.
#include <filesystem>
#include <string>
#include <vector>

namespace meshtrace::viewer {

struct BrowserEntry {
  std::string label;  // "..", or "name/"
  std::filesystem::path path;
};

class FolderBrowser {
 public:
  // Starts in `folder` (made absolute, so ".." always leads somewhere).
  explicit FolderBrowser(const std::filesystem::path& folder = std::filesystem::current_path());

  const std::filesystem::path& folder() const { return folder_; }
  const std::vector<BrowserEntry>& entries() const { return entries_; }

  // Moves into entry `index` of entries(); out of range does nothing.
  void enter(std::size_t index);
  void moveTo(const std::filesystem::path& folder);

 private:
  std::filesystem::path folder_;
  std::vector<BrowserEntry> entries_;
};

}  // namespace meshtrace::viewer
