// Our angle-weighted vertex normals against OpenMesh's half-edge computation,
// on every mesh we have: the seed's (when ../shared/seed exists), our
// scenes' and the tests' own.
#include "crosscheck/normals_crosscheck.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "meshtrace/geometry/mesh_generators.h"
#include "meshtrace/geometry/triangle.h"
#include "meshtrace/io/off_reader.h"
#include "support/paths.h"

namespace meshtrace {
namespace {

namespace fs = std::filesystem;

// Both sides sum the same angles and unit normals in double precision, in
// different orders and through different formulas for the angle (atan2 ours,
// acos OpenMesh's), so they agree to rounding.
constexpr double kMaxDegrees = 1e-9;  // measured: at most 2.3e-14

std::vector<fs::path> meshesUnder(const fs::path& dir) {
  std::vector<fs::path> out;
  if (!fs::is_directory(dir)) return out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file() && e.path().extension() == ".off") out.push_back(e.path());
  std::sort(out.begin(), out.end());
  return out;
}

void expectAgreement(const fs::path& file) {
  const MeshData data = readOff(file);
  const Mesh mesh(file, data, Shading::Phong, Material{});
  const crosscheck::NormalsReport r = crosscheck::crossCheckNormals(mesh);
  std::printf(
      "[ figures  ] %-40s %6zu vertices: max %.2e deg, mean %.2e deg, %zu faces refused, %zu "
      "skipped\n",
      file.filename().string().c_str(), r.vertices, r.maxDegrees, r.meanDegrees, r.facesRejected,
      r.verticesSkipped);
  EXPECT_LE(r.maxDegrees, kMaxDegrees) << file;
  // Refused faces would hide disagreements: every vertex in use is compared.
  EXPECT_EQ(r.facesRejected, 0u) << file;
  EXPECT_EQ(r.verticesSkipped, 0u) << file;
  EXPECT_GT(r.compared, 0u) << file;
}

TEST(NormalsCrossCheck, SeedMeshesAgreeWithOpenMesh) {
  MESHTRACE_REQUIRE_SEED();
  const auto files = meshesUnder(test::seedDir() / "scenes");
  ASSERT_FALSE(files.empty());
  for (const fs::path& f : files) expectAgreement(f);
}

TEST(NormalsCrossCheck, OurMeshesAgreeWithOpenMesh) {
  auto files = meshesUnder(test::sourceDir() / "scenes");
  const auto ours = meshesUnder(test::sourceDir() / "tests" / "app" / "viewer" / "scenes");
  files.insert(files.end(), ours.begin(), ours.end());
  ASSERT_FALSE(files.empty());
  for (const fs::path& f : files) expectAgreement(f);
}

TEST(NormalsCrossCheck, GeneratedMeshesAgreeWithOpenMesh) {
  for (const MeshData& data :
       {makeIcosphere(Vec3(0.0), 1.0, 3), makeTorus(Vec3(1.0), 2.0, 0.5, 40, 16),
        makeTorusKnot(Vec3(0.0), 1.0, 2, 3, 0.2, 120, 10), makeGrid(Vec3(0.0), 2.0, 8)}) {
    const auto r = crosscheck::crossCheckNormals(data, angleWeightedVertexNormals(data));
    EXPECT_LE(r.maxDegrees, kMaxDegrees);
    EXPECT_EQ(r.compared, data.vertices.size());
  }
}

// The check must be able to fail: a wrong normal shows as its angle, and the
// worst vertices come first.
TEST(NormalsCrossCheck, ReportsAWrongNormalAndItsVertex) {
  const MeshData cube = makeGriddedBox(Vec3(-1.0), Vec3(1.0), 2);
  const Mesh mesh("cube.off", cube, Shading::Phong, Material{});
  std::vector<Vec3> normals = mesh.vertexNormals();
  const Vec3 right = normals[5];
  const Vec3 axis =
      glm::normalize(glm::cross(right, glm::abs(right.x) < 0.9 ? Vec3(1, 0, 0) : Vec3(0, 1, 0)));
  normals[5] =
      glm::normalize(right * std::cos(glm::radians(3.0)) + axis * std::sin(glm::radians(3.0)));
  const auto r = crosscheck::crossCheckNormals(cube, normals, 3);
  EXPECT_NEAR(r.maxDegrees, 3.0, 1e-9);
  ASSERT_FALSE(r.worst.empty());
  EXPECT_EQ(r.worst[0].vertex, 5u);
  EXPECT_NEAR(r.perVertexDegrees[5], 3.0f, 1e-5f);
  EXPECT_NEAR(r.meanDegrees, 3.0 / r.compared, 1e-9);
}

// A face OpenMesh cannot take (a third face on one edge) is counted, and its
// corners are left out of the comparison rather than reported as wrong.
TEST(NormalsCrossCheck, CountsFacesOpenMeshRefuses) {
  MeshData fan;
  fan.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1)};
  fan.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};  // three faces on edge 0-1
  const Mesh mesh("fan.off", fan, Shading::Phong, Material{});
  const auto r = crosscheck::crossCheckNormals(mesh);
  EXPECT_EQ(r.facesRejected, 1u);
  EXPECT_EQ(r.verticesSkipped, 3u);
  EXPECT_EQ(r.compared, 2u);
}

}  // namespace
}  // namespace meshtrace
