#pragma once
// The ray-box test of the 8-wide BVH: float slab tests that are
// conservative, so that they never cull a box holding a hit that the
// primitive kernels would report. SlabPadding says how much wider than exact
// a box must be tested, SlabRay prepares a ray for it (and tests a single
// box, a root leaf's), and BoxRay8 tests the eight children of a node at once.
#include <emmintrin.h>
#include <xmmintrin.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

#include "accel/bvh8.h"
#include "meshtrace/geometry/aabb.h"
#include "meshtrace/geometry/triangle.h"
#include "meshtrace/util/math.h"

namespace meshtrace {

// The padding for kernels with unit roundoff `u` (2^-53 or 2^-24), a ray
// origin and a scene whose coordinates are at most `sceneScale` in size:
// twice the slack within which a triangle kernel's hits lie (HitSlack,
// triangle.h), which leaves room for the float test's own roundings.
// Double: 2^-20 covers the quadrics' sqrt(u) ~ 1e-8 and cos(theta) down to
// ~1e-9; the absolute pad is 2^23 u. Float: 2^-12 and 2^-14, that is 2^12 u
// and 2^10 u.
inline SlabPadding slabPadding(bool singlePrecisionTriangles, const Vec3& origin,
                               double sceneScale) {
  const double scale = maxAbsComponent(origin) + sceneScale;
  const HitSlack slack = hitSlack(singlePrecisionTriangles ? Precision::Single : Precision::Double);
  return SlabPadding{2 * slack.relative, 2 * slack.absolute * scale};
}

// The padding of a double-precision box test (intersectSlabs) of a box
// around triangles whose coordinates are at most `scale` in size, so that
// it holds every hit `kernel` reports on them: slabPadding for Cramer and
// Moller-Trumbore, whose hits may lie up to their HitSlack outside their
// triangle's box, and for every single-precision kernel, whose corners,
// rounded to float, may lie outside the double box. None for the default
// kernel, the watertight one in double, whose hits lie within a few
// roundings of their triangle's box: exact, the test can still turn away a
// ray spawned from a face on the box, which starts outside it by about as
// little (the spawn offset), where the padding would take it in.
inline SlabPadding boxPadding(TriangleKernel kernel, const Vec3& origin, double scale) {
  if (kernel.test == TriangleTest::Watertight && kernel.precision == Precision::Double) return {};
  return slabPadding(kernel.precision == Precision::Single, origin, scale);
}

// The ray prepared for float slab tests that stay conservative: every box is
// tested as if widened by pad.absolute, with the distances scaled by
// 1 -/+ pad.relative (SlabPadding), whatever the float rounding does. The
// set-up runs in float on all three axes at once (u = 2^-24 below):
// - The origin is moved toward the far plane for the near distance (and the
//   other way for the far one) by shift = a + 2^-21 |o|, a = pad.absolute
//   (1 + 2^-20) rounded to float (2^-21 |o| is exact, a power of two).
//   Converting o and a, adding to form shift and adding it to o lose at most
//   2u |o| + 3u a; the 8u |o| and 16u a in shift cover that, so the float
//   origin is still on the widened side.
// - A reciprocal goes through five roundings (direction to float, the
//   division, the scale factor, the subtraction and the product of the slab
//   test), a relative error below 5u < 2^-21; the scale factors carry 2^-19
//   beyond pad.relative, which covers it with room for the factor's own
//   rounding (2^-24).
// - A zero or tiny component gets reciprocal +-1e30 rather than inf, so that
//   (plane - origin) * reciprocal is never 0 * inf = NaN.
class SlabRay {
 public:
  [[gnu::always_inline]] SlabRay(const Ray& ray, const SlabPadding& pad) {
    const __m128 signBit = _mm_set1_ps(-0.0f);
    const __m128 o = toFloats(ray.origin), d = toFloats(ray.direction);
    const __m128 dSign = _mm_and_ps(d, signBit);
    const __m128 absD = _mm_max_ps(_mm_andnot_ps(signBit, d), _mm_set1_ps(1e-30f));
    const __m128 inv = _mm_or_ps(_mm_div_ps(_mm_set1_ps(1.0f), absD), dSign);
    const __m128 absShift =
        _mm_add_ps(_mm_set1_ps(static_cast<float>(pad.absolute * (1.0 + 0x1p-20))),
                   _mm_mul_ps(_mm_set1_ps(0x1p-21f), _mm_andnot_ps(signBit, o)));
    const __m128 shift = _mm_or_ps(absShift, dSign);  // toward the far plane
    originNear = _mm_add_ps(o, shift);
    originFar = _mm_sub_ps(o, shift);
    invNear = _mm_mul_ps(inv, _mm_set1_ps(static_cast<float>(1.0 - pad.relative - 0x1p-19)));
    invFar = _mm_mul_ps(inv, _mm_set1_ps(static_cast<float>(1.0 + pad.relative + 0x1p-19)));
    // By the reciprocal's sign, so that -0.0 goes with the negative side,
    // as its reciprocal does.
    negative_ = _mm_cmplt_ps(invNear, _mm_setzero_ps());
    octant = _mm_movemask_ps(negative_) & 7;
  }

