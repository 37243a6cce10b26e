// Closest-hit and any-hit queries through the scene's two-level BVH.
#include <new>
#include <type_traits>

#include "accel/primitive_query.h"
#include "accel/scene_bvh.h"
#include "util/prefetch.h"

namespace meshtrace {

namespace {

// Set bits of a 4-bit lane mask (std::popcount is a library call without
// the popcnt instruction of later x86-64 levels).
int laneCount(int mask) {
  static constexpr int kCount[16] = {0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4};
  return kCount[mask & 15];
}

// Where the triangles of a block live: their vertex-index rows and their
// (scene mesh, triangle) references. A block holds triangles of one mesh
// only (each mesh's tree is built on its own before the trees are joined,
// bvh_build.cpp), so the mesh is found once per block: straight off the set
// when there is one mesh, by a search of the set's meshes otherwise (that
// search for every lane, twice, cost rings' shadow rays 250 instructions
// a ray).
struct BlockMesh {
  const TriangleIndices* rows;
  const Vec3* vertexArray;
  std::uint32_t sceneIndex;
  std::uint32_t firstId;  // the set id of the mesh's triangle 0

  const TriangleIndices* row(std::uint32_t id) const { return rows + (id - firstId); }
  const Vec3* vertices() const { return vertexArray; }
  PrimitiveRef ref(std::uint32_t id) const { return {ObjectKind::Mesh, sceneIndex, id - firstId}; }
};

// The one mesh's set ids are its triangle indices. Not a BlockMesh with
// firstId 0: the compiler keeps the subtraction on every lane then, 13
// instructions a shadow ray on fandisk.
class SoleMesh {
 public:
  explicit SoleMesh(const TriangleSet& set) {
    const TriangleSet::Member first = set[0];
    rows_ = first.mesh->triangles().data();
    vertices_ = first.mesh->vertices().data();
    sceneIndex_ = first.sceneIndex;
  }
  const SoleMesh& of(const TriangleBlock4&) const { return *this; }
  const TriangleIndices* row(std::uint32_t id) const { return rows_ + id; }
  const Vec3* vertices() const { return vertices_; }
  PrimitiveRef ref(std::uint32_t id) const { return {ObjectKind::Mesh, sceneIndex_, id}; }

 private:
  const TriangleIndices* rows_;
  const Vec3* vertices_;
  std::uint32_t sceneIndex_;
};

class ManyMeshes {
 public:
  explicit ManyMeshes(const TriangleSet& set) : set_(set) {}
  BlockMesh of(const TriangleBlock4& block) const {
    const TriangleSet::Member m = set_[block.id[0]];
    return {m.mesh->triangles().data(), m.mesh->vertices().data(), m.sceneIndex,
            block.id[0] - m.triangle};
  }

