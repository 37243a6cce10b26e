#include "meshtrace/aabb.h"

namespace meshtrace {

namespace {
// gamma(n) = n*u / (1 - n*u), the bound on relative rounding error after n
// floating-point operations (pbrt, section 6.8.1).
constexpr double gamma(int n) {
  constexpr double u = std::numeric_limits<double>::epsilon() * 0.5;
  return (n * u) / (1 - n * u);
}
}  // namespace

bool intersectSlabs(const Aabb& box, const RayInverse& ray, double tMin, double tMax,
                    double& tEnter, double& tExit) {
  for (int axis = 0; axis < 3; ++axis) {
    if (ray.direction[axis] == 0.0) {
      if (ray.origin[axis] < box.min[axis] || ray.origin[axis] > box.max[axis]) return false;
      continue;
    }
    double tNear = (box.min[axis] - ray.origin[axis]) * ray.invDirection[axis];
    double tFar = (box.max[axis] - ray.origin[axis]) * ray.invDirection[axis];
    if (tNear > tFar) std::swap(tNear, tFar);
    tFar *= 1.0 + 2.0 * gamma(3);
    tMin = std::max(tMin, tNear);
    tMax = std::min(tMax, tFar);
    if (tMin > tMax) return false;
  }
  tEnter = tMin;
  tExit = tMax;
  return true;
}

}  // namespace meshtrace
