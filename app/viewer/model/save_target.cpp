#include "viewer/model/save_target.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>

namespace meshtrace::viewer {

namespace fs = std::filesystem;

FileExists::FileExists(const fs::path& path)
    : std::runtime_error(path.string() + " exists: not replaced"), path(path) {}

void refuseExisting(const fs::path& target, Existing existing) {
  std::error_code ec;
  if (existing == Existing::Refuse && fs::exists(fs::symlink_status(target, ec)))
    throw FileExists(target);
}

bool isCourseData(const fs::path& path) {
  std::error_code ec;
  const fs::path absolute = fs::weakly_canonical(fs::absolute(path, ec), ec);
  std::string previous;
  for (const fs::path& part : absolute) {
    if (previous == "shared" && part == "seed") return true;
    previous = part.string();
  }
  return false;
}

bool isWritableFolder(const fs::path& dir) {
  struct stat st {};
  if (::stat(dir.c_str(), &st) != 0 || !S_ISDIR(st.st_mode)) return false;
  if ((st.st_mode & (S_IWUSR | S_IWGRP | S_IWOTH)) == 0) return false;
  return ::access(dir.c_str(), W_OK | X_OK) == 0;
}

fs::path chooseSaveFolder(const std::vector<fs::path>& candidates, const fs::path& fallback) {
  std::error_code ec;
  for (const fs::path& c : candidates) {
    if (c.empty() || !isWritableFolder(c) || isCourseData(c)) continue;
    const fs::path absolute = fs::absolute(c, ec);
    return ec ? c : absolute.lexically_normal();
  }
  return fallback;
}

fs::path freeName(const fs::path& folder, const std::string& stem, const std::string& extension) {
  std::error_code ec;
  for (int n = 1;; ++n) {
    std::string name = stem;
    if (n > 1) name.append("-").append(std::to_string(n));
    const fs::path p = folder / name.append(extension);
    if (!fs::exists(fs::symlink_status(p, ec))) return p;
  }
}

std::vector<fs::path> userFolders() {
  std::vector<fs::path> folders;
  std::error_code ec;
  folders.push_back(fs::current_path(ec));
  if (const char* home = std::getenv("HOME"); home && *home) folders.emplace_back(home);
  folders.push_back(fs::temp_directory_path(ec));
  return folders;
}

}  // namespace meshtrace::viewer
