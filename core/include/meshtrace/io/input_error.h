#pragma once
// The one error type for bad input: it always names where the problem is.
#include <filesystem>
#include <stdexcept>
#include <string>

namespace meshtrace {

class InputError : public std::runtime_error {
 public:
  // `where` is "file:line" or "file: element", already formatted.
  InputError(const std::string& where, const std::string& what)
      : std::runtime_error(where + ": " + what) {}

  static InputError atLine(const std::filesystem::path& file, std::size_t line,
                           const std::string& what) {
    return InputError(file.string() + ":" + std::to_string(line), what);
  }
  static InputError inFile(const std::filesystem::path& file, const std::string& what) {
    return InputError(file.string(), what);
  }
};

}  // namespace meshtrace
