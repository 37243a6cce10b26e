#pragma once
// The two-level acceleration structure of a scene: one BVH over the
// triangles of every mesh large enough to profit from one, and a top-level
// BVH over all bounded objects (spheres, cylinders, smaller meshes and that
// triangle BVH), so that 1,600 spheres cost about what one mesh does.
// Infinite planes have no box and are tested apart.
//
// The meshes share one triangle BVH rather than having one each: a ray
// crossing several meshes then descends a single hierarchy, where the hit in
// the nearer mesh culls the farther one's boxes at every level (BENCHMARKS.md
// gives what that is worth on the seed's multi-mesh scenes).
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "accel/bvh8.h"
#include "accel/slab_ray.h"
#include "accel/triangle_block.h"
#include "accel/triangle_set.h"
#include "meshtrace/accel/bvh_stats.h"
#include "meshtrace/accel/trace_options.h"
#include "meshtrace/geometry/scene.h"
#include "meshtrace/util/counters.h"

namespace meshtrace {

class PrimitiveQuery;

// The BVH over the triangles of a set of meshes: 8-wide nodes whose leaves
// are triangle blocks.
struct MeshBvh {
  TriangleSet triangles;  // what a block lane's id refers to
  Bvh8 tree;              // a leaf's block is blocks.block(first, count)
  TriangleBlocks blocks;
  BlockFrame frame;
  bool prefetch = false;  // whether traversals fetch children ahead

  bool empty() const { return blocks.empty(); }
  std::size_t bytes() const { return tree.nodes.size() * sizeof(Bvh8Node) + blocks.bytes(); }
};

class SceneBvh {
 public:
  SceneBvh(const Scene& scene, const SceneBvhOptions& options = {});

  // Offers every primitive the search's ray may hit to `search`, a
  // ClosestHitSearch or an AnyHitSearch (primitive_query.h), until the
  // search is over; returns whether it ended early (an any-hit search found
  // a blocker).
  template <typename Search>
  bool trace(Search& search, Counters& counters) const;
  // trace() for the searches of a packet named in `active` (bit r:
  // searches[r]), with the same outcome as a trace() of each; returns those
  // that ended early. Closest-hit rays are traced together where they share
  // an octant of directions, any-hit rays always. The searches of inactive
  // rays are still read (give them an active ray's).
  template <typename Search>
  std::uint32_t tracePacket(Search* searches, std::uint32_t active, Counters& counters) const;

  const SceneBvhStats& stats() const { return stats_; }
  // The triangle BVH, over the meshes large enough for one.
  const MeshBvh& meshBvh() const { return meshBvh_; }
  // Whether mesh `i`'s triangles are in it (else the mesh is too small).
  bool inMeshBvh(std::size_t i) const { return inMeshBvh_[i]; }
  const Bvh8& topLevel() const { return top_; }

 private:
  SlabRay slabRay(const PrimitiveQuery& query) const;
  // The infinite planes, which have no box: tested before the tree.
  template <typename Search>
  bool tracePlanes(Search& search) const;
  // Whether a ray spawned from a triangle turns away from the triangle BVH
  // before its float boxes (below).
  bool leavesTheMeshBvhBox(const PrimitiveQuery& query, double tLimit) const;
  // Its test for a ray that starts outside the box, out of line: the
  // queries are large enough, and most rays start inside.
  [[gnu::noinline]] bool missesTheMeshBvhBox(const PrimitiveQuery& query, double tLimit) const;
  // trace() with the ray's slab ray already made.
  template <typename Search>
  bool traceBounded(const SlabRay& ray, Search& search, Counters& counters) const;

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
