#pragma once
// A 4-wide BVH: each node holds the float boxes of up to four children in
// structure-of-arrays form, so one SSE slab test checks all four
// (bvh4_traverse.h). Made by collapsing a binary Bvh.
#include <array>
#include <cstdint>
#include <vector>

#include "meshtrace/bvh.h"

namespace meshtrace {

// 128 bytes. An unused slot has an empty box (lo = +inf, hi = -inf), which
// no ray meets.
struct alignas(64) Bvh4Node {
  float lo[3][4];            // [axis][child]
  float hi[3][4];
  std::uint32_t first[4];    // interior child: node index; leaf: start in Bvh4::order
  std::uint16_t count[4];    // 0 for an interior child, else primitives in the leaf
  // For each octant of ray directions (bit a: d[a] < 0), the children from
  // nearest to farthest along that octant's diagonal, as an index into
  // kChildOrders: the traversal visits children in this order instead of
  // sorting their entry distances (see bvh4_traverse.h).
  std::uint8_t order[8];
};
static_assert(sizeof(Bvh4Node) == 128);

// The 24 orders of four children, each as four 2-bit slots, nearest first.
inline constexpr int kChildOrderCount = 24;
inline constexpr auto kChildOrders = [] {
  std::array<std::uint8_t, kChildOrderCount> orders{};
  int k = 0;
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      for (int c = 0; c < 4; ++c)
        if (a != b && a != c && b != c) orders[k++] = a | b << 2 | c << 4 | (6 - a - b - c) << 6;
  return orders;
}();

struct Bvh4 {
  std::vector<Bvh4Node> nodes;       // nodes[0] is the root, unless the root is a leaf
  std::vector<std::uint32_t> order;  // primitive indices, grouped by leaf
  std::uint32_t rootCount = 0;       // primitives when the whole tree is one leaf
  float rootBounds[6] = {0, 0, 0, 0, 0, 0};
  int depth = 0;

  bool empty() const { return nodes.empty() && rootCount == 0; }
  std::size_t bytes() const {
    return nodes.size() * sizeof(Bvh4Node) + order.size() * sizeof(std::uint32_t);
  }
};

// Each node takes its binary node's two children, then repeatedly replaces
// the interior child of largest surface area by its own two children while
// there is room for four.
Bvh4 collapseToBvh4(const Bvh& binary);

}  // namespace meshtrace
