#pragma once
// What a load reports as it goes, for a progress display the program draws
// (the core draws nothing): the bytes of each mesh file read so far and the
// phase after reading. Meshes load side by side, so an observer is called
// from several threads at once and must be safe for that.
#include <cstdint>
#include <filesystem>
#include <string_view>

namespace meshtrace {

class LoadObserver {
 public:
  virtual ~LoadObserver() = default;

  // `bytes` more of `file`, a file of `fileBytes`, have been read. Called
  // once per piece the reader takes from the file (hundreds of KiB), never
  // per line or element.
  virtual void bytesRead(const std::filesystem::path& file, std::uint64_t bytes,
                         std::uint64_t fileBytes) = 0;
  // `file` has been read and is now in `phase` ("normals").
  virtual void phase(const std::filesystem::path& file, std::string_view phase) = 0;
};

}  // namespace meshtrace
