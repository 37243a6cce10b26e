#pragma once
// atan2 for two angles at once, in the two lanes of an SSE2 register: the
// vertex normals take two corner angles a triangle, and glibc's scalar
// atan2 was most of their time. Plain SSE2 adds, multiplies and one divide,
// so the bits are the same on every x86-64 machine (no FMA, no choice of
// code path at run time, as glibc's vector atan2 makes).
//
// Within 2 ulp of the exact angle (tests/core/util/atan2_pair_test.cpp),
// where glibc's atan2 is within 1: the reduced argument w below carries
// two roundings, and the polynomial alone is within 1.6e-17 of atan(w),
// relative.
#include <emmintrin.h>

#include <array>

namespace meshtrace {

// {atan2(y, x0), atan2(y, x1)} in [0, pi], for finite y >= 0 and x not both
// zero with y. An infinite x gives 0 or pi.
[[gnu::always_inline]] inline std::array<double, 2> atan2Pair(double y, double x0, double x1) {
  // atan(w) = w + w s P(s), s = w^2, on |w| <= 1/2: P interpolates
  // (atan(w) / w - 1) / s at 12 Chebyshev points of s in [0, 1/4]
  // (scripts/atan_coefficients.py).
  static constexpr double c[12] = {
      -0x1.5555555555554p-2, 0x1.9999999998dc7p-3, -0x1.2492492404d83p-3, 0x1.c71c7173fae64p-4,
      -0x1.745d0a99d91e0p-4, 0x1.3b128bfd32fbbp-4, -0x1.110025075dddcp-4, 0x1.e0955a999ace7p-5,
      -0x1.a680f4658c711p-5, 0x1.5ee9281016ed2p-5, -0x1.da5fdeb30e33ep-6, 0x1.6d755fc1636f4p-7};
  // pi / 4, pi / 2 and pi, each as hi + lo.
  constexpr double kQuarterPi[2] = {0x1.921fb54442d18p-1, 0x1.1a62633145c07p-55};
  constexpr double kHalfPi[2] = {0x1.921fb54442d18p+0, 0x1.1a62633145c07p-54};
  constexpr double kPi[2] = {0x1.921fb54442d18p+1, 0x1.1a62633145c07p-53};

  const auto splat = [](double v) { return _mm_set1_pd(v); };
  const auto select = [](__m128d mask, __m128d a, __m128d b) {
    return _mm_or_pd(_mm_and_pd(mask, a), _mm_andnot_pd(mask, b));
  };
  const __m128d signBit = splat(-0.0);
  const __m128d vy = splat(y), x = _mm_set_pd(x1, x0);
  const __m128d ax = _mm_andnot_pd(signBit, x);

  // The angle of (|x|, y) is base + atan(w) with |w| <= 1/2:
  //   y <= |x| / 2:  w = y / |x|,                base 0
  //   |x| <= y / 2:  w = -|x| / y,               base pi / 2
  //   otherwise:     w = (y - |x|) / (y + |x|),  base pi / 4
  // In the third case y - |x| is exact (Sterbenz), and |w| <= 1/3.
  const __m128d low = _mm_cmple_pd(vy, _mm_mul_pd(splat(0.5), ax));
  const __m128d high = _mm_cmple_pd(ax, _mm_mul_pd(splat(0.5), vy));
  const __m128d middle = _mm_andnot_pd(_mm_or_pd(low, high), _mm_cmpeq_pd(vy, vy));
  __m128d num = select(low, vy, select(high, _mm_xor_pd(signBit, ax), _mm_sub_pd(vy, ax)));
  const __m128d den = select(low, ax, select(high, vy, _mm_add_pd(vy, ax)));
  __m128d baseHi =
      _mm_or_pd(_mm_and_pd(high, splat(kHalfPi[0])), _mm_and_pd(middle, splat(kQuarterPi[0])));
  __m128d baseLo =
      _mm_or_pd(_mm_and_pd(high, splat(kHalfPi[1])), _mm_and_pd(middle, splat(kQuarterPi[1])));
  // For x < 0 the angle is pi minus that of (|x|, y): pi - base - atan(w),
  // and atan is odd. pi - base is exact in its high part.
  const __m128d negative = _mm_cmplt_pd(x, _mm_setzero_pd());
  num = _mm_xor_pd(num, _mm_and_pd(signBit, x));
  baseHi = select(negative, _mm_sub_pd(splat(kPi[0]), baseHi), baseHi);
  baseLo = select(negative, _mm_sub_pd(splat(kPi[1]), baseLo), baseLo);

  const __m128d w = _mm_div_pd(num, den), s = _mm_mul_pd(w, w);
  // P by Estrin's scheme: a third of Horner's chain of dependent steps.
  const auto linear = [&](int k) {
    return _mm_add_pd(splat(c[k]), _mm_mul_pd(splat(c[k + 1]), s));
  };
  const __m128d s2 = _mm_mul_pd(s, s), s4 = _mm_mul_pd(s2, s2), s8 = _mm_mul_pd(s4, s4);
  const __m128d p0 = _mm_add_pd(linear(0), _mm_mul_pd(s2, linear(2)));
  const __m128d p1 = _mm_add_pd(linear(4), _mm_mul_pd(s2, linear(6)));
  const __m128d p2 = _mm_add_pd(linear(8), _mm_mul_pd(s2, linear(10)));
  const __m128d p = _mm_add_pd(p0, _mm_add_pd(_mm_mul_pd(s4, p1), _mm_mul_pd(s8, p2)));
  // Smallest terms first: w s P is under a tenth of w.
  const __m128d angle =
      _mm_add_pd(baseHi, _mm_add_pd(w, _mm_add_pd(_mm_mul_pd(_mm_mul_pd(w, s), p), baseLo)));
  std::array<double, 2> out;
  _mm_storeu_pd(out.data(), angle);
  return out;
}

}  // namespace meshtrace
