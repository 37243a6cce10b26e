#include "io/text.h"

#include <algorithm>
#include <charconv>
#include <cstring>
#include <system_error>

namespace meshtrace::text {

bool parseDouble(std::string_view token, double& out) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, out);
  return ec == std::errc() && ptr == end && !token.empty();
}

bool parseInt64(std::string_view token, std::int64_t& out) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const char* end = token.data() + token.size();
  const auto [ptr, ec] = std::from_chars(token.data(), end, out);
  return ec == std::errc() && ptr == end && !token.empty();
}

std::size_t wholeLinesEnd(std::string_view text, bool crAtEndEndsALine) {
  std::size_t n = text.size();
  if (!crAtEndEndsALine && n > 0 && text[n - 1] == '\r') --n;
  const auto after = [&](const void* p) {
    return p ? static_cast<std::size_t>(static_cast<const char*>(p) - text.data()) + 1 : 0;
  };
  // A CR before the last LF may be half of a CRLF; one after it is alone
  // (the byte after it is known and is no LF): either way the later wins.
  return std::max(after(::memrchr(text.data(), '\n', n)), after(::memrchr(text.data(), '\r', n)));
}

std::size_t countLineEnds(std::string_view text) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < text.size(); ++i)
    n += text[i] == '\n' || (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n'));
  return n;
}

bool hasLoneCr(std::string_view text) {
  const char* end = text.data() + text.size();
  for (const char* p = text.data();; ++p) {
    p = static_cast<const char*>(std::memchr(p, '\r', static_cast<std::size_t>(end - p)));
    if (!p) return false;
    if (p + 1 == end || p[1] != '\n') return true;
  }
}

LineReader::LineReader(std::string_view text, bool loneCr)
    : text_(text),
      loneCr_(loneCr),
      comments_(std::memchr(text.data(), '#', text.size()) != nullptr) {}

bool LineReader::nextNonEmpty(std::string_view& line) {
  while (pos_ < text_.size()) {
    const char* begin = text_.data() + pos_;
    const std::size_t left = text_.size() - pos_;
    const auto* lf = static_cast<const char*>(std::memchr(begin, '\n', left));
    std::size_t length = lf ? static_cast<std::size_t>(lf - begin) : left;
    std::size_t next = lf ? length + 1 : left;
    // A CR ends the line too, unless it is the CR of a CRLF.
    const void* cr = loneCr_ ? std::memchr(begin, '\r', length) : nullptr;
    if (cr) {
      const auto at = static_cast<std::size_t>(static_cast<const char*>(cr) - begin);
      if (!lf || at + 1 < length) length = at, next = at + 1;
    }
    std::string_view raw(begin, length);
    pos_ += next;
    ++line_;
    if (comments_) {
      const std::size_t hash = raw.find('#');
      if (hash != std::string_view::npos) raw = raw.substr(0, hash);
    }
    for (char c : raw) {
      if (!isSpace(c)) {
        line = raw;
        return true;
      }
    }
  }
  return false;
}

bool TokenReader::skipSpaces() {
  const char* p = line_.data() + pos_;
  const char* end = line_.data() + line_.size();
  while (p < end && isSpace(*p)) ++p;
  pos_ = static_cast<std::size_t>(p - line_.data());
  return p < end;
}

std::string_view TokenReader::rest() {
  const std::size_t start = pos_;
  while (pos_ < line_.size() && !isSpace(line_[pos_])) ++pos_;
  return line_.substr(start, pos_ - start);
}

bool TokenReader::next(std::string_view& token) {
  if (!skipSpaces()) return false;
  token = rest();
  return true;
}

NumberToken TokenReader::nextInt64(std::int64_t& out, std::string_view& token) {
  return nextInteger(out, token, false);
}

NumberToken TokenReader::nextLeadingInt64(std::int64_t& out, std::string_view& token) {
  return nextInteger(out, token, true);
}

NumberToken TokenReader::nextInteger(std::int64_t& out, std::string_view& token, bool toSlash) {
  if (!skipSpaces()) return NumberToken::LineEnded;
  // Up to 18 digits cannot overflow; a token that is not only such digits
  // (a sign, more digits, anything else) is left to parseInt64.
  const char* start = line_.data() + pos_;
  const char* end = line_.data() + line_.size();
  const char* last = start + std::min<std::ptrdiff_t>(18, end - start);
  const char* p = start;
  std::int64_t value = 0;
  // Two digits a step: the chain of dependent multiply-adds, which bounds
  // the speed here, is half as long.
  for (; last - p >= 2; p += 2) {
    const auto high = static_cast<unsigned>(p[0] - '0'), low = static_cast<unsigned>(p[1] - '0');
    if (high > 9 || low > 9) break;
    value = value * 100 + static_cast<std::int64_t>(high * 10 + low);
  }
  if (p < last) {
    const auto digit = static_cast<unsigned>(*p - '0');
    if (digit <= 9) value = value * 10 + static_cast<std::int64_t>(digit), ++p;
  }
  if (p > start && (p == end || isSpace(*p) || (toSlash && *p == '/'))) {
    out = value;
    if (toSlash) {
      token = rest();
    } else {
      token = std::string_view(start, static_cast<std::size_t>(p - start));
      pos_ = static_cast<std::size_t>(p - line_.data());
    }
    return NumberToken::Read;
  }
  token = rest();
  return parseInt64(toSlash ? token.substr(0, token.find('/')) : token, out)
             ? NumberToken::Read
             : NumberToken::NotANumber;
}

NumberToken TokenReader::nextDouble(double& out, std::string_view& token) {
  if (!skipSpaces()) return NumberToken::LineEnded;
  // from_chars stops at the first byte no number can hold, a space among
  // them; a number that ends where its token ends is the token's value.
  const std::size_t start = pos_;
  const char* end = line_.data() + line_.size();
  const auto [ptr, ec] = std::from_chars(line_.data() + start, end, out);
  if (ec == std::errc() && (ptr == end || isSpace(*ptr))) {
    pos_ = static_cast<std::size_t>(ptr - line_.data());
    token = line_.substr(start, pos_ - start);
    return NumberToken::Read;
  }
  token = rest();
  return parseDouble(token, out) ? NumberToken::Read : NumberToken::NotANumber;
}

}  // namespace meshtrace::text
