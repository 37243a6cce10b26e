#include "meshtrace/geometry/polygon.h"

namespace meshtrace {

void appendPolygonTriangles(std::span<const std::uint32_t> corners,
                            std::vector<TriangleIndices>& out) {
  for (std::size_t k = 2; k < corners.size(); ++k)
    out.push_back({corners[0], corners[k - 1], corners[k]});
}

}  // namespace meshtrace
