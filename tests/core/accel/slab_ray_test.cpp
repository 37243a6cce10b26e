// The float slab tests of the 8-wide BVH are conservative: whenever the
// exact ray meets a box widened by the padding of slab_ray.h (within the
// padded distance range), BoxRay8 reports the child, and SlabRay::meets
// (a root leaf's box) reports the box. Checked against
// a long double reference on random boxes and rays, rays aimed exactly at box
// faces, edges and corners, origins from 1e-3 to 1e6, and directions with
// zero and tiny components.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "accel/traverse.h"

namespace meshtrace {
namespace {

struct FloatBox {
  float lo[3], hi[3];
};

// The reference: the exact slab interval of the box widened by
// pad.absolute, its ends scaled by 1 -/+ pad.relative, met within
// [tMin, tMax]. Long double carries 11 more bits than the inputs, far below
// the padding.
bool exactPaddedHit(const FloatBox& box, const Ray& ray, const SlabPadding& pad, double tMin,
                    double tMax) {
  long double enter = tMin, exit = tMax;
  for (int a = 0; a < 3; ++a) {
    const long double lo = static_cast<long double>(box.lo[a]) - pad.absolute;
    const long double hi = static_cast<long double>(box.hi[a]) + pad.absolute;
    const long double o = ray.origin[a], d = ray.direction[a];
    if (d == 0) {
      if (o < lo || o > hi) return false;
      continue;
    }
    long double t0 = (lo - o) / d, t1 = (hi - o) / d;
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > 0) t0 *= 1 - static_cast<long double>(pad.relative);
    t1 *= 1 + static_cast<long double>(pad.relative);
    enter = std::max(enter, t0);
    exit = std::min(exit, t1);
  }
  return enter <= exit;
}

// The float test as the traversal runs it: the box in lane `lane` of a node
// whose other lanes are empty, with tMin and tMax rounded outward.
bool floatHit(const FloatBox& box, int lane, const Ray& ray, const SlabPadding& pad, double tMin,
              double tMax) {
  Bvh8Node node{};
  for (int a = 0; a < 3; ++a)
    for (int i = 0; i < kBvhWidth; ++i) {
      node.lo[a][i] = i == lane ? box.lo[a] : 1.0f;
      node.hi[a][i] = i == lane ? box.hi[a] : -1.0f;
    }
  const BoxRay8 boxRay(SlabRay(ray, pad));
  alignas(16) float tEnter[kBvhWidth];
  const unsigned mask = boxRay.intersect(node, _mm_set1_ps(bvh8::atMost(tMin)),
                                         _mm_set1_ps(bvh8::atLeast(tMax)), tEnter);
  return (mask >> lane) & 1;
}

// The test of a tree whose root is a leaf, on the same box.
bool floatRootHit(const FloatBox& box, const Ray& ray, const SlabPadding& pad, double tMin,
                  double tMax) {
  alignas(16) float lo[4], hi[4];
  for (int a = 0; a < 4; ++a) {
    lo[a] = box.lo[std::min(a, 2)];
    hi[a] = box.hi[std::min(a, 2)];
  }
  return SlabRay(ray, pad).meets(lo, hi, bvh8::atMost(tMin), bvh8::atLeast(tMax));
}

class BoxRay8Conservative : public ::testing::TestWithParam<double> {};

TEST_P(BoxRay8Conservative, ReportsEveryBoxTheExactPaddedTestMeets) {
  const double scale = GetParam();
  std::mt19937_64 rng(20261121);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), frac(0.0, 1.0);
  const double tiny[] = {0.0, -0.0, 1e-35, -1e-35, 1e-20, -3e-9};
  std::size_t cases = 0, hits = 0, missed = 0, missedAsRoot = 0;
  for (int k = 0; k < 60000; ++k) {
    // A box somewhere in [-scale, scale]^3, sometimes flat on one axis.
    FloatBox box;
    for (int a = 0; a < 3; ++a) {
      const double c = unit(rng) * scale, h = frac(rng) * scale * 0.3;
      box.lo[a] = static_cast<float>(c - h);
      box.hi[a] = k % 7 == a ? box.lo[a] : static_cast<float>(c + h);
    }
    Ray ray;
    for (int a = 0; a < 3; ++a) ray.origin[a] = unit(rng) * 2 * scale;
    // Aim at a point of the box's surface: a face, an edge or a corner.
    Vec3 target;
    for (int a = 0; a < 3; ++a) {
      const double t = frac(rng);
      target[a] = box.lo[a] + t * (static_cast<double>(box.hi[a]) - box.lo[a]);
    }
    const int pinned = 1 + k % 3;  // coordinates put on a box plane
    for (int a = 0; a < pinned; ++a) {
      const int axis = (k + a) % 3;
      target[axis] = (k >> 3) & 1 ? box.hi[axis] : box.lo[axis];
    }
    ray.direction = target - ray.origin;
    if (k % 5 == 0) ray.direction[k % 3] = tiny[(k / 5) % 6];
    if (k % 11 == 0) ray.direction = Vec3(unit(rng), unit(rng), unit(rng));
    if (glm::length(ray.direction) == 0.0) continue;
    ray.direction = glm::normalize(ray.direction);
    const double sceneScale = 2 * scale;
    for (bool single : {false, true}) {
      const SlabPadding pad = slabPadding(single, ray.origin, sceneScale);
      for (double tMax : {kInfinity, glm::length(target - ray.origin)}) {
        const double tMin = k % 2 ? 0.0 : 1e-9 * scale;
        ++cases;
        if (!exactPaddedHit(box, ray, pad, tMin, tMax)) continue;
        ++hits;
        if (!floatHit(box, k % kBvhWidth, ray, pad, tMin, tMax)) {
          ++missed;
          if (missed <= 5)
            ADD_FAILURE() << "box culled: k " << k << " single " << single << " tMax " << tMax;
        }
        if (!floatRootHit(box, ray, pad, tMin, tMax) && ++missedAsRoot <= 5)
          ADD_FAILURE() << "root box culled: k " << k << " single " << single << " tMax " << tMax;
      }
    }
  }
  std::printf("scale %g: %zu cases, %zu exact hits, %zu culled as a child, %zu as a root\n", scale,
              cases, hits, missed, missedAsRoot);
  EXPECT_EQ(missed, 0u);
  EXPECT_EQ(missedAsRoot, 0u);
  EXPECT_GT(hits, cases / 2);  // most rays are aimed at the box
}

INSTANTIATE_TEST_SUITE_P(Scales, BoxRay8Conservative, ::testing::Values(1e-3, 1.0, 1e3, 1e6));

}  // namespace
}  // namespace meshtrace
