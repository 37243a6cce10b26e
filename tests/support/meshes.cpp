#include "support/meshes.h"

#include <cmath>
#include <utility>

namespace meshtrace::test {

Mesh makeMesh(const char* name, MeshData data) {
  return Mesh(name, std::move(data), Shading::Flat, Material{});
}

std::vector<Aabb> triangleBoxes(const MeshData& m) {
  std::vector<Aabb> boxes;
  for (const auto& t : m.triangles) {
    Aabb b;
    for (auto k : t) b.extend(m.vertices[k]);
    boxes.push_back(b);
  }
  return boxes;
}

MeshData withCopies(MeshData m, std::size_t every, int copies) {
  const std::size_t n = m.triangles.size();
  const auto vertex = [&](const Vec3& p) {
    m.vertices.push_back(p);
    return static_cast<std::uint32_t>(m.vertices.size() - 1);
  };
  for (std::size_t i = 0; i < n; i += every) {
    const TriangleIndices t = m.triangles[i];
    const auto [a, b, c] = t;
    for (int k = 0; k < copies; ++k) m.triangles.push_back(t);
    for (int k = 0; k < copies; ++k)
      m.triangles.push_back({vertex(m.vertices[a]), vertex(m.vertices[b]), vertex(m.vertices[c])});
    for (const TriangleIndices& order :
         {TriangleIndices{b, c, a}, {c, a, b}, {a, c, b}, {c, b, a}, {b, a, c}})
      m.triangles.push_back(order);
    Vec3 moved = m.vertices[a];
    moved.x = std::nextafter(moved.x, kInfinity);
    m.triangles.push_back({vertex(moved), b, c});
  }
  return m;
}

}  // namespace meshtrace::test
