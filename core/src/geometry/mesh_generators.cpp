#include "meshtrace/geometry/mesh_generators.h"

#include <glm/gtc/constants.hpp>
#include <map>
#include <utility>

namespace meshtrace {

namespace {
constexpr double kTwoPi = glm::two_pi<double>();

std::uint32_t index(std::size_t i) { return static_cast<std::uint32_t>(i); }

// Triangulates a (rows x cols) grid of vertices, starting at `first`, whose
// columns wrap around when `wrapCols` (and rows when `wrapRows`).
void addQuads(MeshData& m, std::size_t first, int rows, int cols, bool wrapRows, bool wrapCols) {
  const int quadRows = wrapRows ? rows : rows - 1;
  const int quadCols = wrapCols ? cols : cols - 1;
  for (int r = 0; r < quadRows; ++r) {
    for (int c = 0; c < quadCols; ++c) {
      const auto at = [&](int rr, int cc) {
        return index(first + static_cast<std::size_t>(rr % rows) * cols + cc % cols);
      };
      m.triangles.push_back({at(r, c), at(r + 1, c), at(r + 1, c + 1)});
      m.triangles.push_back({at(r, c), at(r + 1, c + 1), at(r, c + 1)});
    }
  }
}
}  // namespace

MeshData makeIcosphere(const Vec3& center, double radius, int level) {
  const double t = (1.0 + std::sqrt(5.0)) / 2.0;
  std::vector<Vec3> unit = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0},
                            {0, -1, t}, {0, 1, t}, {0, -1, -t}, {0, 1, -t},
                            {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for (Vec3& v : unit) v = glm::normalize(v);
  std::vector<TriangleIndices> tris = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                       {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                       {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                       {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int l = 0; l < level; ++l) {
    // Each edge's midpoint is shared by its two triangles: cache it by edge.
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
    const auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      const auto key = std::minmax(a, b);
      const auto [it, inserted] = midpoints.try_emplace(key, index(unit.size()));
      if (inserted) unit.push_back(glm::normalize(unit[a] + unit[b]));
      return it->second;
    };
    std::vector<TriangleIndices> finer;
    finer.reserve(tris.size() * 4);
    for (const auto& [a, b, c] : tris) {
      const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      finer.push_back({a, ab, ca});
      finer.push_back({b, bc, ab});
      finer.push_back({c, ca, bc});
      finer.push_back({ab, bc, ca});
    }
    tris = std::move(finer);
  }
  MeshData m;
  m.vertices.reserve(unit.size());
  for (const Vec3& v : unit) m.vertices.push_back(center + radius * v);
  m.triangles = std::move(tris);
  return m;
}

MeshData makeTorus(const Vec3& center, double ringRadius, double tubeRadius, int ringSegments,
                   int tubeSegments) {
  MeshData m;
  for (int i = 0; i < ringSegments; ++i) {
    const double u = kTwoPi * i / ringSegments;
    for (int j = 0; j < tubeSegments; ++j) {
      const double v = kTwoPi * j / tubeSegments;
      const double r = ringRadius + tubeRadius * std::cos(v);
      m.vertices.push_back(center +
                           Vec3(r * std::cos(u), tubeRadius * std::sin(v), -r * std::sin(u)));
    }
  }
  addQuads(m, 0, ringSegments, tubeSegments, true, true);
  return m;
}

MeshData makeTorusKnot(const Vec3& center, double scale, int p, int q, double tubeRadius,
                       int segments, int tubeSegments) {
  const auto curve = [&](double s) {
    const double r = 2.0 + std::cos(q * s);
    return Vec3(r * std::cos(p * s), -std::sin(q * s), r * std::sin(p * s));
  };
  MeshData m;
  for (int i = 0; i < segments; ++i) {
    const double s = kTwoPi * i / segments;
    const double ds = 1e-4;
    const Vec3 c = curve(s);
    const Vec3 tangent = glm::normalize(curve(s + ds) - curve(s - ds));
    // A frame from the curve's offset from the origin: it never degenerates
    // for torus knots, whose curve stays away from the central axis.
    const Vec3 side = glm::normalize(glm::cross(tangent, c));
    const Vec3 normal = glm::cross(side, tangent);
    for (int j = 0; j < tubeSegments; ++j) {
      const double a = kTwoPi * j / tubeSegments;
      // (tangent, normal, side) is right-handed, so stepping the angle
      // towards -side keeps the winding counter-clockwise seen from outside.
      const Vec3 offset = tubeRadius * (std::cos(a) * normal - std::sin(a) * side);
      m.vertices.push_back(center + scale * (c + offset));
    }
  }
  addQuads(m, 0, segments, tubeSegments, true, true);
  return m;
}

MeshData makeGrid(const Vec3& center, double size, int n) {
  MeshData m;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j)
      m.vertices.push_back(center +
                           Vec3(size * (double(j) / n - 0.5), 0.0, size * (double(i) / n - 0.5)));
  addQuads(m, 0, n + 1, n + 1, false, false);
  return m;
}

MeshData makeGriddedBox(const Vec3& min, const Vec3& max, int n) {
  MeshData m;
  // Each face: an origin corner and two edge vectors whose cross product
  // points outward.
  const Vec3 e = max - min;
  const Vec3 x(e.x, 0, 0), y(0, e.y, 0), z(0, 0, e.z);
  const std::array<std::array<Vec3, 3>, 6> faces = {
      {{min, z, y}, {min + x, y, z}, {min, x, z}, {min + y, z, x}, {min, y, x}, {min + z, x, y}}};
  for (const auto& [origin, u, v] : faces) {
    const std::size_t first = m.vertices.size();
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j)
        m.vertices.push_back(origin + (double(i) / n) * u + (double(j) / n) * v);
    addQuads(m, first, n + 1, n + 1, false, false);
  }
  return m;
}

void reverseWinding(MeshData& mesh) {
  for (TriangleIndices& t : mesh.triangles) std::swap(t[1], t[2]);
}

}  // namespace meshtrace
