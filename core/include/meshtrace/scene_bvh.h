#pragma once
// The two-level acceleration structure of a scene: one BVH over the
// triangles of every mesh large enough to profit from one, and a top-level
// BVH over all bounded objects (spheres, cylinders, smaller meshes and that
// triangle BVH), so that 1,600 spheres cost about what one mesh does.
// Infinite planes have no box and are tested apart.
//
// The meshes share one triangle BVH rather than having one each: a ray
// crossing several meshes then descends a single hierarchy, where the hit in
// the nearer mesh culls the farther one's boxes at every level. Primary rays
// on one thread against rtcIntersect1, median of five alternating runs:
// rings (two interlocked meshes) 0.56x -> 0.63x, toon_faces (six meshes)
// 0.64x -> 0.69x; single-mesh scenes unchanged (BENCHMARKS.md).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "meshtrace/bvh8.h"
#include "meshtrace/bvh8_packet.h"
#include "meshtrace/bvh8_traverse.h"
#include "meshtrace/counters.h"
#include "meshtrace/scene.h"
#include "meshtrace/triangle_block.h"
#include "meshtrace/triangle_set.h"

namespace meshtrace {

class ClosestHit;
class PrimitiveQuery;

// Meshes with fewer triangles stay out of the triangle BVH: testing their few
// triangles after their top-level box is faster. Measured by
// `bench --crossover` (see BENCHMARKS.md) on 100 meshes of n triangles: with
// all of them in the shared BVH, 2-triangle squares lose in every run
// (0.91-0.99x) and 3-triangle fans gain in every run (1.01-1.08x); medians
// over eleven runs 0.96x at 2 triangles, 1.02-1.15x from 3 to 7.
inline constexpr std::size_t kMinBvhTriangles = 3;

// From this size of nodes and blocks on, the triangle BVH's traversals ask
// for the children a ray meets before visiting them (bvh8::PrefetchChildren).
// Measured on generated knots, 1 thread, primary rays in packets, shadow rays
// in packets, single primary rays: 300k triangles (18 MB) 1.02x, 1.07x and
// 1.08x the time without it; 600k (36 MB) 0.95x, 0.91x and 0.99x; 1M (59 MB)
// 0.89x, 0.89x and 0.94x. Smaller trees only pay for the instructions
// (fandisk and armadillo: shadow rays 1.03-1.07x the time with it).
inline constexpr std::size_t kPrefetchBvhBytes = std::size_t{24} << 20;

// The BVH over the triangles of a set of meshes: 8-wide nodes whose leaves
// are triangle blocks.
struct MeshBvh {
  TriangleSet triangles;  // what a block lane's id refers to
  Bvh8 tree;              // a leaf's `first` is its block index
  BuildVector<TriangleBlock4> blocks;
  BlockFrame frame;
  bool prefetch = false;  // whether traversals fetch children ahead

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
  // A triangle BVH of this many bytes or more fetches children ahead.
  std::size_t prefetchBytes = kPrefetchBvhBytes;
};

struct SceneBvhStats {
  double buildSeconds = 0.0;
  std::size_t meshesWithBvh = 0;  // meshes whose triangles are in the triangle BVH
  std::size_t trianglesInBvhs = 0;
  std::size_t meshBvhBytes = 0;  // nodes and triangle blocks of the triangle BVH
  std::size_t topLevelObjects = 0;
  std::size_t topLevelBytes = 0;
  int maxDepth = 0;              // top level plus the triangle BVH
  std::vector<std::string> leftOut;  // meshes too small for a BVH, and why
};

class SceneBvh {
 public:
  SceneBvh(const Scene& scene, const SceneBvhOptions& options = {});

  // Offers every primitive the ray may hit to `closest` (see primitive_query.h).
  void closestHit(const PrimitiveQuery& query, ClosestHit& closest, Counters& counters) const;
  // closestHit for the rays of a packet named in `active` (bit r:
  // queries[r], offering to closest[r]); the same hits as a closestHit call
  // for each. The queries of inactive rays are still read (give them any
  // ray, best one of an active ray's octant).
  void closestHitPacket(const PrimitiveQuery* queries, ClosestHit* closest, std::uint32_t active,
                        Counters& counters) const;
  // True if some primitive is hit at tMin < t < tMax.
  bool occluded(const PrimitiveQuery& query, double tMax, Counters& counters) const;

  // occluded for the rays of a packet named in `active` (bit r: queries[r],
  // limit tMax[r]); returns those blocked. The queries of inactive rays are
  // still read (give them any ray). The same answers as occluded gives.
  std::uint32_t occludedPacket(const PrimitiveQuery* queries, const double* tMax,
                               std::uint32_t active, Counters& counters) const;

  const SceneBvhStats& stats() const { return stats_; }
  // The triangle BVH, over the meshes large enough for one.
  const MeshBvh& meshBvh() const { return meshBvh_; }
  // Whether mesh `i`'s triangles are in it (else the mesh is too small).
  bool inMeshBvh(std::size_t i) const { return inMeshBvh_[i]; }
  const Bvh8& topLevel() const { return top_; }

 private:
  SlabRay slabRay(const PrimitiveQuery& query) const;
  // closestHit with the query's slab ray already made.
  void closestHit(const PrimitiveQuery& query, const SlabRay& ray, ClosestHit& closest,
                  Counters& counters) const;

  struct Object {
    ObjectKind kind;
    std::uint32_t index;  // kMeshBvh for the triangle BVH (kind Mesh)
  };
  static constexpr std::uint32_t kMeshBvh = 0xffffffffu;

  const Scene& scene_;
  MeshBvh meshBvh_;
  std::vector<bool> inMeshBvh_;
  std::vector<Object> objects_;  // top-level primitives
  Bvh8 top_;
  double sceneScale_ = 0.0;  // largest coordinate of a bounded object
  SceneBvhStats stats_;
};

}  // namespace meshtrace
