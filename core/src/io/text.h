#pragma once
// Tokenising and number parsing shared by the scene and OFF readers. Numbers
// are parsed with std::from_chars: no locale, no iostream on the hot path.
//
// Lines end at LF, CRLF or a CR alone (as editors show a stray CR): a CR
// inside a line never silently joins two lines into one.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "meshtrace/util/quoted.h"

namespace meshtrace::text {

// What a NUL byte in a text file means.
inline constexpr const char* kNulByteMessage = "binary data (a NUL byte): not a text file";

inline bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }
// What ends a word of a scene file: white space, a line end, a comment's
// '#', or a NUL (refused where it is met).
inline bool endsWord(char c) { return isSpace(c) || c == '\n' || c == '#' || c == '\0'; }

bool parseDouble(std::string_view token, double& out);
bool parseInt64(std::string_view token, std::int64_t& out);

// Where the whole lines of `text` end: just after its last line end, or 0
// if it holds none. A CR as the last byte may be the first half of a CRLF
// whose LF is still unread, so it ends a line only if `crAtEndEndsALine`.
std::size_t wholeLinesEnd(std::string_view text, bool crAtEndEndsALine);

// The number of line ends in `text`, counted as LineReader counts them.
std::size_t countLineEnds(std::string_view text);

// Splits text into lines with comments ('#' to end of line) removed,
// counting lines from 1.
// Whether any CR in `text` is not the first half of a CRLF.
bool hasLoneCr(std::string_view text);

class LineReader {
 public:
  explicit LineReader(std::string_view text) : LineReader(text, hasLoneCr(text)) {}
  // With hasLoneCr(text) known: lines are looked at for a CR only if true.
  LineReader(std::string_view text, bool loneCr);
  // The next line that has any token; false at the end of the text.
  bool nextNonEmpty(std::string_view& line);
  std::size_t lineNumber() const { return line_; }
  // Where the next line starts in the text.
  std::size_t offset() const { return pos_; }

 private:
  std::string_view text_;
  bool loneCr_;
  bool comments_;  // whether the text has a '#' at all: lines are searched for one only if so
  std::size_t pos_ = 0;
  std::size_t line_ = 0;
};

// What reading a token as a number found.
enum class NumberToken { Read, LineEnded, NotANumber };

// Whitespace-separated tokens of one line.
class TokenReader {
 public:
  explicit TokenReader(std::string_view line) : line_(line) {}
  bool next(std::string_view& token);
  // The first byte of the next token, which is not read; '\0' at the end of
  // the line.
  char peek() { return skipSpaces() ? line_[pos_] : '\0'; }
  // The next token as parseInt64 or parseDouble would read it, parsed
  // where it stands rather than found first and parsed after: a mesh's
  // text is mostly numbers. `token` is set to the token read, unless the
  // line ended.
  NumberToken nextInt64(std::int64_t& out, std::string_view& token);
  NumberToken nextDouble(double& out, std::string_view& token);
  // The integer before the first '/' of the next token, or the whole token
  // without one (an OBJ corner: "7", "7/2", "7//5", "7/2/5"), as parseInt64
  // reads that part; `token` is set to the whole token.
  NumberToken nextLeadingInt64(std::int64_t& out, std::string_view& token);

 private:
  NumberToken nextInteger(std::int64_t& out, std::string_view& token, bool toSlash);
  // Skips spaces: false at the end of the line.
  bool skipSpaces();
  // The token from the current position, which is then after it.
  std::string_view rest();

  std::string_view line_;
  std::size_t pos_ = 0;
};

}  // namespace meshtrace::text
