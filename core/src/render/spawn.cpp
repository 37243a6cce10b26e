#include "meshtrace/render/spawn.h"

namespace meshtrace {

namespace {
// The float nearest to x in the direction of `sign` (or to nearest if 0):
// rounding never brings the origin back toward the surface.
double toFloatAway(double x, double sign) {
  float f = static_cast<float>(x);
  if (sign > 0.0 && double(f) < x) f = nextUp(f);
  if (sign < 0.0 && double(f) > x) f = nextDown(f);
  return f;
}
}  // namespace

Vec3 spawnOrigin(const SurfacePoint& sp, const Vec3& direction) {
  const Vec3& n = sp.geometricNormal;
  // The distance along n that leaves the error box: the support of the box
  // in direction n (pbrt-v4 OffsetRayOrigin).
  const double d = glm::dot(glm::abs(n), sp.error);
  Vec3 offset = d * n;
  if (glm::dot(direction, n) < 0.0) offset = -offset;
  Vec3 po = sp.point + offset;
  // The addition rounds to nearest, possibly back toward p: step one ulp on.
  for (int i = 0; i < 3; ++i) {
    if (offset[i] > 0.0) po[i] = nextUp(po[i]);
    if (offset[i] < 0.0) po[i] = nextDown(po[i]);
    if (sp.precision == Precision::Single) po[i] = toFloatAway(po[i], offset[i]);
  }
  return po;
}

}  // namespace meshtrace
