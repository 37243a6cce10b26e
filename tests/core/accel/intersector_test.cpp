// SceneIntersector's queries with the BVH against brute force (--accel
// none): over a million random rays on generated meshes and object scenes
// (origins inside, outside and exactly on the bounding box; axis-parallel
// directions included), the BVH must report the same primitive, t and
// barycentrics, and its any-hit query must agree with the closest hit. Rays
// spawned off the hits, told the triangle they leave, must agree too; so must
// packets of four rays, the BVH with children fetched ahead, and meshes full
// of exact copies of their triangles, of which the BVH holds two. So must
// the BVH and --accel aabb on slivers, with every kernel, and with
// single-precision kernels far from the origin. Also the accel method's
// default, names and parsing.
#include "meshtrace/accel/intersector.h"

#include <gtest/gtest.h>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "accel/scene_bvh.h"
#include "meshtrace/geometry/mesh_generators.h"
#include "meshtrace/render/spawn.h"
#include "meshtrace/report/stability.h"
#include "support/meshes.h"
#include "support/sanitizers.h"

namespace meshtrace {
namespace {

using test::makeMesh;

// Rotates every vertex so that no face stays axis-aligned.
MeshData rotated(MeshData m, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  for (Vec3& v : m.vertices) {
    v = {c * v.x - s * v.z, v.y, s * v.x + c * v.z};
    v = {v.x, c * v.y - s * v.z, s * v.y + c * v.z};
  }
  return m;
}

// Random triangles, a few of them repeated exactly (equal-t ties between
// different indices) and a few sharing a vertex with the previous one.
MeshData triangleSoup(int n, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), small(-0.2, 0.2);
  MeshData m;
  for (int i = 0; i < n; ++i) {
    const auto next = static_cast<std::uint32_t>(m.vertices.size());
    if (i % 10 == 9) {  // a duplicate of the previous triangle
      m.triangles.push_back(m.triangles.back());
      continue;
    }
    const Vec3 c(u(rng), u(rng), u(rng));
    for (int k = 0; k < 3; ++k) m.vertices.push_back(c + Vec3(small(rng), small(rng), small(rng)));
    m.triangles.push_back({next, next + 1, next + 2});
  }
  return m;
}

Scene meshScene(std::vector<Mesh> meshes) {
  Scene scene;
  scene.meshes = std::move(meshes);
  return scene;
}

// Spheres (two of them identical: a tie), cylinders, planes and meshes,
// one of them (2 triangles) too small for a BVH.
Scene objectScene(std::mt19937_64& rng) {
  Scene scene;
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int i = 0; i < 150; ++i)
    scene.spheres.push_back({Vec3(u(rng), u(rng), u(rng)), 0.02 + 0.1 * std::abs(u(rng)), {}});
  scene.spheres.push_back(scene.spheres[7]);
  for (int i = 0; i < 20; ++i) {
    const Vec3 axis = glm::normalize(Vec3(u(rng), u(rng), u(rng)));
    scene.cylinders.push_back({Vec3(u(rng), u(rng), u(rng)), 0.05, axis, 0.3, {}});
  }
  scene.planes.push_back({Vec3(0.0, -1.0, 0.0), Vec3(0.0, 1.0, 0.0), {}});
  scene.planes.push_back({Vec3(0.0, 0.0, -1.2), glm::normalize(Vec3(0.1, 0.2, 1.0)), {}});
  scene.meshes.push_back(makeMesh("ball", makeIcosphere(Vec3(0.3, 0.2, 0.1), 0.4, 2)));
  scene.meshes.push_back(makeMesh("cube", makeGriddedBox(Vec3(-0.5), Vec3(-0.2), 1)));
  scene.meshes.push_back(makeMesh("floor", makeGrid(Vec3(0.0, -0.5, 0.0), 1.5, 6)));
  scene.meshes.push_back(makeMesh("square", makeGrid(Vec3(0.5, 0.6, -0.3), 0.4, 1)));
  return scene;
}

Aabb sceneBox(const Scene& scene) {
  Aabb box;
  for (const Mesh& m : scene.meshes) box.extend(m.bounds());
  for (const Sphere& s : scene.spheres) {
    box.extend(s.center - Vec3(s.radius));
    box.extend(s.center + Vec3(s.radius));
  }
  return box;
}

// A target point on the scene's geometry, so that most rays hit something.
Vec3 randomTarget(const Scene& scene, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  if (!scene.spheres.empty() && u(rng) < 0.5) {
    const Sphere& s = scene.spheres[rng() % scene.spheres.size()];
    const Vec3 d = glm::normalize(Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5));
    return s.center + s.radius * d;
  }
  const Mesh& m = scene.meshes[rng() % scene.meshes.size()];
  const TriangleIndices& t = m.triangles()[rng() % m.triangles().size()];
  double b = u(rng), g = u(rng);
  if (b + g > 1.0) b = 1.0 - b, g = 1.0 - g;
  // Exactly on a vertex or an edge now and then.
  if (u(rng) < 0.05) b = 0.0;
  if (u(rng) < 0.05) g = 0.0;
  const auto& v = m.vertices();
  return (1.0 - b - g) * v[t[0]] + b * v[t[1]] + g * v[t[2]];
}

