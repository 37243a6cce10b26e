#pragma once
// Closest-hit and any-hit queries over a whole scene, with a selectable
// acceleration method.
#include <cstdint>
#include <memory>

#include "meshtrace/accel/bvh_stats.h"
#include "meshtrace/accel/trace_options.h"
#include "meshtrace/geometry/scene.h"
#include "meshtrace/util/counters.h"

namespace meshtrace {

class SceneBvh;

// Rays traced together by the packet queries: the 2x2 pixel quads of a
// render, their shadow rays and their mirror reflections.
inline constexpr int kPacketSize = 4;

// Another engine answering the same two queries: the benchmark plugs Embree
// in here to render with exactly our shading.
class ExternalIntersector {
 public:
  virtual ~ExternalIntersector() = default;
  virtual bool closestHit(const Ray& ray, double tMin, Hit& hit, Counters& counters) const = 0;
  virtual bool occluded(const Ray& ray, double tMin, double tMax, Counters& counters) const = 0;
};

// The primitive that blocked the last shadow ray toward a light, kept by
// the caller from one such query to the next (one per light and thread).
// Shadow rays from neighbouring pixels toward one light are mostly blocked
// by the same wall or floor, if at all: testing that primitive first
// answers them without a traversal. A ray the primitive does not block is
// traced as without it, so the answers are the same; a ray nothing blocks
// forgets it, and lit surfaces pay for no test. Where the blockers keep
// failing (a mesh shadowing itself, each ray by other small triangles),
// the caller's run of rays stops keeping them after kMaxMisses in a row.
struct LastBlocker {
  static constexpr int kMaxMisses = 3;

  bool known = false;
  PrimitiveRef primitive;
  int misses = 0;  // blockers in a row that blocked none of the rays tested

  bool givenUp() const { return misses >= kMaxMisses; }
  // After it was tested on a query's rays: whether it blocked any.
  void tested(bool blockedSome) { misses = blockedSome ? 0 : misses + 1; }
  // After the traversal of the rays it did not block: a blocker `found`
  // there replaces it; without one it is forgotten, unless it blocked some
  // of the query's rays itself (`answeredSome`).
  void traversed(const PrimitiveRef* found, bool answeredSome) {
    if (found) {
      known = true;
      primitive = *found;
    } else if (!answeredSome) {
      known = false;
    }
  }
};

// About how many bytes constructing a SceneIntersector for `scene` with
// `options` allocates at the peak of its build: an estimate with a margin,
// from the sizes of the build's arrays, for a caller to check against a
// memory limit before building. 0 for the methods that build nothing.
std::uint64_t accelerationBytes(const Scene& scene, const TraceOptions& options);

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
  // closestHit for the kPacketSize rays named in `active`
  // (bit r: rays[r], leaving start[r] when `start` is given), answered
  // exactly as separate calls would be; with --accel bvh, rays that share an
  // octant of directions, such as the primary rays of a 2x2 pixel quad or
  // their mirror reflections off a plane, are traced together. found[r]
  // tells whether ray r hit (false for inactive rays). Every rays[r] must be
  // a valid ray, active or not: give inactive slots a copy of an active ray.
  void closestHitPacket(const Ray* rays, double tMin, Hit* hits, bool* found, Counters& counters,
                        const PrimitiveRef* start = nullptr, std::uint32_t active = 0xfu) const;
  // occluded for the kPacketSize rays named in `active` (bit r: rays[r], up
  // to tMax[r], leaving start[r]), all toward one light; returns those
  // blocked, exactly as four calls would. With --accel bvh they are traced
  // together. Every rays[r] must be a valid ray, active or not.
  std::uint32_t occludedPacket(const Ray* rays, double tMin, const double* tMax,
                               const PrimitiveRef* start, std::uint32_t active, Counters& counters,
                               LastBlocker* last = nullptr) const;
  // True if anything lies at tMin < t < tMax; `start` as above. `last`, if
  // given, is tested first and updated (not with an external intersector,
  // which does not name what it met).
  bool occluded(const Ray& ray, double tMin, double tMax, Counters& counters,
                const PrimitiveRef* start = nullptr, LastBlocker* last = nullptr) const;

  const Scene& scene() const { return scene_; }
  const TraceOptions& options() const { return options_; }
  // What the scene's BVH holds and left out; null for the other methods.
  const SceneBvhStats* bvhStats() const;
  // The BVH itself, for the library's own tests (its type is internal).
  const SceneBvh* bvh() const { return bvh_.get(); }

 private:
  // The search of the acceleration method, brute force or the BVH: `Search`
  // holds the ray and what it looks for (see SceneBvh::trace).
  template <typename Search>
  bool trace(Search& search, Counters& counters) const;

  const Scene& scene_;
  TraceOptions options_;
  std::unique_ptr<SceneBvh> bvh_;
  const ExternalIntersector* external_ = nullptr;
};

}  // namespace meshtrace
