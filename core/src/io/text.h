#pragma once
// Tokenising and number parsing shared by the scene and OFF readers. Numbers
// are parsed with std::from_chars: no locale, no iostream on the hot path.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "meshtrace/util/quoted.h"
#include "util/build_vector.h"

namespace meshtrace::text {

// A whole file's bytes. Not zero-filled before the read, and a large file
// lands on huge pages (build_vector.h): a std::string would be zero-filled
// from one thread, with a page fault every 4 KiB, before the copy, which
// doubles the time a large mesh takes to read.
class FileBytes {
 public:
  explicit FileBytes(std::size_t size) : bytes_(size) {}
  char* data() { return bytes_.data(); }
  std::string_view text() const { return {bytes_.data(), bytes_.size()}; }

 private:
  BuildVector<char> bytes_;
};

// Reads a whole file into memory. Throws InputError for a missing file, a
// directory, an unreadable file, or one larger than `maxBytes`.
FileBytes readFile(const std::filesystem::path& file, std::uintmax_t maxBytes);

// Throws InputError if the text holds a NUL byte: a binary file, not text.
// A large text is searched in parallel.
void requireText(std::string_view text, const std::filesystem::path& file);

bool parseDouble(std::string_view token, double& out);
bool parseInt64(std::string_view token, std::int64_t& out);

// Splits text into lines (LF or CRLF) with comments ('#' to end of line)
// removed, counting lines from 1.
class LineReader {
 public:
  explicit LineReader(std::string_view text) : text_(text) {}
  // The next line that has any token; false at the end of the text.
  bool nextNonEmpty(std::string_view& line);
  std::size_t lineNumber() const { return line_; }
  // Where the next line starts in the text.
  std::size_t offset() const { return std::min(pos_, text_.size()); }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_ = 0;
};

// Whitespace-separated tokens of one line.
class TokenReader {
 public:
  explicit TokenReader(std::string_view line) : line_(line) {}
  bool next(std::string_view& token);

 private:
  std::string_view line_;
  std::size_t pos_ = 0;
};

}  // namespace meshtrace::text
