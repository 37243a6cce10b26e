#include "io/token_stream.h"

#include <cstring>
#include <string>

#include "io/text.h"
#include "meshtrace/io/input_error.h"

namespace meshtrace::text {

namespace {

constexpr std::size_t kBlockBytes = std::size_t{1} << 16;

}  // namespace

TokenStream::TokenStream(std::string_view text, const std::filesystem::path& file)
    : file_(file), data_(text.data()), end_(text.size()) {}

TokenStream::TokenStream(FileSource& source)
    : file_(source.file()),
      source_(&source),
      buffer_(new char[kBlockBytes + kMaxWordBytes]),
      data_(buffer_.get()) {}

void TokenStream::fail(const std::string& what) const {
  throw InputError::atLine(file_, line_, what);
}

bool TokenStream::refill(std::size_t& keepFrom) {
  if (!source_) return false;
  const std::size_t kept = end_ - keepFrom;
  if (kept >= kMaxWordBytes)
    fail("a word of more than " + std::to_string(kMaxWordBytes) + " bytes: not a scene file");
  std::memmove(buffer_.get(), buffer_.get() + keepFrom, kept);
  pos_ -= keepFrom;
  keepFrom = 0;
  end_ = kept + source_->read(buffer_.get() + kept, kBlockBytes);
  return end_ > kept;
}

bool TokenStream::next(Word& word) {
  for (;;) {
    if (pos_ == end_) {
      std::size_t keep = pos_;
      if (!refill(keep)) return false;
    }
    const char c = data_[pos_];
    const bool lf = c == '\n' && !afterCr_;
    afterCr_ = c == '\r';
    if (lf || c == '\r') {
      ++line_;
      inComment_ = false;
      ++pos_;
      continue;
    }
    if (c == '\0') fail(kNulByteMessage);
    if (inComment_ || isSpace(c) || c == '\n') {
      ++pos_;
      continue;
    }
    sawText_ = true;
    if (c == '#') {
      inComment_ = true;
      ++pos_;
      continue;
    }
    std::size_t start = pos_;
    for (;;) {
      while (pos_ < end_ && !endsWord(data_[pos_])) ++pos_;
      if (pos_ < end_ || !refill(start)) break;
    }
    if (pos_ < end_ && data_[pos_] == '\0') fail(kNulByteMessage);
    word = {std::string_view(data_ + start, pos_ - start), line_};
    return true;
  }
}

}  // namespace meshtrace::text