 private:
  const TriangleSet& set_;
};

// Calls visit with the locator that fits `set` (see above).
template <typename Visit>
[[gnu::always_inline]] inline auto withLocator(const TriangleSet& set, Visit&& visit) {
  return set.meshCount() == 1 ? visit(SoleMesh(set)) : visit(ManyMeshes(set));
}

// The lanes of the block that the float filter passes on to the exact test.
// Every lane counts as one triangle test: those dropped here, the others in
// the exact test.
// The exact test starts by reading the triangle's vertex indices from its
// mesh, a cache miss on a large mesh; asking for them before the filter
// runs overlaps that wait with it (knot1m's hitting primary rays: about
// 880 ns -> 770 ns; no change on meshes that fit in cache).
template <typename Mesh>
int candidateLanes(const BlockRay& ray, const TriangleBlock4& block, std::uint32_t n,
                   const Mesh& mesh, double tMin, double tMax, Counters& counters) {
  for (std::uint32_t k = 0; k < n; ++k) prefetchLine(mesh.row(block.id[k]));
  const int mask = ray.candidates(block, static_cast<int>(n), tMin, tMax);
  counters.triangleTests += n - laneCount(mask);
  return mask;
}

// Calls exact(triangle) with the PrimitiveRef of each lane in `lanes` until
// one call returns true.
template <typename Mesh, typename Exact>
bool forEachLane(const TriangleBlock4& block, int lanes, const Mesh& mesh, Exact&& exact) {
  for (; lanes; lanes &= lanes - 1)
    if (exact(mesh.ref(block.id[__builtin_ctz(static_cast<unsigned>(lanes))]))) return true;
  return false;
}

// Asks for the vertices of the lanes in `lanes`, so that the exact tests of
// several lanes wait for them together, not in turn. The packet's closest
// hits on large trees filter the block for all their rays first, then ask
// for the vertices of every lane passed, then test: knot1m's hitting quads,
// 1 thread, six alternating runs, 548-564 -> 523-548 ns a ray (the rays
// of a quad mostly meet their hits in different triangles). Shadow packets
// were slower with it (316-340 -> 345-378 ns: nearly all their candidates
// are lanes the exact test rejects), so they test at once.
template <typename Mesh>
void prefetchVertices(const TriangleBlock4& block, int lanes, const Mesh& mesh) {
  for (; lanes; lanes &= lanes - 1) {
    const TriangleIndices& row = *mesh.row(block.id[__builtin_ctz(static_cast<unsigned>(lanes))]);
    for (int c = 0; c < 3; ++c) prefetchObject(mesh.vertices()[row[c]]);
  }
}

// candidateLanes, then the exact test of each, as above.
template <typename Locate, typename Exact>
bool forEachCandidate(const BlockRay& ray, const TriangleBlock4& block, std::uint32_t n,
                      const Locate& locate, double tMin, double tMax, Counters& counters,
                      Exact&& exact) {
  const auto& mesh = locate.of(block);
  return forEachLane(block, candidateLanes(ray, block, n, mesh, tMin, tMax, counters), mesh, exact);
}

// What the triangle BVH's traversals ask for ahead: a leaf's data is its
// block.
auto childPrefetch(const MeshBvh& bvh) {
  const auto block = [blocks = bvh.blocks.data()](std::uint32_t b) { prefetchObject(blocks[b]); };
  return bvh8::PrefetchChildren<decltype(block)>(bvh.prefetch, block);
}

// The triangle BVH's BlockRay, made when the ray first reaches one of its
// blocks: most rays that miss the meshes never do. (std::optional is not
// used because GCC zero-fills its storage up front with `rep stos`, which
// costs more than the set-up itself.)
class LazyBlockRay {
 public:
  LazyBlockRay(const Ray& ray, const BlockFrame& frame, TriangleKernel kernel)
      : ray_(ray), frame_(frame), kernel_(kernel) {}
  const BlockRay& get() {
    if (!made_) {
      new (storage_) BlockRay(ray_, frame_, kernel_);
      made_ = true;
    }
    return *std::launder(reinterpret_cast<const BlockRay*>(storage_));
  }

 private:
  static_assert(std::is_trivially_destructible_v<BlockRay>);
  const Ray& ray_;
  const BlockFrame& frame_;
  TriangleKernel kernel_;
  bool made_ = false;
  alignas(BlockRay) unsigned char storage_[sizeof(BlockRay)];
};

// A packet's LazyBlockRays, one per ray.
class PacketBlockRays {
 public:
  PacketBlockRays(const PrimitiveQuery* queries, const BlockFrame& frame)
      : rays_{{queries[0].ray(), frame, queries[0].kernel()},
              {queries[1].ray(), frame, queries[1].kernel()},
              {queries[2].ray(), frame, queries[2].kernel()},
              {queries[3].ray(), frame, queries[3].kernel()}} {}
  const BlockRay& get(int r) { return rays_[r].get(); }

