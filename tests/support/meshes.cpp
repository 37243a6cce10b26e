#include "support/meshes.h"

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

}  // namespace meshtrace::test
