// Reading a file in pieces of whole lines: wherever the pieces fall (here
// pieces of 1 to 40 bytes), they hold the file's text in order, each ends
// after a line end (a CR that may be half of a CRLF waits for the next
// piece), and a NUL stops the reading at the line that holds it.
#include "io/line_pieces.h"

#include <gtest/gtest.h>

#include <string>

#include "io/text.h"
#include "support/files.h"
#include "support/paths.h"

namespace meshtrace {
namespace {

// Every kind of line end, blank lines, a long line, and no final line end.
const std::string kText =
    "OFF\r\n3 1 0\n\n-1 -1 0\r1 -1 0\r\n\r\r\n0 1 0 # a comment that runs on and on and on\n"
    "\r3 0 1 2\r\n# last line, no end";

std::size_t linesIn(std::string_view text) {
  text::LineReader lines(text);
  std::string_view line;
  while (lines.nextNonEmpty(line)) {
  }
  return lines.lineNumber();
}

TEST(LinePieces, HoldTheTextInWholeLinesWhereverTheyFall) {
  const auto file = test::writeFile(test::scratchDir() / "text.off", kText);
  for (std::size_t bytes = 1; bytes <= 40; ++bytes) {
    text::FileSource source(file, 1 << 20);
    text::LinePieces pieces(source, bytes);
    text::LinePiece piece;
    std::string joined;
    std::size_t lines = 0;
    while (pieces.next(piece)) {
      const std::string_view t = piece.text();
      ASSERT_FALSE(t.empty()) << bytes;
      EXPECT_FALSE(piece.nulAfter());
      joined += t;
      if (joined.size() < kText.size()) {
        const bool lineEnd = t.back() == '\n' || (t.back() == '\r' && kText[joined.size()] != '\n');
        EXPECT_TRUE(lineEnd) << "piece size " << bytes << " cut a line: " << t;
      }
      lines += linesIn(t);
    }
    EXPECT_EQ(joined, kText) << "piece size " << bytes;
    EXPECT_EQ(lines, linesIn(kText)) << "piece size " << bytes;
  }
  EXPECT_EQ(linesIn(kText), 11u) << "CRLF, LF and CR each end one line";
}

TEST(LinePieces, StopAtTheLineOfTheFirstNul) {
  std::string withNul = kText;
  withNul[withNul.find("0 1 0")] = '\0';  // on line 8
  const auto file = test::writeFile(test::scratchDir() / "text.off", withNul);
  for (std::size_t bytes : {1, 7, 1000}) {
    text::FileSource source(file, 1 << 20);
    text::LinePieces pieces(source, bytes);
    text::LinePiece piece;
    std::size_t lines = 0;
    bool stopped = false;
    while (pieces.next(piece)) {
      lines += linesIn(piece.text());
      stopped = piece.nulAfter();
    }
    EXPECT_TRUE(stopped) << bytes;
    EXPECT_EQ(lines, 7u) << "the lines before the NUL's, piece size " << bytes;
  }
}

}  // namespace
}  // namespace meshtrace
