#pragma once
// A piece of input shown in a message: in single quotes, at most 40
// characters, anything not printable ASCII as '?', so that a binary file or
// a huge token never floods or garbles the terminal.
#include <string>
#include <string_view>

namespace meshtrace {

std::string quoted(std::string_view token);

// A number in a message: the shortest text that reads back as it, so that
// 5e-324 shows as 5e-324, not 4.94066e-324 or 0.000000.
std::string shortestText(double x);

}  // namespace meshtrace