Ray randomRay(const Scene& scene, const Aabb& box, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const Vec3 lo = box.min, hi = box.max, e = box.extent();
  Vec3 o;
  const double kind = u(rng);
  if (kind < 0.35) {  // inside the box
    o = lo + Vec3(u(rng), u(rng), u(rng)) * e;
  } else if (kind < 0.7) {  // outside it, up to one box size away
    o = lo - e + 3.0 * Vec3(u(rng), u(rng), u(rng)) * e;
  } else {  // exactly on one of its faces
    o = lo + Vec3(u(rng), u(rng), u(rng)) * e;
    const int axis = static_cast<int>(rng() % 3);
    o[axis] = rng() % 2 ? lo[axis] : hi[axis];
  }
  Vec3 d;
  const double dir = u(rng);
  if (dir < 0.25) {  // axis-parallel
    d = Vec3(0.0);
    d[rng() % 3] = rng() % 2 ? 1.0 : -1.0;
  } else if (dir < 0.4) {  // along a box face (one component zero)
    d = glm::normalize(Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5));
    d[rng() % 3] = 0.0;
    d = glm::normalize(d);
  } else if (dir < 0.55) {  // uniformly random
    d = glm::normalize(Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5));
  } else {  // toward the geometry
    d = randomTarget(scene, rng) - o;
    if (d == Vec3(0.0)) d = Vec3(0.0, 0.0, 1.0);
    d = glm::normalize(d);
  }
  return {o, d};
}

std::string describe(const Ray& ray, const Hit& h) {
  std::ostringstream s;
  s.precision(17);
  s << "ray o=(" << ray.origin.x << ", " << ray.origin.y << ", " << ray.origin.z << ") d=("
    << ray.direction.x << ", " << ray.direction.y << ", " << ray.direction.z << "): ";
  if (!h.found()) return s.str() + "miss";
  s << toString(h.ref.kind) << " " << h.ref.object << " triangle " << h.ref.triangle
    << " t=" << h.t;
  return s.str();
}

struct Disagreements {
  std::uint64_t rays = 0, hits = 0, closest = 0, anyHit = 0, spawned = 0;
  std::string example;
  void add(const Disagreements& o) {
    rays += o.rays;
    hits += o.hits;
    closest += o.closest;
    anyHit += o.anyHit;
    spawned += o.spawned;
    if (example.empty()) example = o.example;
  }
};

bool sameHit(bool foundA, const Hit& a, bool foundB, const Hit& b) {
  return foundA == foundB &&
         (!foundA || (a.t == b.t && a.ref.kind == b.ref.kind && a.ref.object == b.ref.object &&
                      a.ref.triangle == b.ref.triangle && a.beta == b.beta && a.gamma == b.gamma));
}

// Casts `count` random rays (a share of them under AddressSanitizer)
// through the BVH (or `accel`) and brute force and counts where they disagree: in the
// closest hit, in any-hit against brute force, in any-hit against the
// closest hit, and for a ray spawned off each hit.
Disagreements compare(const Scene& scene, std::uint64_t count, std::uint64_t seed,
                      TriangleKernel kernel = {}, const SceneBvhOptions& bvhOptions = {},
                      AccelMethod accel = AccelMethod::Bvh) {
  count = test::sanitizerShare(count);
  const SceneIntersector bvh(scene, {.accel = accel, .triangle = kernel, .bvh = bvhOptions});
  const SceneIntersector brute(scene, {.accel = AccelMethod::None, .triangle = kernel});
  const Aabb box = sceneBox(scene);
  const bool exactLimit = kernel.test != TriangleTest::Watertight;
  constexpr std::uint64_t kChunk = 4096;
  return tbb::parallel_reduce(
      tbb::blocked_range<std::uint64_t>(0, (count + kChunk - 1) / kChunk), Disagreements(),
      [&](const tbb::blocked_range<std::uint64_t>& r, Disagreements acc) {
        Counters c;
        std::uniform_real_distribution<double> u(0.0, 1.0);
        for (std::uint64_t chunk = r.begin(); chunk < r.end(); ++chunk) {
          std::mt19937_64 rng(seed * 1000003 + chunk);
          for (std::uint64_t i = 0; i < kChunk && chunk * kChunk + i < count; ++i) {
            const Ray ray = randomRay(scene, box, rng);
            Hit a, b;
            const bool fa = bvh.closestHit(ray, 0.0, a, c);
            const bool fb = brute.closestHit(ray, 0.0, b, c);
            ++acc.rays;
            acc.hits += fb;
            if (!sameHit(fa, a, fb, b)) {
              ++acc.closest;
              if (acc.example.empty())
                acc.example = "bvh " + describe(ray, a) + " | brute force " + describe(ray, b);
            }
            // One limit per ray: beyond the closest hit, exactly at it, or before it.
            const double scale[] = {1.25, 1.0, 0.8};
            const double tMax = (fb ? b.t : 2.0) * scale[rng() % 3];
            {
              const bool oa = bvh.occluded(ray, 0.0, tMax, c);
              const bool ob = brute.occluded(ray, 0.0, tMax, c);
              // With an exact t < tMax cut-off, any-hit is the closest hit's t
              // compared with the limit.
              const bool consistent = !exactLimit || oa == (fb && b.t < tMax);
              if (oa != ob || !consistent) {
                ++acc.anyHit;
                if (acc.example.empty())
                  acc.example = "any-hit to " + std::to_string(tMax) + ": bvh " +
                                std::to_string(oa) + ", brute force " + std::to_string(ob) +
                                ", closest " + describe(ray, b);
              }
            }
            // A ray spawned off the hit in a random direction, told the
            // primitive it leaves (spawn.h), as shadow and reflection rays are.
            if (fb) {
              const SurfacePoint sp = surfaceAt(scene, ray, b, kernel.precision);
              const Vec3 d = glm::normalize(Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5));
              const Ray spawned{spawnOrigin(sp, d), d};
              Hit sa, sb;
              const bool ga = bvh.closestHit(spawned, kSpawnTMin, sa, c, &sp.primitive);
              const bool gb = brute.closestHit(spawned, kSpawnTMin, sb, c, &sp.primitive);
              const double limit = (gb ? sb.t : 2.0) * scale[rng() % 3];
              if (!sameHit(ga, sa, gb, sb) ||
                  bvh.occluded(spawned, kSpawnTMin, limit, c, &sp.primitive) !=
                      brute.occluded(spawned, kSpawnTMin, limit, c, &sp.primitive)) {
                ++acc.spawned;
                if (acc.example.empty())
                  acc.example = "spawned: bvh " + describe(spawned, sa) + " | brute force " +
                                describe(spawned, sb);
              }
            }
          }
        }
        return acc;
      },
      [](Disagreements a, const Disagreements& b) {
        a.add(b);
        return a;
      });
}

