#include "meshtrace/geometry/polygon.h"

namespace meshtrace {

void appendPolygonTriangles(std::span<std::uint32_t> corners, std::vector<TriangleIndices>& out) {
  std::size_t left = corners.size();
  while (left > 3) {
    // One round: cut ears (i, i+1, i+2) for even i and keep their first
    // corners, then the one or two corners no ear ended at.
    std::size_t kept = 0, i = 0;
    for (; i + 2 < left; i += 2) {
      out.push_back({corners[i], corners[i + 1], corners[i + 2]});
      corners[kept++] = corners[i];
    }
    for (; i < left; ++i) corners[kept++] = corners[i];
    left = kept;
  }
  out.push_back({corners[0], corners[1], corners[2]});
}

}  // namespace meshtrace
