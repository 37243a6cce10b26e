#pragma once
// Whether files changed since they were last looked at, by polling their
// modification time and size: a few stat calls, cheap enough to make from
// the frame loop, and the same on every platform. A file that disappears
// or reappears counts as changed.
#include <cstdint>
#include <filesystem>
#include <vector>

namespace meshtrace::viewer {

class FileWatch {
 public:
  // Watches `files` from their state now.
  void watch(const std::vector<std::filesystem::path>& files);
  void clear() { seen_.clear(); }
  // The watched files whose state differs from the one recorded; records
  // the new state, so each change is reported once.
  std::vector<std::filesystem::path> changed();
  std::vector<std::filesystem::path> files() const;

 private:
  struct Seen {
    std::filesystem::path file;
    bool exists = false;
    std::filesystem::file_time_type time;
    std::uintmax_t size = 0;
    bool operator==(const Seen&) const = default;
  };
  static Seen look(const std::filesystem::path& file);
  std::vector<Seen> seen_;
};

}  // namespace meshtrace::viewer
