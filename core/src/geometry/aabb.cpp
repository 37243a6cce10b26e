#include "meshtrace/geometry/aabb.h"

#include <cmath>

namespace meshtrace {

bool intersectSlabs(const Aabb& box, const RayInverse& ray, double tMin, double tMax,
                    double& tEnter, double& tExit, const SlabPadding& pad) {
  for (int axis = 0; axis < 3; ++axis) {
    const double lo = box.min[axis] - pad.absolute, hi = box.max[axis] + pad.absolute;
    if (ray.direction[axis] == 0.0) {
      if (ray.origin[axis] < lo || ray.origin[axis] > hi) return false;
      continue;
    }
    // Near and far planes chosen by the direction's sign, not by swapping:
    // for an empty box (min = +inf, max = -inf) a swap would turn the
    // interval into (-inf, inf) and report a hit for every ray.
    const bool negative = ray.invDirection[axis] < 0.0;
    double tNear = ((negative ? hi : lo) - ray.origin[axis]) * ray.invDirection[axis];
    double tFar = ((negative ? lo : hi) - ray.origin[axis]) * ray.invDirection[axis];
    tFar *= 1.0 + 2.0 * roundingGamma<double>(3);
    if (pad.relative != 0.0) {  // outward whatever their signs
      tNear -= pad.relative * std::abs(tNear);
      tFar += pad.relative * std::abs(tFar);
    }
    tMin = std::max(tMin, tNear);
    tMax = std::min(tMax, tFar);
    if (tMin > tMax) return false;
  }
  tEnter = tMin;
  tExit = tMax;
  return true;
}

}  // namespace meshtrace
