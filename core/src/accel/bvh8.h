#pragma once
// An 8-wide BVH: each node holds the float boxes of up to eight children in
// structure-of-arrays form, so that two SSE slab tests check all eight
// (slab_ray.h, traverse.h). Made by collapsing a binary Bvh. Eight children per
// node rather than four leave a third fewer levels to descend, and a ray's
// time goes mostly into that chain of dependent node visits.
#include <cstdint>
#include <vector>

#include "accel/binary_bvh.h"
#include "util/build_vector.h"

namespace meshtrace {

inline constexpr int kBvhWidth = 8;

// 256 bytes, four cache lines. An unused slot has an empty box
// (lo = +inf, hi = -inf), which no ray meets.
struct alignas(64) Bvh8Node {
  float lo[3][kBvhWidth];  // [axis][child]
  float hi[3][kBvhWidth];
  std::uint32_t first[kBvhWidth];  // interior child: node index; leaf: start in Bvh8::order
  std::uint8_t count[kBvhWidth];   // 0 for an interior child, else primitives in the leaf
  // For each octant of ray directions (bit a: d[a] < 0), the slots of the
  // children from nearest to farthest along the octant's diagonal: eight
  // 3-bit slots in three bytes, nearest in the lowest bits. The traversal
  // visits children in this order instead of sorting their entry distances.
  std::uint8_t order[8][3];

  // The child order for octant `octant`, as 24 bits.
  [[gnu::always_inline]] std::uint32_t childOrder(int octant) const {
    const std::uint8_t* o = order[octant];
    return o[0] | static_cast<std::uint32_t>(o[1]) << 8 | static_cast<std::uint32_t>(o[2]) << 16;
  }
};
static_assert(sizeof(Bvh8Node) == 256);

// The largest leaf a node can point to (count is a byte).
inline constexpr std::uint32_t kMaxBvh8Leaf = 255;

struct Bvh8 {
  BuildVector<Bvh8Node> nodes;       // nodes[0] is the root, unless the root is a leaf
  std::vector<std::uint32_t> order;  // primitive indices, grouped by leaf
  std::uint32_t rootCount = 0;       // primitives when the whole tree is one leaf
  // The root's box, (x, y, z, z) each, for testing a root leaf in one go.
  alignas(16) float rootLo[4] = {0, 0, 0, 0};
  alignas(16) float rootHi[4] = {0, 0, 0, 0};
  int depth = 0;

  bool empty() const { return nodes.empty() && rootCount == 0; }
  std::size_t bytes() const {
    return nodes.size() * sizeof(Bvh8Node) + order.size() * sizeof(std::uint32_t);
  }
};

// A leaf of a Bvh8: its primitives are order[first, first + count) (in a
// triangle BVH, whose order the blocks replace, `first` places its block).
struct Bvh8Leaf {
  std::uint32_t first, count;
};
// Every leaf of `tree`, node by node (the root, when the tree is one leaf).
std::vector<Bvh8Leaf> leavesOf(const Bvh8& tree);

// Keeps the binary tree's leaves and makes 8-wide nodes of the binary nodes
// whose boxes' areas sum to the least (bvh8.cpp), each node taking the
// leaves and 8-wide nodes below it as its up to eight children.
// Throws std::length_error for a leaf larger than kMaxBvh8Leaf. Takes the
// binary tree by value: its primitive order moves into the result.
Bvh8 collapseToBvh8(Bvh binary);

}  // namespace meshtrace
