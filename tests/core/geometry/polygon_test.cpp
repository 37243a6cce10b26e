// How a polygon becomes triangles (polygon.h): n corners give n - 2
// triangles that tile a convex polygon exactly, keep its winding, leave a
// quad as the fan it always was, and overlap little enough in their boxes
// that a point of a 100k-corner disc lies in the boxes of a handful.
#include "meshtrace/geometry/polygon.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <glm/glm.hpp>
#include <map>
#include <numeric>
#include <random>
#include <utility>
#include <vector>

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

// Faces of 3 to 7 corners in a mixed order: the records numbered as they
// go lead each triangle back to its face, counted here face by face.
TEST(PolygonTriangles, EachTriangleLeadsBackToItsFace) {
  const std::vector<std::uint32_t> cornerCounts = {3, 4, 3, 3, 6, 7, 3, 4, 4, 3, 5};
  MeshData data;
  std::vector<FaceOfTriangle> expected;
  for (std::uint32_t f = 0; f < cornerCounts.size(); ++f) {
    std::vector<std::uint32_t> corners(cornerCounts[f]);
    std::iota(corners.begin(), corners.end(), 0u);
    appendPolygonTriangles(corners, data.triangles, &data.polygons);
    for (std::uint32_t t = 0; t + 2 < cornerCounts[f]; ++t)
      expected.push_back({f, cornerCounts[f]});
  }
  data.vertices.assign(7, Vec3(0.0));
  const Mesh mesh("faces.off", std::move(data), Shading::Flat, Material{});
  ASSERT_EQ(mesh.triangles().size(), expected.size());
  for (std::uint32_t t = 0; t < expected.size(); ++t) {
    SCOPED_TRACE(t);
    EXPECT_EQ(mesh.faceOf(t).face, expected[t].face);
    EXPECT_EQ(mesh.faceOf(t).corners, expected[t].corners);
  }
}

// --- polygons that are not convex (tileNonConvexPolygons) -------------------

// A polygon in its own plane (2D points, counter-clockwise) and the vertex
// array of its 3D copy: rotated about an axis, scaled and moved far from
// the origin, as a file would place it.
struct PlacedPolygon {
  std::vector<glm::dvec2> outline;
  std::vector<Vec3> vertices;
};

PlacedPolygon place(std::vector<glm::dvec2> outline, double angle, double scale, Vec3 offset) {
  const glm::dvec3 axis = glm::normalize(glm::dvec3(0.3, -0.8, 0.52));
  const glm::dvec3 u = glm::normalize(glm::cross(axis, glm::dvec3(0, 0, 1)));
  const glm::dvec3 v = glm::cross(axis, u);
  const glm::dvec3 ru = std::cos(angle) * u + std::sin(angle) * v;
  const glm::dvec3 rv = glm::cross(axis, ru);
  PlacedPolygon out{std::move(outline), {}};
  for (const glm::dvec2& p : out.outline)
    out.vertices.push_back(offset + scale * (p.x * ru + p.y * rv));
  return out;
}

// The first triangulation and the one tileNonConvexPolygons leaves.
struct Retiled {
  std::vector<TriangleIndices> before, after;
  PolygonTiling tiling;
};

Retiled retile(const PlacedPolygon& polygon) {
  Retiled r;
  std::vector<std::uint32_t> ring(polygon.outline.size());
  std::iota(ring.begin(), ring.end(), 0u);
  std::vector<PolygonFace> faces;
  appendPolygonTriangles(ring, r.before, &faces);
  r.after = r.before;
  r.tiling = tileNonConvexPolygons(polygon.vertices, faces, r.after);
  return r;
}

double shoelaceArea(const std::vector<glm::dvec2>& outline) {
  double twice = 0.0;
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const glm::dvec2 a = outline[i], b = outline[(i + 1) % outline.size()];
    twice += a.x * b.y - a.y * b.x;
  }
  return 0.5 * twice;
}

