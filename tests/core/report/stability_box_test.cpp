// Stability case 5, bounding boxes stay exact: axis-parallel rays, origins
// on a box plane and flat (zero-thickness) boxes, first for intersectSlabs
// against the exact answer, then at scene level, where every acceleration
// method must return what brute force returns.
#include <gtest/gtest.h>

#include "meshtrace/accel/intersector.h"
#include "meshtrace/geometry/aabb.h"

namespace meshtrace {
namespace {

constexpr double kU = std::numeric_limits<double>::epsilon() / 2;

// The exact slab answer for a ray with a single nonzero direction component
// (`axis`, sign `s`): the box is met iff the origin lies within the other two
// slabs and the box is not entirely behind.
bool exactAxisHit(const Aabb& box, const Vec3& o, int axis, double s, double& tEnter,
                  double& tExit) {
  for (int k = 0; k < 3; ++k)
    if (k != axis && (o[k] < box.min[k] || o[k] > box.max[k])) return false;
  const double near = s > 0 ? box.min[axis] - o[axis] : o[axis] - box.max[axis];
  const double far = s > 0 ? box.max[axis] - o[axis] : o[axis] - box.min[axis];
  if (far < 0) return false;
  tEnter = std::max(0.0, near);
  tExit = far;
  return true;
}

TEST(StabilityBox, AxisParallelRaysAndOriginsOnBoxPlanes) {
  // A solid box and two flat ones (zero thickness in y, in x and y).
  const Aabb boxes[] = {{Vec3(0.0), Vec3(1.0)},
                        {Vec3(0.0, 0.5, 0.0), Vec3(1.0, 0.5, 1.0)},
                        {Vec3(0.25, 0.5, 0.0), Vec3(0.25, 0.5, 1.0)}};
  // Coordinates outside, on each box plane and inside.
  const double coords[] = {-0.5, 0.0, 0.25, 0.5, 1.0, 1.5};
  std::size_t cases = 0, wrong = 0;
  for (const Aabb& box : boxes)
    for (double x : coords)
      for (double y : coords)
        for (double z : coords)
          for (int axis = 0; axis < 3; ++axis)
            for (double s : {-1.0, 1.0}) {
              Vec3 d(0.0);
              d[axis] = s;
              const Vec3 o(x, y, z);
              double e0 = 0, e1 = 0, t0 = 0, t1 = 0;
              const bool expected = exactAxisHit(box, o, axis, s, e0, e1);
              const bool got = intersectSlabs(box, RayInverse(Ray{o, d}), 0.0, kInfinity, t0, t1);
              ++cases;
              if (got != expected) {
                ++wrong;
                ADD_FAILURE() << "box " << box.min.x << "," << box.min.y << " o " << x << "," << y
                              << "," << z << " axis " << axis << " sign " << s;
                continue;
              }
              if (!got) continue;
              // Entry exact; exit exact up to the 1 + 2 gamma(3) padding.
              EXPECT_EQ(t0, e0);
              EXPECT_GE(t1, e1);
              EXPECT_LE(t1, e1 * (1 + 8 * kU) + 0.0);
            }
  EXPECT_EQ(wrong, 0u) << "of " << cases;
}

TEST(StabilityBox, ObliqueRaysFromABoxPlane) {
  const Aabb box{Vec3(0.0), Vec3(1.0)};
  const Aabb flat{Vec3(0.0, 0.5, 0.0), Vec3(1.0, 0.5, 1.0)};
  double t0, t1;
  // From a face, outward and inward: the closed box contains the origin.
  for (const Vec3& d : {Vec3(-0.6, 0.8, 0.0), Vec3(0.6, 0.8, 0.0)}) {
    EXPECT_TRUE(
        intersectSlabs(box, RayInverse(Ray{Vec3(0.0, 0.5, 0.5), d}), 0.0, kInfinity, t0, t1));
    EXPECT_EQ(t0, 0.0);
  }
  // Through a flat box obliquely, from either side: met at one point.
  for (double s : {-1.0, 1.0}) {
    const Vec3 o(0.5, 0.5 - s * 0.25, 0.5);
    ASSERT_TRUE(intersectSlabs(flat, RayInverse(Ray{o, glm::normalize(Vec3(0.3, s, 0.2))}), 0.0,
                               kInfinity, t0, t1));
    EXPECT_LE(t0, t1);
  }
  // In the flat box's plane, moving within it: met; just off it: missed.
  EXPECT_TRUE(intersectSlabs(flat, RayInverse(Ray{Vec3(-1, 0.5, 0.5), Vec3(1, 0, 0)}), 0.0,
                             kInfinity, t0, t1));
  EXPECT_FALSE(
      intersectSlabs(flat, RayInverse(Ray{Vec3(-1, std::nextafter(0.5, 1.0), 0.5), Vec3(1, 0, 0)}),
                     0.0, kInfinity, t0, t1));
}

// A flat grid mesh in the plane y = 0 (a zero-thickness bounding box), hit by
// axis-parallel rays exactly at its vertices and edges, by rays from the
// plane itself and by rays moving within it: every acceleration method
// returns the same hit as brute force, primitive for primitive.
TEST(StabilityBox, SceneLevelAgreesWithBruteForce) {
  Scene scene;
  scene.file = "flat.sce";
  MeshData grid;
  const int n = 8;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) grid.vertices.emplace_back(double(i) / n, 0.0, double(j) / n);
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t j = 0; j < n; ++j) {
      const std::uint32_t v = i * (n + 1) + j;
      grid.triangles.push_back({v, v + 1, v + n + 2});
      grid.triangles.push_back({v, v + n + 2, v + n + 1});
    }
  scene.meshes.emplace_back("grid.off", std::move(grid), Shading::Flat, Material{});

  std::vector<Ray> rays;
  for (int i = -1; i <= 2 * n + 1; ++i)
    for (int j = -1; j <= 2 * n + 1; ++j) {
      const double x = double(i) / (2 * n), z = double(j) / (2 * n);
      rays.push_back({Vec3(x, 1.0, z), Vec3(0, -1, 0)});                     // down onto the grid
      rays.push_back({Vec3(x, -1.0, z), Vec3(0, 1, 0)});                     // up from below
      rays.push_back({Vec3(x, 0.0, z), glm::normalize(Vec3(0.3, 1, 0.1))});  // from the plane
      rays.push_back({Vec3(x, 0.0, z), Vec3(1, 0, 0)});                      // within the plane
    }
  Counters counters;
  const SceneIntersector brute(scene, {.accel = AccelMethod::None});
  std::size_t hits = 0;
  for (AccelMethod accel : {AccelMethod::BoundingBox, AccelMethod::Bvh}) {
    const SceneIntersector fast(scene, {.accel = accel});
    for (const Ray& ray : rays) {
      Hit a, b;
      const bool ha = brute.closestHit(ray, 0.0, a, counters);
      const bool hb = fast.closestHit(ray, 0.0, b, counters);
      hits += ha;
      ASSERT_EQ(ha, hb) << toString(accel);
      if (ha) {
        EXPECT_EQ(a.t, b.t) << toString(accel);
        EXPECT_EQ(a.ref.triangle, b.ref.triangle) << toString(accel);
      }
      EXPECT_EQ(brute.occluded(ray, 0.0, kInfinity, counters),
                fast.occluded(ray, 0.0, kInfinity, counters))
          << toString(accel);
    }
  }
  // Every ray aimed down or up at the grid's closed square hits it.
  EXPECT_GE(hits, 2u * 2 * (2 * n + 1) * (2 * n + 1));
}

}  // namespace
}  // namespace meshtrace
