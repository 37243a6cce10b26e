#include "io/vertex_line.h"

#include <cmath>
#include <string>

#include "io/element_problems.h"
#include "meshtrace/io/input_error.h"
#include "meshtrace/util/quoted.h"

namespace meshtrace::text {

Vec3 readVertexCoordinates(TokenReader& tokens, const std::filesystem::path& file, std::size_t line,
                           std::int64_t index) {
  const auto fail = [&](const std::string& what) {
    throw InputError::atLine(file, line, "vertex " + std::to_string(index) + what);
  };
  Vec3 v;
  for (int k = 0; k < 3; ++k) {
    std::string_view token;
    const NumberToken read = tokens.nextDouble(v[k], token);
    if (read == NumberToken::LineEnded) fail(" has fewer than 3 coordinates");
    if (read == NumberToken::NotANumber) fail(": " + quoted(token) + " is not a number");
    if (!std::isfinite(v[k])) fail(element_problems::nonFiniteCoordinate(token));
  }
  return v;
}

}  // namespace meshtrace::text
