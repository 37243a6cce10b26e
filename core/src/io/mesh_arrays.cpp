#include "io/mesh_arrays.h"

#include <string>

#include "util/build_vector.h"

namespace meshtrace::mesh_arrays {

void sizeVertices(MeshData& mesh, MemoryBudget& budget, std::size_t count,
                  const std::filesystem::path& file) {
  budget.reserve(count * sizeof(Vec3), "load",
                 "the " + std::to_string(count) + " vertices of " + file.filename().string());
  reserveOnLargePages(mesh.vertices, count);
  mesh.vertices.resize(count);
}

void growTriangles(MeshData& mesh, MemoryBudget& budget, std::size_t capacity,
                   const std::filesystem::path& file) {
  const std::size_t old = mesh.triangles.capacity();
  budget.reserve(capacity * sizeof(TriangleIndices), "load",
                 "the triangles of " + file.filename().string() + " (room for " +
                     std::to_string(capacity) + ")");
  reserveOnLargePages(mesh.triangles, capacity);
  budget.release(old * sizeof(TriangleIndices));
}

}  // namespace meshtrace::mesh_arrays
