#include "meshtrace/geometry/aabb.h"

namespace meshtrace {

bool intersectSlabs(const Aabb& box, const RayInverse& ray, double tMin, double tMax,
                    double& tEnter, double& tExit) {
  for (int axis = 0; axis < 3; ++axis) {
    if (ray.direction[axis] == 0.0) {
      if (ray.origin[axis] < box.min[axis] || ray.origin[axis] > box.max[axis]) return false;
      continue;
    }
    // Near and far planes chosen by the direction's sign, not by swapping:
    // for an empty box (min = +inf, max = -inf) a swap would turn the
    // interval into (-inf, inf) and report a hit for every ray.
    const bool negative = ray.invDirection[axis] < 0.0;
    const double tNear =
        ((negative ? box.max : box.min)[axis] - ray.origin[axis]) * ray.invDirection[axis];
    double tFar =
        ((negative ? box.min : box.max)[axis] - ray.origin[axis]) * ray.invDirection[axis];
    tFar *= 1.0 + 2.0 * roundingGamma<double>(3);
    tMin = std::max(tMin, tNear);
    tMax = std::min(tMax, tFar);
    if (tMin > tMax) return false;
  }
  tEnter = tMin;
  tExit = tMax;
  return true;
}

}  // namespace meshtrace
