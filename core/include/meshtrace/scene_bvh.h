#pragma once
// The two-level acceleration structure of a scene: a BVH per mesh large
// enough to profit from one, and a top-level BVH over all bounded objects
// (spheres, cylinders and meshes), so that 1,600 spheres cost about what one
// mesh does. Infinite planes have no box and are tested apart.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "meshtrace/bvh8.h"
#include "meshtrace/bvh8_traverse.h"
#include "meshtrace/counters.h"
#include "meshtrace/scene.h"
#include "meshtrace/triangle_block.h"

namespace meshtrace {

class ClosestHit;
class PrimitiveQuery;

// Meshes with fewer triangles get no BVH: testing their few triangles after
// the top-level box is as fast. Measured by `bench --crossover` (see
// BENCHMARKS.md): a BVH loses at 8 triangles and pays from 12 on.
inline constexpr std::size_t kMinBvhTriangles = 12;

// A mesh's BVH: 8-wide nodes whose leaves are triangle blocks.
struct MeshBvh {
  Bvh8 tree;  // a leaf's `first` is its block index
  std::vector<TriangleBlock4> blocks;
  BlockFrame frame;

  bool empty() const { return blocks.empty(); }
  std::size_t bytes() const {
    return tree.nodes.size() * sizeof(Bvh8Node) + blocks.size() * sizeof(TriangleBlock4);
  }
};

struct SceneBvhOptions {
  std::size_t minMeshTriangles = kMinBvhTriangles;
  // A leaf is one block of up to four triangles, tested at once.
  BvhBuildOptions mesh{.bins = 16, .maxLeafSize = 4, .nodeCost = 1.0, .primitiveCost = 1.0,
                       .leafBlock = 4};
  BvhBuildOptions top{.bins = 16, .maxLeafSize = 2, .nodeCost = 1.0, .primitiveCost = 2.0};
};

struct SceneBvhStats {
  double buildSeconds = 0.0;
  std::size_t meshesWithBvh = 0;
  std::size_t trianglesInBvhs = 0;
  std::size_t meshBvhBytes = 0;  // nodes and triangle blocks of all mesh BVHs
  std::size_t topLevelObjects = 0;
  std::size_t topLevelBytes = 0;
  int maxDepth = 0;              // top level plus the deepest mesh BVH
  std::vector<std::string> leftOut;  // meshes too small for a BVH, and why
};

class SceneBvh {
 public:
  SceneBvh(const Scene& scene, const SceneBvhOptions& options = {});

  // Offers every primitive the ray may hit to `closest` (see primitive_query.h).
  void closestHit(const PrimitiveQuery& query, ClosestHit& closest, Counters& counters) const;
  // True if some primitive is hit at tMin < t < tMax.
  bool occluded(const PrimitiveQuery& query, double tMax, Counters& counters) const;

  const SceneBvhStats& stats() const { return stats_; }
  // The BVH of mesh `i`; empty when the mesh is too small to have one.
  const MeshBvh& meshBvh(std::size_t i) const { return meshBvhs_[i]; }
  const Bvh8& topLevel() const { return top_; }

 private:
  SlabRay slabRay(const PrimitiveQuery& query) const;

  struct Object {
    ObjectKind kind;
    std::uint32_t index;
  };

  const Scene& scene_;
  std::vector<MeshBvh> meshBvhs_;
  std::vector<Object> objects_;  // top-level primitives
  Bvh8 top_;
  double sceneScale_ = 0.0;  // largest coordinate of a bounded object
  SceneBvhStats stats_;
};

}  // namespace meshtrace
