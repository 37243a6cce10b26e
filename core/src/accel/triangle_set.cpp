#include "accel/triangle_set.h"

#include <limits>
#include <stdexcept>

namespace meshtrace {

void TriangleSet::add(const Mesh& mesh, std::uint32_t sceneIndex) {
  const std::size_t end = size() + mesh.triangles().size();
  if (end > std::numeric_limits<std::uint32_t>::max())
    throw std::length_error("more than 2^32 - 1 triangles in one BVH");
  meshes_.push_back(&mesh);
  sceneIndex_.push_back(sceneIndex);
  first_.push_back(static_cast<std::uint32_t>(end));
  bounds_.extend(mesh.bounds());
}

}  // namespace meshtrace
