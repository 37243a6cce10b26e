#pragma once
// The progress line of meshes loading: "loading knot1m.off: 38% (19 of
// 51 MB), 0.3 s left", summed over the meshes of a scene that load side by
// side ("loading 3 meshes: ..."), then "computing normals". Drawn like the
// other progress lines (only on a terminal, never with --quiet), at most
// ten times a second, and only for loads of many megabytes, so that small
// meshes never flash a line. Cleared when destroyed.
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <map>
#include <mutex>
#include <string_view>

#include "common/progress.h"
#include "meshtrace/io/load_observer.h"

namespace meshtrace::app {

class LoadProgress : public LoadObserver {
 public:
  void bytesRead(const std::filesystem::path& file, std::uint64_t bytes,
                 std::uint64_t fileBytes) override;
  void phase(const std::filesystem::path& file, std::string_view phase) override;

 private:
  struct FileRead {
    std::uint64_t read = 0;
    std::uint64_t size = 0;
  };

  // With lock_ held: redraws the line if it is time to.
  void drawIfDue(bool phaseChanged);

  std::mutex lock_;
  std::map<std::filesystem::path, FileRead> files_;
  bool normals_ = false;                         // a mesh is past reading, in its normals
  std::chrono::steady_clock::time_point start_;  // of the first byte read
  std::chrono::steady_clock::time_point lastDraw_;
  ProgressLine line_;
};

}  // namespace meshtrace::app
