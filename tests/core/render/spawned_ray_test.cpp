// A query told the primitive its ray starts on (spawn.h) leaves that
// primitive out when it is a triangle, with every acceleration method, and
// tests curved shapes as before.
#include <gtest/gtest.h>

#include <cmath>

#include "meshtrace/accel/intersector.h"
#include "meshtrace/geometry/mesh_generators.h"

namespace meshtrace {
namespace {

// A 16 x 16 grid (512 triangles, enough for a BVH) in the plane y = 0, and a
// unit sphere around (0, 5, 0).
Scene gridAndSphere() {
  Scene s;
  s.meshes.emplace_back("grid.off", makeGrid(Vec3(0.0), 2.0, 16), Shading::Flat, Material{});
  s.spheres.push_back({{0.0, 5.0, 0.0}, 1.0, Material{}});
  return s;
}

constexpr AccelMethod kMethods[] = {AccelMethod::None, AccelMethod::BoundingBox, AccelMethod::Bvh};

// A ray from below the grid through it: the grid triangle at t = 1 is the
// nearest hit, unless the ray is said to start on that very triangle.
TEST(SpawnedRays, LeaveOutTheTriangleTheyStartOn) {
  const Scene scene = gridAndSphere();
  const Ray up{{0.03, -1.0, 0.07}, {0.0, 1.0, 0.0}};
  for (AccelMethod method : kMethods) {
    SCOPED_TRACE(toString(method));
    const SceneIntersector is(scene, {.accel = method});
    Counters c;
    Hit grid;
    ASSERT_TRUE(is.closestHit(up, 0.0, grid, c));
    ASSERT_EQ(grid.ref.kind, ObjectKind::Mesh);
    EXPECT_DOUBLE_EQ(grid.t, 1.0);
    EXPECT_TRUE(is.occluded(up, 0.0, 2.0, c));

    // Said to start on the grid triangle: the sphere behind it is next.
    Hit beyond;
    ASSERT_TRUE(is.closestHit(up, 0.0, beyond, c, &grid.ref));
    EXPECT_EQ(beyond.ref.kind, ObjectKind::Sphere);
    EXPECT_NEAR(beyond.t, 6.0 - std::sqrt(1.0 - 0.03 * 0.03 - 0.07 * 0.07), 1e-12);
    EXPECT_FALSE(is.occluded(up, 0.0, 2.0, c, &grid.ref));

    // Another triangle of the same mesh leaves the hit alone.
    PrimitiveRef neighbour = grid.ref;
    neighbour.triangle ^= 1;
    Hit again;
    ASSERT_TRUE(is.closestHit(up, 0.0, again, c, &neighbour));
    EXPECT_EQ(again.ref.triangle, grid.ref.triangle);
    EXPECT_TRUE(is.occluded(up, 0.0, 2.0, c, &neighbour));
  }
}

// A ray leaving a sphere from inside still meets it: curved shapes are
// always tested.
TEST(SpawnedRays, StillMeetTheCurvedShapeTheyStartOn) {
  const Scene scene = gridAndSphere();
  const Ray inside{{0.0, 5.0, 0.0}, {1.0, 0.0, 0.0}};
  const PrimitiveRef sphere{ObjectKind::Sphere, 0, 0};
  for (AccelMethod method : kMethods) {
    SCOPED_TRACE(toString(method));
    const SceneIntersector is(scene, {.accel = method});
    Counters c;
    Hit hit;
    ASSERT_TRUE(is.closestHit(inside, 0.0, hit, c, &sphere));
    EXPECT_EQ(hit.ref.kind, ObjectKind::Sphere);
    EXPECT_DOUBLE_EQ(hit.t, 1.0);
    EXPECT_TRUE(is.occluded(inside, 0.0, 2.0, c, &sphere));
  }
}

}  // namespace
}  // namespace meshtrace
