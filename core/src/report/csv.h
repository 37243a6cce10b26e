#pragma once
// The CSV of the report's files (RFC 4180): fields separated by commas, a
// field holding a comma, quote or line end quoted with its quotes doubled.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace meshtrace::csv {

// `text` as one field: quoted only where it must be.
std::string field(std::string_view text);

struct Row {
  std::size_t line = 0;  // where the row starts, from 1
  std::vector<std::string> fields;
};

// The rows of `text`, read from `file`. Throws InputError naming the file
// and line of an unterminated quote.
std::vector<Row> parse(std::string_view text, const std::filesystem::path& file);

// The whole of `file` (at most `maxBytes`); throws InputError naming it.
std::string readFile(const std::filesystem::path& file, std::uintmax_t maxBytes);

}  // namespace meshtrace::csv
