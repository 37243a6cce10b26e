// Triangle normals and angle-weighted vertex normals, against hand-computed
// cases, and the Mesh that holds them.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "meshtrace/geometry/mesh.h"
#include "meshtrace/geometry/triangle.h"

namespace meshtrace {
namespace {

constexpr double kTol = 1e-12;

void expectNear(const Vec3& actual, const Vec3& expected, double tol = kTol) {
  EXPECT_NEAR(actual.x, expected.x, tol) << "x";
  EXPECT_NEAR(actual.y, expected.y, tol) << "y";
  EXPECT_NEAR(actual.z, expected.z, tol) << "z";
}

std::vector<Vec3> triangleNormalsOf(const MeshData& mesh) {
  std::vector<Vec3> normals;
  for (const TriangleIndices& t : mesh.triangles)
    normals.push_back(
        triangleNormal(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]));
  return normals;
}

std::vector<Vec3> vertexNormalsOf(const MeshData& mesh) { return angleWeightedVertexNormals(mesh); }

// The unit cube [0,1]^3, each face split by one diagonal, wound so that
// (B - A) x (C - A) points outward. Corners on a face's diagonal see two 45°
// triangles of it, the other corners one 90° triangle.
MeshData unitCube() {
  MeshData cube;
  for (int i = 0; i < 8; ++i) cube.vertices.push_back(Vec3(i & 1, (i >> 1) & 1, (i >> 2) & 1));
  // Vertex index = x + 2y + 4z.
  cube.triangles = {
      {0, 2, 3}, {0, 3, 1},  // z = 0, normal -z
      {4, 5, 7}, {4, 7, 6},  // z = 1, normal +z
      {0, 1, 5}, {0, 5, 4},  // y = 0, normal -y
      {2, 6, 7}, {2, 7, 3},  // y = 1, normal +y
      {0, 4, 6}, {0, 6, 2},  // x = 0, normal -x
      {1, 3, 7}, {1, 7, 5},  // x = 1, normal +x
  };
  return cube;
}

TEST(TriangleNormal, FollowsTheWindingRightHanded) {
  const Vec3 a(0, 0, 0), b(2, 0, 0), c(0, 3, 0);
  expectNear(triangleNormal(a, b, c), Vec3(0, 0, 1));
  expectNear(triangleNormal(a, c, b), Vec3(0, 0, -1));
}

TEST(TriangleNormal, IsUnitLengthForAnyScale) {
  expectNear(triangleNormal(Vec3(1e-6, 0, 0), Vec3(0, 1e-6, 0), Vec3(0, 0, 1e-6)),
             Vec3(1.0 / std::sqrt(3.0)));
  expectNear(triangleNormal(Vec3(1e6, 0, 0), Vec3(0, 1e6, 0), Vec3(0, 0, 1e6)),
             Vec3(1.0 / std::sqrt(3.0)));
}

TEST(TriangleNormal, IsZeroNotNanForDegenerateTriangles) {
  EXPECT_EQ(triangleNormal(Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(2, 2, 2)), Vec3(0.0)) << "collinear";
  EXPECT_EQ(triangleNormal(Vec3(1, 2, 3), Vec3(1, 2, 3), Vec3(0, 1, 0)), Vec3(0.0)) << "repeated";
  EXPECT_EQ(triangleNormal(Vec3(4), Vec3(4), Vec3(4)), Vec3(0.0)) << "a point";
}

// hasNormal stands for triangleNormal(...) != 0 at every scale: where the
// cross product's squared length underflows or overflows too, and where
// the cross product itself does.
TEST(TriangleNormal, HasNormalExactlyWhenTheNormalIsNotZeroAtEveryScale) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int withNormal = 0, without = 0;
  for (int exponent = -330; exponent <= 310; ++exponent) {
    const double scale = std::pow(10.0, exponent);
    for (int k = 0; k < 8; ++k) {
      const Vec3 a(unit(rng), unit(rng), unit(rng)), b(unit(rng), unit(rng), unit(rng)),
          c(unit(rng), unit(rng), unit(rng));
      const Vec3 sa = a * scale, sb = b * scale, sc = c * scale;
      const bool expected = triangleNormal(sa, sb, sc) != Vec3(0.0);
      ASSERT_EQ(hasNormal(sa, sb, sc), expected) << "scale 1e" << exponent << ", triangle " << k;
      (expected ? withNormal : without) += 1;
    }
  }
  EXPECT_EQ(hasNormal(Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(2, 2, 2)), false) << "collinear";
  // Both answers occur: a cross product of size scale^2 is finite and not
  // zero for scales of about 1e-161 to 1e153.
  EXPECT_GT(withNormal, 2400);
  EXPECT_GT(without, 2400);
}

