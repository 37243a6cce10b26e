#include "io/line_pieces.h"

#include <algorithm>
#include <cstring>

#include "io/text.h"

namespace meshtrace::text {

LinePieces::LinePieces(FileSource& source, std::size_t pieceBytes)
    : source_(source), pieceBytes_(pieceBytes) {}

bool LinePieces::next(LinePiece& piece) {
  if (stopped_ || (atEnd_ && carry_.empty())) return false;
  const std::size_t want = carry_.size() + pieceBytes_;
  if (piece.capacity_ < want) {
    piece.bytes_.reset(new char[want]);  // not zero-filled: the read fills it
    piece.capacity_ = want;
  }
  std::memcpy(piece.bytes_.get(), carry_.data(), carry_.size());
  std::size_t filled = carry_.size();
  carry_.clear();
  piece.nulAfter_ = false;
  for (;;) {
    const std::size_t read =
        atEnd_ ? 0 : source_.read(piece.bytes_.get() + filled, piece.capacity_ - filled);
    atEnd_ = atEnd_ || read == 0;
    const char* fresh = piece.bytes_.get() + filled;
    filled += read;
    const std::string_view text(piece.bytes_.get(), filled);
    if (const void* nul = std::memchr(fresh, '\0', read)) {
      // The lines before the NUL's line; the byte after a CR there is known.
      const auto at = static_cast<std::size_t>(static_cast<const char*>(nul) - text.data());
      piece.size_ = wholeLinesEnd(text.substr(0, at), true);
      piece.nulAfter_ = true;
      stopped_ = true;
      return true;
    }
    const std::size_t end = atEnd_ ? filled : wholeLinesEnd(text, false);
    if (end > 0 || atEnd_) {
      carry_.assign(text.substr(end));
      piece.size_ = end;
      return end > 0;
    }
    // No line end yet: a line longer than the piece. Grow it.
    const std::size_t capacity = piece.capacity_ * 2;
    std::unique_ptr<char[]> grown(new char[capacity]);
    std::memcpy(grown.get(), piece.bytes_.get(), filled);
    piece.bytes_ = std::move(grown);
    piece.capacity_ = capacity;
  }
}

}  // namespace meshtrace::text
