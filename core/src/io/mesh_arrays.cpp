#include "io/mesh_arrays.h"

#include <algorithm>
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

namespace {
// Room for `capacity` elements in `array`, "the `what` of FILE": the new
// array planned in `budget` before it is allocated, the old one given back
// once it is copied.
template <typename T>
void grow(std::vector<T>& array, MemoryBudget& budget, std::size_t capacity, const char* what,
          const std::filesystem::path& file) {
  const std::size_t old = array.capacity();
  budget.reserve(capacity * sizeof(T), "load",
                 std::string("the ") + what + " of " + file.filename().string() + " (room for " +
                     std::to_string(capacity) + ")");
  reserveOnLargePages(array, capacity);
  budget.release(old * sizeof(T));
}
}  // namespace

void growVertices(MeshData& mesh, MemoryBudget& budget, std::size_t capacity,
                  const std::filesystem::path& file) {
  grow(mesh.vertices, budget, capacity, "vertices", file);
}

void growTriangles(MeshData& mesh, MemoryBudget& budget, std::size_t capacity,
                   const std::filesystem::path& file) {
  grow(mesh.triangles, budget, capacity, "triangles", file);
}

void growPolygons(MeshData& mesh, MemoryBudget& budget, std::size_t capacity,
                  const std::filesystem::path& file) {
  grow(mesh.polygons, budget, capacity, "face records", file);
}

void appendTriangles(MeshData& mesh, MemoryBudget& budget, const MeshChunk& chunk,
                     std::uint32_t firstFace, const std::filesystem::path& file) {
  const std::size_t triangles = mesh.triangles.size() + chunk.triangles.size();
  if (triangles > mesh.triangles.capacity())
    growTriangles(mesh, budget, std::max(2 * mesh.triangles.capacity(), triangles), file);
  for (PolygonFace face : chunk.polygons) {
    face.firstTriangle += static_cast<std::uint32_t>(mesh.triangles.size());
    face.face += firstFace;
    mesh.polygons.push_back(face);
  }
  mesh.triangles.insert(mesh.triangles.end(), chunk.triangles.begin(), chunk.triangles.end());
}

}  // namespace meshtrace::mesh_arrays
