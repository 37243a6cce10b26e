#pragma once
// What is wrong with a vertex or a face of a mesh file, in the same words
// whatever the format. Each message follows the element's name ("face 17")
// in an InputError naming the file.
#include <cstdint>
#include <string>
#include <string_view>

namespace meshtrace::element_problems {

// A polygon lists each of its corners once: more corners than the mesh has
// vertices would only repeat them, and triangulate into as many triangles.
inline bool validCornerCount(std::int64_t corners, std::int64_t vertices) {
  return corners >= 3 && corners <= vertices;
}
// " has 2 corners; at least 3 are needed", or more than the mesh's vertices.
std::string badCornerCount(std::int64_t corners, std::int64_t vertices);

inline bool validIndex(std::int64_t index, std::int64_t vertices) {
  return index >= 0 && index < vertices;
}
// ": vertex index 7 out of range (the mesh has 3 vertices)"
std::string indexOutOfRange(std::int64_t index, std::int64_t vertices);

// " has a non-finite coordinate 'nan'", `shown` the value as the file has it.
std::string nonFiniteCoordinate(std::string_view shown);

}  // namespace meshtrace::element_problems
