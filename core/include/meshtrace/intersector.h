#pragma once
// Closest-hit and any-hit queries over a whole scene, with a selectable
// acceleration method.
#include <string_view>

#include "meshtrace/counters.h"
#include "meshtrace/scene.h"

namespace meshtrace {

enum class AccelMethod {
  None,         // every triangle of every mesh
  BoundingBox,  // a mesh's triangles only when the ray meets its box
};

const char* toString(AccelMethod method);
// Throws std::invalid_argument for an unknown name.
AccelMethod parseAccelMethod(std::string_view name);

// Every choice that changes how rays are intersected. Accelerated and brute
// force queries use the same triangle kernel, so they find the same hits.
struct TraceOptions {
  AccelMethod accel = AccelMethod::BoundingBox;
};

class SceneIntersector {
 public:
  SceneIntersector(const Scene& scene, const TraceOptions& options);

  // Nearest hit with t > tMin; `hit.t` may carry an upper limit on entry.
  bool closestHit(const Ray& ray, double tMin, Hit& hit, Counters& counters) const;
  // True if anything lies at tMin < t < tMax.
  bool occluded(const Ray& ray, double tMin, double tMax, Counters& counters) const;

  const Scene& scene() const { return scene_; }
  const TraceOptions& options() const { return options_; }

 private:
  bool intersectMesh(std::uint32_t index, const Ray& ray, const RayInverse& inverse,
                     double tMin, Hit& hit, bool anyHit, Counters& counters) const;

  const Scene& scene_;
  TraceOptions options_;
};

}  // namespace meshtrace
