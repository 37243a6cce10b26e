// The binned SAH build of the binary BVH (binary_bvh): every primitive in
// exactly one leaf, every box inside its parent's, every primitive inside its
// leaf's box, whether the splits come from all of a node's primitives or a
// sample of them, over one set of boxes or meshes' trees joined under one;
// the same tree on one thread as on all; small leaves though boxes coincide;
// of a set of exact copies of a triangle, only the two lowest in leaves.
#include "accel/binary_bvh.h"

#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cstdint>
#include <random>
#include <vector>

#include "accel/triangle_copies.h"
#include "accel/triangle_set.h"
#include "meshtrace/geometry/mesh_generators.h"
#include "support/meshes.h"

namespace meshtrace {
namespace {

using test::makeMesh;
using test::triangleBoxes;

// Whether box b lies within a node's float bounds (min x y z, max x y z).
bool inside(const Aabb& b, const float* n) {
  return n[0] <= b.min.x && n[1] <= b.min.y && n[2] <= b.min.z && n[3] >= b.max.x &&
         n[4] >= b.max.y && n[5] >= b.max.z;
}

void expectEveryPrimitiveOnceInsideNestedBoxes(const Bvh& bvh, const std::vector<Aabb>& boxes) {
  ASSERT_FALSE(bvh.empty());
  EXPECT_LE(bvh.depth, kMaxBvhDepth);
  std::vector<int> seen(boxes.size(), 0);
  for (const BvhNode& node : bvh.nodes) {
    if (node.isLeaf()) {
      EXPECT_LE(node.count, 4u);
      for (std::uint32_t k = node.first; k < node.first + node.count; ++k) {
        ++seen[bvh.order[k]];
        EXPECT_TRUE(inside(boxes[bvh.order[k]], node.bounds));
      }
      continue;
    }
    for (std::uint32_t c : {node.first, node.first + 1}) {
      const float* b = bvh.nodes[c].bounds;
      const Aabb child{Vec3(b[0], b[1], b[2]), Vec3(b[3], b[4], b[5])};
      EXPECT_TRUE(inside(child, node.bounds));
    }
  }
  for (int s : seen) ASSERT_EQ(s, 1);
}

TEST(BinaryBvhBuild, LeavesCoverEveryPrimitiveOnceInsideNestedBoxes) {
  const std::vector<Aabb> boxes = triangleBoxes(makeTorusKnot(Vec3(0.0), 1.0, 3, 5, 0.2, 400, 12));
  expectEveryPrimitiveOnceInsideNestedBoxes(buildBvh(boxes), boxes);
}

// Large nodes choose their split from a sample of their primitives; the
// boxes of their children must still hold the primitives left out of it.
// Here one box in fifty reaches far out, and the sample cannot see them all.
TEST(BinaryBvhBuild, SplitsChosenFromASampleStillGiveBoxesHoldingEveryPrimitive) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Aabb> boxes(100000);
  for (Aabb& b : boxes) {
    const Vec3 p(unit(rng), unit(rng), unit(rng));
    const double reach = unit(rng) < 0.02 ? 5.0 * unit(rng) : 0.001;
    b = {p, p + Vec3(0.001, reach, 0.001)};
  }
  expectEveryPrimitiveOnceInsideNestedBoxes(buildBvh(boxes), boxes);
}

// Several meshes: their trees are built apart and joined under one over
// the meshes' boxes. Walking the joined tree from its root reaches every
// triangle of the set exactly once, each inside its leaf's box, every box
// inside its parent's.
TEST(BinaryBvhBuild, JoinedMeshTreesReachEveryTriangleOnce) {
  const std::vector<Mesh> meshes = {
      makeMesh("knot", makeTorusKnot(Vec3(0.0), 1.0, 3, 5, 0.2, 200, 12)),
      makeMesh("ball", makeIcosphere(Vec3(0.5, 0.0, 0.0), 0.7, 3)),  // overlaps the knot
      makeMesh("box", makeGriddedBox(Vec3(3.0), Vec3(4.0), 3)),
      makeMesh("twin", makeGriddedBox(Vec3(3.0), Vec3(4.0), 3))};  // the same box again
  TriangleSet set;
  for (std::uint32_t i = 0; i < meshes.size(); ++i) set.add(meshes[i], i);
  const Bvh bvh = buildBvh(set, {.leafBlock = 4});
  ASSERT_FALSE(bvh.empty());
  EXPECT_LE(bvh.depth, kMaxBvhDepth);
  std::vector<int> seen(set.size(), 0);
  std::vector<std::uint32_t> stack = {0};
  while (!stack.empty()) {
    const BvhNode& node = bvh.nodes[stack.back()];
    stack.pop_back();
    if (node.isLeaf()) {
      EXPECT_LE(node.count, 4u);
      for (std::uint32_t k = node.first; k < node.first + node.count; ++k) {
        const std::uint32_t id = bvh.order[k];
        ASSERT_LT(id, set.size());
        ++seen[id];
        const TriangleSet::Member t = set[id];
        Aabb box;
        for (std::uint32_t v : t.mesh->triangles()[t.triangle]) box.extend(t.mesh->vertices()[v]);
        EXPECT_TRUE(inside(box, node.bounds)) << "triangle " << id;
      }
      continue;
    }
    for (std::uint32_t c : {node.first, node.first + 1}) {
      const float* b = bvh.nodes[c].bounds;
      EXPECT_TRUE(inside({Vec3(b[0], b[1], b[2]), Vec3(b[3], b[4], b[5])}, node.bounds));
      stack.push_back(c);
    }
  }
  for (std::size_t id = 0; id < seen.size(); ++id) ASSERT_EQ(seen[id], 1) << "triangle " << id;
}

// The build is parallel, but the tree does not depend on the thread count.
TEST(BinaryBvhBuild, SameTreeOnOneThreadAsOnAll) {
  const MeshData ball = makeIcosphere(Vec3(0.0), 1.0, 6);  // 82k triangles
  const std::vector<Aabb> boxes = triangleBoxes(ball);
  const Bvh all = buildBvh(boxes);
  Bvh one;
  tbb::task_arena(1).execute([&] { one = buildBvh(boxes); });
  EXPECT_EQ(all.nodes.size(), one.nodes.size());
  EXPECT_EQ(all.depth, one.depth);
  EXPECT_TRUE(all.order == one.order);
}

// Copies share their box, so nothing but their index tells them apart: of
// each set, the two lowest indices are in exactly one leaf each and the
// others, the spares, in none; every other triangle, the other corner
// orders and the one-ulp neighbour among them, is in exactly one leaf.
TEST(BinaryBvhBuild, CopiesLeaveOnlyTheTwoLowestOfEachSetInLeaves) {
  const Mesh mesh = makeMesh("copies", test::withCopies(makeIcosphere(Vec3(0.0), 1.0, 1), 1, 6));
  TriangleSet set;
  set.add(mesh, 0);
  const Bvh bvh = buildBvh(set, {.leafBlock = 4});
  std::vector<int> seen(set.size(), 0);
  for (const BvhNode& node : bvh.nodes)
    if (node.isLeaf())
      for (std::uint32_t k = node.first; k < node.first + node.count; ++k) ++seen[bvh.order[k]];
  std::vector<std::uint32_t> all(set.size());
  for (std::uint32_t i = 0; i < all.size(); ++i) all[i] = i;
  const std::vector<char> spare = markSpareCopies(mesh, all);
  std::size_t spares = 0;
  for (std::size_t i = 0; i < seen.size(); ++i) {
    ASSERT_EQ(seen[i], spare[i] ? 0 : 1) << "triangle " << i;
    spares += spare[i];
  }
  EXPECT_EQ(spares, 80u * 11);  // twelve copies of each of the 80 triangles
  EXPECT_EQ(bvh.copiesLeftOut, spares);
}

TEST(BinaryBvhBuild, CoincidentBoxesStillGiveSmallLeaves) {
  const std::vector<Aabb> boxes(1000, Aabb{Vec3(1.0), Vec3(2.0)});
  const Bvh bvh = buildBvh(boxes);
  for (const BvhNode& node : bvh.nodes)
    if (node.isLeaf()) {
      EXPECT_LE(node.count, 4u);
    }
  EXPECT_LE(bvh.depth, 12);
}

}  // namespace
}  // namespace meshtrace
