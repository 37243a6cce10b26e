#pragma once
// A text file read in order, in pieces of whole lines, without holding more
// of it than the pieces in use: what lets a reader check a huge file as it
// streams. Each piece is checked for NUL bytes as it is read; at the first,
// reading stops, and the piece before it says so.
#include <cstddef>
#include <memory>
#include <string>
#include <string_view>

#include "io/file_source.h"

namespace meshtrace::text {

// Whole lines of the file, in a buffer that is reused from piece to piece.
class LinePiece {
 public:
  std::string_view text() const { return {bytes_.get(), size_}; }
  // Whether the line after this piece holds a NUL byte: a binary file, the
  // end of what is read.
  bool nulAfter() const { return nulAfter_; }

 private:
  friend class LinePieces;
  std::unique_ptr<char[]> bytes_;
  std::size_t capacity_ = 0;
  std::size_t size_ = 0;
  bool nulAfter_ = false;
};

// A piece as a pipeline's stages see it (piece_pipeline.h), whatever a
// reader adds to it: its lines and their place in the file.
struct PieceChunk {
  LinePiece piece;
  std::size_t begin = 0;       // where its lines start in the piece
  std::size_t lines = 0;       // all its lines
  std::size_t lineBefore = 0;  // the number of the line before its first

  std::string_view text() const { return piece.text().substr(begin); }
};

class LinePieces {
 public:
  // Pieces of about `pieceBytes` (more for a longer line).
  LinePieces(FileSource& source, std::size_t pieceBytes);

  // Fills `piece` with the next whole lines; false when nothing is left.
  // A piece with nulAfter() ends the file's pieces and may hold no line.
  bool next(LinePiece& piece);

 private:
  FileSource& source_;
  std::size_t pieceBytes_;
  std::string carry_;  // the start of a line the last piece could not hold
  bool atEnd_ = false;
  bool stopped_ = false;
};

}  // namespace meshtrace::text
