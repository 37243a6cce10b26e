// The closest-hit traversal of the 8-wide BVH visits leaves nearest first
// in every octant of ray directions, and skips those beyond the best hit.
// The order comes from each node's per-octant child order, not from sorting
// distances, so these pin that the order and the pushes agree.
#include "accel/traverse.h"

#include <gtest/gtest.h>

#include <vector>

#include "accel/binary_bvh.h"

namespace meshtrace {
namespace {

// Unit boxes centred at k * 3 * diagonal, k = 0 .. count - 1, each its own leaf.
Bvh8 boxesAlong(const Vec3& diagonal, int count) {
  std::vector<Aabb> boxes;
  for (int k = 0; k < count; ++k) {
    const Vec3 centre = diagonal * (3.0 * k);
    boxes.push_back(Aabb{centre - Vec3(0.5), centre + Vec3(0.5)});
  }
  BvhBuildOptions options;
  options.maxLeafSize = 1;
  return collapseToBvh8(buildBvh(boxes, options));
}

// The box indices of the leaves the traversal offers, in order; the leaf
// lowers the best distance to `hitAt` when it reaches box `hitBox`.
std::vector<std::uint32_t> leavesVisited(const Bvh8& bvh, const Ray& ray, int hitBox = -1,
                                         double hitAt = kInfinity) {
  const SlabRay slab(ray, SlabPadding{0x1p-20, 1e-9});
  double tBest = kInfinity;
  std::uint64_t visits = 0;
  std::vector<std::uint32_t> seen;
  traverse<HitKind::Closest>(bvh, slab, 0.0, tBest, visits,
                             [&](std::uint32_t first, std::uint32_t count) {
                               for (std::uint32_t k = first; k < first + count; ++k) {
                                 seen.push_back(bvh.order[k]);
                                 if (static_cast<int>(bvh.order[k]) == hitBox) tBest = hitAt;
                               }
                               return false;
                             });
  return seen;
}

Vec3 octantDiagonal(int octant) {
  return Vec3(octant & 1 ? -1.0 : 1.0, octant & 2 ? -1.0 : 1.0, octant & 4 ? -1.0 : 1.0);
}

TEST(Bvh8Traverse, OffersLeavesNearestFirstInEveryOctant) {
  for (int octant = 0; octant < 8; ++octant) {
    const Vec3 diagonal = octantDiagonal(octant);
    const Bvh8 bvh = boxesAlong(diagonal, 600);
    ASSERT_GT(bvh.depth, 2);  // the order holds across levels, through the stack
    const Ray ray{-2.0 * diagonal, glm::normalize(diagonal)};
    std::vector<std::uint32_t> expected(600);
    for (std::uint32_t k = 0; k < 600; ++k) expected[k] = k;
    EXPECT_EQ(leavesVisited(bvh, ray), expected) << "octant " << octant;
  }
}

TEST(Bvh8Traverse, SkipsLeavesBeyondTheBestHit) {
  for (int octant = 0; octant < 8; ++octant) {
    const Vec3 diagonal = octantDiagonal(octant);
    const Bvh8 bvh = boxesAlong(diagonal, 600);
    const Ray ray{-2.0 * diagonal, glm::normalize(diagonal)};
    // A hit in the middle of box 5 leaves only the boxes up to 5 to visit:
    // box 6 starts farther along the ray.
    const double hitAt = glm::length(diagonal * 15.0 + 2.0 * diagonal);
    const std::vector<std::uint32_t> expected{0, 1, 2, 3, 4, 5};
    EXPECT_EQ(leavesVisited(bvh, ray, 5, hitAt), expected) << "octant " << octant;
  }
}

// Every node's order for each octant lists each of its eight slots once.
TEST(Bvh8Traverse, ChildOrdersArePermutationsOfTheSlots) {
  const Bvh8 bvh = boxesAlong(Vec3(1.0, 0.5, -0.25), 500);
  ASSERT_GT(bvh.nodes.size(), 8u);
  for (const Bvh8Node& node : bvh.nodes)
    for (int octant = 0; octant < 8; ++octant) {
      unsigned seen = 0;
      for (int k = 0; k < kBvhWidth; ++k) seen |= 1u << (node.childOrder(octant) >> (3 * k) & 7);
      EXPECT_EQ(seen, 0xffu) << "octant " << octant;
    }
}

}  // namespace
}  // namespace meshtrace
