// Which triangles are exact copies of another (triangle_copies): the same
// corners, bit for bit, in the same order, whatever vertex indices hold
// them; every member of a set is a spare but the two lowest indices,
// wherever they stand in the list; and hashes that collide change nothing.
#include "accel/triangle_copies.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <random>
#include <vector>

#include "meshtrace/geometry/mesh_generators.h"
#include "support/meshes.h"

namespace meshtrace {
namespace {

using test::makeMesh;

// Triangle 0 and what each later one is to it (or to triangle 3).
Mesh mixedMesh() {
  MeshData m;
  m.vertices = {{0.0, 0.0, 1.0},
                {1.0, 0.0, 1.0},
                {0.0, 1.0, 1.0},  // triangle 0
                {0.0, 0.0, 1.0},
                {1.0, 0.0, 1.0},
                {0.0, 1.0, 1.0},                       // the same positions again
                {std::nextafter(0.0, 1.0), 0.0, 1.0},  // 6: one ulp off vertex 0
                {-0.0, 0.0, 1.0}};                     // 7: vertex 0 with x = -0
  m.triangles = {
      {0, 1, 2},  // 0
      {0, 1, 2},  // 1: copy of 0, the same indices
      {3, 4, 5},  // 2: copy of 0, other indices at the same positions
      {1, 2, 0},  // 3: the same corners in another order: not a copy
      {6, 1, 2},  // 4: one ulp apart: not a copy
      {4, 5, 3},  // 5: copy of 3
      {7, 1, 2},  // 6: -0 for +0: not a copy
      {0, 1, 2},  // 7: copy of 0
  };
  return makeMesh("mixed", std::move(m));
}
// The copies of 0 past 0 and 1; 3 and 5 are a set of two.
const std::vector<char> kMixedSpares = {0, 0, 1, 0, 0, 0, 0, 1};

// markSpareCopies over all of a mesh's triangles, listed in a shuffled order,
// with the marks put back in triangle order.
std::vector<char> marksInTriangleOrder(const Mesh& mesh, CornerHash hash, std::uint64_t seed) {
  std::vector<std::uint32_t> list(mesh.triangles().size());
  std::iota(list.begin(), list.end(), 0u);
  std::shuffle(list.begin(), list.end(), std::mt19937_64(seed));
  const std::vector<char> marks =
      hash ? markSpareCopies(mesh, list, hash) : markSpareCopies(mesh, list);
  std::vector<char> byTriangle(list.size());
  for (std::size_t k = 0; k < list.size(); ++k) byTriangle[list[k]] = marks[k];
  return byTriangle;
}

std::uint64_t collidingHash(const CornerBits&) { return 42; }

TEST(TriangleCopies, SameCornersInTheSameOrderBitForBit) {
  const Mesh mesh = mixedMesh();
  for (std::uint32_t t = 1; t < mesh.triangles().size(); ++t) {
    const bool copyOfZero = t == 1 || t == 2 || t == 7;
    EXPECT_EQ(sameCorners(mesh, 0, mesh, t), copyOfZero) << "triangle " << t;
  }
  EXPECT_TRUE(sameCorners(mesh, 3, mesh, 5));
  // Across meshes: positions count, not the mesh.
  const Mesh other = mixedMesh();
  EXPECT_TRUE(sameCorners(mesh, 2, other, 0));
}

TEST(TriangleCopies, SparesAreAllButTheTwoLowestIndicesOfEachSet) {
  const Mesh mesh = mixedMesh();
  for (std::uint64_t seed = 1; seed <= 5; ++seed)
    EXPECT_EQ(marksInTriangleOrder(mesh, nullptr, seed), kMixedSpares) << "seed " << seed;
}

// With every hash equal, the one run of equal hashes holds many distinct
// sets, and the marks must not change.
TEST(TriangleCopies, CollidingHashesGiveTheSameMarks) {
  EXPECT_EQ(marksInTriangleOrder(mixedMesh(), collidingHash, 3), kMixedSpares);
  const Mesh many = makeMesh("many", test::withCopies(makeGrid(Vec3(0.0), 1.0, 4), 1, 2));
  EXPECT_EQ(marksInTriangleOrder(many, collidingHash, 4), marksInTriangleOrder(many, nullptr, 4));
  const std::vector<char> marks = marksInTriangleOrder(many, nullptr, 5);
  // Each of the grid's 32 triangles has four copies, three of them spares.
  EXPECT_EQ(std::count(marks.begin(), marks.end(), 1), 32 * 3);
}

}  // namespace
}  // namespace meshtrace
