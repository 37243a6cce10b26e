#pragma once
// An input file opened for reading as a stream of bytes: the checks before
// the first byte is read, with messages that say what is wrong (a symlink
// loop is not "file not found"), and reads that report failure as
// InputError naming the file.
#include <cstddef>
#include <cstdint>
#include <filesystem>

namespace meshtrace {
class LoadObserver;
}

namespace meshtrace::text {

class FileSource {
 public:
  // Throws InputError naming `file` if it is missing, a symlink loop or a
  // dangling symlink, unreadable, a directory, not a regular file (a pipe
  // or device: it might never end), or larger than `maxBytes`. Each read
  // is reported to `observer` if there is one.
  FileSource(const std::filesystem::path& file, std::uintmax_t maxBytes,
             LoadObserver* observer = nullptr);
  ~FileSource();
  FileSource(const FileSource&) = delete;
  FileSource& operator=(const FileSource&) = delete;

  const std::filesystem::path& file() const { return file_; }
  // The size when the file was opened.
  std::uintmax_t size() const { return size_; }
  // Reads up to `capacity` bytes; returns how many (0 at the end).
  std::size_t read(char* out, std::size_t capacity);

 private:
  std::filesystem::path file_;
  int fd_ = -1;
  std::uintmax_t size_ = 0;
  LoadObserver* observer_ = nullptr;
};

}  // namespace meshtrace::text
