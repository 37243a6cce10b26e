#include "support/meshes.h"

#include <cmath>
#include <utility>

#include "meshtrace/geometry/camera.h"
#include "meshtrace/geometry/mesh_generators.h"

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

Scene hallScene(int width, int height) {
  Scene scene;
  scene.meshes.push_back(makeMesh("hall", makeHall(40.0, 16.0, 8.0)));
  scene.lights.push_back({Vec3(60.0, 30.0, -5.0), Color(0.8, 0.75, 0.65)});
  scene.lights.push_back({Vec3(0.0, 7.0, 4.0), Color(0.35, 0.35, 0.38)});
  scene.camera = Camera(CameraSpec{Vec3(2.0, 1.7, 18.0), Vec3(-1.5, 2.6, -12.0),
                                   Vec3(0.0, 1.0, 0.0), 70.0, width, height});
  return scene;
}

}  // namespace meshtrace::test
