#include "viewer/model/folder_browser.h"

#include "viewer/model/scene_catalog.h"

namespace meshtrace::viewer {

namespace fs = std::filesystem;

FolderBrowser::FolderBrowser(const fs::path& folder) { moveTo(folder); }

void FolderBrowser::moveTo(const fs::path& folder) {
  std::error_code ec;
  folder_ = fs::absolute(folder, ec);
  if (ec) folder_ = folder;
  if (fs::path canonical = fs::weakly_canonical(folder_, ec); !ec) folder_ = canonical;
  entries_.clear();
  if (folder_.has_parent_path() && folder_.parent_path() != folder_)
    entries_.push_back({"..", folder_.parent_path()});
  for (const fs::path& dir : subfolders(folder_))
    entries_.push_back({dir.filename().string() + "/", dir});
}

void FolderBrowser::enter(std::size_t index) {
  if (index < entries_.size()) moveTo(entries_[index].path);
}

}  // namespace meshtrace::viewer