void expectAgreement(const char* label, const Disagreements& d) {
  std::printf(
      "[ figures  ] %-12s %llu rays, %llu hits; closest-hit differences %llu, any-hit %llu, "
      "spawned %llu\n",
      label, static_cast<unsigned long long>(d.rays), static_cast<unsigned long long>(d.hits),
      static_cast<unsigned long long>(d.closest), static_cast<unsigned long long>(d.anyHit),
      static_cast<unsigned long long>(d.spawned));
  EXPECT_GT(d.hits, d.rays / 5) << label << ": too few rays hit to mean much";
  EXPECT_EQ(d.closest, 0u) << label << ": " << d.example;
  EXPECT_EQ(d.anyHit, 0u) << label << ": " << d.example;
  EXPECT_EQ(d.spawned, 0u) << label << ": " << d.example;
}

// Over a million rays in all, on meshes of a few hundred triangles (brute
// force has to keep up).
TEST(BvhAgreesWithBruteForce, GeneratedMeshes) {
  std::mt19937_64 rng(42);
  const Scene knot =
      meshScene({makeMesh("knot", makeTorusKnot(Vec3(0.0), 1.0, 2, 3, 0.25, 48, 6))});
  const Scene ball =
      meshScene({makeMesh("ball", rotated(makeIcosphere(Vec3(0.1, 0.2, 0.3), 1.0, 2), 0.3))});
  const Scene boxes = meshScene({makeMesh("box", makeGriddedBox(Vec3(-1.0), Vec3(1.0), 4)),
                                 makeMesh("grid", makeGrid(Vec3(0.0, 0.25, 0.0), 1.5, 8))});
  const Scene soup = meshScene({makeMesh("soup", triangleSoup(400, rng))});
  expectAgreement("torus knot", compare(knot, 300000, 1));
  expectAgreement("icosphere", compare(ball, 250000, 2));
  expectAgreement("gridded box", compare(boxes, 250000, 3));
  expectAgreement("soup", compare(soup, 250000, 4));
}

// The meshes of a scene share one triangle BVH: a tie between two meshes
// still goes to the lower mesh index, as in brute force, and a small mesh
// far from a large one keeps its hits though the blocks' float frame is
// sized for both.
TEST(BvhAgreesWithBruteForce, MeshesSharingOneTree) {
  const MeshData ball = makeIcosphere(Vec3(0.0), 1.0, 2);
  const Scene twins =
      meshScene({makeMesh("ball", ball), makeMesh("twin", ball),
                 makeMesh("knot", makeTorusKnot(Vec3(0.5, 0.0, 0.0), 0.8, 2, 3, 0.2, 48, 6))});
  const Scene apart = meshScene(
      {makeMesh("ball", ball),
       makeMesh("speck", makeTorusKnot(Vec3(1000.0, 0.0, 0.0), 0.01, 2, 3, 0.25, 48, 6))});
  expectAgreement("twin meshes", compare(twins, 200000, 11));
  expectAgreement("far speck", compare(apart, 200000, 12));
}

TEST(BvhAgreesWithBruteForce, ObjectsOfEveryKind) {
  std::mt19937_64 rng(7);
  expectAgreement("objects", compare(objectScene(rng), 200000, 5));
}

