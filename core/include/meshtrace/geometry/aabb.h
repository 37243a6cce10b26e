#pragma once
// Axis-aligned box and its ray slab test.
#include <algorithm>

#include "meshtrace/util/math.h"

namespace meshtrace {

struct Aabb {
  Vec3 min{kInfinity};
  Vec3 max{-kInfinity};

  void extend(const Vec3& p) {
    min = glm::min(min, p);
    max = glm::max(max, p);
  }
  void extend(const Aabb& b) {
    min = glm::min(min, b.min);
    max = glm::max(max, b.max);
  }
  bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
  Vec3 extent() const { return max - min; }
  Vec3 center() const { return 0.5 * (min + max); }
  // The largest |coordinate| of its corners: the size of the numbers in it.
  double largestCoordinate() const { return std::max(maxAbsComponent(min), maxAbsComponent(max)); }
};

// The reciprocal direction, computed once per ray and reused for every box.
struct RayInverse {
  Vec3 origin;
  Vec3 direction;
  Vec3 invDirection;

  explicit RayInverse(const Ray& ray)
      : origin(ray.origin), direction(ray.direction), invDirection(1.0 / ray.direction) {}
};

// How much wider than exact a box test must be. Ize ("Robust BVH Ray
// Traversal", JCGT 2(2) 2013) pads the far distance by 1 + 2 gamma(3)
// (~7e-16) to cover the slab test's own rounding. A box around triangles
// must be wider, because it must hold not the exact hit but the one the
// kernels compute:
// - `relative` scales the near distance by 1 - relative and the far one by
//   1 + relative. A kernel's t is off by about u t / cos(theta) for a ray at
//   angle theta to a triangle, and a quadric's root by up to about sqrt(u) t
//   for a grazing ray (cancellation in the discriminant).
// - `absolute` widens every box by that distance on each side: the kernels'
//   rounding of the ray origin and of the vertices, about u (|o| + |v|), which
//   does not shrink with t (a float kernel rounds the origin to float).
struct SlabPadding {
  double relative = 0.0;
  double absolute = 0.0;
};

// Parametric interval [tEnter, tExit] of the ray inside the closed box,
// widened by `pad`, clipped to [tMin, tMax]. Returns false if the interval
// is empty.
//
// Numerics: an axis-parallel direction has a zero component; its slab is
// decided by comparing the origin with the slab instead of multiplying
// (box - origin) by inf, which would give NaN for an origin on a box plane.
// The exit distance is padded by 1 + 2*gamma(3) (Ize) so rounding never
// makes the test miss a surface that lies on the box, which would lose hits
// that brute force finds.
bool intersectSlabs(const Aabb& box, const RayInverse& ray, double tMin, double tMax,
                    double& tEnter, double& tExit, const SlabPadding& pad = {});

}  // namespace meshtrace
