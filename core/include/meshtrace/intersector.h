#pragma once
// Closest-hit and any-hit queries over a whole scene, with a selectable
// acceleration method.
#include <memory>
#include <string_view>

#include "meshtrace/counters.h"
#include "meshtrace/scene.h"
#include "meshtrace/scene_bvh.h"
#include "meshtrace/triangle.h"

namespace meshtrace {

enum class AccelMethod {
  None,         // every triangle of every mesh
  BoundingBox,  // a mesh's triangles only when the ray meets its box
  Bvh,          // a two-level bounding volume hierarchy (scene_bvh.h)
};

const char* toString(AccelMethod method);
// Throws std::invalid_argument for an unknown name.
AccelMethod parseAccelMethod(std::string_view name);

// Every choice that changes how rays are intersected. Accelerated and brute
// force queries use the same triangle kernel and the same order-independent
// choice among equal distances (primitive_query.h), so they find the same
// hits: the acceleration method changes the speed, never the image.
struct TraceOptions {
  AccelMethod accel = AccelMethod::Bvh;
  TriangleKernel triangle;  // algorithm and precision of the triangle test
  SceneBvhOptions bvh;      // build choices for --accel bvh (speed only)
};

// Another engine answering the same two queries: the benchmark plugs Embree
// in here to render with exactly our shading.
class ExternalIntersector {
 public:
  virtual ~ExternalIntersector() = default;
  virtual bool closestHit(const Ray& ray, double tMin, Hit& hit, Counters& counters) const = 0;
  virtual bool occluded(const Ray& ray, double tMin, double tMax, Counters& counters) const = 0;
};

class SceneIntersector {
 public:
  // Builds the BVH when options.accel is Bvh.
  SceneIntersector(const Scene& scene, const TraceOptions& options);
  // Every query goes to `external` (which must outlive this); `options` still
  // tells shading the precision of the hits.
  SceneIntersector(const Scene& scene, const TraceOptions& options,
                   const ExternalIntersector& external);
  ~SceneIntersector();

  // Nearest hit with t > tMin; `hit.t` may carry an upper limit on entry.
  // `start`, for a spawned ray, is the primitive it leaves
  // (SurfacePoint::primitive): a triangle there is not tested (spawn.h).
  bool closestHit(const Ray& ray, double tMin, Hit& hit, Counters& counters,
                  const PrimitiveRef* start = nullptr) const;
  // closestHit for the kPacketSize rays (scene_bvh.h) named in `active`
  // (bit r: rays[r], leaving start[r] when `start` is given), answered
  // exactly as separate calls would be; with --accel bvh, rays that share an
  // octant of directions, such as the primary rays of a 2x2 pixel quad or
  // their mirror reflections off a plane, are traced together. found[r]
  // tells whether ray r hit (false for inactive rays). Every rays[r] must be
  // a valid ray, active or not: give inactive slots a copy of an active ray.
  void closestHitPacket(const Ray* rays, double tMin, Hit* hits, bool* found, Counters& counters,
                        const PrimitiveRef* start = nullptr, std::uint32_t active = 0xfu) const;
  // occluded for the kPacketSize rays named in `active` (bit r: rays[r], up
  // to tMax[r], leaving start[r]); returns those blocked, exactly as four
  // calls would. With --accel bvh they are traced together. Every rays[r]
  // must be a valid ray, active or not.
  std::uint32_t occludedPacket(const Ray* rays, double tMin, const double* tMax,
                               const PrimitiveRef* start, std::uint32_t active,
                               Counters& counters) const;
  // True if anything lies at tMin < t < tMax; `start` as above.
  bool occluded(const Ray& ray, double tMin, double tMax, Counters& counters,
                const PrimitiveRef* start = nullptr) const;

  const Scene& scene() const { return scene_; }
  const TraceOptions& options() const { return options_; }
  // The scene's BVH, or null for the other methods.
  const SceneBvh* bvh() const { return bvh_.get(); }

 private:
  // Brute force: false only when the aabb method rules the mesh out by its box.
  bool meshMayBeHit(std::uint32_t index, const RayInverse& inverse, double tMin, double tMax,
                    Counters& counters) const;

  const Scene& scene_;
  TraceOptions options_;
  std::unique_ptr<SceneBvh> bvh_;
  const ExternalIntersector* external_ = nullptr;
};

}  // namespace meshtrace
