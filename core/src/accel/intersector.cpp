#include "meshtrace/accel/intersector.h"

#include <stdexcept>
#include <string>

#include "accel/primitive_query.h"
#include "accel/scene_bvh.h"

namespace meshtrace {

const char* toString(AccelMethod method) {
  switch (method) {
    case AccelMethod::None: return "none";
    case AccelMethod::BoundingBox: return "aabb";
    case AccelMethod::Bvh: return "bvh";
  }
  return "?";
}

AccelMethod parseAccelMethod(std::string_view name) {
  if (name == "none") return AccelMethod::None;
  if (name == "aabb") return AccelMethod::BoundingBox;
  if (name == "bvh") return AccelMethod::Bvh;
  throw std::invalid_argument("unknown acceleration method '" + std::string(name) +
                              "' (use none, aabb or bvh)");
}

SceneIntersector::SceneIntersector(const Scene& scene, const TraceOptions& options)
    : scene_(scene), options_(options) {
  if (options.accel == AccelMethod::Bvh) bvh_ = std::make_unique<SceneBvh>(scene, options.bvh);
}

SceneIntersector::SceneIntersector(const Scene& scene, const TraceOptions& options,
                                   const ExternalIntersector& external)
    : scene_(scene), options_(options), external_(&external) {}

SceneIntersector::~SceneIntersector() = default;

const SceneBvhStats* SceneIntersector::bvhStats() const {
  return bvh_ ? &bvh_->stats() : nullptr;
}

bool SceneIntersector::meshMayBeHit(std::uint32_t index, const RayInverse& inverse, double tMin,
                                    double tMax, Counters& counters) const {
  if (options_.accel != AccelMethod::BoundingBox) return true;
  ++counters.boxTests;
  double tEnter, tExit;
  return intersectSlabs(scene_.meshes[index].bounds(), inverse, tMin, tMax, tEnter, tExit);
}

bool SceneIntersector::closestHit(const Ray& ray, double tMin, Hit& hit, Counters& counters,
                                  const PrimitiveRef* start) const {
  if (external_) return external_->closestHit(ray, tMin, hit, counters);
  const PrimitiveQuery query(scene_, ray, options_.triangle, tMin, counters, start);
  ClosestHit closest(hit);
  if (bvh_) {
    bvh_->closestHit(query, closest, counters);
    return closest.found();
  }
  // Brute force, in the order that defines ties (primitive_query.h).
  for (std::uint32_t i = 0; i < scene_.spheres.size(); ++i)
    query.offerShape(ObjectKind::Sphere, i, closest);
  for (std::uint32_t i = 0; i < scene_.planes.size(); ++i)
    query.offerShape(ObjectKind::Plane, i, closest);
  for (std::uint32_t i = 0; i < scene_.cylinders.size(); ++i)
    query.offerShape(ObjectKind::Cylinder, i, closest);
  if (!scene_.meshes.empty()) {
    const RayInverse inverse(ray);
    for (std::uint32_t m = 0; m < scene_.meshes.size(); ++m) {
      if (!meshMayBeHit(m, inverse, tMin, hit.t, counters)) continue;
      const auto count = static_cast<std::uint32_t>(scene_.meshes[m].triangles().size());
      for (std::uint32_t t = 0; t < count; ++t) query.offerTriangle(m, t, closest);
    }
  }
  return closest.found();
}

void SceneIntersector::closestHitPacket(const Ray* rays, double tMin, Hit* hits, bool* found,
                                        Counters& counters, const PrimitiveRef* start,
                                        std::uint32_t active) const {
  const auto leaving = [start](int r) { return start ? &start[r] : nullptr; };
  if (!bvh_) {
    for (int r = 0; r < kPacketSize; ++r)
      found[r] = (active >> r & 1) && closestHit(rays[r], tMin, hits[r], counters, leaving(r));
    return;
  }
  const PrimitiveQuery queries[kPacketSize] = {
      {scene_, rays[0], options_.triangle, tMin, counters, leaving(0)},
      {scene_, rays[1], options_.triangle, tMin, counters, leaving(1)},
      {scene_, rays[2], options_.triangle, tMin, counters, leaving(2)},
      {scene_, rays[3], options_.triangle, tMin, counters, leaving(3)}};
  ClosestHit closest[kPacketSize] = {ClosestHit(hits[0]), ClosestHit(hits[1]),
                                     ClosestHit(hits[2]), ClosestHit(hits[3])};
  bvh_->closestHitPacket(queries, closest, active, counters);
  for (int r = 0; r < kPacketSize; ++r) found[r] = (active >> r & 1) && closest[r].found();
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
  const PrimitiveQuery queries[kPacketSize] = {
      {scene_, rays[0], options_.triangle, tMin, counters, &start[0]},
      {scene_, rays[1], options_.triangle, tMin, counters, &start[1]},
      {scene_, rays[2], options_.triangle, tMin, counters, &start[2]},
      {scene_, rays[3], options_.triangle, tMin, counters, &start[3]}};
  return bvh_->occludedPacket(queries, tMax, active, counters);
}

bool SceneIntersector::occluded(const Ray& ray, double tMin, double tMax, Counters& counters,
                                const PrimitiveRef* start) const {
  if (external_) return external_->occluded(ray, tMin, tMax, counters);
  const PrimitiveQuery query(scene_, ray, options_.triangle, tMin, counters, start);
  if (bvh_) return bvh_->occluded(query, tMax, counters);
  const auto blocks = [&](ObjectKind kind, std::size_t n) {
    for (std::uint32_t i = 0; i < n; ++i)
      if (query.shapeBlocks(kind, i, tMax)) return true;
    return false;
  };
  if (blocks(ObjectKind::Sphere, scene_.spheres.size()) ||
      blocks(ObjectKind::Plane, scene_.planes.size()) ||
      blocks(ObjectKind::Cylinder, scene_.cylinders.size()))
    return true;
  if (!scene_.meshes.empty()) {
    const RayInverse inverse(ray);
    for (std::uint32_t m = 0; m < scene_.meshes.size(); ++m) {
      if (!meshMayBeHit(m, inverse, tMin, tMax, counters)) continue;
      const auto count = static_cast<std::uint32_t>(scene_.meshes[m].triangles().size());
      for (std::uint32_t t = 0; t < count; ++t)
        if (query.triangleBlocks(m, t, tMax)) return true;
    }
  }
  return false;
}

}  // namespace meshtrace