// A triangle's normal and corner angles do not depend on its size, from
// edges of 1e-150 to 1e150, where the squares of its edges and of its
// area under- and overflow.
TEST(TriangleNormal, AndCornerAnglesAreTheSameAtEveryScale) {
  const Vec3 a(0.3, -0.2, 0.1), b(1.1, 0.4, -0.3), c(-0.2, 0.9, 0.6);
  const Vec3 normal = triangleNormal(a, b, c), angles = cornerAngles(a, b, c);
  for (int exponent = -150; exponent <= 150; exponent += 10) {
    const double s = std::pow(10.0, exponent);
    expectNear(triangleNormal(a * s, b * s, c * s), normal, 1e-14);
    expectNear(cornerAngles(a * s, b * s, c * s), angles, 1e-14);
  }
}

TEST(CornerAngles, SumToPiAndMatchARightTriangle) {
  const Vec3 angles = cornerAngles(Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0));
  EXPECT_NEAR(angles[0], std::numbers::pi / 2, kTol);
  EXPECT_NEAR(angles[1], std::numbers::pi / 4, kTol);
  EXPECT_NEAR(angles[2], std::numbers::pi / 4, kTol);
}

// The angle at corner `at` of (at, p, q) from the same formula carried out
// in long double (64-bit significand): differences of nearby coordinates
// are exact there, and the cross product keeps 11 more bits through the
// cancellation of a thin corner.
long double referenceAngle(const Vec3& at, const Vec3& p, const Vec3& q) {
  using L = long double;
  const L u[3] = {L(p.x) - at.x, L(p.y) - at.y, L(p.z) - at.z};
  const L v[3] = {L(q.x) - at.x, L(q.y) - at.y, L(q.z) - at.z};
  const L c[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  return std::atan2(std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]),
                    u[0] * v[0] + u[1] * v[1] + u[2] * v[2]);
}

// A needle in a random direction: its tip's two long edges cross almost
// parallel, where their own cross product cancels to ~1e-8 of its terms.
// Each corner's angle must keep its relative accuracy: the tip's weight in
// its vertex normal is that angle.
TEST(CornerAngles, KeepTheirDigitsAtANeedlesTip) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  const auto randomVector = [&] { return Vec3(coordinate(rng), coordinate(rng), coordinate(rng)); };
  double worst = 0.0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 tip = randomVector(), b = randomVector();
    const Vec3 c = b + 1e-8 * randomVector();
    const Vec3 corners[3] = {tip, b, c};
    const Vec3 angles = cornerAngles(tip, b, c);
    for (int k = 0; k < 3; ++k) {
      const long double expected =
          referenceAngle(corners[k], corners[(k + 1) % 3], corners[(k + 2) % 3]);
      worst = std::max(worst, static_cast<double>(std::fabs(angles[k] - expected) / expected));
    }
  }
  EXPECT_LT(worst, 1e-8) << "largest relative error of a corner angle";
}