// Whatever triangle kernel TraceOptions selects, the BVH calls that one.
TEST(BvhAgreesWithBruteForce, EveryTriangleKernel) {
  std::mt19937_64 rng(9);
  const Scene scene = meshScene({makeMesh("soup", triangleSoup(300, rng)),
                                 makeMesh("box", makeGriddedBox(Vec3(-0.3), Vec3(0.4), 3))});
  for (TriangleTest test :
       {TriangleTest::Cramer, TriangleTest::MollerTrumbore, TriangleTest::Watertight})
    for (Precision precision : {Precision::Double, Precision::Single}) {
      const std::string label = std::string(toString(test)) + "/" + toString(precision);
      expectAgreement(label.c_str(), compare(scene, 40000, 6, {test, precision}));
    }
}

// Long triangles a hundredth to a hundred-millionth as wide, around
// `center`.
MeshData slivers(int n, const Vec3& center, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0), along(-0.5, 0.5), exponent(-8.0, -2.0);
  MeshData m;
  for (int i = 0; i < n; ++i) {
    const Vec3 axis = glm::normalize(Vec3(u(rng), u(rng), u(rng)) + Vec3(0.0, 0.0, 1e-3));
    const Vec3 across = glm::normalize(glm::cross(axis, Vec3(u(rng), u(rng), u(rng))));
    const Vec3 mid = center + Vec3(u(rng), u(rng), u(rng));
    const double length = 1.0 + 0.5 * u(rng), width = std::pow(10.0, exponent(rng));
    const auto next = static_cast<std::uint32_t>(m.vertices.size());
    m.vertices.push_back(mid - 0.5 * length * axis);
    m.vertices.push_back(mid + 0.5 * length * axis);
    m.vertices.push_back(mid + along(rng) * length * axis + width * length * across);
    m.triangles.push_back({next, next + 1, next + 2});
  }
  return m;
}

// On slivers Cramer's rule and Moller-Trumbore compute det with few or no
// correct digits, and beta, gamma and t need not describe one point: they
// may report a hit far outside the triangle, which no box around it holds,
// unless they refuse it (TriangleRay::intersect). Both the BVH and the
// per-mesh boxes must find what brute force finds, with every kernel.
TEST(BvhAgreesWithBruteForce, SliversForEveryKernelNearAndFarFromTheOrigin) {
  std::mt19937_64 rng(23);
  const Scene near = meshScene({makeMesh("slivers", slivers(300, Vec3(0.3, -0.2, 0.1), rng))});
  const Scene far = meshScene({makeMesh("slivers", slivers(300, Vec3(3e6, -1e6, 2e6), rng))});
  for (const TriangleKernel& k : allTriangleKernels())
    for (const AccelMethod accel : {AccelMethod::Bvh, AccelMethod::BoundingBox}) {
      const std::string label =
          std::string(toString(accel)) + " " + toString(k.test) + "/" + toString(k.precision);
      expectAgreement((label + " near").c_str(), compare(near, 20000, 31, k, {}, accel));
      expectAgreement((label + " far").c_str(), compare(far, 20000, 32, k, {}, accel));
    }
}

// Far from the origin a single-precision kernel's corners, rounded to
// float, lie outside the mesh's double box (here by up to 2, half a float's
// spacing at 6e7): a ray can meet a float triangle and miss that box.
// --accel aabb pads its boxes as the BVH does, so both find what brute
// force finds, here for rays at a grazing angle over a flat mesh, aimed at
// its whole extent and beyond.
TEST(BvhAgreesWithBruteForce, FlatMeshFarFromTheOriginInSinglePrecision) {
  std::mt19937_64 rng(29);
  std::uniform_real_distribution<double> u(-20.0, 20.0);
  const Vec3 center(61892616.26, 0.0, 0.0334);
  MeshData m;
  for (std::uint32_t i = 0; i < 600; ++i) {
    for (int k = 0; k < 3; ++k) m.vertices.push_back(center + Vec3(u(rng), u(rng), 0.0));
    m.triangles.push_back({3 * i, 3 * i + 1, 3 * i + 2});
  }
  const Scene scene = meshScene({makeMesh("flat", std::move(m))});
  const Vec3 eye = center + Vec3(143.4, 146.7, -139.6);
  // A 201 x 201 grid of rays over the mesh; under AddressSanitizer every
  // stride-th one in each direction, the share sanitizerShare takes.
  const int stride = static_cast<int>(std::lround(std::sqrt(double(test::kSanitizerDivisor))));
  const int side = 1 + 200 / stride;
  const double step = 50.0 / (side - 1);
  for (const TriangleTest test :
       {TriangleTest::Watertight, TriangleTest::Cramer, TriangleTest::MollerTrumbore}) {
    const TriangleKernel k{test, Precision::Single};
    const SceneIntersector brute(scene, {.accel = AccelMethod::None, .triangle = k});
    for (const AccelMethod accel : {AccelMethod::Bvh, AccelMethod::BoundingBox}) {
      const SceneIntersector fast(scene, {.accel = accel, .triangle = k});
      std::uint64_t rays = 0, hits = 0, differences = 0;
      Counters c;
      for (int i = 0; i < side; ++i)
        for (int j = 0; j < side; ++j) {
          const double x = -25.0 + i * step, y = -25.0 + j * step;
          const Ray ray{eye, glm::normalize(center + Vec3(x, y, 0.0) - eye)};
          Hit a, b;
          const bool fa = fast.closestHit(ray, 0.0, a, c), fb = brute.closestHit(ray, 0.0, b, c);
          ++rays;
          hits += fb;
          differences += !sameHit(fa, a, fb, b);
        }
      const std::string label = std::string(toString(accel)) + " " + toString(test);
      std::printf("[ figures  ] %-16s %llu rays, %llu hits, differences %llu\n", label.c_str(),
                  static_cast<unsigned long long>(rays), static_cast<unsigned long long>(hits),
                  static_cast<unsigned long long>(differences));
      EXPECT_GT(hits, rays / 5) << label;
      EXPECT_EQ(differences, 0u) << label;
    }
  }
}

