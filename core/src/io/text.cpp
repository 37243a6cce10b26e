#include "io/text.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <charconv>
#include <fstream>
#include <system_error>

#include "meshtrace/io/input_error.h"

namespace meshtrace::text {

namespace {
bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }
}  // namespace

FileBytes readFile(const std::filesystem::path& file, std::uintmax_t maxBytes) {
  std::error_code ec;
  const auto status = std::filesystem::status(file, ec);
  if (ec || !std::filesystem::exists(status)) throw InputError::inFile(file, "file not found");
  if (std::filesystem::is_directory(status))
    throw InputError::inFile(file, "is a directory, not a file");
  const std::uintmax_t size = std::filesystem::file_size(file, ec);
  if (ec) throw InputError::inFile(file, "cannot determine the file size");
  if (size > maxBytes) {
    throw InputError::inFile(file, "file is " + std::to_string(size) + " bytes, more than the " +
                                       std::to_string(maxBytes) + " accepted");
  }
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError::inFile(file, "cannot open file for reading");
  FileBytes data(static_cast<std::size_t>(size));
  in.read(data.data(), static_cast<std::streamsize>(size));
  if (static_cast<std::uintmax_t>(in.gcount()) != size)
    throw InputError::inFile(file, "could not read the whole file");
  return data;
}

void requireText(std::string_view text, const std::filesystem::path& file) {
  // The first NUL byte: each block's first, the least of those.
  constexpr std::size_t kBlock = std::size_t{1} << 20;
  const std::size_t nul = tbb::parallel_reduce(
      tbb::blocked_range<std::size_t>(0, (text.size() + kBlock - 1) / kBlock),
      std::string_view::npos,
      [&](const tbb::blocked_range<std::size_t>& r, std::size_t first) {
        for (std::size_t b = r.begin(); b < r.end(); ++b) {
          const std::size_t found = text.substr(b * kBlock, kBlock).find('\0');
          if (found != std::string_view::npos) first = std::min(first, b * kBlock + found);
        }
        return first;
      },
      [](std::size_t a, std::size_t b) { return std::min(a, b); });
  if (nul != std::string_view::npos) {
    throw InputError::inFile(
        file, "binary data (a NUL byte at offset " + std::to_string(nul) + "): not a text file");
  }
}

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

bool LineReader::nextNonEmpty(std::string_view& line) {
  while (pos_ < text_.size()) {
    std::size_t end = text_.find('\n', pos_);
    if (end == std::string_view::npos) end = text_.size();
    std::string_view raw = text_.substr(pos_, end - pos_);
    pos_ = end + 1;
    ++line_;
    const std::size_t hash = raw.find('#');
    if (hash != std::string_view::npos) raw = raw.substr(0, hash);
    for (char c : raw) {
      if (!isSpace(c)) {
        line = raw;
        return true;
      }
    }
  }
  return false;
}

bool TokenReader::next(std::string_view& token) {
  while (pos_ < line_.size() && isSpace(line_[pos_])) ++pos_;
  if (pos_ >= line_.size()) return false;
  const std::size_t start = pos_;
  while (pos_ < line_.size() && !isSpace(line_[pos_])) ++pos_;
  token = line_.substr(start, pos_ - start);
  return true;
}

}  // namespace meshtrace::text
