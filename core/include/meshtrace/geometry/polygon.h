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
// them, so a reader can plan the room before calling, each keeping the
// polygon's winding. `corners` is the working space and is left reordered.
//
// Every other corner is cut off as an ear, (0 1 2), (2 3 4), ..., and the
// corners left are cut again, until one triangle remains. A triangle and a
// quad come out as a fan from corner 0 would make them ((0 1 2), (0 2 3)).
// For a convex polygon of n corners this is a valid triangulation, as the
// fan is, but where a fan's n - 2 slivers all meet at corner 0 and a point
// near it lies in the boxes of nearly all of them, the ears of each round
// are disjoint and twice as wide as the last round's: a point lies in the
// boxes of O(log n) triangles, and a BVH separates them.
void appendPolygonTriangles(std::span<std::uint32_t> corners, std::vector<TriangleIndices>& out);

}  // namespace meshtrace
