#pragma once
// A polygon's corners into triangles: the one triangulation every mesh
// reader uses, so that a mesh read from any format has the same triangles
// in the same order.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "meshtrace/geometry/mesh.h"
#include "meshtrace/util/math.h"

namespace meshtrace {

// Appends the triangles of the polygon whose vertex indices are `corners`
// (at least 3, in order around it) to `out`: always corners.size() - 2 of
// them, so a reader can plan the room before calling, each keeping the
// polygon's winding. `corners` is the working space and is left reordered.
// With `polygons` (those of the faces appended to `out` so far, which all
// went through here), a face of four corners or more is recorded there,
// numbered by the faces before it, for tileNonConvexPolygons once the
// vertices are known. At 12 bytes a face, the records take at most half
// the triangles' room.
//
// Every other corner is cut off as an ear, (0 1 2), (2 3 4), ..., and the
// corners left are cut again, until one triangle remains. A triangle and a
// quad come out as a fan from corner 0 would make them ((0 1 2), (0 2 3)).
// For a convex polygon of n corners this is a valid triangulation, as the
// fan is, but where a fan's n - 2 slivers all meet at corner 0 and a point
// near it lies in the boxes of nearly all of them, the ears of each round
// are disjoint and twice as wide as the last round's: a point lies in the
// boxes of O(log n) triangles, and a BVH separates them.
void appendPolygonTriangles(std::span<std::uint32_t> corners, std::vector<TriangleIndices>& out,
                            std::vector<PolygonFace>* polygons = nullptr);

// What tileNonConvexPolygons did to a mesh's polygons.
struct PolygonTiling {
  std::size_t recut = 0;    // not convex, and cut again by ear clipping
  std::size_t untiled = 0;  // left as they were, though their triangles cover area outside
                            // them: they cross themselves (a bow tie, a pentagram), or
                            // need more work than allowed (kEarClipTestsPerCorner tests
                            // a corner)
};

// The ears of appendPolygonTriangles tile a convex polygon; in one that is
// not, some ear turns against the polygon and covers area outside it. For
// each of `polygons`, this projects its corners onto the plane of its
// Newell normal and, if a triangle turns the wrong way there, cuts it again
// by ear clipping, in place: the same number of triangles, each keeping the
// polygon's winding. A convex polygon keeps its triangles, at O(corners).
PolygonTiling tileNonConvexPolygons(std::span<const Vec3> vertices,
                                    std::span<const PolygonFace> polygons,
                                    std::span<TriangleIndices> triangles);

// The most point-in-triangle tests ear clipping may spend on a polygon, per
// corner: a clip tests each ear against the reflex corners left near it
// (in a grid of them, for polygons of many), so this clips any polygon
// whose ears lie near up to about this many reflex corners, a comb of
// 10,000 teeth among them, and bounds the time any file's polygons can
// take (a sunburst of 10,000 rays, its reflex corners all at its centre,
// is given up).
inline constexpr std::size_t kEarClipTestsPerCorner = 256;

}  // namespace meshtrace
