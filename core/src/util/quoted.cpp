#include "meshtrace/util/quoted.h"

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

}  // namespace meshtrace
