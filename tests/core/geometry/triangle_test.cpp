// Ray-triangle intersection by Cramer's rule: barycentrics, edges and
// vertices, the t limits and parallel rays; and for every kernel, hits on
// slivers within the BVH's padding of the triangle's box.
#include "meshtrace/geometry/triangle.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

namespace meshtrace {
namespace {

constexpr double kTol = 1e-12;
const Vec3 kA(0, 0, 0), kB(1, 0, 0), kC(0, 1, 0);

// A ray straight down -z onto the point (x, y) of the z = 0 plane from z = 5.
Ray downAt(double x, double y) { return {Vec3(x, y, 5), Vec3(0, 0, -1)}; }

bool hits(const Ray& ray, double tMin = 0.0, double tMax = kInfinity) {
  TriangleHit h;
  return intersectTriangle(kA, kB, kC, ray, tMin, tMax, h);
}

TEST(TriangleIntersection, ReportsDistanceAndBarycentrics) {
  TriangleHit h;
  ASSERT_TRUE(intersectTriangle(kA, kB, kC, downAt(0.2, 0.3), 0.0, kInfinity, h));
  EXPECT_NEAR(h.t, 5.0, kTol);
  EXPECT_NEAR(h.beta, 0.2, kTol);
  EXPECT_NEAR(h.gamma, 0.3, kTol);
}

TEST(TriangleIntersection, BarycentricsRebuildTheHitPointOfAGeneralTriangle) {
  const Vec3 a(1, 2, 3), b(-2, 0.5, 4), c(0.5, -1, -2);
  const Vec3 target = 0.5 * a + 0.2 * b + 0.3 * c;
  const Vec3 origin(7, 8, 9);
  const Ray ray{origin, glm::normalize(target - origin)};
  TriangleHit h;
  ASSERT_TRUE(intersectTriangle(a, b, c, ray, 0.0, kInfinity, h));
  EXPECT_NEAR(h.t, glm::length(target - origin), 1e-10);
  EXPECT_NEAR(h.beta, 0.2, 1e-12);
  EXPECT_NEAR(h.gamma, 0.3, 1e-12);
  const Vec3 rebuilt = (1 - h.beta - h.gamma) * a + h.beta * b + h.gamma * c;
  EXPECT_NEAR(glm::length(rebuilt - ray.at(h.t)), 0.0, 1e-10);
}

TEST(TriangleIntersection, HitsFromBehindToo) {
  TriangleHit h;
  ASSERT_TRUE(
      intersectTriangle(kA, kB, kC, Ray{Vec3(0.2, 0.3, -2), Vec3(0, 0, 1)}, 0.0, kInfinity, h));
  EXPECT_NEAR(h.t, 2.0, kTol);
}

TEST(TriangleIntersection, AcceptsPointsOnTheEdges) {
  EXPECT_TRUE(hits(downAt(0.5, 0.0))) << "edge AB, gamma = 0";
  EXPECT_TRUE(hits(downAt(0.0, 0.5))) << "edge AC, beta = 0";
  EXPECT_TRUE(hits(downAt(0.5, 0.5))) << "edge BC, alpha = 0";
}

TEST(TriangleIntersection, AcceptsTheVertices) {
  TriangleHit h;
  ASSERT_TRUE(intersectTriangle(kA, kB, kC, downAt(0, 0), 0.0, kInfinity, h));
  EXPECT_EQ(h.beta, 0.0);
  EXPECT_EQ(h.gamma, 0.0);
  ASSERT_TRUE(intersectTriangle(kA, kB, kC, downAt(1, 0), 0.0, kInfinity, h));
  EXPECT_NEAR(h.beta, 1.0, kTol);
  ASSERT_TRUE(intersectTriangle(kA, kB, kC, downAt(0, 1), 0.0, kInfinity, h));
  EXPECT_NEAR(h.gamma, 1.0, kTol);
}

TEST(TriangleIntersection, RejectsPointsJustOutside) {
  EXPECT_FALSE(hits(downAt(0.5, -1e-9)));
  EXPECT_FALSE(hits(downAt(-1e-9, 0.5)));
  EXPECT_FALSE(hits(downAt(0.5 + 1e-9, 0.5)));
  EXPECT_FALSE(hits(downAt(2, 2)));
}

TEST(TriangleIntersection, AcceptsOnlyTStrictlyBetweenTheLimits) {
  EXPECT_TRUE(hits(downAt(0.2, 0.2), 0.0, 5.0 + 1e-9));
  EXPECT_FALSE(hits(downAt(0.2, 0.2), 0.0, 5.0)) << "t == tMax is not nearer";
  EXPECT_FALSE(hits(downAt(0.2, 0.2), 5.0)) << "t == tMin is not beyond";
  EXPECT_FALSE(hits(Ray{Vec3(0.2, 0.2, 5), Vec3(0, 0, 1)})) << "behind the origin";
  EXPECT_FALSE(hits(Ray{Vec3(0.2, 0.2, 0), Vec3(0, 0, -1)})) << "t = 0 from the surface";
}

TEST(TriangleIntersection, ParallelRaysMiss) {
  EXPECT_FALSE(hits(Ray{Vec3(-1, 0.2, 0), Vec3(1, 0, 0)})) << "in the triangle's plane";
  EXPECT_FALSE(hits(Ray{Vec3(-1, 0.2, 1), Vec3(1, 0, 0)}));
}

TEST(TriangleIntersection, DegenerateTrianglesAreNeverHit) {
  TriangleHit h;
  EXPECT_FALSE(intersectTriangle(kA, kB, Vec3(2, 0, 0), Ray{Vec3(0.5, 0, 5), Vec3(0, 0, -1)}, 0.0,
                                 kInfinity, h));
  EXPECT_FALSE(
      intersectTriangle(kA, kA, kA, Ray{Vec3(0, 0, 5), Vec3(0, 0, -1)}, 0.0, kInfinity, h));
}

// Whether o + t d lies within the BVH's padding of the box of a, b, c: on
// each axis 2^-20 (float kernels: 2^-12) of t |d|, plus 2^-30 (2^-14) of the
// largest coordinate of the origin and the corners (slab_ray.h).
bool withinPaddingOfTheBox(const Vec3& a, const Vec3& b, const Vec3& c, const Ray& ray, double t,
                           Precision precision) {
  const bool single = precision == Precision::Single;
  const double relative = single ? 0x1p-12 : 0x1p-20, absoluteShare = single ? 0x1p-14 : 0x1p-30;
  const Vec3 lo = glm::min(glm::min(a, b), c), hi = glm::max(glm::max(a, b), c);
  const double absolute = absoluteShare * (maxAbsComponent(ray.origin) +
                                           std::max(maxAbsComponent(lo), maxAbsComponent(hi)));
  for (int axis = 0; axis < 3; ++axis) {
    const double p = ray.origin[axis] + t * ray.direction[axis];
    const double room = absolute + relative * std::abs(t * ray.direction[axis]);
    if (p < lo[axis] - room || p > hi[axis] + room) return false;
  }
  return true;
}

// A sliver 7e-8 wide seen from 50 away: in float, Moller-Trumbore's det has
// no correct digit, and it reported a hit at t = 61.34, 1.9 outside the
// triangle's box, which brute force found and the BVH could not. Then
// slivers of every width from 1e-2 to 1e-16 of their length and rays aimed
// at them: no kernel, in either precision, reports a hit that the BVH's
// boxes around the triangle would not hold.
TEST(TriangleIntersection, NoKernelReportsAHitOutsideTheTrianglesBox) {
  const Vec3 a(-1.4291007080209244, -0.4409911669230843, 2.010166228894372);
  const Vec3 b(4.640121035817512, -0.44099109460725655, 2.010166228894372);
  const Vec3 c(0.32311182579988595, -0.4409911669230843, 2.010166196840913);
  const Ray seen{Vec3(30.574507781304131, 41.097131329604032, -27.795915353336149),
                 Vec3(-0.55264634899432086, -0.67712824785568138, 0.48587997375806952)};
  TriangleHit h;
  EXPECT_FALSE(TriangleRay(seen, {TriangleTest::MollerTrumbore, Precision::Single})
                   .intersect(a, b, c, 0.0, kInfinity, h))
      << "t = " << h.t;

  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0), exponent(-16.0, -2.0);
  for (const TriangleTest test :
       {TriangleTest::Cramer, TriangleTest::MollerTrumbore, TriangleTest::Watertight})
    for (const Precision precision : {Precision::Double, Precision::Single}) {
      int hits = 0, outside = 0;
      for (int i = 0; i < 20000; ++i) {
        const Vec3 axis = glm::normalize(Vec3(u(rng), u(rng), u(rng)));
        const Vec3 across = glm::normalize(glm::cross(axis, Vec3(u(rng), u(rng), u(rng))));
        const Vec3 p0 = Vec3(u(rng), u(rng), u(rng)) - axis;
        const Vec3 p1 = p0 + 2.0 * axis;
        const Vec3 p2 = p0 + (1.0 + u(rng)) * axis + std::pow(10.0, exponent(rng)) * across;
        const Vec3 origin = 50.0 * Vec3(u(rng), u(rng), u(rng));
        const Vec3 target = p0 + (1.0 + u(rng)) * axis;
        const Ray ray{origin, glm::normalize(target - origin)};
        if (!TriangleRay(ray, {test, precision}).intersect(p0, p1, p2, 0.0, kInfinity, h)) continue;
        ++hits;
        outside += !withinPaddingOfTheBox(p0, p1, p2, ray, h.t, precision);
      }
      std::printf("[ figures  ] %s/%s: %d of 20000 rays hit a sliver, %d outside its box\n",
                  toString(test), toString(precision), hits, outside);
      EXPECT_EQ(outside, 0) << toString(test) << "/" << toString(precision);
    }
}

}  // namespace
}  // namespace meshtrace
