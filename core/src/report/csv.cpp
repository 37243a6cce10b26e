#include "report/csv.h"

#include "io/file_source.h"
#include "meshtrace/io/input_error.h"

namespace meshtrace::csv {

std::string field(std::string_view text) {
  if (text.find_first_of(",\"\r\n") == std::string_view::npos) return std::string(text);
  std::string out = "\"";
  for (char c : text) {
    if (c == '"') out += '"';
    out += c;
  }
  return out + "\"";
}

std::vector<Row> parse(std::string_view text, const std::filesystem::path& file) {
  std::vector<Row> rows;
  std::size_t line = 1, i = 0;
  while (i < text.size()) {
    Row row{line, {}};
    std::string value;
    for (;;) {
      if (i < text.size() && text[i] == '"') {
        const std::size_t openedOn = line;
        for (++i;; ++i) {
          if (i >= text.size())
            throw InputError::atLine(file, openedOn, "a quoted field is never closed");
          if (text[i] == '"') {
            if (i + 1 < text.size() && text[i + 1] == '"') {
              value += '"';
              ++i;
              continue;
            }
            ++i;
            break;
          }
          if (text[i] == '\n') ++line;
          value += text[i];
        }
      }
      while (i < text.size() && text[i] != ',' && text[i] != '\n' && text[i] != '\r')
        value += text[i++];
      row.fields.push_back(std::move(value));
      value.clear();
      if (i < text.size() && text[i] == ',') {
        ++i;
        continue;
      }
      if (i < text.size() && text[i] == '\r') ++i;
      if (i < text.size() && text[i] == '\n') ++i;
      ++line;
      break;
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

std::string readFile(const std::filesystem::path& file, std::uintmax_t maxBytes) {
  text::FileSource source(file, maxBytes);
  std::string bytes(source.size(), '\0');
  std::size_t got = 0;
  while (got < bytes.size()) {
    const std::size_t n = source.read(bytes.data() + got, bytes.size() - got);
    if (n == 0) break;
    got += n;
  }
  bytes.resize(got);
  return bytes;
}

}  // namespace meshtrace::csv
