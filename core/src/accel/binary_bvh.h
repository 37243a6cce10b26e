#pragma once
// A bounding volume hierarchy over a set of primitive boxes: the layout and
// its binned SAH build. Used twice per scene: over the triangles of its
// meshes, and over its objects (spheres, cylinders, small meshes and that
// triangle BVH).
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "meshtrace/accel/trace_options.h"
#include "meshtrace/geometry/aabb.h"
#include "util/build_vector.h"

namespace meshtrace {

class TriangleSet;

// 32 bytes: a box in float, rounded outward so that it holds its primitives
// exactly, and either two adjacent children or a range of primitives. The
// traversal uses the 8-wide form made from it (bvh8.h).
struct BvhNode {
  float bounds[6];      // min x y z, max x y z
  std::uint32_t first;  // interior: index of the left child (right = first + 1);
                        // leaf: first entry of the leaf's range in Bvh::order
  std::uint32_t count;  // 0 for an interior node, else primitives in the leaf

  bool isLeaf() const { return count != 0; }
};
static_assert(sizeof(BvhNode) == 32);

struct Bvh {
  BuildVector<BvhNode> nodes;        // nodes[0] is the root; empty for no primitives
  std::vector<std::uint32_t> order;  // primitive indices, grouped by leaf
  int depth = 0;                     // longest root-to-leaf path (root = 1)
  // Triangles no leaf holds, each a copy of two that leaves hold
  // (triangle_copies.h); their slots in `order` are unused.
  std::uint32_t copiesLeftOut = 0;

  bool empty() const { return nodes.empty(); }
  std::size_t bytes() const {
    return nodes.size() * sizeof(BvhNode) + order.size() * sizeof(std::uint32_t);
  }
};

// Binned SAH (Wald, "On fast construction of SAH-based bounding volume
// hierarchies", 2007): at each node, primitives are sorted into bins by
// centroid along each axis and the cheapest bin boundary by the surface area
// heuristic is taken; a node becomes a leaf when that is cheaper and it holds
// at most maxLeafSize primitives. Large nodes are binned and both subtrees
// built in parallel; the largest choose their split from a strided sample
// of their primitives (binary_bvh.cpp). The tree does not depend on the
// thread count, though the numbering of its nodes may.
Bvh buildBvh(std::span<const Aabb> boxes, const BvhBuildOptions& options = {});
// The same over the triangles of a set of meshes (primitive i = triangle i
// of the set), their boxes taken straight from the vertices: no array of
// double boxes (48 bytes a triangle) to fill and read back. With several
// meshes, each mesh's tree is built on its own, in parallel, and the trees
// are joined under a tree over the meshes' boxes. Of a set of copies of a
// triangle in one mesh, only the two lowest indices are in leaves.
Bvh buildBvh(const TriangleSet& triangles, const BvhBuildOptions& options = {});

// The largest depth a built tree can have (traversal stacks are this deep).
inline constexpr int kMaxBvhDepth = 128;

}  // namespace meshtrace
