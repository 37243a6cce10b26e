// SceneIntersector's shadow queries given a LastBlocker: the blocker of the
// previous ray toward the same light is tested first, and the answers must
// be those of the queries without it (brute force decides), for the BVH
// ray by ray and in packets and for brute force itself; a blocker that
// blocks nothing, or names some other primitive of the scene, must cost
// only its test. The rays are those a render casts: from the hits of a
// camera's rays in scan order, spawned toward two lights, inside a hall
// whose walls, beams and bars block most of them.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "meshtrace/accel/intersector.h"
#include "meshtrace/render/spawn.h"
#include "meshtrace/render/surface.h"
#include "support/meshes.h"

namespace meshtrace {
namespace {

// The hall with a ball, a post and a floor plane below it, so that a
// blocker may be a triangle or a shape.
Scene hallScene() {
  Scene scene = test::hallScene(96, 72);
  scene.spheres.push_back({Vec3(-4.0, 1.5, 2.0), 1.0, {}});
  scene.cylinders.push_back({Vec3(5.0, 0.0, -3.0), 0.4, Vec3(0.0, 1.0, 0.0), 5.0, {}});
  scene.planes.push_back({Vec3(0.0, -0.5, 0.0), Vec3(0.0, 1.0, 0.0), {}});
  return scene;
}

// A shadow query as the renderer makes one: from a surface point toward a
// light, leaving the primitive the point is on.
struct ShadowRay {
  Ray ray;
  double tMax;
  PrimitiveRef start;
  std::size_t light;
};

// Per light, the shadow rays from the camera's hits, in scan order.
std::vector<std::vector<ShadowRay>> shadowRays(const Scene& scene,
                                               const SceneIntersector& intersector) {
  std::vector<std::vector<ShadowRay>> out(scene.lights.size());
  Counters c;
  for (int y = 0; y < scene.camera.height(); ++y)
    for (int x = 0; x < scene.camera.width(); ++x) {
      const Ray primary = scene.camera.primaryRay(x, y);
      Hit hit;
      if (!intersector.closestHit(primary, kSpawnTMin, hit, c)) continue;
      const SurfacePoint sp = surfaceAt(scene, primary, hit, Precision::Double);
      for (std::size_t l = 0; l < scene.lights.size(); ++l) {
        const Vec3 toLight = scene.lights[l].position - sp.point;
        const Vec3 d = glm::normalize(toLight);
        if (!(glm::dot(sp.normal, d) > 0.0)) continue;
        const Ray shadow{spawnOrigin(sp, d), d};
        out[l].push_back(
            {shadow, glm::length(scene.lights[l].position - shadow.origin), sp.primitive, l});
      }
    }
  return out;
}

// Any primitive of the scene, as a stale or unrelated blocker.
PrimitiveRef randomPrimitive(const Scene& scene, std::mt19937_64& rng) {
  switch (rng() % 4) {
    case 0: return {ObjectKind::Sphere, 0, 0};
    case 1: return {ObjectKind::Cylinder, 0, 0};
    case 2: return {ObjectKind::Plane, 0, 0};
    default: {
      const auto n = static_cast<std::uint32_t>(scene.meshes[0].triangles().size());
      return {ObjectKind::Mesh, 0, static_cast<std::uint32_t>(rng() % n)};
    }
  }
}

TEST(LastBlocker, AnswersEveryShadowRayAsWithoutIt) {
  const Scene scene = hallScene();
  const SceneIntersector bvh(scene, {.accel = AccelMethod::Bvh});
  const SceneIntersector brute(scene, {.accel = AccelMethod::None});
  std::mt19937_64 rng(7);
  std::uint64_t rays = 0, blocked = 0, differences = 0, keeping = 0, named = 0, namesABlocker = 0;
  Counters withBvh, withBrute, plain;
  for (const std::vector<ShadowRay>& run : shadowRays(scene, bvh)) {
    LastBlocker bvhLast, bruteLast;
    for (std::size_t i = 0; i < run.size(); ++i) {
      const ShadowRay& s = run[i];
      // Runs of 64 rays, as a render's tiles are: each starts afresh.
      if (i % 64 == 0) bvhLast = bruteLast = {};
      // Now and then a blocker that has nothing to do with this ray.
      if (i % 31 == 3) {
        bvhLast.known = bruteLast.known = true;
        bvhLast.primitive = bruteLast.primitive = randomPrimitive(scene, rng);
      }
      const bool kept = !bvhLast.givenUp();
      keeping += kept;
      const bool expected = brute.occluded(s.ray, kSpawnTMin, s.tMax, plain, &s.start);
      const bool viaBvh = bvh.occluded(s.ray, kSpawnTMin, s.tMax, withBvh, &s.start, &bvhLast);
      const bool viaBrute =
          brute.occluded(s.ray, kSpawnTMin, s.tMax, withBrute, &s.start, &bruteLast);
      ++rays;
      blocked += expected;
      differences += (viaBvh != expected) + (viaBrute != expected);
      // Unless given up, a blocked ray leaves a blocker that blocks it and a
      // lit one leaves none.
      EXPECT_TRUE(!kept || bvhLast.known == expected);
      if (kept && expected && bvhLast.known) {
        ++named;
        LastBlocker again = bvhLast;
        again.misses = 0;
        Counters c;
        EXPECT_TRUE(bvh.occluded(s.ray, kSpawnTMin, s.tMax, c, &s.start, &again));
        namesABlocker += c.lastBlockerHits == 1;
      }
    }
  }
  std::printf(
      "[ figures  ] %llu shadow rays, %llu blocked; answered by the last blocker: "
      "%llu (BVH), %llu (brute force)\n",
      static_cast<unsigned long long>(rays), static_cast<unsigned long long>(blocked),
      static_cast<unsigned long long>(withBvh.lastBlockerHits),
      static_cast<unsigned long long>(withBrute.lastBlockerHits));
  EXPECT_EQ(differences, 0u);
  EXPECT_GT(blocked, rays / 4);          // walls and bars block many
  EXPECT_LT(blocked, rays - rays / 10);  // the windows let some through
  EXPECT_GT(keeping, rays / 2);          // walls stay blockers: the runs seldom give up
  EXPECT_EQ(namesABlocker, named);
  // The neighbour's blocker answers many blocked rays. Brute force and the
  // BVH meet the blockers in another order and may keep others.
  EXPECT_GT(withBvh.lastBlockerHits, blocked / 3);
  EXPECT_GT(withBrute.lastBlockerHits, blocked / 3);
  EXPECT_EQ(plain.lastBlockerHits, 0u);
}

TEST(LastBlocker, AnswersEveryShadowPacketAsFourRaysAlone) {
  const Scene scene = hallScene();
  const SceneIntersector bvh(scene, {.accel = AccelMethod::Bvh});
  std::mt19937_64 rng(11);
  std::uint64_t rays = 0, blocked = 0, differences = 0;
  Counters withLast, plain;
  for (const std::vector<ShadowRay>& run : shadowRays(scene, bvh)) {
    LastBlocker last;
    for (std::size_t first = 0; first + kPacketSize <= run.size(); first += kPacketSize) {
      Ray packet[kPacketSize];
      double tMax[kPacketSize];
      PrimitiveRef start[kPacketSize];
      for (int r = 0; r < kPacketSize; ++r) {
        packet[r] = run[first + r].ray;
        tMax[r] = run[first + r].tMax;
        start[r] = run[first + r].start;
      }
      const auto active =
          static_cast<std::uint32_t>(first / kPacketSize % 5 == 4 ? rng() % 15 + 1 : 0xfu);
      if (first % 256 == 0) last = {};  // a tile's run of packets
      if (first % 124 == 20) {
        last.known = true;
        last.primitive = randomPrimitive(scene, rng);
      }
      const bool kept = !last.givenUp();
      const std::uint32_t got =
          bvh.occludedPacket(packet, kSpawnTMin, tMax, start, active, withLast, &last);
      for (int r = 0; r < kPacketSize; ++r) {
        const bool expected =
            (active >> r & 1) && bvh.occluded(packet[r], kSpawnTMin, tMax[r], plain, &start[r]);
        rays += active >> r & 1;
        blocked += expected;
        differences += ((got >> r & 1) != 0) != expected;
      }
      // A packet nothing blocks forgets the blocker.
      EXPECT_TRUE(!kept || got != 0 || !last.known);
    }
  }
  std::printf(
      "[ figures  ] %llu shadow rays in packets, %llu blocked, %llu answered by the "
      "last blocker\n",
      static_cast<unsigned long long>(rays), static_cast<unsigned long long>(blocked),
      static_cast<unsigned long long>(withLast.lastBlockerHits));
  EXPECT_EQ(differences, 0u);
  EXPECT_GT(blocked, rays / 4);
  EXPECT_GT(withLast.lastBlockerHits, blocked / 4);
}

// Rays of a mesh shadowing itself are each blocked by other small
// triangles: after kMaxMisses blockers in a row that block nothing, the
// run of rays stops testing them and pays only for its traversals.
TEST(LastBlocker, IsGivenUpAfterMissesInARow) {
  const Scene scene = hallScene();
  const SceneIntersector bvh(scene, {.accel = AccelMethod::Bvh});
  // Up the hall and out through the far wall: the ceiling's beams, the end
  // wall or the columns block it, never the floor stripe named.
  const Ray ray{Vec3(0.5, 2.0, 10.0), glm::normalize(Vec3(0.0, 0.3, -1.0))};
  const PrimitiveRef floor{ObjectKind::Mesh, 0, 0};
  LastBlocker last;
  int tests = 0;
  for (int k = 0; k < LastBlocker::kMaxMisses + 2; ++k) {
    last.known = true;
    last.primitive = floor;
    Counters with, without;
    EXPECT_TRUE(bvh.occluded(ray, 0.0, 100.0, with, nullptr, &last));
    EXPECT_TRUE(bvh.occluded(ray, 0.0, 100.0, without));
    EXPECT_EQ(with.lastBlockerHits, 0u);
    tests += with.triangleTests > without.triangleTests;
  }
  EXPECT_EQ(tests, LastBlocker::kMaxMisses);
  EXPECT_TRUE(last.givenUp());
}

// An external intersector does not name what blocked a ray: the blocker
// given is neither used nor changed.
TEST(LastBlocker, IsLeftAsItIsByAnExternalIntersector) {
  struct EverythingBlocks final : ExternalIntersector {
    bool closestHit(const Ray&, double, Hit&, Counters&) const override { return false; }
    bool occluded(const Ray&, double, double, Counters&) const override { return true; }
  } external;
  const Scene scene = hallScene();
  const SceneIntersector intersector(scene, {}, external);
  LastBlocker last{true, {ObjectKind::Sphere, 0, 0}};
  Counters c;
  const Ray ray{Vec3(0.0, 1.0, 0.0), Vec3(0.0, 0.0, 1.0)};
  EXPECT_TRUE(intersector.occluded(ray, 0.0, 1.0, c, nullptr, &last));
  EXPECT_TRUE(last.known);
  EXPECT_EQ(last.primitive.kind, ObjectKind::Sphere);
  EXPECT_EQ(c.lastBlockerHits, 0u);
}

}  // namespace
}  // namespace meshtrace