// Whether `triangles` tile the outline, judged in the outline's own plane
// (not the projection the code under test chose): each of its edges once,
// in its direction, each diagonal twice, once each way, no triangle turning
// backwards by more than rounding, and the areas adding up to its area.
::testing::AssertionResult tiles(const std::vector<glm::dvec2>& outline,
                                 const std::vector<TriangleIndices>& triangles) {
  const std::size_t n = outline.size();
  if (triangles.size() != n - 2)
    return ::testing::AssertionFailure() << triangles.size() << " triangles";
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;
  double area = 0.0, extent = 0.0;
  for (const glm::dvec2& p : outline) extent = std::max({extent, std::abs(p.x), std::abs(p.y)});
  for (const TriangleIndices& t : triangles) {
    for (int k = 0; k < 3; ++k) ++edges[{t[k], t[(k + 1) % 3]}];
    const double a = signedArea(outline[t[0]], outline[t[1]], outline[t[2]]);
    if (a < -1e-12 * extent * extent)
      return ::testing::AssertionFailure()
             << "triangle (" << t[0] << " " << t[1] << " " << t[2] << ") turns backwards: " << a;
    area += a;
  }
  for (const auto& [edge, count] : edges) {
    const bool outlineEdge = (edge.first + 1) % n == edge.second;
    if (count != 1 || (!outlineEdge && edges.count({edge.second, edge.first}) != 1))
      return ::testing::AssertionFailure() << "edge " << edge.first << "-" << edge.second;
  }
  for (std::uint32_t i = 0; i < n; ++i)
    if (edges.count({i, static_cast<std::uint32_t>((i + 1) % n)}) != 1)
      return ::testing::AssertionFailure() << "outline edge " << i << " missing";
  if (std::abs(area - shoelaceArea(outline)) > 1e-9 * extent * extent)
    return ::testing::AssertionFailure() << "area " << area << " of " << shoelaceArea(outline);
  return ::testing::AssertionSuccess();
}

// Star-shaped about the origin, so simple: n corners at increasing angles,
// each at its own random distance.
std::vector<glm::dvec2> randomStar(std::size_t n, std::mt19937& random) {
  std::uniform_real_distribution<double> radius(0.15, 1.0), jitter(0.05, 0.95);
  std::vector<glm::dvec2> out;
  for (std::size_t i = 0; i < n; ++i) {
    const double a =
        2.0 * M_PI * (static_cast<double>(i) + jitter(random)) / static_cast<double>(n);
    const double r = radius(random);
    out.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  return out;
}

TEST(PolygonTriangles, NonConvexPolygonsAreCutAgainIntoTrianglesThatTileThem) {
  std::vector<std::vector<glm::dvec2>> shapes = {
      {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}},                  // L
      {{0, 0}, {2, 1}, {0, 2}, {0.5, 1}},                                // dart, 0-2 outside
      {{0.5, 1}, {0, 0}, {2, 1}, {0, 2}},                                // dart, 0-2 inside
      {{0, 0}, {4, 0}, {4, 3}, {3, 1}, {2, 3}, {1, 1}, {0, 3}},          // comb
      {{0, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}, {0, 1}},  // L with flat corners
  };
  std::mt19937 random(7);
  for (std::size_t n : {5, 6, 7, 9, 12, 17, 30, 64, 200}) shapes.push_back(randomStar(n, random));
  std::size_t recut = 0;
  for (std::size_t k = 0; k < shapes.size(); ++k) {
    SCOPED_TRACE(k);
    const PlacedPolygon polygon =
        place(shapes[k], 0.37 * static_cast<double>(k), 10.0, Vec3(1e6, -2e5, 3e5));
    const Retiled r = retile(polygon);
    EXPECT_TRUE(tiles(polygon.outline, r.after));
    // Recut exactly when the first cut did not tile it.
    const bool firstTiled = static_cast<bool>(tiles(polygon.outline, r.before));
    EXPECT_EQ(r.tiling.recut, firstTiled ? 0u : 1u);
    EXPECT_EQ(r.tiling.untiled, 0u);
    if (firstTiled) {
      EXPECT_EQ(r.after, r.before);
    }
    recut += r.tiling.recut;
  }
  // The L, the first dart, the comb and most stars: the check above would
  // pass vacuously if nothing needed recutting.
  EXPECT_GE(recut, 8u);
}

TEST(PolygonTriangles, ConvexPolygonsKeepTheirTriangles) {
  for (std::size_t n = 4; n <= 200; n += 7) {
    SCOPED_TRACE(n);
    const PlacedPolygon polygon = place(regularPolygon(n), 1.0, 1e-3, Vec3(-5e4, 1.0, 7.0));
    const Retiled r = retile(polygon);
    EXPECT_EQ(r.tiling.recut, 0u);
    EXPECT_EQ(r.after, r.before);
  }
}

// A face whose hole is joined to its outline by a cut: the cut's two ends
// each appear twice, as separate corners at the same place.
TEST(PolygonTriangles, AFaceWithAHoleJoinedByACutIsTiled) {
  const std::vector<glm::dvec2> outline = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 0},
                                           {1, 1}, {1, 3}, {3, 3}, {3, 1}, {1, 1}};
  const PlacedPolygon polygon = place(outline, 0.2, 1.0, Vec3(0.0));
  const Retiled r = retile(polygon);
  EXPECT_EQ(r.tiling.recut, 1u);
  EXPECT_TRUE(tiles(outline, r.after));
}