TEST(CornerAngles, SumToPiForAnyShape) {
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  for (int i = 0; i < 1000; ++i) {
    const Vec3 a(coordinate(rng), coordinate(rng), coordinate(rng));
    const Vec3 b(coordinate(rng), coordinate(rng), coordinate(rng));
    const Vec3 c = i % 2 ? Vec3(coordinate(rng), coordinate(rng), coordinate(rng))
                         : a + (b - a) * 0.5 + 1e-7 * Vec3(coordinate(rng), 0.0, 0.0);
    const Vec3 angles = cornerAngles(a, b, c);
    EXPECT_NEAR(angles[0] + angles[1] + angles[2], std::numbers::pi, 1e-14) << i;
    for (int k = 0; k < 3; ++k) EXPECT_GE(angles[k], 0.0) << i;
  }
}

TEST(CornerAngles, AreZeroWhereAnEdgeHasNoLength) {
  EXPECT_EQ(cornerAngles(Vec3(4), Vec3(4), Vec3(4)), Vec3(0.0));
  const Vec3 collinear = cornerAngles(Vec3(0, 0, 0), Vec3(1, 1, 1), Vec3(2, 2, 2));
  EXPECT_EQ(collinear[0], 0.0);
  EXPECT_NEAR(collinear[1], std::numbers::pi, 1e-15);
  EXPECT_EQ(collinear[2], 0.0);
}

TEST(VertexNormals, CubeTriangleNormalsPointOutward) {
  const MeshData cube = unitCube();
  const std::vector<Vec3> normals = triangleNormalsOf(cube);
  for (std::size_t i = 0; i < cube.triangles.size(); ++i) {
    const auto& t = cube.triangles[i];
    const Vec3 centroid = (cube.vertices[t[0]] + cube.vertices[t[1]] + cube.vertices[t[2]]) / 3.0;
    EXPECT_GT(glm::dot(normals[i], centroid - Vec3(0.5)), 0.0) << "triangle " << i;
    EXPECT_NEAR(maxAbsComponent(normals[i]), 1.0, kTol) << "axis-aligned face, triangle " << i;
  }
}

// Every cube corner meets three faces at 90° each, whether a face reaches it
// with one 90° triangle or two 45° ones: the angle-weighted normal is the
// diagonal. An unweighted average would lean toward the split faces.
TEST(VertexNormals, CubeCornerIsTheDiagonalWhateverTheTriangulation) {
  const MeshData cube = unitCube();
  const std::vector<Vec3> normals = vertexNormalsOf(cube);
  for (std::size_t v = 0; v < cube.vertices.size(); ++v)
    expectNear(normals[v], glm::normalize(cube.vertices[v] - Vec3(0.5)));
}

TEST(VertexNormals, AFlatFanGivesEveryVertexThePlaneNormal) {
  MeshData fan;
  fan.vertices.push_back(Vec3(0, 0, 2));
  constexpr int kSides = 7;  // unequal angles at the rim on purpose
  for (int i = 0; i < kSides; ++i) {
    const double a = 2 * std::numbers::pi * i / kSides + 0.1 * i * i;
    fan.vertices.push_back(Vec3(std::cos(a), std::sin(a), 2));
  }
  for (std::uint32_t i = 0; i < kSides; ++i)
    fan.triangles.push_back({0, i + 1, (i + 1) % kSides + 1});
  for (const Vec3& n : vertexNormalsOf(fan)) expectNear(n, Vec3(0, 0, 1));
}

TEST(VertexNormals, DegenerateTrianglesContributeNothingAndGiveNoNan) {
  MeshData mesh;
  mesh.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(2, 0, 0), Vec3(5, 5, 5)};
  mesh.triangles = {
      {0, 1, 2},  // the real triangle, normal +z
      {0, 1, 3},  // collinear: zero area
      {1, 1, 2},  // a repeated corner
      {4, 4, 4},  // a point, and the only triangle of vertex 4
  };
  const std::vector<Vec3> normals = vertexNormalsOf(mesh);
  for (int v = 0; v < 3; ++v) expectNear(normals[v], Vec3(0, 0, 1));
  EXPECT_EQ(normals[3], Vec3(0.0)) << "a vertex only on a degenerate triangle has no normal";
  EXPECT_EQ(normals[4], Vec3(0.0));
  for (const Vec3& n : normals) EXPECT_TRUE(isFinite(n));
}

