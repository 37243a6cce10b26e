#include "meshtrace/util/quoted.h"

#include <charconv>

namespace meshtrace {

std::string quoted(std::string_view token) {
  constexpr std::size_t kShown = 40;
  std::string s = "'";
  for (char c : token.substr(0, kShown)) {
    const auto u = static_cast<unsigned char>(c);
    s += (u >= 0x20 && u < 0x7f) ? c : '?';
  }
  if (token.size() > kShown) s += "...";
  return s + "'";
}

std::string shortestText(double x) {
  char buffer[32];
  const char* end = std::to_chars(buffer, buffer + sizeof buffer, x).ptr;
  return std::string(buffer, static_cast<std::size_t>(end - buffer));
}

}  // namespace meshtrace
