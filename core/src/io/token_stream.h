#pragma once
// The words of a scene file with their line numbers, read as they are
// needed: a mistake on line 2 of a huge file is found after one block, and
// memory stays within a block and the longest word whatever the length of
// the file or of its lines. '#' starts a comment to the end of the line;
// lines end at LF, CRLF or a CR alone.
#include <cstddef>
#include <filesystem>
#include <memory>
#include <string_view>

#include "io/file_source.h"

namespace meshtrace::text {

struct Word {
  std::string_view text;  // valid until the next call to TokenStream::next
  std::size_t line = 0;
};

class TokenStream {
 public:
  // Words longer than this are refused: no number or path comes close.
  static constexpr std::size_t kMaxWordBytes = std::size_t{1} << 16;

  // Over text already in memory that claims to come from `file`.
  TokenStream(std::string_view text, const std::filesystem::path& file);
  // Over a file, read a block at a time.
  explicit TokenStream(FileSource& source);

  // The next word; false at the end of the text. Throws InputError naming
  // the file and line at a NUL byte (a binary file) or an overlong word.
  bool next(Word& word);
  // Whether anything but white space was seen (a comment counts).
  bool sawText() const { return sawText_; }

 private:
  // Reads more text, keeping data_[keepFrom, end_) at the front of the
  // buffer; false at the end of the file.
  bool refill(std::size_t& keepFrom);
  [[noreturn]] void fail(const std::string& what) const;

  std::filesystem::path file_;
  FileSource* source_ = nullptr;
  std::unique_ptr<char[]> buffer_;
  const char* data_ = nullptr;
  std::size_t pos_ = 0, end_ = 0;
  std::size_t line_ = 1;
  bool afterCr_ = false;  // the last byte was a CR: an LF now ends no new line
  bool inComment_ = false;
  bool sawText_ = false;
};

}  // namespace meshtrace::text