// A triangle listed again, in any vertex order or winding, adds nothing:
// the normals are those of the mesh without the repeats.
TEST(VertexNormals, ATriangleListedTwiceCountsOnce) {
  MeshData once;
  once.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 1, 1), Vec3(1, 1, 0)};
  once.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 4, 2}};
  MeshData repeated = once;
  repeated.triangles.insert(repeated.triangles.begin() + 1, {2, 0, 1});  // rotated
  repeated.triangles.push_back({3, 2, 0});                               // reversed
  repeated.triangles.push_back({0, 1, 2});                               // a third copy
  repeated.triangles.push_back({0, 1, 4});  // shares a corner set with no other
  once.triangles.push_back({0, 1, 4});
  const std::vector<Vec3> expected = vertexNormalsOf(once);
  const std::vector<Vec3> normals = vertexNormalsOf(repeated);
  ASSERT_EQ(normals.size(), expected.size());
  for (std::size_t v = 0; v < normals.size(); ++v) EXPECT_EQ(normals[v], expected[v]) << v;
}

// A 200 x 200 grid of vertices on a wave, 79,202 triangles: several of the
// chunks the corner angles are taken in.
MeshData wavyGrid() {
  MeshData grid;
  constexpr std::uint32_t kSide = 200;
  for (std::uint32_t y = 0; y < kSide; ++y)
    for (std::uint32_t x = 0; x < kSide; ++x)
      grid.vertices.push_back(Vec3(x, y, std::sin(0.3 * x) * std::cos(0.2 * y)));
  for (std::uint32_t y = 0; y + 1 < kSide; ++y)
    for (std::uint32_t x = 0; x + 1 < kSide; ++x) {
      const std::uint32_t v = y * kSide + x;
      grid.triangles.push_back({v, v + 1, v + kSide + 1});
      grid.triangles.push_back({v, v + kSide + 1, v + kSide});
    }
  return grid;
}

// The corner angles are taken in parallel, in chunks: a mesh larger than a
// chunk must get the normals of the one-triangle-at-a-time sum, bit for bit.
TEST(VertexNormals, ALargeMeshGetsTheSameNormalsAsTheSerialSum) {
  const MeshData grid = wavyGrid();
  const std::vector<Vec3> triangleNormals = triangleNormalsOf(grid);
  std::vector<Vec3> serial(grid.vertices.size(), Vec3(0.0));
  for (std::size_t i = 0; i < grid.triangles.size(); ++i) {
    const auto& t = grid.triangles[i];
    const Vec3 w = cornerAngles(grid.vertices[t[0]], grid.vertices[t[1]], grid.vertices[t[2]]);
    for (int k = 0; k < 3; ++k) serial[t[k]] += w[k] * triangleNormals[i];
  }
  const std::vector<Vec3> normals = angleWeightedVertexNormals(grid);
  for (std::size_t v = 0; v < normals.size(); ++v)
    ASSERT_EQ(normals[v], serial[v] / glm::length(serial[v])) << v;
}

// The sums take every triangle first and remake those of a repeat's
// corners: across many chunks, the normals must still be those of the mesh
// without the repeats, bit for bit.
TEST(VertexNormals, ALargeMeshWithRepeatsGetsTheNormalsOfTheMeshWithout) {
  const MeshData once = wavyGrid();
  MeshData repeated;
  repeated.vertices = once.vertices;
  for (std::size_t i = 0; i < once.triangles.size(); ++i) {
    const TriangleIndices& t = once.triangles[i];
    repeated.triangles.push_back(t);
    if (i % 997 == 0) repeated.triangles.push_back({t[2], t[1], t[0]});  // reversed, next
  }
  for (std::size_t i = 500; i < once.triangles.size(); i += 1009)
    repeated.triangles.push_back(once.triangles[i]);  // again, at the end
  const std::vector<Vec3> expected = vertexNormalsOf(once);
  const std::vector<Vec3> normals = vertexNormalsOf(repeated);
  for (std::size_t v = 0; v < normals.size(); ++v) ASSERT_EQ(normals[v], expected[v]) << v;
}

