#include "io/element_problems.h"

#include "meshtrace/util/quoted.h"

namespace meshtrace::element_problems {

std::string badCornerCount(std::int64_t corners, std::int64_t vertices) {
  if (corners < 3) return " has " + std::to_string(corners) + " corners; at least 3 are needed";
  return " has " + std::to_string(corners) + " corners, more than the " + std::to_string(vertices) +
         " vertices of the mesh";
}

std::string indexOutOfRange(std::int64_t index, std::int64_t vertices) {
  return ": vertex index " + std::to_string(index) + " out of range (the mesh has " +
         std::to_string(vertices) + " vertices)";
}

std::string nonFiniteCoordinate(std::string_view shown) {
  return " has a non-finite coordinate " + quoted(shown);
}

}  // namespace meshtrace::element_problems