// A bow tie winds once each way around its two halves, and has no area in
// all: no triangles cover it with its winding. It keeps its triangles and is counted, so that a
// reader can say so.
TEST(PolygonTriangles, ABowTieIsCountedAndKept) {
  const PlacedPolygon polygon = place({{0, 0}, {1, 1}, {1, 0}, {0, 1}}, 0.0, 1.0, Vec3(0.0));
  const Retiled r = retile(polygon);
  EXPECT_EQ(r.tiling.untiled, 1u);
  EXPECT_EQ(r.after, r.before);
}

// A pentagram crosses itself: all its triangulations are fans, and every
// fan of it has a triangle turning backwards. It too is counted and kept.
TEST(PolygonTriangles, APentagramIsCountedAndKept) {
  std::vector<glm::dvec2> pentagram;
  for (int i = 0; i < 5; ++i) {
    const double a = 2.0 * M_PI * (2 * i) / 5.0;
    pentagram.emplace_back(std::cos(a), std::sin(a));
  }
  const Retiled r = retile(place(pentagram, 0.4, 2.0, Vec3(3.0, 0.0, 0.0)));
  EXPECT_EQ(r.tiling.untiled, 1u);
  EXPECT_EQ(r.after, r.before);
}

// Stars of hundreds to thousands of corners, about half of them reflex:
// enough that an ear is tested only against the reflex corners near it
// (the grid of clipEars), which must find every one that blocks it.
TEST(PolygonTriangles, PolygonsWithManyReflexCornersAreTiled) {
  std::mt19937 random(8);
  for (std::size_t n : {150, 400, 1000, 3000}) {
    SCOPED_TRACE(n);
    const PlacedPolygon polygon =
        place(randomStar(n, random), 0.1 * static_cast<double>(n), 3.0, Vec3(-2e5, 7e5, 1e4));
    const Retiled r = retile(polygon);
    EXPECT_FALSE(tiles(polygon.outline, r.before));
    EXPECT_EQ(r.tiling.recut, 1u);
    EXPECT_TRUE(tiles(polygon.outline, r.after));
  }
}

// A comb of 10,000 teeth has 10,000 reflex corners (its valleys): tested
// against all of them, its ears would take 10^8 tests, past the allowance.
// Each ear is near a few of them, and its flat corners (the valleys once
// the teeth are cut) go as they are met, so it is clipped.
TEST(PolygonTriangles, ACombOf10000TeethIsTiled) {
  const int teeth = 10000;
  // Teeth point up from a base, the valleys between them reflex; the
  // outline runs counter-clockwise.
  std::vector<glm::dvec2> outline = {{0, -1}, {teeth, -1}};
  for (int i = teeth - 1; i >= 0; --i) {
    outline.emplace_back(i + 1.0, 0.0);
    outline.emplace_back(i + 0.5, 1.0);
  }
  outline.emplace_back(0.0, 0.0);
  // Starting at a tip, the first ears span the valleys: they turn
  // backwards, so the comb must be clipped.
  std::rotate(outline.begin(), outline.begin() + 3, outline.end());
  const PlacedPolygon polygon = place(outline, 0.0, 1.0, Vec3(0.0));
  const Retiled r = retile(polygon);
  EXPECT_FALSE(tiles(outline, r.before));
  EXPECT_EQ(r.tiling.recut, 1u);
  EXPECT_TRUE(tiles(outline, r.after));
}

// A sunburst of 10,000 rays has its 10,000 reflex corners on a small circle
// at its centre, in the box of every ear: near all of them, each ear is
// tested against them all. It is given up after the allowance, kept and
// counted, instead of holding the load for seconds.
TEST(PolygonTriangles, AFaceTooIntricateToClipIsCountedAndKept) {
  const int rays = 10000;
  std::vector<glm::dvec2> outline;
  for (int i = 0; i < rays; ++i) {
    const double a = 2.0 * M_PI * i / rays, b = 2.0 * M_PI * (i + 0.5) / rays;
    outline.emplace_back(0.01 * std::cos(a), 0.01 * std::sin(a));
    outline.emplace_back(std::cos(b), std::sin(b));
  }
  // Starting at a tip, the first ears span the reflex corners between
  // the rays and turn backwards.
  std::rotate(outline.begin(), outline.begin() + 1, outline.end());
  const PlacedPolygon polygon = place(outline, 0.0, 1.0, Vec3(0.0));
  const Retiled r = retile(polygon);
  EXPECT_FALSE(tiles(outline, r.before));
  EXPECT_EQ(r.tiling.untiled, 1u);
  EXPECT_EQ(r.after, r.before);
}
}  // namespace
}  // namespace meshtrace
