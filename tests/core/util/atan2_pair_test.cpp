// The two-lane atan2 of the vertex normals, against atan2 in long double
// (64-bit significand: its own error is a two-thousandth of a double ulp).
#include "util/atan2_pair.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

namespace meshtrace {
namespace {

// |got - exact| in units of the last place of the double nearest `exact`.
double ulpsFrom(double got, long double exact) {
  const double nearest = static_cast<double>(exact);
  const double ulp = std::nextafter(std::fabs(nearest), INFINITY) - std::fabs(nearest);
  return static_cast<double>(std::fabs(static_cast<long double>(got) - exact)) / ulp;
}

TEST(Atan2Pair, IsWithinTwoUlpOfTheExactAngleInBothLanes) {
  std::mt19937_64 rng(21);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), exponent(-60.0, 60.0);
  double worst = 0.0;
  for (int i = 0; i < 2'000'000; ++i) {
    const double y = std::fabs(unit(rng)) * std::exp2(i % 4 == 0 ? exponent(rng) : 0.0);
    double x0 = unit(rng) * std::exp2(i % 3 == 0 ? exponent(rng) : 0.0);
    // Near the boundaries of the reduction, where the reduced argument is
    // largest: y = |x| / 2 and y = 2 |x|.
    if (i % 5 == 1) x0 = 2.0 * y * (1.0 + 1e-3 * unit(rng));
    if (i % 5 == 2) x0 = -0.5 * y * (1.0 + 1e-3 * unit(rng));
    const double x1 = -x0 * (1.0 + 1e-6 * unit(rng));
    const auto [a0, a1] = atan2Pair(y, x0, x1);
    worst = std::max(worst, ulpsFrom(a0, std::atan2(static_cast<long double>(y), x0)));
    worst = std::max(worst, ulpsFrom(a1, std::atan2(static_cast<long double>(y), x1)));
  }
  EXPECT_LT(worst, 2.0) << "largest error in ulps";
}

TEST(Atan2Pair, GivesTheAxesAndTheDiagonalExactly) {
  constexpr double pi = std::numbers::pi;
  EXPECT_EQ(atan2Pair(0.0, 3.0, -3.0), (std::array<double, 2>{0.0, pi}));
  EXPECT_EQ(atan2Pair(2.0, 0.0, -0.0), (std::array<double, 2>{pi / 2, pi / 2}));
  EXPECT_EQ(atan2Pair(5.0, 5.0, -5.0), (std::array<double, 2>{pi / 4, 3 * pi / 4}));
  EXPECT_EQ(atan2Pair(1e300, INFINITY, -INFINITY), (std::array<double, 2>{0.0, pi}));
}

// Each side of a boundary of the reduction takes another formula; the
// angle must still not rise as x grows.
TEST(Atan2Pair, FallsSteadilyAcrossTheReductionsBoundaries) {
  for (const double boundary : {-2.0, -0.5, 0.5, 2.0}) {
    double x = boundary;
    for (int k = 0; k < 64; ++k) x = std::nextafter(x, -INFINITY);
    double previous = atan2Pair(1.0, x, x)[0];
    for (int k = 0; k < 128; ++k) {
      x = std::nextafter(x, INFINITY);
      const double angle = atan2Pair(1.0, x, x)[0];
      EXPECT_LE(angle, previous) << "x = " << x;
      previous = angle;
    }
  }
}

}  // namespace
}  // namespace meshtrace
