// nextUp and nextDown step the bits of a float or double; they must give what
// std::nextafter toward +-infinity gives, on every kind of value.
#include "meshtrace/util/math.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <type_traits>
#include <vector>

namespace meshtrace {
namespace {

template <typename Real>
std::vector<Real> edgeValues() {
  using L = std::numeric_limits<Real>;
  return {Real(0),       -Real(0),       L::denorm_min(), -L::denorm_min(), L::min(),
          -L::min(),     Real(1),        Real(-1),        L::max(),         -L::max(),
          L::infinity(), -L::infinity(), L::epsilon(),    Real(1e-30),      Real(-3.5)};
}

// Compared as bit patterns, so that -0 and +0 count as different.
template <typename Real>
auto bitsOf(Real x) {
  return std::bit_cast<std::conditional_t<sizeof(Real) == 4, std::uint32_t, std::uint64_t>>(x);
}

template <typename Real>
void expectSameAsNextafter(Real x) {
  const Real inf = std::numeric_limits<Real>::infinity();
  EXPECT_EQ(bitsOf(nextUp(x)), bitsOf(std::nextafter(x, inf))) << x;
  EXPECT_EQ(bitsOf(nextDown(x)), bitsOf(std::nextafter(x, -inf))) << x;
}

template <typename Real>
void checkAll() {
  for (Real x : edgeValues<Real>()) expectSameAsNextafter(x);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> exponent(-40.0, 40.0), sign(-1.0, 1.0);
  for (int i = 0; i < 100000; ++i)
    expectSameAsNextafter(static_cast<Real>(std::copysign(std::exp2(exponent(rng)), sign(rng))));
}

TEST(NextUpDown, MatchNextafterOnFloats) { checkAll<float>(); }
TEST(NextUpDown, MatchNextafterOnDoubles) { checkAll<double>(); }

TEST(NextUpDown, LeaveNaNANaN) {
  EXPECT_TRUE(std::isnan(nextUp(std::numeric_limits<double>::quiet_NaN())));
  EXPECT_TRUE(std::isnan(nextDown(std::numeric_limits<float>::quiet_NaN())));
}

}  // namespace
}  // namespace meshtrace
