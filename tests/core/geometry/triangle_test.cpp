// Ray-triangle intersection by Cramer's rule: barycentrics, edges and
// vertices, the t limits and parallel rays.
#include "meshtrace/geometry/triangle.h"

#include <gtest/gtest.h>

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

}  // namespace
}  // namespace meshtrace