// 1.9e8 from the origin floats are 16 apart: a single-precision kernel sees
// these triangles, and a shadow ray's origin, snapped to that grid. The ray,
// spawned off the first triangle, starts outside the triangle BVH's double
// box and leaves it, yet meets the second triangle's float copy at t = 0.04.
// The box test that turns such rays away is padded for these kernels
// (boxPadding), so the BVH answers as brute force does.
TEST(BvhAgreesWithBruteForce, SpawnedRayMeetingAFloatTriangleOutsideTheDoubleBox) {
  MeshData m;
  m.vertices = {{-0.66077927058253094, -2.3642757088100081, -188973240.29516175},
                {-0.99854159902504425, -2.1587971373237975, -188973240.27678156},
                {-0.020807356134898116, -2.7560303718184769, -188973239.19776794},
                {0.13689582222667901, -1.5588818211102662, -188973240.06359836},
                {-0.77551466834993799, -2.1435993485154499, -188973239.28821546},
                {0.79291825314120978, -2.0498644782861759, -188973239.8446967},
                {0.5, 0.5, -188973250.0},
                {1.5, 0.5, -188973250.0},
                {0.5, 1.5, -188973250.0}};
  m.triangles = {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}};
  const Scene scene = meshScene({makeMesh("far", std::move(m))});
  const Ray shadow{Vec3(-0.69579648971557617, -2.1740946769714355, -188973232.0),
                   Vec3(-0.41058438582989831, 0.87877814880903815, -0.24324766656320684)};
  const PrimitiveRef start{ObjectKind::Mesh, 0, 0};
  for (const TriangleTest test :
       {TriangleTest::Watertight, TriangleTest::Cramer, TriangleTest::MollerTrumbore}) {
    const TriangleKernel k{test, Precision::Single};
    const SceneIntersector bvh(scene, {.accel = AccelMethod::Bvh, .triangle = k});
    const SceneIntersector brute(scene, {.accel = AccelMethod::None, .triangle = k});
    ASSERT_EQ(bvh.bvhStats()->trianglesInBvhs, 3u);
    Counters c;
    Hit a, b;
    const bool fa = bvh.closestHit(shadow, kSpawnTMin, a, c, &start);
    const bool fb = brute.closestHit(shadow, kSpawnTMin, b, c, &start);
    EXPECT_TRUE(fb) << toString(test) << ": the float copy is no longer met";
    EXPECT_TRUE(sameHit(fa, a, fb, b)) << toString(test) << ": bvh " << describe(shadow, a)
                                       << " | brute force " << describe(shadow, b);
    EXPECT_EQ(bvh.occluded(shadow, kSpawnTMin, 89.4, c, &start),
              brute.occluded(shadow, kSpawnTMin, 89.4, c, &start))
        << toString(test);
  }
}

// Meshes full of exact copies of their triangles, of which the BVH holds
// only the two lowest indices (triangle_copies.h), and near copies, which
// it all holds: with every kernel, every query finds what brute force
// finds.
TEST(BvhAgreesWithBruteForce, TrianglesWithCopies) {
  const Scene scene = meshScene(
      {makeMesh("copies", test::withCopies(rotated(makeIcosphere(Vec3(0.1), 1.0, 1), 0.4), 1, 3))});
  ASSERT_EQ(SceneBvh(scene).stats().copiesLeftOut, 80u * 5);  // seven copies of each, five spare
  for (const TriangleKernel& k : allTriangleKernels()) {
    const std::string label =
        std::string("copies ") + toString(k.test) + "/" + toString(k.precision);
    expectAgreement(label.c_str(), compare(scene, 20000, 13, k));
  }
}

