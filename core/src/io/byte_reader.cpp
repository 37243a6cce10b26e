#include "io/byte_reader.h"

#include <algorithm>
#include <cstring>

namespace meshtrace::text {

ByteReader::ByteReader(FileSource& source, std::size_t bufferBytes)
    : source_(source), buffer_(bufferBytes) {
  const std::size_t n = source_.read(buffer_.data(), buffer_.size());
  read_ = n;
  pos_ = buffer_.data();
  end_ = pos_ + n;
}

const char* ByteReader::refillAndTake(std::size_t n) {
  if (n > buffer_.size()) return nullptr;
  const auto kept = static_cast<std::size_t>(end_ - pos_);
  std::memmove(buffer_.data(), pos_, kept);
  const std::size_t added = source_.read(buffer_.data() + kept, buffer_.size() - kept);
  read_ += added;
  pos_ = buffer_.data();
  end_ = pos_ + kept + added;
  if (kept + added < n) return nullptr;
  pos_ += n;
  return buffer_.data();
}

bool ByteReader::skip(std::uint64_t n) {
  while (n > 0) {
    const auto here = std::min<std::uint64_t>(n, static_cast<std::uint64_t>(end_ - pos_));
    pos_ += here;
    n -= here;
    if (n == 0) break;
    const std::size_t added = source_.read(buffer_.data(), buffer_.size());
    if (added == 0) return false;
    read_ += added;
    pos_ = buffer_.data();
    end_ = pos_ + added;
  }
  return true;
}

std::uint64_t ByteReader::left() const {
  const std::uint64_t taken = read_ - static_cast<std::uint64_t>(end_ - pos_);
  return source_.size() > taken ? source_.size() - taken : 0;
}

}  // namespace meshtrace::text
