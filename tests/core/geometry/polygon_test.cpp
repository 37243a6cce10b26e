// How a polygon becomes triangles (polygon.h): n corners give n - 2
// triangles that tile a convex polygon exactly, keep its winding, leave a
// quad as the fan it always was, and overlap little enough in their boxes
// that a point of a 100k-corner disc lies in the boxes of a handful.
#include "meshtrace/geometry/polygon.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <map>
#include <numeric>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

namespace meshtrace {
namespace {

std::vector<TriangleIndices> triangulate(std::size_t corners) {
  std::vector<std::uint32_t> ring(corners);
  std::iota(ring.begin(), ring.end(), 0u);
  std::vector<TriangleIndices> triangles;
  appendPolygonTriangles(ring, triangles);
  return triangles;
}

std::vector<glm::dvec2> regularPolygon(std::size_t corners) {
  std::vector<glm::dvec2> points;
  for (std::size_t i = 0; i < corners; ++i) {
    const double a = 2.0 * M_PI * static_cast<double>(i) / static_cast<double>(corners);
    points.emplace_back(std::cos(a), std::sin(a));
  }
  return points;
}

double signedArea(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
  return 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

// A tiling of the polygon, checked without geometry: each of the polygon's
// edges is an edge of exactly one triangle, in the polygon's direction, and
// every other edge (a diagonal) of exactly two, once each way. With every
// triangle turning the polygon's way, that makes a triangulated disc.
TEST(PolygonTriangles, TileEveryPolygonOfUpTo200CornersAndKeepItsWinding) {
  for (std::size_t n = 3; n <= 200; ++n) {
    SCOPED_TRACE(n);
    const std::vector<TriangleIndices> triangles = triangulate(n);
    ASSERT_EQ(triangles.size(), n - 2);
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> directedEdges;
    const std::vector<glm::dvec2> points = regularPolygon(n);
    double area = 0.0;
    for (const TriangleIndices& t : triangles) {
      for (int k = 0; k < 3; ++k) ++directedEdges[{t[k], t[(k + 1) % 3]}];
      const double a = signedArea(points[t[0]], points[t[1]], points[t[2]]);
      EXPECT_GT(a, 0.0);
      area += a;
    }
    for (const auto& [edge, count] : directedEdges) {
      EXPECT_EQ(count, 1);
      const bool polygonEdge = (edge.first + 1) % n == edge.second;
      if (!polygonEdge) {
        EXPECT_EQ(directedEdges.count({edge.second, edge.first}), 1u);
      }
    }
    for (std::uint32_t i = 0; i < n; ++i)
      EXPECT_EQ(directedEdges.count({i, static_cast<std::uint32_t>((i + 1) % n)}), 1u);
    const double polygonArea = 0.5 * static_cast<double>(n) * std::sin(2.0 * M_PI / n);
    EXPECT_NEAR(area, polygonArea, 1e-12 * static_cast<double>(n));
  }
}

// Quads are the common polygon; they keep the diagonal from corner 0 that
// meshes read before had (and that most tools take).
TEST(PolygonTriangles, AQuadIsSplitFromItsFirstCorner) {
  const std::vector<TriangleIndices> triangles = triangulate(4);
  ASSERT_EQ(triangles.size(), 2u);
  EXPECT_EQ(triangles[0], (TriangleIndices{0, 1, 2}));
  EXPECT_EQ(triangles[1], (TriangleIndices{0, 2, 3}));
}

// A fan's slivers all meet at corner 0, so a point near it lies in nearly
// every triangle's box and no BVH can part them (3,800 triangle tests a
// ray on a 100k-corner disc). Here no point of the disc lies in more than
// 3 log2(n) boxes; the points are a grid over the disc, its centre, and
// points just inside corner 0 and corner n/2.
TEST(PolygonTriangles, APointOfAHugeDiscLiesInFewTriangleBoxes) {
  const std::size_t n = 100003;
  const std::vector<glm::dvec2> points = regularPolygon(n);
  const std::vector<TriangleIndices> triangles = triangulate(n);
  std::vector<glm::dvec4> boxes;  // min x, min y, max x, max y
  for (const TriangleIndices& t : triangles) {
    const glm::dvec2 a = points[t[0]], b = points[t[1]], c = points[t[2]];
    boxes.emplace_back(std::min({a.x, b.x, c.x}), std::min({a.y, b.y, c.y}),
                       std::max({a.x, b.x, c.x}), std::max({a.y, b.y, c.y}));
  }
  std::vector<glm::dvec2> probes = {{0.0, 0.0}, 0.999999 * points[0], 0.999999 * points[n / 2]};
  for (int y = -10; y <= 10; ++y)
    for (int x = -10; x <= 10; ++x)
      if (x * x + y * y < 100) probes.emplace_back(0.099 * x, 0.099 * y);
  std::size_t most = 0;
  for (const glm::dvec2& p : probes) {
    std::size_t inside = 0;
    for (const glm::dvec4& box : boxes)
      inside += p.x >= box.x && p.y >= box.y && p.x <= box.z && p.y <= box.w;
    most = std::max(most, inside);
  }
  EXPECT_GE(most, 1u);
  EXPECT_LE(static_cast<double>(most), 3.0 * std::log2(static_cast<double>(n)));
  std::printf("a point lies in at most %zu of %zu triangle boxes\n", most, boxes.size());
}

}  // namespace
}  // namespace meshtrace
