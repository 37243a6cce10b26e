#include "viewer/model/line_breaks.h"

namespace meshtrace::viewer {

std::vector<std::string> breakAtSpaces(const std::string& text, float firstWidth, float width,
                                       const std::function<float(const std::string&)>& measure) {
  std::vector<std::string> pieces;
  std::string line;  // with the spaces that followed its last word
  std::size_t i = 0;
  while (i < text.size()) {
    // A word and the spaces after it.
    std::size_t end = text.find(' ', i);
    end = end == std::string::npos ? text.size() : text.find_first_not_of(' ', end);
    if (end == std::string::npos) end = text.size();
    const std::string chunk = text.substr(i, end - i);
    const std::string word = chunk.substr(0, chunk.find_last_not_of(' ') + 1);
    const float limit = pieces.empty() ? firstWidth : width;
    if (!line.empty() && measure(line + word) > limit) {
      pieces.push_back(line.substr(0, line.find_last_not_of(' ') + 1));
      line.clear();
    }
    line += chunk;
    i = end;
  }
  pieces.push_back(line);
  return pieces;
}

std::vector<std::string> breakBetweenFields(
    const std::vector<std::string>& fields, const std::string& separator, float width,
    const std::function<float(const std::string&)>& measure) {
  std::vector<std::string> lines;
  for (const std::string& field : fields) {
    if (!lines.empty() && measure(lines.back() + separator + field) <= width)
      lines.back() += separator + field;
    else
      lines.push_back(field);
  }
  if (lines.empty()) lines.emplace_back();
  return lines;
}

std::string elide(const std::string& text, float width,
                  const std::function<float(const std::string&)>& measure) {
  if (measure(text) <= width) return text;
  // Whole UTF-8 characters only: never cut inside one.
  const auto characterStart = [&](std::size_t i) {
    return i >= text.size() || (static_cast<unsigned char>(text[i]) & 0xC0) != 0x80;
  };
  std::size_t keep = 1;
  while (keep < text.size() && !characterStart(keep)) ++keep;
  for (std::size_t n = keep + 1; n < text.size(); ++n) {
    if (!characterStart(n)) continue;
    if (measure(text.substr(0, n) + "...") > width) break;
    keep = n;
  }
  return text.substr(0, keep) + "...";
}

}  // namespace meshtrace::viewer
