#include "meshtrace/accel/intersector.h"

#include "accel/primitive_query.h"
#include "accel/scene_bvh.h"
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
// method. Returns whether the search ended early.
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
      double tEnter, tExit;
      if (!intersectSlabs(mesh.bounds(), inverse, query.tMin(), search.limit(), tEnter, tExit))
        continue;
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
                                const PrimitiveRef* start) const {
  if (external_) return external_->occluded(ray, tMin, tMax, counters);
  AnyHitSearch search(tMax, scene_, ray, options_.triangle, tMin, counters, start);
  return trace(search, counters);
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
                                               Counters& counters) const {
  if (active == 0) return 0;  // a quad with no hit, or a light behind all four
  if (!bvh_) {
    std::uint32_t blocked = 0;
    for (int r = 0; r < kPacketSize; ++r)
      if (active >> r & 1 && occluded(rays[r], tMin, tMax[r], counters, &start[r]))
        blocked |= 1u << r;
    return blocked;
  }
  auto searches = makeLanes<kPacketSize>([&](std::size_t r) {
    return AnyHitSearch(tMax[r], scene_, rays[r], options_.triangle, tMin, counters, &start[r]);
  });
  return bvh_->tracePacket(searches.data(), active, counters);
}

}  // namespace meshtrace
