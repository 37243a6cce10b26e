// The closest-hit traversal of the 4-wide BVH visits leaves nearest first
// in every octant of ray directions, and skips those beyond the best hit.
// The order comes from each node's per-octant child order and the visit
// plans, not from sorting distances, so these pin that the two agree.
#include "meshtrace/bvh4_traverse.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "meshtrace/bvh.h"

namespace meshtrace {
namespace {

// Unit boxes centred at k * 3 * diagonal, k = 0 .. count - 1, each its own leaf.
Bvh4 boxesAlong(const Vec3& diagonal, int count) {
  std::vector<Aabb> boxes;
  for (int k = 0; k < count; ++k) {
    const Vec3 centre = diagonal * (3.0 * k);
    boxes.push_back(Aabb{centre - Vec3(0.5), centre + Vec3(0.5)});
  }
  BvhBuildOptions options;
  options.maxLeafSize = 1;
  return collapseToBvh4(buildBvh(boxes, options));
}

// The box indices of the leaves the traversal offers, in order; the leaf
// lowers the best distance to `hitAt` when it reaches box `hitBox`.
std::vector<std::uint32_t> leavesVisited(const Bvh4& bvh, const Ray& ray, int hitBox = -1,
                                         double hitAt = kInfinity) {
  const BoxRay4 boxRay(ray, SlabPadding{0x1p-20, 1e-9});
  double tBest = kInfinity;
  std::uint64_t visits = 0;
  std::vector<std::uint32_t> seen;
  traverseClosest(bvh, boxRay, 0.0, tBest, visits, [&](std::uint32_t first, std::uint32_t count) {
    for (std::uint32_t k = first; k < first + count; ++k) {
      seen.push_back(bvh.order[k]);
      if (static_cast<int>(bvh.order[k]) == hitBox) tBest = hitAt;
    }
  });
  return seen;
}

Vec3 octantDiagonal(int octant) {
  return Vec3(octant & 1 ? -1.0 : 1.0, octant & 2 ? -1.0 : 1.0, octant & 4 ? -1.0 : 1.0);
}

TEST(Bvh4Traverse, OffersLeavesNearestFirstInEveryOctant) {
  for (int octant = 0; octant < 8; ++octant) {
    const Vec3 diagonal = octantDiagonal(octant);
    const Bvh4 bvh = boxesAlong(diagonal, 64);
    ASSERT_GT(bvh.depth, 2);
    const Ray ray{-2.0 * diagonal, glm::normalize(diagonal)};
    std::vector<std::uint32_t> expected(64);
    for (std::uint32_t k = 0; k < 64; ++k) expected[k] = k;
    EXPECT_EQ(leavesVisited(bvh, ray), expected) << "octant " << octant;
  }
}

TEST(Bvh4Traverse, SkipsLeavesBeyondTheBestHit) {
  for (int octant = 0; octant < 8; ++octant) {
    const Vec3 diagonal = octantDiagonal(octant);
    const Bvh4 bvh = boxesAlong(diagonal, 64);
    const Ray ray{-2.0 * diagonal, glm::normalize(diagonal)};
    // A hit in the middle of box 5 leaves only the boxes up to 5 to visit:
    // box 6 starts farther along the ray.
    const double hitAt = glm::length(diagonal * 15.0 + 2.0 * diagonal);
    const std::vector<std::uint32_t> expected{0, 1, 2, 3, 4, 5};
    EXPECT_EQ(leavesVisited(bvh, ray, 5, hitAt), expected) << "octant " << octant;
  }
}

// Each plan names the first hit child in the order, the number hit, and the
// others farthest first: for every order and every mask of hit children.
TEST(Bvh4Traverse, VisitPlansFollowTheChildOrder) {
  std::vector<std::uint8_t> orders(kChildOrders.begin(), kChildOrders.end());
  std::sort(orders.begin(), orders.end());
  EXPECT_EQ(std::unique(orders.begin(), orders.end()), orders.end()) << "orders repeat";
  for (int o = 0; o < kChildOrderCount; ++o) {
    std::vector<unsigned> slots;
    for (int k = 0; k < 4; ++k) slots.push_back(kChildOrders[o] >> (2 * k) & 3u);
    ASSERT_TRUE(
        std::is_permutation(slots.begin(), slots.end(), std::vector<unsigned>{0, 1, 2, 3}.begin()));
    for (unsigned mask = 1; mask < 16; ++mask) {
      std::vector<unsigned> hit;
      for (unsigned s : slots)
        if (mask >> s & 1) hit.push_back(s);
      const unsigned plan = bvh4::kVisitPlans[o][mask];
      ASSERT_EQ(plan & 3, hit.front());
      ASSERT_EQ(plan >> 2 & 7, hit.size());
      for (std::size_t k = 0; k + 1 < hit.size(); ++k)
        ASSERT_EQ(plan >> (5 + 2 * k) & 3, hit[hit.size() - 1 - k])
            << "order " << o << " mask " << mask;
    }
  }
}

}  // namespace
}  // namespace meshtrace
