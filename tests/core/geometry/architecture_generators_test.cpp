// The interiors' generators: what the bench's interior scenes rely on.
#include <gtest/gtest.h>

#include <algorithm>

#include "meshtrace/geometry/mesh_generators.h"

namespace meshtrace {
namespace {

Aabb boundsOf(const MeshData& m) {
  Aabb box;
  for (const Vec3& v : m.vertices) box.extend(v);
  return box;
}

// Every part is a box of 12 triangles, listed part by part: each triangle
// faces away from its own box's centre.
void expectBoxesFaceOutward(const MeshData& m) {
  ASSERT_EQ(m.triangles.size() % 12, 0u);
  for (std::size_t first = 0; first < m.triangles.size(); first += 12) {
    Aabb box;
    for (std::size_t t = first; t < first + 12; ++t)
      for (const std::uint32_t v : m.triangles[t]) box.extend(m.vertices[v]);
    for (std::size_t t = first; t < first + 12; ++t) {
      const Vec3 &a = m.vertices[m.triangles[t][0]], &b = m.vertices[m.triangles[t][1]],
                 &c = m.vertices[m.triangles[t][2]];
      const Vec3 outward = (a + b + c) / 3.0 - box.center();
      ASSERT_GT(glm::dot(glm::cross(b - a, c - a), outward), 0.0) << "triangle " << t;
    }
  }
}

TEST(MengerSponge, KeepsTwentyOfTwentySevenCubesAtEachLevel) {
  EXPECT_EQ(makeMengerSponge(Vec3(0), 1.0, 0).triangles.size(), 12u);
  EXPECT_EQ(makeMengerSponge(Vec3(0), 1.0, 1).triangles.size(), 20u * 12u);
  EXPECT_EQ(makeMengerSponge(Vec3(0), 1.0, 2).triangles.size(), 400u * 12u);
}

TEST(MengerSponge, FillsItsCubeAndLeavesTheCentreOpen) {
  const MeshData m = makeMengerSponge(Vec3(1, 2, 3), 3.0, 1);
  const Aabb box = boundsOf(m);
  EXPECT_EQ(box.min, Vec3(-0.5, 0.5, 1.5));
  EXPECT_EQ(box.max, Vec3(2.5, 3.5, 4.5));
  // No vertex lies inside the middle cube: it and its six face neighbours
  // are removed.
  for (const Vec3& v : m.vertices) {
    const Vec3 d = glm::abs(v - Vec3(1, 2, 3));
    EXPECT_FALSE(d.x < 0.5 && d.y < 0.5 && d.z < 0.5);
  }
  expectBoxesFaceOutward(m);
}

TEST(Hall, SpansItsSizeWithTrianglesAsLongAsTheHall) {
  const MeshData m = makeHall(40.0, 16.0, 8.0);
  const Aabb box = boundsOf(m);
  EXPECT_NEAR(box.min.z, -20.3, 1e-12);
  EXPECT_NEAR(box.max.z, 20.3, 1e-12);
  EXPECT_LT(box.min.x, -8.0);
  EXPECT_GT(box.max.x, 8.0);
  EXPECT_NEAR(box.max.y, 8.3, 1e-12);
  // The long, thin triangles the scene is for: the floor stripes run the
  // hall's whole length.
  std::size_t long_ = 0;
  for (const auto& t : m.triangles) {
    Aabb tb;
    for (const std::uint32_t v : t) tb.extend(m.vertices[v]);
    if (tb.extent().z >= 40.0 && std::min(tb.extent().x, tb.extent().y) < 0.5) ++long_;
  }
  EXPECT_GE(long_, 48u * 2u);
  expectBoxesFaceOutward(m);
}

}  // namespace
}  // namespace meshtrace