// A ray that leaves a triangle, told so, does not test it, but does test
// its copies, and the second lowest of a set answers for them: rays from
// points on a triangle, which the kernels without an error bound (Cramer,
// Moller-Trumbore) often report as hitting the triangle itself at a t near
// 0, must find that copy through the BVH as brute force does.
TEST(BvhAgreesWithBruteForce, RaysLeavingATriangleMeetItsCopies) {
  MeshData m;
  m.vertices = {{0.1, 0.2, 0.3}, {1.3, 0.4, 0.1}, {0.2, 1.1, 0.7}};
  m.triangles.assign(8, {0, 1, 2});
  const Scene scene = meshScene({makeMesh("copies", std::move(m))});
  const auto& v = scene.meshes[0].vertices();
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (const TriangleKernel& k : allTriangleKernels()) {
    const SceneIntersector bvh(scene, {.accel = AccelMethod::Bvh, .triangle = k});
    const SceneIntersector brute(scene, {.accel = AccelMethod::None, .triangle = k});
    ASSERT_EQ(bvh.bvhStats()->copiesLeftOut, 6u);
    std::size_t selfHits = 0, differences = 0;
    Counters c;
    for (int i = 0; i < 20000; ++i) {
      const double b = 0.5 * u(rng), g = 0.5 * u(rng);
      const Ray ray{(1.0 - b - g) * v[0] + b * v[1] + g * v[2],
                    glm::normalize(Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5))};
      TriangleHit th;
      if (!TriangleRay(ray, k).intersect(v[0], v[1], v[2], 0.0, kInfinity, th)) continue;
      ++selfHits;
      // Leaving the lowest, the second answers; leaving another, the lowest.
      for (std::uint32_t leaving : {0u, 1u, 5u}) {
        const PrimitiveRef start{ObjectKind::Mesh, 0, leaving};
        Hit a, h;
        const bool fa = bvh.closestHit(ray, 0.0, a, c, &start);
        const bool fh = brute.closestHit(ray, 0.0, h, c, &start);
        differences += !fh || h.ref.triangle != (leaving == 0 ? 1u : 0u) ||
                       !sameHit(fa, a, fh, h) || !bvh.occluded(ray, 0.0, 1.0, c, &start);
      }
    }
    const std::string label = std::string(toString(k.test)) + "/" + toString(k.precision);
    std::printf("[ figures  ] %-18s %zu rays from the triangle hit it again; differences %zu\n",
                label.c_str(), selfHits, differences);
    if (k.test != TriangleTest::Watertight) {
      EXPECT_GT(selfHits, 0u) << label << ": no ray to tell the copies apart";
    }
    EXPECT_EQ(differences, 0u) << label;
  }
}

// Whether two directions have the same octant (the sign bits, -0 included,
// as the slab ray takes them).
bool sameOctant(const Vec3& a, const Vec3& b) {
  for (int k = 0; k < 3; ++k)
    if (std::signbit(a[k]) != std::signbit(b[k])) return false;
  return true;
}

