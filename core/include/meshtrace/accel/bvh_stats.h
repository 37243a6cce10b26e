#pragma once
// What a scene's BVH holds and what it left out, for `raytrace --stats`.
#include <cstddef>
#include <string>
#include <vector>

namespace meshtrace {

struct SceneBvhStats {
  double buildSeconds = 0.0;
  std::size_t meshesWithBvh = 0;  // meshes whose triangles are in the triangle BVH
  std::size_t trianglesInBvhs = 0;
  std::size_t copiesLeftOut = 0;  // of those, exact copies of two others, left out
  std::size_t meshBvhBytes = 0;   // nodes and triangle blocks of the triangle BVH
  std::size_t topLevelObjects = 0;
  std::size_t topLevelBytes = 0;
  int maxDepth = 0;                  // top level plus the triangle BVH
  std::vector<std::string> leftOut;  // meshes too small for a BVH, and why
};

}  // namespace meshtrace
