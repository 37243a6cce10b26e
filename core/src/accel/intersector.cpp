#include "meshtrace/accel/intersector.h"

#include <tbb/task_arena.h>

#include <bit>

#include "accel/primitive_query.h"
#include "accel/scene_bvh.h"
#include "accel/slab_ray.h"
#include "meshtrace/util/enum_names.h"
#include "util/lanes.h"

namespace meshtrace {

namespace {
constexpr EnumName<AccelMethod> kAccelMethods[] = {
    {AccelMethod::None, "none"}, {AccelMethod::BoundingBox, "aabb"}, {AccelMethod::Bvh, "bvh"}};
}  // namespace

const char* toString(AccelMethod method) { return nameIn(kAccelMethods, method); }
AccelMethod parseAccelMethod(std::string_view name) {
  return parseNamed(kAccelMethods, name, "acceleration method");
}

namespace {
// The binned build's peak per triangle: its reference (32 bytes), room for
// two nodes (2 x 32) and its place in the leaf order (4). Collapsing to
// 8-wide nodes keeps that tree (68) beside at most 9 bytes per binary node
// (2 per triangle) and the 8-wide nodes (256 bytes per 8 triangles or
// more); the triangle blocks (40 bytes a triangle, a block padded to 32:
// 64 for a leaf of one) and the list of leaves being packed (20 bytes a
// leaf) come once the binary tree is gone. 128 covers the largest stage
// with a margin.
constexpr std::uint64_t kBuildBytesPerTriangle = 128;
// With several meshes each one's tree (68 per triangle) is kept until all
// are joined into one copy of them.
constexpr std::uint64_t kJoinBytesPerTriangle = 68;
// Each vertex's box while its mesh's tree is built.
constexpr std::uint64_t kBuildBytesPerVertex = 32;
// A top-level object: its box, reference, nodes and share of 8-wide nodes.
constexpr std::uint64_t kBuildBytesPerObject = 256;
// A thread's buffer for the small subtrees it builds alone.
constexpr std::uint64_t kBuildBytesPerThread = std::uint64_t{256} << 10;
}  // namespace

std::uint64_t accelerationBytes(const Scene& scene, const TraceOptions& options) {
  if (options.accel != AccelMethod::Bvh) return 0;
  std::uint64_t triangles = 0, vertices = 0, meshes = 0;
  for (const Mesh& mesh : scene.meshes) {
    const std::size_t n = mesh.triangles().size();
    if (n == 0 || n < options.bvh.minMeshTriangles) continue;
    triangles += n;
    vertices += mesh.vertices().size();
    ++meshes;
  }
  const std::uint64_t objects = scene.objectCount() + 1;
  const auto threads = static_cast<std::uint64_t>(tbb::this_task_arena::max_concurrency());
  return triangles * (kBuildBytesPerTriangle + (meshes > 1 ? kJoinBytesPerTriangle : 0)) +
         vertices * kBuildBytesPerVertex + objects * kBuildBytesPerObject +
         threads * kBuildBytesPerThread;
}

SceneIntersector::SceneIntersector(const Scene& scene, const TraceOptions& options)
    : scene_(scene), options_(options) {
  if (options.accel == AccelMethod::Bvh) bvh_ = std::make_unique<SceneBvh>(scene, options.bvh);
}

SceneIntersector::SceneIntersector(const Scene& scene, const TraceOptions& options,
                                   const ExternalIntersector& external)
    : scene_(scene), options_(options), external_(&external) {}

SceneIntersector::~SceneIntersector() = default;

const SceneBvhStats* SceneIntersector::bvhStats() const { return bvh_ ? &bvh_->stats() : nullptr; }

namespace {

// Brute force: every primitive, in the order that defines ties
// (primitive_query.h), a mesh's triangles only after its box with the aabb
// method, padded so that it holds every hit the kernel reports (boxPadding).
// Returns whether the search ended early.
template <typename Search>
bool bruteForce(const Scene& scene, AccelMethod accel, Search& search, Counters& counters) {
  const auto shapes = [&](ObjectKind kind, std::size_t n) {
    for (std::uint32_t i = 0; i < n; ++i)
      if (search.shape(kind, i)) return true;
    return false;
  };
  if (shapes(ObjectKind::Sphere, scene.spheres.size()) ||
      shapes(ObjectKind::Plane, scene.planes.size()) ||
      shapes(ObjectKind::Cylinder, scene.cylinders.size()))
    return true;
  if (scene.meshes.empty()) return false;
  const PrimitiveQuery& query = search.query();
  const RayInverse inverse(query.ray());
  for (std::uint32_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    if (accel == AccelMethod::BoundingBox) {
      ++counters.boxTests;
      const Aabb& box = mesh.bounds();
      const SlabPadding pad =
          boxPadding(query.kernel(), query.ray().origin, box.largestCoordinate());
      double tEnter, tExit;
      if (!intersectSlabs(box, inverse, query.tMin(), search.limit(), tEnter, tExit, pad)) continue;
    }
    const auto count = static_cast<std::uint32_t>(mesh.triangles().size());
    for (std::uint32_t t = 0; t < count; ++t)
      if (search.triangle(m, t)) return true;
  }
  return false;
}

}  // namespace

template <typename Search>
bool SceneIntersector::trace(Search& search, Counters& counters) const {
  return bvh_ ? bvh_->trace(search, counters)
              : bruteForce(scene_, options_.accel, search, counters);
}

bool SceneIntersector::closestHit(const Ray& ray, double tMin, Hit& hit, Counters& counters,
                                  const PrimitiveRef* start) const {
  if (external_) return external_->closestHit(ray, tMin, hit, counters);
  ClosestHitSearch search(hit, scene_, ray, options_.triangle, tMin, counters, start);
  trace(search, counters);
  return search.found();
}

bool SceneIntersector::occluded(const Ray& ray, double tMin, double tMax, Counters& counters,
                                const PrimitiveRef* start, LastBlocker* last) const {
  if (external_) return external_->occluded(ray, tMin, tMax, counters);
  AnyHitSearch search(tMax, scene_, ray, options_.triangle, tMin, counters, start);
  if (!last || last->givenUp()) return trace(search, counters);
  if (last->known) {
    const bool answered = search.primitive(last->primitive);
    last->tested(answered);
    if (answered) {
      ++counters.lastBlockerHits;
      return true;
    }
  }
  const bool blocked = trace(search, counters);
  last->traversed(blocked ? &search.blocker() : nullptr, false);
  return blocked;
}

void SceneIntersector::closestHitPacket(const Ray* rays, double tMin, Hit* hits, bool* found,
                                        Counters& counters, const PrimitiveRef* start,
                                        std::uint32_t active) const {
  const auto leaving = [start](std::size_t r) { return start ? &start[r] : nullptr; };
  if (!bvh_) {
    for (int r = 0; r < kPacketSize; ++r)
      found[r] = (active >> r & 1) && closestHit(rays[r], tMin, hits[r], counters, leaving(r));
    return;
  }
  auto searches = makeLanes<kPacketSize>([&](std::size_t r) {
    return ClosestHitSearch(hits[r], scene_, rays[r], options_.triangle, tMin, counters,
                            leaving(r));
  });
  bvh_->tracePacket(searches.data(), active, counters);
  for (int r = 0; r < kPacketSize; ++r) found[r] = (active >> r & 1) && searches[r].found();
}

std::uint32_t SceneIntersector::occludedPacket(const Ray* rays, double tMin, const double* tMax,
                                               const PrimitiveRef* start, std::uint32_t active,
                                               Counters& counters, LastBlocker* last) const {
  if (active == 0) return 0;  // a quad with no hit, or a light behind all four
  if (!bvh_) {
    std::uint32_t blocked = 0;
    for (int r = 0; r < kPacketSize; ++r)
      if (active >> r & 1 && occluded(rays[r], tMin, tMax[r], counters, &start[r], last))
        blocked |= 1u << r;
    return blocked;
  }
  auto searches = makeLanes<kPacketSize>([&](std::size_t r) {
    return AnyHitSearch(tMax[r], scene_, rays[r], options_.triangle, tMin, counters, &start[r]);
  });
  if (!last || last->givenUp()) return bvh_->tracePacket(searches.data(), active, counters);
  // The rays the last blocker blocks, tested in turn up to the first it
  // does not: where it fails once, it seldom serves the rest, and a mesh's
  // small triangles would cost four tests a packet to no avail.
  std::uint32_t known = 0;
  if (last->known) {
    for (std::uint32_t rays = active; rays != 0; rays &= rays - 1) {
      const int r = std::countr_zero(rays);
      if (!searches[r].primitive(last->primitive)) break;
      known |= 1u << r;
    }
    counters.lastBlockerHits += static_cast<std::uint64_t>(std::popcount(known));
    last->tested(known != 0);
  }
  const std::uint32_t rest = active & ~known;
  const std::uint32_t traced = rest ? bvh_->tracePacket(searches.data(), rest, counters) : 0;
  last->traversed(traced ? &searches[std::countr_zero(traced)].blocker() : nullptr, known != 0);
  return known | traced;
}

}  // namespace meshtrace
