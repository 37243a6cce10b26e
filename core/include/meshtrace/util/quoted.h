#pragma once
// A piece of input shown in a message: in single quotes, at most 40
// characters, anything not printable ASCII as '?', so that a binary file or
// a huge token never floods or garbles the terminal.
#include <string>
#include <string_view>

namespace meshtrace {

std::string quoted(std::string_view token);

}  // namespace meshtrace