// Packets of four rays through SceneIntersector::closestHitPacket and
// occludedPacket against brute force, ray by ray: the packet as given, then
// some of its rays (any-hit and closest-hit), spawned off their hits in one
// direction as shadow and reflection rays are. Most packets are what a
// camera makes: one origin and directions a little apart, or one direction
// (axis-parallel ones too) from origins a little apart; every fourth is four
// unrelated rays, which seldom share an octant and go ray by ray.
struct PacketCheck {
  std::uint64_t rays = 0, hits = 0, differences = 0, sharedOctant = 0;
  std::uint64_t blocked = 0, anyHitDifferences = 0;
  std::uint64_t spawnedHits = 0;  // of the spawned rays' closest hits
  std::string example;
};
PacketCheck comparePackets(const Scene& scene, int packets, std::uint64_t seed,
                           const SceneBvhOptions& bvhOptions = {}) {
  const SceneIntersector bvh(scene, {.accel = AccelMethod::Bvh, .bvh = bvhOptions});
  const SceneIntersector brute(scene, {.accel = AccelMethod::None});
  const Aabb box = sceneBox(scene);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  PacketCheck check;
  Counters c;
  for (int p = 0; p < packets; ++p) {
    Ray rays[kPacketSize];
    const Ray lead = randomRay(scene, box, rng);
    const double spread = p % 2 ? 1e-3 : 1e-2;
    for (int r = 0; r < kPacketSize; ++r) {
      if (p % 4 == 3) {
        rays[r] = randomRay(scene, box, rng);
      } else if (p % 4 == 2) {
        rays[r] = {lead.origin + spread * box.extent() * Vec3(u(rng), u(rng), u(rng)),
                   lead.direction};
      } else {
        const Vec3 d = lead.direction + spread * Vec3(u(rng), u(rng), u(rng));
        rays[r] = {lead.origin, r == 0 ? lead.direction : glm::normalize(d)};
      }
    }
    bool shared = true;
    for (const Ray& r : rays) shared = shared && sameOctant(r.direction, rays[0].direction);
    check.sharedOctant += shared;
    const double tMin = p % 3 == 0 ? kSpawnTMin : 0.0;
    Hit hits[kPacketSize];
    bool found[kPacketSize];
    bvh.closestHitPacket(rays, tMin, hits, found, c);
    // Any-hit: some rays left out, the others up to a limit near their
    // hit, and, as shadow rays, spawned off it and told what they leave.
    double limit[kPacketSize];
    PrimitiveRef start[kPacketSize];
    Ray spawned[kPacketSize];
    const std::uint32_t active = static_cast<std::uint32_t>(rng() % 15) + 1;
    const bool fromHits = p % 2 == 0;
    const Vec3 towards = glm::normalize(Vec3(u(rng), u(rng), u(rng)));
    for (int r = 0; r < kPacketSize; ++r) {
      const double scale[] = {1.25, 1.0, 0.8};
      limit[r] = (found[r] ? hits[r].t : 2.0) * scale[rng() % 3];
      spawned[r] = rays[r];
      if (fromHits && found[r]) {
        const SurfacePoint sp = surfaceAt(scene, rays[r], hits[r], Precision::Double);
        spawned[r] = {spawnOrigin(sp, towards), towards};
        start[r] = sp.primitive;
      }
    }
    const double anyTMin = fromHits ? kSpawnTMin : tMin;
    const std::uint32_t packetBlocked =
        bvh.occludedPacket(spawned, anyTMin, limit, start, active, c);
    // Closest hits of the same rays, as mirror reflections are traced.
    Hit spawnedHits[kPacketSize];
    bool spawnedFound[kPacketSize];
    bvh.closestHitPacket(spawned, anyTMin, spawnedHits, spawnedFound, c, start, active);
    // Counts a closest hit that differs from brute force's.
    const auto compareClosest = [&](const char* label, const Ray& ray, bool packetFound,
                                    const Hit& packetHit, bool bruteFound, const Hit& bruteHit) {
      if (sameHit(packetFound, packetHit, bruteFound, bruteHit)) return;
      ++check.differences;
      if (check.example.empty())
        check.example = std::string(label) + " " + describe(ray, packetHit) + " | brute force " +
                        describe(ray, bruteHit);
    };
    for (int r = 0; r < kPacketSize; ++r) {
      Hit b;
      const bool fb = brute.closestHit(rays[r], tMin, b, c);
      ++check.rays;
      check.hits += fb;
      compareClosest("packet", rays[r], found[r], hits[r], fb, b);
      Hit spawnedBrute;
      const bool spawnedExpected =
          (active >> r & 1) && brute.closestHit(spawned[r], anyTMin, spawnedBrute, c, &start[r]);
      check.spawnedHits += spawnedExpected;
      compareClosest("spawned packet", spawned[r], spawnedFound[r], spawnedHits[r], spawnedExpected,
                     spawnedBrute);
      const bool expected =
          (active >> r & 1) && brute.occluded(spawned[r], anyTMin, limit[r], c, &start[r]);
      check.blocked += expected;
      if (((packetBlocked >> r & 1) != 0) != expected) {
        ++check.anyHitDifferences;
        if (check.example.empty())
          check.example =
              "any-hit packet, " + describe(spawned[r], Hit{}) + " to " + std::to_string(limit[r]);
      }
    }
  }
  return check;
}

// A ray spawned outward from a face that lies on the mesh's box starts
// outside the box by a rounding's width: the box's exact test turns it away
// before any block is filtered, for single rays and packets alike, and it
// finds what brute force finds (nothing).
TEST(SpawnedRays, LeavingAFaceOfTheMeshBoxOutwardTestNoTriangle) {
  const Scene scene = meshScene({makeMesh("box", makeGriddedBox(Vec3(-0.5), Vec3(0.7), 3))});
  const SceneIntersector bvh(scene, {.accel = AccelMethod::Bvh});
  const SceneIntersector brute(scene, {.accel = AccelMethod::None});
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int spawned = 0;
  for (int i = 0; i < 2000; ++i) {
    // From a point well outside toward a point inside the box.
    const Vec3 from = 3.0 * glm::normalize(Vec3(u(rng), u(rng), u(rng)));
    const Vec3 to(0.1 + 0.5 * u(rng), 0.1 + 0.5 * u(rng), 0.1 + 0.5 * u(rng));
    const Ray ray{from, glm::normalize(to - from)};
    Hit hit;
    Counters c;
    ASSERT_TRUE(bvh.closestHit(ray, 0.0, hit, c));
    const SurfacePoint sp = surfaceAt(scene, ray, hit);
    // Back out through the face: the face's normal, tilted at random.
    const Vec3 n =
        sp.geometricNormal * (glm::dot(sp.geometricNormal, ray.direction) < 0 ? 1.0 : -1.0);
    const Vec3 d = glm::normalize(n + 0.45 * Vec3(u(rng), u(rng), u(rng)));
    if (glm::dot(d, n) <= 0.05) continue;
    const Ray out{spawnOrigin(sp, d), d};
    Counters single, packet;
    Hit a, b;
    EXPECT_FALSE(bvh.closestHit(out, kSpawnTMin, a, single, &sp.primitive));
    EXPECT_FALSE(brute.closestHit(out, kSpawnTMin, b, single, &sp.primitive));
    single = {};
    EXPECT_FALSE(bvh.occluded(out, kSpawnTMin, kInfinity, single, &sp.primitive));
    EXPECT_EQ(single.triangleTests, 0u) << "ray " << i;
    const Ray quad[kPacketSize] = {out, out, out, out};
    const double limits[kPacketSize] = {kInfinity, kInfinity, kInfinity, kInfinity};
    const PrimitiveRef starts[kPacketSize] = {sp.primitive, sp.primitive, sp.primitive,
                                              sp.primitive};
    EXPECT_EQ(bvh.occludedPacket(quad, kSpawnTMin, limits, starts, 0xf, packet), 0u);
    EXPECT_EQ(packet.triangleTests, 0u) << "ray " << i;
    ++spawned;
  }
  EXPECT_GT(spawned, 1000);
}

