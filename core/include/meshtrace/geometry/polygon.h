#pragma once
// A polygon's corners into triangles: the one triangulation every mesh
// reader uses, so that a mesh read from any format has the same triangles
// in the same order.
#include <span>
#include <vector>

#include "meshtrace/geometry/mesh.h"

namespace meshtrace {

// Appends the triangles of the polygon whose vertex indices are `corners`
// (at least 3, in order around it) to `out`: always corners.size() - 2 of
// them, so a reader can plan the room before calling. A fan from the first
// corner.
void appendPolygonTriangles(std::span<const std::uint32_t> corners,
                            std::vector<TriangleIndices>& out);

}  // namespace meshtrace
