// Ray intersections with spheres, planes and open cylinders, and their normals.
#include "meshtrace/geometry/shapes.h"

#include <gtest/gtest.h>

namespace meshtrace {
namespace {

constexpr double kTol = 1e-12;

Ray rayFrom(const Vec3& origin, const Vec3& direction) {
  return {origin, glm::normalize(direction)};
}

// The distance at which `shape` is hit, or infinity for a miss.
template <typename Shape>
double hitDistance(const Shape& shape, const Ray& ray, double tMin = 0.0,
                   double tLimit = kInfinity) {
  double t = tLimit;
  const bool hit = intersect(shape, ray, tMin, t);
  EXPECT_EQ(hit, t < tLimit) << "the result and the updated t must agree";
  return hit ? t : kInfinity;
}

void expectNear(const Vec3& a, const Vec3& b) {
  EXPECT_NEAR(glm::length(a - b), 0.0, kTol) << "(" << a.x << ", " << a.y << ", " << a.z << ")";
}

const Sphere kSphere{Vec3(1, 2, 3), 2.0, {}};

TEST(SphereIntersection, HitsTheNearSideFromOutside) {
  const Ray ray = rayFrom(Vec3(1, 2, 13), Vec3(0, 0, -1));
  EXPECT_NEAR(hitDistance(kSphere, ray), 8.0, kTol);
  expectNear(normalAt(kSphere, ray.at(8.0)), Vec3(0, 0, 1));
}

TEST(SphereIntersection, HitsTheFarSideFromInside) {
  const Ray ray = rayFrom(Vec3(1, 2, 3), Vec3(1, 0, 0));
  EXPECT_NEAR(hitDistance(kSphere, ray), 2.0, kTol);
  expectNear(normalAt(kSphere, ray.at(2.0)), Vec3(1, 0, 0));
}

TEST(SphereIntersection, MissesBesideAndBehind) {
  EXPECT_EQ(hitDistance(kSphere, rayFrom(Vec3(1, 4.01, 13), Vec3(0, 0, -1))), kInfinity);
  EXPECT_EQ(hitDistance(kSphere, rayFrom(Vec3(1, 2, 13), Vec3(0, 0, 1))), kInfinity);
}

TEST(SphereIntersection, RespectsTMinAndTheCurrentNearestHit) {
  const Ray ray = rayFrom(Vec3(1, 2, 13), Vec3(0, 0, -1));  // roots at 8 and 12
  EXPECT_NEAR(hitDistance(kSphere, ray, 9.0), 12.0, kTol) << "tMin skips the near root";
  EXPECT_EQ(hitDistance(kSphere, ray, 0.0, 7.5), kInfinity) << "something nearer was found";
  EXPECT_EQ(hitDistance(kSphere, ray, 12.5), kInfinity);
}

const Plane kFloor{Vec3(0, -1, 0), Vec3(0, 1, 0), {}};

TEST(PlaneIntersection, HitsFromEitherSide) {
  EXPECT_NEAR(hitDistance(kFloor, rayFrom(Vec3(3, 4, -2), Vec3(0, -1, 0))), 5.0, kTol);
  EXPECT_NEAR(hitDistance(kFloor, rayFrom(Vec3(3, -4, -2), Vec3(0, 1, 0))), 3.0, kTol);
  EXPECT_NEAR(hitDistance(kFloor, rayFrom(Vec3(0, 1, 0), Vec3(1, -1, 0))), 2 * std::sqrt(2.0),
              kTol);
  expectNear(normalAt(kFloor), Vec3(0, 1, 0));
}

TEST(PlaneIntersection, ParallelRaysMissEvenInThePlane) {
  EXPECT_EQ(hitDistance(kFloor, rayFrom(Vec3(0, 1, 0), Vec3(1, 0, 0))), kInfinity);
  EXPECT_EQ(hitDistance(kFloor, rayFrom(Vec3(0, -1, 0), Vec3(0, 0, 1))), kInfinity);
}

TEST(PlaneIntersection, MissesWhenPointingAwayOrBeyondTheLimit) {
  EXPECT_EQ(hitDistance(kFloor, rayFrom(Vec3(0, 1, 0), Vec3(0, 1, 0))), kInfinity);
  EXPECT_EQ(hitDistance(kFloor, rayFrom(Vec3(0, 1, 0), Vec3(0, -1, 0)), 0.0, 2.0), kInfinity);
}

// Radius 1 around the y axis, from y = -1 to y = 1.
const Cylinder kTube{Vec3(0.0), 1.0, Vec3(0, 1, 0), 2.0, {}};

TEST(CylinderIntersection, HitsTheOutsideWithAnOutwardNormal) {
  const Ray ray = rayFrom(Vec3(5, 0.5, 0), Vec3(-1, 0, 0));
  EXPECT_NEAR(hitDistance(kTube, ray), 4.0, kTol);
  expectNear(normalAt(kTube, ray.at(4.0), ray.direction), Vec3(1, 0, 0));
}

TEST(CylinderIntersection, OnlyWithinHalfTheHeightAlongTheAxis) {
  EXPECT_NEAR(hitDistance(kTube, rayFrom(Vec3(5, 0.999, 0), Vec3(-1, 0, 0))), 4.0, kTol);
  EXPECT_NEAR(hitDistance(kTube, rayFrom(Vec3(5, -1.0, 0), Vec3(-1, 0, 0))), 4.0, kTol)
      << "the rim itself counts";
  EXPECT_EQ(hitDistance(kTube, rayFrom(Vec3(5, 1.001, 0), Vec3(-1, 0, 0))), kInfinity);
  EXPECT_EQ(hitDistance(kTube, rayFrom(Vec3(5, -1.5, 0), Vec3(-1, 0, 0))), kInfinity);
}

TEST(CylinderIntersection, FromInsideHitsTheWallWithANormalFacingTheRay) {
  const Ray ray = rayFrom(Vec3(0.0), Vec3(0, 0, 1));
  EXPECT_NEAR(hitDistance(kTube, ray), 1.0, kTol);
  expectNear(normalAt(kTube, ray.at(1.0), ray.direction), Vec3(0, 0, -1));
}

// The tube is open: a ray entering above the rim passes through the opening
// and meets the far wall from inside.
TEST(CylinderIntersection, ARayThroughTheOpenEndHitsTheInnerWall) {
  const Ray ray = rayFrom(Vec3(-3, 3.5, 0), Vec3(1, -1, 0));
  const double t = hitDistance(kTube, ray);
  ASSERT_NEAR(t, 4 * std::sqrt(2.0), kTol);  // x = 1, y = -0.5
  expectNear(normalAt(kTube, ray.at(t), ray.direction), Vec3(-1, 0, 0));
}

TEST(CylinderIntersection, RaysAlongTheAxisMiss) {
  EXPECT_EQ(hitDistance(kTube, rayFrom(Vec3(0, 5, 0), Vec3(0, -1, 0))), kInfinity);
  EXPECT_EQ(hitDistance(kTube, rayFrom(Vec3(1, 5, 0), Vec3(0, -1, 0))), kInfinity) << "on the wall";
}

TEST(CylinderIntersection, WorksForATiltedAxisOffTheOrigin) {
  const Cylinder tilted{Vec3(1, 1, 1), 0.5, glm::normalize(Vec3(1, 0, 1)), 4.0, {}};
  // The ray crosses the axis at its centre, perpendicular to it.
  const Ray ray = rayFrom(Vec3(1, 6, 1), Vec3(0, -1, 0));
  const double t = hitDistance(tilted, ray);
  EXPECT_NEAR(t, 4.5, kTol);
  expectNear(normalAt(tilted, ray.at(t), ray.direction), Vec3(0, 1, 0));
}

}  // namespace
}  // namespace meshtrace