TEST(BvhPacket, FindsWhatBruteForceFindsForEachRay) {
  std::mt19937_64 rng(21);
  const MeshData ball = makeIcosphere(Vec3(0.0), 1.0, 2);
  const MeshData knot = makeTorusKnot(Vec3(0.0), 1.0, 2, 3, 0.25, 48, 6);
  const Scene scenes[] = {meshScene({makeMesh("knot", knot)}),
                          meshScene({makeMesh("ball", ball), makeMesh("twin", ball),
                                     makeMesh("box", makeGriddedBox(Vec3(-0.5), Vec3(0.7), 3))}),
                          objectScene(rng),
                          meshScene({makeMesh("copies", test::withCopies(knot, 4, 3))})};
  const char* labels[] = {"knot", "twin meshes", "objects", "knot with copies"};
  const int packets[] = {40000, 40000, 40000, 10000};
  for (int i = 0; i < 4; ++i) {
    const PacketCheck check =
        comparePackets(scenes[i], static_cast<int>(test::sanitizerShare(packets[i])), 31 + i);
    std::printf(
        "[ figures  ] %-12s %llu rays in packets (%llu of %llu packets share an "
        "octant), %llu hits, %llu spawned hits; differences %llu; any-hit: %llu "
        "blocked, differences %llu\n",
        labels[i], static_cast<unsigned long long>(check.rays),
        static_cast<unsigned long long>(check.sharedOctant),
        static_cast<unsigned long long>(check.rays / kPacketSize),
        static_cast<unsigned long long>(check.hits),
        static_cast<unsigned long long>(check.spawnedHits),
        static_cast<unsigned long long>(check.differences),
        static_cast<unsigned long long>(check.blocked),
        static_cast<unsigned long long>(check.anyHitDifferences));
    EXPECT_GT(check.hits, check.rays / 5) << labels[i];
    EXPECT_GT(check.spawnedHits, check.rays / 20) << labels[i];
    EXPECT_GT(check.sharedOctant, check.rays / kPacketSize / 2) << labels[i];
    EXPECT_GT(check.blocked, check.rays / 10) << labels[i];
    EXPECT_EQ(check.differences, 0u) << labels[i] << ": " << check.example;
    EXPECT_EQ(check.anyHitDifferences, 0u) << labels[i] << ": " << check.example;
  }
}

// Fetching children ahead (and a packet's candidate vertices) is a hint to
// the memory and nothing else: switched on for a small mesh (by default only
// triangle BVHs of kPrefetchBvhBytes or more use it), every query still
// finds what brute force finds; switched off, the stats say so.
TEST(BvhPrefetch, FetchingChildrenAheadChangesNoAnswer) {
  const Scene knot =
      meshScene({makeMesh("knot", makeTorusKnot(Vec3(0.0), 1.0, 2, 3, 0.25, 48, 6))});
  SceneBvhOptions always;
  always.prefetchBytes = 0;
  const SceneIntersector fetching(knot, {.accel = AccelMethod::Bvh, .bvh = always});
  const SceneIntersector plain(knot, {.accel = AccelMethod::Bvh});
  ASSERT_TRUE(fetching.bvh()->meshBvh().prefetch);
  ASSERT_FALSE(plain.bvh()->meshBvh().prefetch);
  const auto saysNotFetched = [](const SceneIntersector& is) {
    for (const std::string& item : is.bvh()->stats().leftOut)
      if (item.rfind("BVH children not fetched ahead", 0) == 0) return true;
    return false;
  };
  EXPECT_FALSE(saysNotFetched(fetching));
  EXPECT_TRUE(saysNotFetched(plain));

  expectAgreement("torus knot, fetching ahead", compare(knot, 200000, 5, {}, always));
  const PacketCheck check =
      comparePackets(knot, static_cast<int>(test::sanitizerShare(20000)), 41, always);
  EXPECT_GT(check.hits, check.rays / 5);
  EXPECT_GT(check.blocked, check.rays / 10);
  EXPECT_EQ(check.differences, 0u) << check.example;
  EXPECT_EQ(check.anyHitDifferences, 0u) << check.example;
}

TEST(AccelMethod, BvhIsTheDefaultAndParses) {
  EXPECT_EQ(TraceOptions{}.accel, AccelMethod::Bvh);
  EXPECT_EQ(parseAccelMethod("bvh"), AccelMethod::Bvh);
  EXPECT_STREQ(toString(AccelMethod::Bvh), "bvh");
  EXPECT_THROW(parseAccelMethod("kd"), std::invalid_argument);
}

}  // namespace
}  // namespace meshtrace
