// The collapse of the binary BVH into the 8-wide one (bvh8): the wide tree
// keeps every leaf, each inside the box its parent holds for it, and of all
// the ways to make binary nodes 8-wide nodes it takes the one with the least
// sum of node areas.
#include "accel/bvh8.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

#include "accel/binary_bvh.h"
#include "meshtrace/geometry/mesh_generators.h"
#include "meshtrace/util/math.h"
#include "support/meshes.h"

namespace meshtrace {
namespace {

using test::triangleBoxes;

// Collapsing keeps every leaf, and every child box holds its node's boxes.
TEST(Bvh8Collapse, KeepsEveryLeafInsideItsBox) {
  const MeshData knot = makeTorusKnot(Vec3(0.0), 1.0, 3, 5, 0.2, 300, 10);
  const std::vector<Aabb> boxes = triangleBoxes(knot);
  const Bvh8 bvh = collapseToBvh8(buildBvh(boxes));
  ASSERT_FALSE(bvh.nodes.empty());
  std::vector<int> seen(boxes.size(), 0);
  // Walk from the root, checking each child against the box it came with.
  struct Item {
    std::uint32_t node;
    Aabb box;
  };
  std::vector<Item> todo{{0, Aabb{Vec3(-kInfinity), Vec3(kInfinity)}}};
  std::size_t visited = 0;
  while (!todo.empty()) {
    const Item item = todo.back();
    todo.pop_back();
    ++visited;
    const Bvh8Node& node = bvh.nodes[item.node];
    for (int i = 0; i < kBvhWidth; ++i) {
      const Aabb child{Vec3(node.lo[0][i], node.lo[1][i], node.lo[2][i]),
                       Vec3(node.hi[0][i], node.hi[1][i], node.hi[2][i])};
      if (child.empty()) continue;  // an unused slot
      EXPECT_TRUE(glm::all(glm::lessThanEqual(item.box.min, child.min)) &&
                  glm::all(glm::lessThanEqual(child.max, item.box.max)));
      if (node.count[i] == 0) {
        todo.push_back({node.first[i], child});
        continue;
      }
      for (std::uint32_t k = node.first[i]; k < node.first[i] + node.count[i]; ++k) {
        ++seen[bvh.order[k]];
        const Aabb& b = boxes[bvh.order[k]];
        EXPECT_TRUE(glm::all(glm::lessThanEqual(child.min, b.min)) &&
                    glm::all(glm::lessThanEqual(b.max, child.max)));
      }
    }
  }
  EXPECT_EQ(visited, bvh.nodes.size());
  for (int s : seen) ASSERT_EQ(s, 1);
}

double halfAreaOf(const float* lo, const float* hi) {
  const double x = double{hi[0]} - lo[0], y = double{hi[1]} - lo[1], z = double{hi[2]} - lo[2];
  return x * y + y * z + z * x;
}

// The least sum of the half-areas of the binary nodes made 8-wide nodes, by
// trying every set of interior nodes that holds the root and leaves each of
// them at most eight children (the leaves and chosen nodes first met below).
double leastWideNodeArea(const Bvh& binary) {
  std::vector<std::uint32_t> interior;
  for (std::uint32_t i = 0; i < binary.nodes.size(); ++i)
    if (!binary.nodes[i].isLeaf()) interior.push_back(i);
  std::vector<int> bit(binary.nodes.size(), -1);
  for (std::size_t k = 0; k < interior.size(); ++k) bit[interior[k]] = static_cast<int>(k);
  double best = kInfinity;
  for (std::uint32_t chosen = 1; chosen < (1u << interior.size()); chosen += 2) {  // root: bit 0
    bool fits = true;
    double area = 0.0;
    for (std::size_t k = 0; k < interior.size() && fits; ++k) {
      if (!(chosen >> k & 1)) continue;
      const BvhNode& wide = binary.nodes[interior[k]];
      area += halfAreaOf(wide.bounds, wide.bounds + 3);
      int children = 0;
      std::vector<std::uint32_t> todo{wide.first, wide.first + 1};
      while (!todo.empty() && children <= kBvhWidth) {
        const std::uint32_t c = todo.back();
        todo.pop_back();
        const BvhNode& node = binary.nodes[c];
        if (node.isLeaf() || (chosen >> bit[c] & 1)) {
          ++children;
        } else {
          todo.push_back(node.first);
          todo.push_back(node.first + 1);
        }
      }
      fits = children <= kBvhWidth;
    }
    if (fits) best = std::min(best, area);
  }
  return best;
}

// Which binary nodes become 8-wide nodes is a choice; the collapse makes the
// one whose nodes' areas sum to the least (the surface area heuristic's
// expected visits), found here by trying every choice on small trees.
TEST(Bvh8Collapse, WideNodesHaveTheLeastAreaSum) {
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(-1.0, 1.0), size(0.01, 0.3);
  for (int tree = 0; tree < 6; ++tree) {
    std::vector<Aabb> boxes;
    for (int k = 0; k < 19; ++k) {
      const Vec3 c(u(rng), u(rng), u(rng) * 0.2), half(size(rng), size(rng), size(rng));
      boxes.push_back(Aabb{c - half, c + half});
    }
    const Bvh binary = buildBvh(boxes, {.maxLeafSize = 1});
    const double least = leastWideNodeArea(binary);
    const Bvh8 wide = collapseToBvh8(binary);
    double sum = halfAreaOf(binary.nodes[0].bounds, binary.nodes[0].bounds + 3);
    for (const Bvh8Node& node : wide.nodes)
      for (int i = 0; i < kBvhWidth; ++i) {
        const float lo[3] = {node.lo[0][i], node.lo[1][i], node.lo[2][i]};
        const float hi[3] = {node.hi[0][i], node.hi[1][i], node.hi[2][i]};
        if (node.count[i] == 0 && lo[0] <= hi[0]) sum += halfAreaOf(lo, hi);  // an 8-wide child
      }
    EXPECT_NEAR(sum, least, 1e-5 * least) << "tree " << tree;
  }
}

}  // namespace
}  // namespace meshtrace
