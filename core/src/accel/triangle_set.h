#pragma once
// The triangles of several meshes numbered one after another, mesh by mesh,
// so that one BVH can hold them all: a ray that crosses several meshes then
// descends one hierarchy, in which the nearer mesh's hit culls the farther
// mesh's boxes, instead of one hierarchy per mesh.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "meshtrace/geometry/aabb.h"
#include "meshtrace/geometry/mesh.h"

namespace meshtrace {

class TriangleSet {
 public:
  // A triangle of the set: its mesh (index in the scene) and its index there.
  struct Member {
    const Mesh* mesh;
    std::uint32_t sceneIndex;
    std::uint32_t triangle;

    const TriangleIndices& indices() const { return mesh->triangles()[triangle]; }
  };

  // Appends the triangles of `mesh`, scene mesh number `sceneIndex`.
  void add(const Mesh& mesh, std::uint32_t sceneIndex);

  bool empty() const { return size() == 0; }
  std::size_t size() const { return first_.back(); }
  std::size_t meshCount() const { return meshes_.size(); }
  const Aabb& bounds() const { return bounds_; }

  // The k-th mesh added, and the id its first triangle has in this set.
  const Mesh& mesh(std::size_t k) const { return *meshes_[k]; }
  std::uint32_t firstId(std::size_t k) const { return first_[k]; }

  // Triangle `id` of the set (0 <= id < size()).
  Member operator[](std::uint32_t id) const {
    if (meshes_.size() == 1) return {meshes_[0], sceneIndex_[0], id};
    // The last mesh whose first id is at most `id`.
    const auto k = static_cast<std::size_t>(
        std::upper_bound(first_.begin() + 1, first_.end() - 1, id) - (first_.begin() + 1));
    return {meshes_[k], sceneIndex_[k], id - first_[k]};
  }

 private:
  std::vector<const Mesh*> meshes_;
  std::vector<std::uint32_t> sceneIndex_;
  std::vector<std::uint32_t> first_{0};  // first id of each mesh, then size()
  Aabb bounds_;
};

}  // namespace meshtrace
