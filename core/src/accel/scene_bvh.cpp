// The scene's two-level BVH: building it (object boxes, the triangle BVH)
// and the one query of each width that both kinds of hit go through.
#include "accel/scene_bvh.h"

#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <new>
#include <type_traits>

#include "accel/primitive_query.h"
#include "accel/traverse.h"
#include "meshtrace/io/input_error.h"
#include "util/lanes.h"
#include "util/prefetch.h"

namespace meshtrace {

namespace {

Aabb sphereBox(const Sphere& s) {
  const Vec3 r(std::abs(s.radius));
  return {s.center - r, s.center + r};
}

// The open tube: along world axis i it reaches |a_i| h/2 from the centre
// through the axis, plus r sqrt(1 - a_i^2) through the circular rim.
Aabb cylinderBox(const Cylinder& c) {
  Vec3 half;
  for (int i = 0; i < 3; ++i) {
    const double a = c.axis[i];
    half[i] = std::abs(a) * 0.5 * std::abs(c.height) +
              std::abs(c.radius) * std::sqrt(std::max(0.0, 1.0 - a * a));
  }
  return {c.center - half, c.center + half};
}

// The BVH's boxes and its rays' origins are single precision. Up to this
// magnitude a box corner, an origin and their difference stay finite in
// float (2 x 2^126 < FLT_MAX), so a slab test errs only toward a visit;
// beyond it they round to infinity, and rays miss what brute force hits.
constexpr double kMaxBvhCoordinate = 0x1p126;

// Throws InputError naming the first object (or the camera) that reaches
// beyond kMaxBvhCoordinate. Ray origins lie on the objects or at the eye.
void refuseBeyondSinglePrecision(const Scene& scene) {
  const auto check = [&](const std::string& what, double reach) {
    if (reach <= kMaxBvhCoordinate) return;
    char text[320];
    std::snprintf(text, sizeof text,
                  "%s reaches %.3g: --accel bvh holds coordinates in single precision, up to "
                  "%.3g; use --accel aabb or none, or scale the scene down",
                  what.c_str(), reach, kMaxBvhCoordinate);
    throw InputError::inFile(scene.file, text);
  };
  check("the camera's eye", maxAbsComponent(scene.camera.spec().eye));
  for (std::size_t i = 0; i < scene.spheres.size(); ++i)
    check("sphere " + std::to_string(i + 1), sphereBox(scene.spheres[i]).largestCoordinate());
  for (std::size_t i = 0; i < scene.cylinders.size(); ++i)
    check("cylinder " + std::to_string(i + 1), cylinderBox(scene.cylinders[i]).largestCoordinate());
  for (const Mesh& mesh : scene.meshes)
    if (!mesh.triangles().empty())
      check("mesh " + mesh.file().filename().string(), mesh.bounds().largestCoordinate());
}

// Returns how many triangles were left out as spare copies.
std::size_t buildMeshBvh(const BvhBuildOptions& options, MeshBvh& out) {
  Bvh binary = buildBvh(out.triangles, options);
  const std::size_t copies = binary.copiesLeftOut;
  out.tree = collapseToBvh8(std::move(binary));
  out.frame = blockFrame(out.triangles.bounds());
  out.blocks = TriangleBlocks(out.triangles, out.frame, out.tree);
  return copies;
}

// Set bits of a 4-bit lane mask (std::popcount is a library call without
// the popcnt instruction of later x86-64 levels).
int laneCount(int mask) {
  static constexpr int kCount[16] = {0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4};
  return kCount[mask & 15];
}

// Where the triangles of a block live: their vertex-index rows and their
// (scene mesh, triangle) references. A block holds triangles of one mesh
// only (each mesh's tree is built on its own before the trees are joined,
// binary_bvh.cpp), so the mesh is found once per block, not per lane:
// straight off the set when there is one mesh, by a search of the set's
// meshes otherwise.
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
// firstId 0: the compiler would keep the subtraction on every lane.
class SoleMesh {
 public:
  explicit SoleMesh(const TriangleSet& set) {
    const TriangleSet::Member first = set[0];
    rows_ = first.mesh->triangles().data();
    vertices_ = first.mesh->vertices().data();
    sceneIndex_ = first.sceneIndex;
  }
  const SoleMesh& of(TriangleBlock) const { return *this; }
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
  BlockMesh of(TriangleBlock block) const {
    const TriangleSet::Member m = set_[block.id(0)];
    return {m.mesh->triangles().data(), m.mesh->vertices().data(), m.sceneIndex,
            block.id(0) - m.triangle};
  }

