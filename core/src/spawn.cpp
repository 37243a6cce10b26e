#include "meshtrace/spawn.h"

namespace meshtrace {

namespace {
// Offset along the normal, relative to the size of the hit point's
// coordinates plus a floor for points near the origin.
constexpr double kRelativeOffset = 1e-9;
constexpr double kAbsoluteOffset = 1e-9;
}  // namespace

Vec3 spawnOrigin(const Vec3& p, const Vec3& n, const Vec3& direction) {
  const double offset = kAbsoluteOffset + kRelativeOffset * maxAbsComponent(p);
  return glm::dot(n, direction) >= 0.0 ? p + offset * n : p - offset * n;
}

}  // namespace meshtrace
