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

}  // namespace meshtrace::viewer