 private:
  LazyBlockRay rays_[kPacketSize];
};

}  // namespace

[[gnu::always_inline]] inline SlabRay SceneBvh::slabRay(const PrimitiveQuery& query) const {
  // One call per precision, so that each folds its padding's constants into
  // SlabRay's scale factors rather than working them out for every ray.
  const Ray& ray = query.ray();
  if (query.kernel().precision == Precision::Single)
    return SlabRay(ray, slabPadding(true, ray.origin, sceneScale_));
  return SlabRay(ray, slabPadding(false, ray.origin, sceneScale_));
}

// The leaf work of both levels is forced inline (GCC and Clang take the
// attribute after a lambda's parameters), as the traversals are: as calls,
// each with its prologue and its own copy of the box ray, a missing primary
// ray ran 374 instructions instead of 329, and primary rays took 2-4% longer.
#define MESHTRACE_INLINE_LEAF __attribute__((always_inline))

void SceneBvh::closestHit(const PrimitiveQuery& query, ClosestHit& closest,
                          Counters& counters) const {
  closestHit(query, slabRay(query), closest, counters);
}

void SceneBvh::closestHit(const PrimitiveQuery& query, const SlabRay& ray, ClosestHit& closest,
                          Counters& counters) const {
  for (std::uint32_t i = 0; i < scene_.planes.size(); ++i)
    query.offerShape(ObjectKind::Plane, i, closest);
  const double tMin = query.tMin();
  std::uint64_t visits = 0;
  const auto offerMesh = [&](std::uint32_t mesh) MESHTRACE_INLINE_LEAF {
    if (mesh != kMeshBvh) {
      const auto count = static_cast<std::uint32_t>(scene_.meshes[mesh].triangles().size());
      for (std::uint32_t t = 0; t < count; ++t) query.offerTriangle(mesh, t, closest);
      return;
    }
    const auto traverse = [&](const auto& locate) MESHTRACE_INLINE_LEAF {
      LazyBlockRay blockRay(query.ray(), meshBvh_.frame, query.kernel());
      const auto offerBlock = [&](std::uint32_t block, std::uint32_t n) MESHTRACE_INLINE_LEAF {
        forEachCandidate(blockRay.get(), meshBvh_.blocks[block], n, locate, tMin, closest.t(),
                         counters, [&](const PrimitiveRef& t) {
                           query.offerTriangle(t.object, t.triangle, closest);
                           return false;
                         });
      };
      traverseClosest(meshBvh_.tree, ray, tMin, closest.t(), visits, offerBlock,
                      childPrefetch(meshBvh_));
    };
    withLocator(meshBvh_.triangles, traverse);
  };
  const auto offerObjects = [&](std::uint32_t first, std::uint32_t n) MESHTRACE_INLINE_LEAF {
    for (std::uint32_t k = first; k < first + n; ++k) {
      const Object& o = objects_[top_.order[k]];
      if (o.kind == ObjectKind::Mesh)
        offerMesh(o.index);
      else
        query.offerShape(o.kind, o.index, closest);
    }
  };
  traverseClosest(top_, ray, tMin, closest.t(), visits, offerObjects);
  counters.nodeVisits += visits;
}

void SceneBvh::closestHitPacket(const PrimitiveQuery* queries, ClosestHit* closest,
                                std::uint32_t active, Counters& counters) const {
  if (active == 0) return;
  const SlabRay slab[kPacketSize] = {slabRay(queries[0]), slabRay(queries[1]),
                                     slabRay(queries[2]), slabRay(queries[3])};
  const int lead = __builtin_ctz(active);
  for (int r = 0; r < kPacketSize; ++r)
    if (active >> r & 1 && slab[r].octant != slab[lead].octant) {
      for (int k = 0; k < kPacketSize; ++k)
        if (active >> k & 1) closestHit(queries[k], slab[k], closest[k], counters);
      return;
    }
  for (int r = 0; r < kPacketSize; ++r)
    if (active >> r & 1)
      for (std::uint32_t i = 0; i < scene_.planes.size(); ++i)
        queries[r].offerShape(ObjectKind::Plane, i, closest[r]);
  double tMin[kPacketSize];
  const double* tBest[kPacketSize];
  for (int r = 0; r < kPacketSize; ++r) {
    tMin[r] = queries[r].tMin();
    tBest[r] = &closest[r].t();
  }
  std::uint64_t visits = 0;
  const auto offerMesh = [&](std::uint32_t mesh, std::uint32_t rays) MESHTRACE_INLINE_LEAF {
    if (mesh != kMeshBvh) {
      const auto count = static_cast<std::uint32_t>(scene_.meshes[mesh].triangles().size());
      for (int r = 0; r < kPacketSize; ++r)
        if (rays >> r & 1)
          for (std::uint32_t t = 0; t < count; ++t)
            queries[r].offerTriangle(mesh, t, closest[r]);
      return;
    }
    const auto traverse = [&](const auto& locate) MESHTRACE_INLINE_LEAF {
      PacketBlockRays blockRay(queries, meshBvh_.frame);
      const auto offerBlock = [&](std::uint32_t index, std::uint32_t n,
                                  std::uint32_t meeting) MESHTRACE_INLINE_LEAF {
        const TriangleBlock4& block = meshBvh_.blocks[index];
        const auto& mesh = locate.of(block);
        int lanes[kPacketSize] = {};
        int any = 0;
        for (int r = 0; r < kPacketSize; ++r) {
          if (!(meeting >> r & 1)) continue;
          lanes[r] = candidateLanes(blockRay.get(r), block, n, mesh, tMin[r], closest[r].t(),
                                    counters);
          any |= lanes[r];
        }
        if (meshBvh_.prefetch) prefetchVertices(block, any, mesh);
        for (int r = 0; r < kPacketSize; ++r) {
          const PrimitiveQuery& query = queries[r];
          ClosestHit& best = closest[r];
          forEachLane(block, lanes[r], mesh, [&](const PrimitiveRef& t) {
            query.offerTriangle(t.object, t.triangle, best);
            return false;
          });
        }
      };
      traverseClosestPacket(meshBvh_.tree, slab, tMin, tBest, rays, visits, offerBlock,
                            childPrefetch(meshBvh_));
    };
    withLocator(meshBvh_.triangles, traverse);
  };
  const auto offerObjects = [&](std::uint32_t first, std::uint32_t n,
                                std::uint32_t rays) MESHTRACE_INLINE_LEAF {
    for (std::uint32_t k = first; k < first + n; ++k) {
      const Object& o = objects_[top_.order[k]];
      if (o.kind == ObjectKind::Mesh) {
        offerMesh(o.index, rays);
      } else {
        for (int r = 0; r < kPacketSize; ++r)
          if (rays >> r & 1) queries[r].offerShape(o.kind, o.index, closest[r]);
      }
    }
  };
  traverseClosestPacket(top_, slab, tMin, tBest, active, visits, offerObjects);
  counters.nodeVisits += visits;
}

bool SceneBvh::occluded(const PrimitiveQuery& query, double tMax, Counters& counters) const {
  for (std::uint32_t i = 0; i < scene_.planes.size(); ++i)
    if (query.shapeBlocks(ObjectKind::Plane, i, tMax)) return true;
  const SlabRay ray = slabRay(query);
  const double tMin = query.tMin();
  std::uint64_t visits = 0;
  const auto meshBlocks = [&](std::uint32_t mesh) MESHTRACE_INLINE_LEAF {
    if (mesh != kMeshBvh) {
      const auto count = static_cast<std::uint32_t>(scene_.meshes[mesh].triangles().size());
      for (std::uint32_t t = 0; t < count; ++t)
        if (query.triangleBlocks(mesh, t, tMax)) return true;
      return false;
    }
    const auto traverse = [&](const auto& locate) MESHTRACE_INLINE_LEAF {
      LazyBlockRay blockRay(query.ray(), meshBvh_.frame, query.kernel());
      const auto blockBlocks = [&](std::uint32_t block, std::uint32_t n) MESHTRACE_INLINE_LEAF {
        return forEachCandidate(blockRay.get(), meshBvh_.blocks[block], n, locate, tMin, tMax,
                                counters, [&](const PrimitiveRef& t) {
                                  return query.triangleBlocks(t.object, t.triangle, tMax);
                                });
      };
      return traverseAny(meshBvh_.tree, ray, tMin, tMax, visits, blockBlocks,
                         childPrefetch(meshBvh_));
    };
    return withLocator(meshBvh_.triangles, traverse);
  };
  const auto objectsBlock = [&](std::uint32_t first, std::uint32_t n) MESHTRACE_INLINE_LEAF {
    for (std::uint32_t k = first; k < first + n; ++k) {
      const Object& o = objects_[top_.order[k]];
      if (o.kind == ObjectKind::Mesh ? meshBlocks(o.index)
                                     : query.shapeBlocks(o.kind, o.index, tMax))
        return true;
    }
    return false;
  };
  const bool blocked = traverseAny(top_, ray, tMin, tMax, visits, objectsBlock);
  counters.nodeVisits += visits;
  return blocked;
}

std::uint32_t SceneBvh::occludedPacket(const PrimitiveQuery* queries, const double* tMax,
                                       std::uint32_t active, Counters& counters) const {
  std::uint32_t found = 0;
  for (int r = 0; r < kPacketSize; ++r)
    if (active >> r & 1)
      for (std::uint32_t i = 0; i < scene_.planes.size(); ++i)
        if (queries[r].shapeBlocks(ObjectKind::Plane, i, tMax[r])) {
          found |= 1u << r;
          break;
        }
  active &= ~found;
  if (!active) return found;
  const SlabRay slab[kPacketSize] = {slabRay(queries[0]), slabRay(queries[1]),
                                     slabRay(queries[2]), slabRay(queries[3])};
  double tMin[kPacketSize];
  for (int r = 0; r < kPacketSize; ++r) tMin[r] = queries[r].tMin();
  std::uint64_t visits = 0;
  const auto meshBlocks = [&](std::uint32_t mesh, std::uint32_t meeting) MESHTRACE_INLINE_LEAF {
    if (mesh != kMeshBvh) {
      std::uint32_t now = 0;
      const auto count = static_cast<std::uint32_t>(scene_.meshes[mesh].triangles().size());
      for (int r = 0; r < kPacketSize; ++r)
        if (meeting >> r & 1)
          for (std::uint32_t t = 0; t < count; ++t)
            if (queries[r].triangleBlocks(mesh, t, tMax[r])) {
              now |= 1u << r;
              break;
            }
      return now;
    }
    const auto traverse = [&](const auto& locate) MESHTRACE_INLINE_LEAF {
      PacketBlockRays blockRay(queries, meshBvh_.frame);
      const auto blockBlocks = [&](std::uint32_t block, std::uint32_t n,
                                   std::uint32_t rays) MESHTRACE_INLINE_LEAF {
        std::uint32_t now = 0;
        for (int r = 0; r < kPacketSize; ++r) {
          if (!(rays >> r & 1)) continue;
          const PrimitiveQuery& query = queries[r];
          const double limit = tMax[r];
          if (forEachCandidate(blockRay.get(r), meshBvh_.blocks[block], n, locate, tMin[r],
                               limit, counters, [&](const PrimitiveRef& t) {
                                 return query.triangleBlocks(t.object, t.triangle, limit);
                               }))
            now |= 1u << r;
        }
        return now;
      };
      return traverseAnyPacket(meshBvh_.tree, slab, tMin, tMax, meeting, visits, blockBlocks,
                               childPrefetch(meshBvh_));
    };
    return withLocator(meshBvh_.triangles, traverse);
  };
  const auto objectsBlock = [&](std::uint32_t first, std::uint32_t n,
                                std::uint32_t meeting) MESHTRACE_INLINE_LEAF {
    std::uint32_t now = 0;
    for (std::uint32_t k = first; k < first + n && meeting & ~now; ++k) {
      const Object& o = objects_[top_.order[k]];
      if (o.kind == ObjectKind::Mesh) {
        now |= meshBlocks(o.index, meeting & ~now);
      } else {
        for (int r = 0; r < kPacketSize; ++r)
          if ((meeting & ~now) >> r & 1 && queries[r].shapeBlocks(o.kind, o.index, tMax[r]))
            now |= 1u << r;
      }
    }
    return now;
  };
  found |= traverseAnyPacket(top_, slab, tMin, tMax, active, visits, objectsBlock);
  counters.nodeVisits += visits;
  return found;
}

#undef MESHTRACE_INLINE_LEAF

}  // namespace meshtrace
