#pragma once
// A binary file read front to back in records: a buffer refilled from the
// file as it is consumed, each record handed out as a pointer into it.
// Only the buffer is in memory, never the whole file.
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <vector>

#include "io/file_source.h"

namespace meshtrace::text {

class ByteReader {
 public:
  // Fills the buffer of `bufferBytes` with the file's first bytes.
  ByteReader(FileSource& source, std::size_t bufferBytes);

  // What the buffer holds from the reading position on: at the start, the
  // file's first bufferBytes bytes (or all of a smaller file).
  std::string_view buffered() const { return {pos_, static_cast<std::size_t>(end_ - pos_)}; }

  // The next `n` bytes (at most the buffer's size), valid until the next
  // call; nullptr if the file ends before them.
  const char* take(std::size_t n) {
    if (static_cast<std::size_t>(end_ - pos_) < n) return refillAndTake(n);
    const char* at = pos_;
    pos_ += n;
    return at;
  }
  // Skips `n` bytes; false if the file ends before them.
  bool skip(std::uint64_t n);
  // The bytes of the file not taken yet, by the size it had when opened.
  std::uint64_t left() const;

 private:
  const char* refillAndTake(std::size_t n);

  FileSource& source_;
  std::vector<char> buffer_;
  const char* pos_ = nullptr;
  const char* end_ = nullptr;
  std::uint64_t read_ = 0;  // bytes read from the file into the buffer so far
};

}  // namespace meshtrace::text