TEST(VertexNormals, WeighEachTriangleByItsAngleAtTheVertex) {
  // Two triangles meet at vertex 0: one in the z = 0 plane with a 90° corner
  // there, one in the x = 0 plane with a 45° corner.
  MeshData mesh;
  mesh.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 1, 1)};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  const std::vector<Vec3> normals = vertexNormalsOf(mesh);
  const Vec3 expected =
      glm::normalize(std::numbers::pi / 2 * Vec3(0, 0, 1) + std::numbers::pi / 4 * Vec3(1, 0, 0));
  expectNear(normals[0], expected);
}

TEST(Mesh, FlatMeshesComputeNoVertexNormals) {
  const Mesh mesh("cube.off", unitCube(), Shading::Flat, Material{});
  EXPECT_TRUE(mesh.vertexNormals().empty());
  const std::vector<Vec3> expected = triangleNormalsOf(unitCube());
  for (std::uint32_t i = 0; i < 12; ++i) EXPECT_EQ(mesh.flatNormal(i), expected[i]) << i;
  expectNear(mesh.shadingNormal(0, 0.3, 0.3), Vec3(0, 0, -1));
}

TEST(Mesh, PhongMeshesInterpolateVertexNormals) {
  const Mesh mesh("cube.off", unitCube(), Shading::Phong, Material{});
  ASSERT_EQ(mesh.vertexNormals().size(), 8u);
  // Triangle {0, 2, 3}: at its corner 0 (beta = gamma = 0) the shading
  // normal is the vertex normal of corner 0.
  expectNear(mesh.shadingNormal(0, 0.0, 0.0), glm::normalize(Vec3(-1, -1, -1)));
  const Vec3 mid = mesh.shadingNormal(0, 0.5, 0.0);  // halfway from vertex 0 to vertex 2
  expectNear(mid,
             glm::normalize(glm::normalize(Vec3(-1, -1, -1)) + glm::normalize(Vec3(-1, 1, -1))));
}

TEST(Mesh, SwitchingToPhongComputesTheVertexNormals) {
  Mesh mesh("cube.off", unitCube(), Shading::Flat, Material{});
  mesh.setShading(Shading::Phong);
  EXPECT_EQ(mesh.vertexNormals().size(), 8u);
}

TEST(Mesh, ACopySwitchedToPhongSharesTheArraysAndLeavesTheOriginalFlat) {
  const Mesh flat("cube.off", unitCube(), Shading::Flat, Material{});
  Mesh copy = flat;
  copy.setShading(Shading::Phong);
  EXPECT_EQ(copy.vertices().data(), flat.vertices().data());
  EXPECT_EQ(copy.triangles().data(), flat.triangles().data());
  EXPECT_EQ(copy.vertexNormals().size(), 8u);
  EXPECT_EQ(flat.shading(), Shading::Flat);
  EXPECT_TRUE(flat.vertexNormals().empty());
  expectNear(flat.shadingNormal(0, 0.0, 0.0), Vec3(0, 0, -1));
  expectNear(copy.shadingNormal(0, 0.0, 0.0), glm::normalize(Vec3(-1, -1, -1)));
}

TEST(Mesh, BoundsAreTheBoxOfTheVertices) {
  MeshData data;
  data.vertices = {Vec3(1, -2, 3), Vec3(-4, 5, 0.5), Vec3(0, 0, -6)};
  data.triangles = {{0, 1, 2}};
  const Mesh mesh("t.off", data, Shading::Flat, Material{});
  EXPECT_EQ(mesh.bounds().min, Vec3(-4, -2, -6));
  EXPECT_EQ(mesh.bounds().max, Vec3(1, 5, 3));
}

}  // namespace
}  // namespace meshtrace
