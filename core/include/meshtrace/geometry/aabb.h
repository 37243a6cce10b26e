#pragma once
// Axis-aligned box and its ray slab test.
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
};

// The reciprocal direction, computed once per ray and reused for every box.
struct RayInverse {
  Vec3 origin;
  Vec3 direction;
  Vec3 invDirection;

  explicit RayInverse(const Ray& ray)
      : origin(ray.origin), direction(ray.direction), invDirection(1.0 / ray.direction) {}
};

// Parametric interval [tEnter, tExit] of the ray inside the closed box,
// clipped to [tMin, tMax]. Returns false if the interval is empty.
//
// Numerics: an axis-parallel direction has a zero component; its slab is
// decided by comparing the origin with the slab instead of multiplying
// (box - origin) by inf, which would give NaN for an origin on a box plane.
// The exit distance is padded by 1 + 2*gamma(3) (Ize, "Robust BVH Ray
// Traversal", JCGT 2013) so rounding never makes the test miss a surface that
// lies on the box, which would lose hits that brute force finds.
bool intersectSlabs(const Aabb& box, const RayInverse& ray, double tMin, double tMax,
                    double& tEnter, double& tExit);

}  // namespace meshtrace