  // Whether the ray meets the widened box lo-hi within [tMin, tMax]: the
  // node test's arithmetic with the three axes side by side (lo and hi are
  // (x, y, z, z)), for a tree whose root is a leaf.
  [[gnu::always_inline]] bool meets(const float* lo, const float* hi, float tMin,
                                    float tMax) const {
    const __m128 low = _mm_load_ps(lo), high = _mm_load_ps(hi);
    const __m128 nearPlane = _mm_or_ps(_mm_and_ps(negative_, high), _mm_andnot_ps(negative_, low));
    const __m128 farPlane = _mm_or_ps(_mm_and_ps(negative_, low), _mm_andnot_ps(negative_, high));
    __m128 enter = _mm_mul_ps(_mm_sub_ps(nearPlane, originNear), invNear);
    __m128 exit = _mm_mul_ps(_mm_sub_ps(farPlane, originFar), invFar);
    enter = _mm_max_ps(enter, _mm_shuffle_ps(enter, enter, 0x4e));
    enter = _mm_max_ps(enter, _mm_shuffle_ps(enter, enter, 0xb1));
    exit = _mm_min_ps(exit, _mm_shuffle_ps(exit, exit, 0x4e));
    exit = _mm_min_ps(exit, _mm_shuffle_ps(exit, exit, 0xb1));
    const float in = _mm_cvtss_f32(enter), out = _mm_cvtss_f32(exit);
    return in <= out && in <= tMax && tMin <= out;
  }

  // Lanes x, y, z (w: a copy of z, harmless in the reductions above).
  __m128 originNear, originFar, invNear, invFar;
  int octant;  // the direction's signs: bit a set if d[a] < 0

 private:
  // (x, y, z, z) in float.
  static __m128 toFloats(const Vec3& v) {
    const __m128 z = _mm_cvtpd_ps(_mm_load1_pd(&v[2]));
    return _mm_movelh_ps(_mm_cvtpd_ps(_mm_loadu_pd(&v[0])), z);
  }

  __m128 negative_;  // lanes whose direction component is negative
};

// The slab ray with each axis splatted over four lanes, for the node test.
// Made when a traversal reaches its first node: a ray that misses a tree
// whose root is a leaf never needs it.
class BoxRay8 {
 public:
  [[gnu::always_inline]] explicit BoxRay8(const SlabRay& ray) : octant_(ray.octant) {
    splat(ray.originNear, originNear_);
    splat(ray.originFar, originFar_);
    splat(ray.invNear, invNear_);
    splat(ray.invFar, invFar_);
    // The near and far planes of each axis in a node, by the direction's
    // signs, so that the slab test picks them without a branch.
    const auto& planes = kPlaneOffsets[octant_];
    for (int k = 0; k < 6; ++k) planeOffset_[k] = planes[k];
  }

  int octant() const { return octant_; }

  // Bit i set if the ray meets child i's widened box within [tMin, tMax];
  // tEnter[i] receives its entry distance. Children 0-3 and 4-7 are tested
  // side by side, two independent chains of the same length as one.
  [[gnu::always_inline]] unsigned intersect(const Bvh8Node& node, __m128 tMin, __m128 tMax,
                                            float* tEnter) const {
    __m128 enterLow = tMin, enterHigh = tMin, exitLow = tMax, exitHigh = tMax;
    const char* base = reinterpret_cast<const char*>(&node);
    const auto slab = [](const float* plane, __m128 origin, __m128 inv, __m128& low, __m128& high) {
      low = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(plane), origin), inv);
      high = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(plane + 4), origin), inv);
    };
    for (int a = 0; a < 3; ++a) {
      __m128 low, high;
      slab(reinterpret_cast<const float*>(base + planeOffset_[a]), originNear_[a], invNear_[a], low,
           high);
      enterLow = _mm_max_ps(enterLow, low);
      enterHigh = _mm_max_ps(enterHigh, high);
      slab(reinterpret_cast<const float*>(base + planeOffset_[3 + a]), originFar_[a], invFar_[a],
           low, high);
      exitLow = _mm_min_ps(exitLow, low);
      exitHigh = _mm_min_ps(exitHigh, high);
    }
    _mm_store_ps(tEnter, enterLow);
    _mm_store_ps(tEnter + 4, enterHigh);
    return static_cast<unsigned>(_mm_movemask_ps(_mm_cmple_ps(enterLow, exitLow)) |
                                 _mm_movemask_ps(_mm_cmple_ps(enterHigh, exitHigh)) << 4);
  }

 private:
  [[gnu::always_inline]] static void splat(__m128 xyz, __m128 out[3]) {
    out[0] = _mm_shuffle_ps(xyz, xyz, 0x00);
    out[1] = _mm_shuffle_ps(xyz, xyz, 0x55);
    out[2] = _mm_shuffle_ps(xyz, xyz, 0xaa);
  }

  // Byte offsets in a Bvh8Node of the near planes (x, y, z), then the far
  // ones, for each sign pattern of the direction (bit a: d[a] < 0).
  static constexpr auto kPlaneOffsets = [] {
    std::array<std::array<std::uint32_t, 6>, 8> table{};
    for (int signs = 0; signs < 8; ++signs)
      for (int a = 0; a < 3; ++a) {
        const std::size_t axis = a * kBvhWidth * sizeof(float);
        const auto lo = static_cast<std::uint32_t>(offsetof(Bvh8Node, lo) + axis);
        const auto hi = static_cast<std::uint32_t>(offsetof(Bvh8Node, hi) + axis);
        const bool flip = (signs >> a) & 1;
        table[signs][a] = flip ? hi : lo;
        table[signs][3 + a] = flip ? lo : hi;
      }
    return table;
  }();

  __m128 originNear_[3], originFar_[3], invNear_[3], invFar_[3];
  std::uint32_t planeOffset_[6];
  int octant_;
};

namespace bvh8 {

// A float no smaller than t (t * (1 + 2^-23) is above t by at least half a
// float ulp, so rounding to nearest cannot fall below t); inf stays inf.
inline float atLeast(double t) { return static_cast<float>(t * (1.0 + 0x1p-23)); }
inline float atMost(double t) {
  return t <= 0.0 ? static_cast<float>(t * (1.0 + 0x1p-23))
                  : static_cast<float>(t * (1.0 - 0x1p-23));
}

}  // namespace bvh8

}  // namespace meshtrace
