#pragma once
// What shading needs to know about a hit: the point, the shading normal and
// the material, plus what spawning a ray from it needs: the geometric normal
// and a bound on the point's rounding error. The one place that builds the
// shading point.
#include "meshtrace/geometry/hit.h"
#include "meshtrace/geometry/scene.h"
#include "meshtrace/geometry/triangle.h"

namespace meshtrace {

struct SurfacePoint {
  Vec3 point;
  Vec3 normal;  // shading normal, unit length
  const Material* material;
  Vec3 geometricNormal{0.0};  // unit normal of the surface itself (zero if degenerate)
  Vec3 error{0.0};            // per-component bound on the distance of `point` from the surface
  Precision precision = Precision::Double;  // of the kernel that found the hit
  PrimitiveRef primitive{};  // the primitive hit, which rays spawned from here start on
};

// The point is not o + t d, whose error grows with t, but is recomputed from
// the primitive: from the barycentrics for triangles (in the kernel's
// precision), and reprojected onto spheres, planes and cylinders. Its error
// bound then depends only on the size of the coordinates (pbrt-v4 6.8.5).
SurfacePoint surfaceAt(const Scene& scene, const Ray& ray, const Hit& hit,
                       Precision precision = Precision::Double);

}  // namespace meshtrace
