#pragma once
// Vector types and the ray. The core traces in double precision throughout.
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace meshtrace {

using Vec3 = glm::dvec3;
using Color = glm::dvec3;

inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct Ray {
  Vec3 origin;
  Vec3 direction;  // unit length, so a ray parameter t is a distance

  Vec3 at(double t) const { return origin + t * direction; }
};

// gamma(n) = n u / (1 - n u), u the unit roundoff of Real: the bound on the
// relative error after n roundings (Higham; pbrt 6.8.1).
template <typename Real>
constexpr Real roundingGamma(int n) {
  constexpr Real u = std::numeric_limits<Real>::epsilon() / 2;
  return (n * u) / (1 - n * u);
}

inline double maxComponent(const Vec3& v) { return std::max({v.x, v.y, v.z}); }
inline double maxAbsComponent(const Vec3& v) {
  return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}
inline bool isFinite(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

}  // namespace meshtrace
