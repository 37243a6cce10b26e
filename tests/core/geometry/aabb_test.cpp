// The slab test: right for axis-parallel rays and for origins on a box
// plane (no 0 * inf NaN), for flat boxes, from inside, and for misses.
#include "meshtrace/geometry/aabb.h"

#include <gtest/gtest.h>

namespace meshtrace {
namespace {

// Relative padding the slab test adds to the exit distance (see aabb.h).
constexpr double kExitPadding = 1e-14;

const Aabb kUnitBox{Vec3(0.0), Vec3(1.0)};

struct SlabResult {
  bool hit = false;
  double tEnter = -1.0, tExit = -1.0;
};

SlabResult slabs(const Aabb& box, const Vec3& origin, const Vec3& direction, double tMin = 0.0,
                 double tMax = kInfinity) {
  SlabResult r;
  r.hit = intersectSlabs(box, RayInverse(Ray{origin, glm::normalize(direction)}), tMin, tMax,
                         r.tEnter, r.tExit);
  return r;
}

void expectHit(const SlabResult& r, double tEnter, double tExit) {
  ASSERT_TRUE(r.hit);
  EXPECT_FALSE(std::isnan(r.tEnter) || std::isnan(r.tExit));
  EXPECT_NEAR(r.tEnter, tEnter, 1e-12);
  EXPECT_GE(r.tExit, tExit) << "the exit may be padded outward, never inward";
  EXPECT_NEAR(r.tExit, tExit, kExitPadding * std::max(1.0, tExit));
}

TEST(Slabs, AxisParallelRayThroughTheBox) {
  expectHit(slabs(kUnitBox, Vec3(-5, 0.5, 0.5), Vec3(1, 0, 0)), 5.0, 6.0);
  expectHit(slabs(kUnitBox, Vec3(0.5, 7, 0.5), Vec3(0, -1, 0)), 6.0, 7.0);
  expectHit(slabs(kUnitBox, Vec3(0.25, 0.75, -2), Vec3(0, 0, 1)), 2.0, 3.0);
}

TEST(Slabs, AxisParallelRayBesideTheBoxMisses) {
  EXPECT_FALSE(slabs(kUnitBox, Vec3(-5, 1.5, 0.5), Vec3(1, 0, 0)).hit);
  EXPECT_FALSE(slabs(kUnitBox, Vec3(-5, 0.5, -0.001), Vec3(1, 0, 0)).hit);
}

// Origin on a box plane with a zero direction component along that axis:
// (plane - origin) * (1 / 0) would be 0 * inf = NaN in a naive test.
TEST(Slabs, OriginOnABoxPlaneWithAZeroDirectionComponentHits) {
  expectHit(slabs(kUnitBox, Vec3(-5, 1.0, 0.5), Vec3(1, 0, 0)), 5.0, 6.0);
  expectHit(slabs(kUnitBox, Vec3(-5, 0.0, 0.5), Vec3(1, 0, 0)), 5.0, 6.0);
  expectHit(slabs(kUnitBox, Vec3(-5, 0.0, 1.0), Vec3(1, 0, 0)), 5.0, 6.0);  // along an edge
}

TEST(Slabs, OriginOnAFacePointingInEntersAtZero) {
  expectHit(slabs(kUnitBox, Vec3(0, 0.5, 0.5), Vec3(1, 0, 0)), 0.0, 1.0);
  expectHit(slabs(kUnitBox, Vec3(1, 1, 1), Vec3(-1, -1, -1)), 0.0, std::sqrt(3.0));
}

TEST(Slabs, OriginOnAFacePointingOutTouchesOnlyAtZero) {
  const SlabResult r = slabs(kUnitBox, Vec3(0, 0.5, 0.5), Vec3(-1, 0, 0));
  ASSERT_TRUE(r.hit) << "the closed box contains its face";
  EXPECT_EQ(r.tEnter, 0.0);
  EXPECT_EQ(r.tExit, 0.0);
  EXPECT_FALSE(slabs(kUnitBox, Vec3(-1e-9, 0.5, 0.5), Vec3(-1, 0, 0)).hit);
}

TEST(Slabs, RayFromInsideEntersAtTMin) {
  expectHit(slabs(kUnitBox, Vec3(0.5), Vec3(0, 0, -1)), 0.0, 0.5);
  expectHit(slabs(kUnitBox, Vec3(0.25, 0.5, 0.5), Vec3(1, 0, 0), 0.1), 0.1, 0.75);
}

TEST(Slabs, FlatZeroThicknessBoxIsHitAcrossAndAlong) {
  const Aabb flat{Vec3(0, 0, 2), Vec3(1, 1, 2)};
  expectHit(slabs(flat, Vec3(0.5, 0.5, 5), Vec3(0, 0, -1)), 3.0, 3.0);
  expectHit(slabs(flat, Vec3(0.3, 0.6, -1), Vec3(0, 0, 1)), 3.0, 3.0);
  expectHit(slabs(flat, Vec3(-2, 0.5, 2), Vec3(1, 0, 0)), 2.0, 3.0);  // in its plane
  EXPECT_FALSE(slabs(flat, Vec3(-2, 0.5, 2.001), Vec3(1, 0, 0)).hit);
}

TEST(Slabs, DiagonalRayThroughACorner) {
  const SlabResult r = slabs(kUnitBox, Vec3(-1, -1, -1), Vec3(1, 1, 1));
  expectHit(r, std::sqrt(3.0), 2 * std::sqrt(3.0));
}

TEST(Slabs, MissesBesideBehindAndBeyondTheLimits) {
  EXPECT_FALSE(slabs(kUnitBox, Vec3(-5, 0.5, 0.5), Vec3(-1, 0, 0)).hit) << "box behind";
  EXPECT_FALSE(slabs(kUnitBox, Vec3(-1, 3.5, 0.5), Vec3(1, -1, 0)).hit) << "passes beside";
  EXPECT_FALSE(slabs(kUnitBox, Vec3(-5, 0.5, 0.5), Vec3(1, 0, 0), 0.0, 4.9).hit) << "beyond tMax";
  EXPECT_FALSE(slabs(kUnitBox, Vec3(-5, 0.5, 0.5), Vec3(1, 0, 0), 6.1).hit) << "before tMin";
}

TEST(Slabs, ClipsTheIntervalToTheLimits) {
  expectHit(slabs(kUnitBox, Vec3(-5, 0.5, 0.5), Vec3(1, 0, 0), 5.5, 5.75), 5.5, 5.75);
}

TEST(Slabs, NegativeDirectionsSwapNearAndFar) {
  expectHit(slabs(kUnitBox, Vec3(3, 0.5, 0.5), Vec3(-1, 0, 0)), 2.0, 3.0);
  expectHit(slabs(kUnitBox, Vec3(0.5, 0.5, 10), Vec3(0, 0, -1)), 9.0, 10.0);
}

TEST(Slabs, NegativeZeroDirectionComponentIsTreatedAsParallel) {
  expectHit(slabs(kUnitBox, Vec3(-5, 1.0, 0.5), Vec3(1, -0.0, 0)), 5.0, 6.0);
  EXPECT_FALSE(slabs(kUnitBox, Vec3(-5, 1.5, 0.5), Vec3(1, -0.0, 0)).hit);
}

// The default box holds no points; no ray may meet it (min = +inf and
// max = -inf must not turn into the interval (-inf, inf)).
TEST(Slabs, EmptyBoxIsNeverHit) {
  const Aabb empty;
  ASSERT_TRUE(empty.empty());
  EXPECT_FALSE(slabs(empty, Vec3(0.0), Vec3(1, 2, 3)).hit);
  EXPECT_FALSE(slabs(empty, Vec3(0.0), Vec3(1, 0, 0)).hit);
}

}  // namespace
}  // namespace meshtrace