 private:
  const TriangleSet& set_;
};

// Calls visit with the locator that fits `set` (see above).
template <typename Visit>
[[gnu::always_inline]] inline auto withLocator(const TriangleSet& set, Visit&& visit) {
  return set.meshCount() == 1 ? visit(SoleMesh(set)) : visit(ManyMeshes(set));
}

// What the float filter tells a search of each kind about a block's lanes:
// an any-hit search, which lanes are certain hits (BlockRay::classify); a
// closest-hit search, the candidates' distance bounds (BlockRay::rank).
template <HitKind kKind>
using FilteredLanes = std::conditional_t<kKind == HitKind::Any, BlockRay::Lanes, BlockRay::Ranked>;

// The lanes of the block that the float filter passes on to the exact test,
// as FilteredLanes. Every lane counts as one triangle test: those dropped
// here, the others in the exact test, as a certain hit or when they lie
// beyond a nearer hit (searchLanes).
// The exact test starts by reading the triangle's vertex indices from its
// mesh, a cache miss on a large mesh; asking for them before the filter
// runs overlaps that wait with it.
template <HitKind kKind, typename Mesh>
FilteredLanes<kKind> filterLanes(const BlockRay& ray, TriangleBlock block, const Mesh& mesh,
                                 double tMin, double tMax, Counters& counters) {
  const int n = block.count();
  for (int k = 0; k < n; ++k) prefetchLine(mesh.row(block.id(k)));
  FilteredLanes<kKind> lanes;
  if constexpr (kKind == HitKind::Any)
    lanes = ray.classify(block, tMin, tMax);
  else
    lanes = ray.rank(block, tMin, tMax);
  counters.triangleTests += static_cast<std::uint64_t>(n - laneCount(lanes.candidates));
  return lanes;
}

// Whether an any-hit search takes one of the certain lanes as its blocker
// without the exact test: any of them but the triangle the ray leaves.
template <typename Search, typename Mesh>
bool takesCertainLane(Search& search, TriangleBlock block, int certain, const Mesh& mesh) {
  if constexpr (Search::kKind == HitKind::Any) {
    for (; certain; certain &= certain - 1) {
      const PrimitiveRef t = mesh.ref(block.id(__builtin_ctz(static_cast<unsigned>(certain))));
      if (search.certainTriangle(t.object, t.triangle)) return true;
    }
  }
  return false;
}

// Calls exact(triangle) with the PrimitiveRef of each lane in `lanes` until
// one call returns true.
template <typename Mesh, typename Exact>
bool forEachLane(TriangleBlock block, int lanes, const Mesh& mesh, Exact&& exact) {
  for (; lanes; lanes &= lanes - 1)
    if (exact(mesh.ref(block.id(__builtin_ctz(static_cast<unsigned>(lanes)))))) return true;
  return false;
}

// The exact tests of a block's candidate lanes, until one ends the search.
// An any-hit search takes them in lane order. A closest-hit search takes
// them nearest first by their bounds and stops at the first that lies
// beyond the hit found so far, as the filter would have dropped it had
// that hit been known: in an interior, a leaf often holds both faces of a
// wall or a beam, and a ray that meets the near one passes the filter for
// the far one too.
template <typename Search, typename Mesh>
[[gnu::always_inline]] inline bool searchLanes(Search& search, const BlockRay& ray,
                                               TriangleBlock block,
                                               const FilteredLanes<Search::kKind>& lanes,
                                               const Mesh& mesh, Counters& counters) {
  if constexpr (Search::kKind == HitKind::Any) {
    return forEachLane(block, lanes.candidates, mesh, [&](const PrimitiveRef& t) {
      return search.triangle(t.object, t.triangle);
    });
  } else {
    int left = lanes.candidates;
    if ((left & (left - 1)) == 0) {  // one candidate or none: nothing to order
      if (left) {
        const PrimitiveRef t = mesh.ref(block.id(__builtin_ctz(static_cast<unsigned>(left))));
        search.triangle(t.object, t.triangle);
      }
      return false;
    }
    while (left) {
      int nearest = __builtin_ctz(static_cast<unsigned>(left));
      for (int rest = left & (left - 1); rest; rest &= rest - 1) {
        const int k = __builtin_ctz(static_cast<unsigned>(rest));
        if (lanes.near[k] < lanes.near[nearest]) nearest = k;
      }
      if (ray.beyond(lanes.near[nearest], search.limit())) {
        counters.triangleTests += static_cast<std::uint64_t>(laneCount(left));
        break;
      }
      left &= ~(1 << nearest);
      const PrimitiveRef t = mesh.ref(block.id(nearest));
      search.triangle(t.object, t.triangle);
    }
    return false;
  }
}

// Asks for the vertices of the lanes in `lanes`, so that the exact tests of
// several lanes wait for them together, not in turn. Closest-hit packets on
// large trees do this between filtering a block for all their rays and
// testing (the rays of a quad mostly meet their hits in different
// triangles); any-hit packets do not, since nearly all their candidates are
// lanes the exact test rejects.
template <typename Mesh>
void prefetchVertices(TriangleBlock block, int lanes, const Mesh& mesh) {
  for (; lanes; lanes &= lanes - 1) {
    const TriangleIndices& row = *mesh.row(block.id(__builtin_ctz(static_cast<unsigned>(lanes))));
    for (int c = 0; c < 3; ++c) prefetchObject(mesh.vertices()[row[c]]);
  }
}

// One ray's search through a block: the filter, a certain lane for an
// any-hit search, then the exact test of each candidate, as above.
template <typename Search, typename Locate>
[[gnu::always_inline]] inline bool searchBlock(Search& search, const BlockRay& ray,
                                               TriangleBlock block, const Locate& locate,
                                               double tMin, Counters& counters) {
  const auto& mesh = locate.of(block);
  const auto lanes = filterLanes<Search::kKind>(ray, block, mesh, tMin, search.limit(), counters);
  if (takesCertainLane(search, block, lanes.certain, mesh)) return true;
  return searchLanes(search, ray, block, lanes, mesh, counters);
}

// What the triangle BVH's traversals ask for ahead: a leaf's data is its
// block.
auto childPrefetch(const MeshBvh& bvh) {
  const auto block = [&blocks = bvh.blocks](std::uint32_t first, std::uint32_t count) {
    const TriangleBlock b = blocks.block(first, count);
    prefetchBytes(b.data(), b.bytes());
  };
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
  [[gnu::always_inline]] const BlockRay& get() {
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
  template <typename Search>
  PacketBlockRays(const Search* searches, const BlockFrame& frame)
      : rays_(makeLanes<kPacketSize>([&](std::size_t r) {
          const PrimitiveQuery& query = searches[r].query();
          return LazyBlockRay(query.ray(), frame, query.kernel());
        })) {}
  [[gnu::always_inline]] const BlockRay& get(int r) { return rays_[r].get(); }

 private:
  std::array<LazyBlockRay, kPacketSize> rays_;
};
}  // namespace

SceneBvh::SceneBvh(const Scene& scene, const SceneBvhOptions& options) : scene_(scene) {
  refuseBeyondSinglePrecision(scene);
  const auto start = std::chrono::steady_clock::now();
  inMeshBvh_.resize(scene.meshes.size());
  for (std::size_t i = 0; i < scene.meshes.size(); ++i) {
    const Mesh& mesh = scene.meshes[i];
    const std::size_t n = mesh.triangles().size();
    inMeshBvh_[i] = n > 0 && n >= options.minMeshTriangles;
    if (inMeshBvh_[i])
      meshBvh_.triangles.add(mesh, static_cast<std::uint32_t>(i));
    else if (n > 0)
      stats_.leftOut.push_back("no BVH for " + mesh.file().filename().string() + ": " +
                               std::to_string(n) + " triangles, under " +
                               std::to_string(options.minMeshTriangles));
  }
  if (!meshBvh_.triangles.empty()) stats_.copiesLeftOut = buildMeshBvh(options.mesh, meshBvh_);
  if (stats_.copiesLeftOut > 0)
    stats_.leftOut.push_back(
        std::to_string(stats_.copiesLeftOut) +
        " triangles out of the triangle BVH: exact copies (the same corners in the same order) "
        "of two triangles it holds, which answer for them");
  meshBvh_.prefetch = !meshBvh_.empty() && meshBvh_.bytes() >= options.prefetchBytes;
  if (!meshBvh_.empty() && !meshBvh_.prefetch) {
    char why[128];
    std::snprintf(why, sizeof why,
                  "BVH children not fetched ahead: the triangle BVH's %.1f MB are under %.1f MB",
                  meshBvh_.bytes() / 1048576.0, options.prefetchBytes / 1048576.0);
    stats_.leftOut.push_back(why);
  }

  std::vector<Aabb> boxes;
  const auto add = [&](ObjectKind kind, std::size_t i, const Aabb& box) {
    objects_.push_back({kind, static_cast<std::uint32_t>(i)});
    boxes.push_back(box);
  };
  for (std::size_t i = 0; i < scene.spheres.size(); ++i)
    add(ObjectKind::Sphere, i, sphereBox(scene.spheres[i]));
  for (std::size_t i = 0; i < scene.cylinders.size(); ++i)
    add(ObjectKind::Cylinder, i, cylinderBox(scene.cylinders[i]));
  for (std::size_t i = 0; i < scene.meshes.size(); ++i)
    if (!scene.meshes[i].triangles().empty() && !inMeshBvh_[i])
      add(ObjectKind::Mesh, i, scene.meshes[i].bounds());
  if (!meshBvh_.empty()) add(ObjectKind::Mesh, kMeshBvh, meshBvh_.triangles.bounds());
  top_ = collapseToBvh8(buildBvh(boxes, options.top));
  for (const Aabb& b : boxes) sceneScale_ = std::max(sceneScale_, b.largestCoordinate());

  stats_.topLevelObjects = objects_.size();
  stats_.topLevelBytes = top_.bytes() + objects_.size() * sizeof(Object);
  stats_.meshesWithBvh = meshBvh_.triangles.meshCount();
  stats_.trianglesInBvhs = meshBvh_.triangles.size();
  stats_.meshBvhBytes = meshBvh_.bytes();
  stats_.maxDepth = top_.depth + meshBvh_.tree.depth;
  stats_.buildSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Queries. The leaf work of both levels is forced inline (GCC and Clang
// take the attribute after a lambda's parameters), as the traversals are:
// as calls, each with its prologue and its own copy of the box ray, the
// queries run measurably slower.
#define MESHTRACE_INLINE_LEAF __attribute__((always_inline))

[[gnu::always_inline]] inline SlabRay SceneBvh::slabRay(const PrimitiveQuery& query) const {
  // One call per precision, so that each folds its padding's constants into
  // SlabRay's scale factors rather than working them out for every ray.
  const Ray& ray = query.ray();
  if (query.kernel().precision == Precision::Single)
    return SlabRay(ray, slabPadding(true, ray.origin, sceneScale_));
  return SlabRay(ray, slabPadding(false, ray.origin, sceneScale_));
}

// A ray spawned from a face that lies on the triangle BVH's box (a box, a
// CAD part, a wall) starts outside that box by the spawn offset, a rounding's
// width. The float boxes are padded far wider, so it would enter the root
// and filter the blocks around its start for nothing. The box's double
// test, exact for the default kernel and padded as --accel aabb's for the
// others (boxPadding), turns it away first; a ray that starts inside the
// box, as most spawned rays do, pays six comparisons.
[[gnu::always_inline]] inline bool SceneBvh::leavesTheMeshBvhBox(const PrimitiveQuery& query,
                                                                 double tLimit) const {
  if (!query.startsOnTriangle()) return false;
  const Aabb& box = meshBvh_.triangles.bounds();
  const Vec3& o = query.ray().origin;
  if (o.x >= box.min.x && o.x <= box.max.x && o.y >= box.min.y && o.y <= box.max.y &&
      o.z >= box.min.z && o.z <= box.max.z)
    return false;
  return missesTheMeshBvhBox(query, tLimit);
}

bool SceneBvh::missesTheMeshBvhBox(const PrimitiveQuery& query, double tLimit) const {
  double tEnter, tExit;
  return !intersectSlabs(meshBvh_.triangles.bounds(), RayInverse(query.ray()), query.tMin(), tLimit,
                         tEnter, tExit,
                         boxPadding(query.kernel(), query.ray().origin, sceneScale_));
}

template <typename Search>
[[gnu::always_inline]] inline bool SceneBvh::tracePlanes(Search& search) const {
  for (std::uint32_t i = 0; i < scene_.planes.size(); ++i)
    if (search.shape(ObjectKind::Plane, i)) return true;
  return false;
}

template <typename Search>
bool SceneBvh::trace(Search& search, Counters& counters) const {
  return traceBounded(slabRay(search.query()), search, counters);
}

template <typename Search>
bool SceneBvh::traceBounded(const SlabRay& ray, Search& search, Counters& counters) const {
  constexpr HitKind kKind = Search::kKind;
  const PrimitiveQuery& query = search.query();
  if (tracePlanes(search)) return true;
  const double tMin = query.tMin();
  std::uint64_t visits = 0;
  // A top-level leaf's mesh: a small one triangle by triangle, or the
  // triangle BVH.
  const auto meshLeaf = [&](std::uint32_t mesh) MESHTRACE_INLINE_LEAF {
    if (mesh != kMeshBvh) {
      const auto count = static_cast<std::uint32_t>(scene_.meshes[mesh].triangles().size());
      for (std::uint32_t t = 0; t < count; ++t)
        if (search.triangle(mesh, t)) return true;
      return false;
    }
    if (leavesTheMeshBvhBox(query, search.limit())) return false;
    const auto traverseMeshes = [&](const auto& locate) MESHTRACE_INLINE_LEAF {
      LazyBlockRay blockRay(query.ray(), meshBvh_.frame, query.kernel());
      const auto blockLeaf = [&](std::uint32_t first, std::uint32_t n) MESHTRACE_INLINE_LEAF {
        return searchBlock(search, blockRay.get(), meshBvh_.blocks.block(first, n), locate, tMin,
                           counters);
      };
      return traverse<kKind>(meshBvh_.tree, ray, tMin, search.limit(), visits, blockLeaf,
                             childPrefetch(meshBvh_));
    };
    return withLocator(meshBvh_.triangles, traverseMeshes);
  };
  const auto objectLeaf = [&](std::uint32_t first, std::uint32_t n) MESHTRACE_INLINE_LEAF {
    for (std::uint32_t k = first; k < first + n; ++k) {
      const Object& o = objects_[top_.order[k]];
      if (o.kind == ObjectKind::Mesh ? meshLeaf(o.index) : search.shape(o.kind, o.index))
        return true;
    }
    return false;
  };
  const bool ended = traverse<kKind>(top_, ray, tMin, search.limit(), visits, objectLeaf);
  counters.nodeVisits += visits;
  return ended;
}

template <typename Search>
std::uint32_t SceneBvh::tracePacket(Search* searches, std::uint32_t active,
                                    Counters& counters) const {
  constexpr HitKind kKind = Search::kKind;
  if (active == 0) return 0;
  const auto slab =
      makeLanes<kPacketSize>([&](std::size_t r) { return slabRay(searches[r].query()); });
  std::uint32_t ended = 0;
  if constexpr (kKind == HitKind::Closest) {
    // The closest-hit traversal orders children by one octant: rays of
    // different octants go one by one.
    const int lead = __builtin_ctz(active);
    for (int r = 0; r < kPacketSize; ++r)
      if (active >> r & 1 && slab[r].octant != slab[lead].octant) {
        for (int k = 0; k < kPacketSize; ++k)
          if (active >> k & 1 && traceBounded(slab[k], searches[k], counters)) ended |= 1u << k;
        return ended;
      }
  }
  for (int r = 0; r < kPacketSize; ++r)
    if (active >> r & 1 && tracePlanes(searches[r])) ended |= 1u << r;
  active &= ~ended;
  if (active == 0) return ended;
  double tMin[kPacketSize];
  const double* tLimit[kPacketSize];
  for (int r = 0; r < kPacketSize; ++r) {
    tMin[r] = searches[r].query().tMin();
    tLimit[r] = &searches[r].limit();
  }
  std::uint64_t visits = 0;
  // As in traceBounded, for the rays named in `rays`; returns those whose
  // search ended.
  const auto meshLeaf = [&](std::uint32_t mesh, std::uint32_t rays) MESHTRACE_INLINE_LEAF {
    std::uint32_t done = 0;
    if (mesh != kMeshBvh) {
      const auto count = static_cast<std::uint32_t>(scene_.meshes[mesh].triangles().size());
      for (int r = 0; r < kPacketSize; ++r)
        if (rays >> r & 1)
          for (std::uint32_t t = 0; t < count; ++t)
            if (searches[r].triangle(mesh, t)) {
              done |= 1u << r;
              break;
            }
      return done;
    }
    for (int r = 0; r < kPacketSize; ++r)
      if (rays >> r & 1 && leavesTheMeshBvhBox(searches[r].query(), searches[r].limit()))
        rays &= ~(1u << r);
    if (rays == 0) return done;
    const auto traverseMeshes = [&](const auto& locate) MESHTRACE_INLINE_LEAF {
      PacketBlockRays blockRay(searches, meshBvh_.frame);
      const auto blockLeaf = [&](std::uint32_t first, std::uint32_t n,
                                 std::uint32_t meeting) MESHTRACE_INLINE_LEAF {
        const TriangleBlock block = meshBvh_.blocks.block(first, n);
        const auto& mesh = locate.of(block);
        // Every ray's filter first, then the exact tests.
        FilteredLanes<kKind> lanes[kPacketSize] = {};
        int any = 0;
        std::uint32_t now = 0;
        for (int r = 0; r < kPacketSize; ++r) {
          if (!(meeting >> r & 1)) continue;
          lanes[r] = filterLanes<kKind>(blockRay.get(r), block, mesh, tMin[r], searches[r].limit(),
                                        counters);
          any |= lanes[r].candidates;
          if (takesCertainLane(searches[r], block, lanes[r].certain, mesh)) {
            now |= 1u << r;
            lanes[r].candidates = 0;
          }
        }
        if (kKind == HitKind::Closest && meshBvh_.prefetch) prefetchVertices(block, any, mesh);
        for (int r = 0; r < kPacketSize; ++r) {
          if (searchLanes(searches[r], blockRay.get(r), block, lanes[r], mesh, counters))
            now |= 1u << r;
        }
        return now;
      };
      return traversePacket<kKind>(meshBvh_.tree, slab.data(), tMin, tLimit, rays, visits,
                                   blockLeaf, childPrefetch(meshBvh_));
    };
    return withLocator(meshBvh_.triangles, traverseMeshes);
  };
  const auto objectLeaf = [&](std::uint32_t first, std::uint32_t n, std::uint32_t rays)
                              MESHTRACE_INLINE_LEAF {
                                std::uint32_t open = rays;
                                for (std::uint32_t k = first; k < first + n && open; ++k) {
                                  const Object& o = objects_[top_.order[k]];
                                  if (o.kind == ObjectKind::Mesh) {
                                    open &= ~meshLeaf(o.index, open);
                                  } else {
                                    for (int r = 0; r < kPacketSize; ++r)
                                      if (open >> r & 1 && searches[r].shape(o.kind, o.index))
                                        open &= ~(1u << r);
                                  }
                                }
                                return rays & ~open;
                              };
  ended |= traversePacket<kKind>(top_, slab.data(), tMin, tLimit, active, visits, objectLeaf);
  counters.nodeVisits += visits;
  return ended;
}

#undef MESHTRACE_INLINE_LEAF

template bool SceneBvh::trace(ClosestHitSearch&, Counters&) const;
template bool SceneBvh::trace(AnyHitSearch&, Counters&) const;
template std::uint32_t SceneBvh::tracePacket(ClosestHitSearch*, std::uint32_t, Counters&) const;
template std::uint32_t SceneBvh::tracePacket(AnyHitSearch*, std::uint32_t, Counters&) const;

}  // namespace meshtrace
