#include "viewer/model/file_watch.h"

namespace meshtrace::viewer {

namespace fs = std::filesystem;

FileWatch::Seen FileWatch::look(const fs::path& file) {
  Seen s;
  s.file = file;
  std::error_code ec;
  s.time = fs::last_write_time(file, ec);
  if (ec) return s;
  s.size = fs::file_size(file, ec);
  s.exists = !ec;
  return s;
}

void FileWatch::watch(const std::vector<fs::path>& files) {
  seen_.clear();
  for (const fs::path& f : files) {
    bool listed = false;
    for (const Seen& s : seen_) listed = listed || s.file == f;
    if (!listed) seen_.push_back(look(f));
  }
}

std::vector<fs::path> FileWatch::changed() {
  std::vector<fs::path> out;
  for (Seen& s : seen_) {
    Seen now = look(s.file);
    if (now == s) continue;
    out.push_back(s.file);
    s = std::move(now);
  }
  return out;
}

std::vector<fs::path> FileWatch::files() const {
  std::vector<fs::path> out;
  for (const Seen& s : seen_) out.push_back(s.file);
  return out;
}

}  // namespace meshtrace::viewer
