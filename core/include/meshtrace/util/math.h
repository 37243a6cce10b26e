#pragma once
// Vector types and the ray. The core traces in double precision throughout.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
#include <limits>
#include <type_traits>

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

// The next representable value above (below) x, as std::nextafter toward
// +inf (-inf) gives it, by stepping the bits: nextafter is a library call,
// and these run for every spawned ray and every primitive box of a build.
// +inf (-inf) and NaN come back unchanged; -0 and +0 step to the smallest
// denormal of the direction's sign.
template <typename Real>
Real nextUp(Real x) {
  static_assert(std::is_same_v<Real, float> || std::is_same_v<Real, double>);
  using Bits = std::conditional_t<std::is_same_v<Real, float>, std::uint32_t, std::uint64_t>;
  if (!(x < std::numeric_limits<Real>::infinity())) return x;
  if (x == 0) return std::numeric_limits<Real>::denorm_min();
  const auto bits = std::bit_cast<Bits>(x);
  return std::bit_cast<Real>(x > 0 ? bits + 1 : bits - 1);
}
template <typename Real>
Real nextDown(Real x) {
  return -nextUp(-x);
}

inline double maxComponent(const Vec3& v) { return std::max({v.x, v.y, v.z}); }
inline double maxAbsComponent(const Vec3& v) {
  return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
}
inline bool isFinite(const Vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// `v` times the power of two 2^-e that brings its largest component into
// [0.5, 1) (e goes to `exponent`): exact, so v's direction can be taken
// from it even where v's own squares underflow (1e-200) or overflow
// (1e200), with the same bits where they do not. `v` finite and not zero.
inline Vec3 scaledToUnitRange(const Vec3& v, int* exponent = nullptr) {
  int e = 0;
  std::frexp(maxAbsComponent(v), &e);
  if (exponent) *exponent = e;
  return {std::ldexp(v.x, -e), std::ldexp(v.y, -e), std::ldexp(v.z, -e)};
}

}  // namespace meshtrace
