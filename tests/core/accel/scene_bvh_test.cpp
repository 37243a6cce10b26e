// The scene's two-level BVH (scene_bvh): which meshes get a triangle BVH
// and which are said to be left out, the large ones sharing one triangle BVH
// that the top level holds as one object, each triangle block holding one
// mesh's triangles, at most 64 bytes of nodes and blocks per triangle, and
// a mesh of one triangle listed a million times costing two triangles.
#include "accel/scene_bvh.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

#include "meshtrace/accel/intersector.h"
#include "meshtrace/geometry/mesh_generators.h"
#include "support/meshes.h"

namespace meshtrace {
namespace {

using test::makeMesh;

TEST(SceneBvh, SmallMeshesGetNoBvhAndAreSaidToBeLeftOut) {
  Scene scene;
  scene.meshes.push_back(makeMesh("square.off", makeGrid(Vec3(0.0), 1.0, 1)));  // 2 triangles
  scene.meshes.push_back(makeMesh("ball.off", makeIcosphere(Vec3(3.0), 1.0, 2)));
  const SceneBvh bvh(scene);
  EXPECT_FALSE(bvh.inMeshBvh(0));
  EXPECT_TRUE(bvh.inMeshBvh(1));
  std::vector<std::string> meshesLeftOut;
  for (const std::string& item : bvh.stats().leftOut)
    if (item.rfind("no BVH for ", 0) == 0) meshesLeftOut.push_back(item);
  ASSERT_EQ(meshesLeftOut.size(), 1u);
  EXPECT_NE(meshesLeftOut[0].find("square.off"), std::string::npos);
}

// Every mesh large enough for a BVH is in the one triangle BVH, which the
// top level holds as a single object beside the meshes left out.
TEST(SceneBvh, LargeMeshesShareOneTriangleBvh) {
  Scene scene;
  scene.meshes.push_back(makeMesh("ball.off", makeIcosphere(Vec3(0.0), 1.0, 2)));
  scene.meshes.push_back(makeMesh("square.off", makeGrid(Vec3(0.0), 1.0, 1)));  // 2 triangles
  scene.meshes.push_back(makeMesh("box.off", makeGriddedBox(Vec3(2.0), Vec3(3.0), 2)));
  const SceneBvh bvh(scene);
  EXPECT_EQ(bvh.stats().meshesWithBvh, 2u);
  EXPECT_EQ(bvh.stats().trianglesInBvhs,
            scene.meshes[0].triangles().size() + scene.meshes[2].triangles().size());
  EXPECT_EQ(bvh.meshBvh().triangles.meshCount(), 2u);
  EXPECT_EQ(bvh.stats().topLevelObjects, 2u);  // the triangle BVH and the square
}

// The queries find a block's mesh once, from its first lane: every block of
// the shared tree must hold triangles of one mesh, however the meshes
// interleave in space.
TEST(SceneBvh, EachTriangleBlockHoldsOneMesh) {
  const MeshData ball = makeIcosphere(Vec3(0.0), 1.0, 3);
  Scene scene;
  scene.meshes.push_back(makeMesh("ball.off", ball));
  scene.meshes.push_back(makeMesh("twin.off", ball));
  scene.meshes.push_back(makeMesh("box.off", makeGriddedBox(Vec3(-0.9), Vec3(0.9), 5)));
  const SceneBvh bvh(scene);
  const MeshBvh& shared = bvh.meshBvh();
  ASSERT_EQ(shared.triangles.meshCount(), 3u);
  std::size_t lanes = 0, mixed = 0;
  for (const TriangleBlock4& block : shared.blocks)
    for (int lane = 0; lane < 4 && block.id[lane] != kNoTriangle; ++lane) {
      ++lanes;
      mixed +=
          shared.triangles[block.id[lane]].sceneIndex != shared.triangles[block.id[0]].sceneIndex;
    }
  EXPECT_EQ(lanes, shared.triangles.size());
  EXPECT_EQ(mixed, 0u);
}

// Nodes and triangle blocks together stay within 64 bytes per triangle on
// large meshes: the collapse keeps small subtrees inside their parent rather
// than giving them nodes of their own with few children.
TEST(SceneBvh, TakesAtMost64BytesPerTriangle) {
  Scene scene;
  scene.meshes.push_back(makeMesh("ball.off", makeIcosphere(Vec3(0.0), 1.0, 6)));  // 82k
  scene.meshes.push_back(
      makeMesh("knot.off", makeTorusKnot(Vec3(3.0), 1.0, 2, 3, 0.3, 600, 40)));  // 48k
  const auto bytesPerTriangle = [](const Scene& s) {
    const SceneBvh bvh(s);
    return static_cast<double>(bvh.meshBvh().bytes()) /
           static_cast<double>(bvh.stats().trianglesInBvhs);
  };
  for (const Mesh& mesh : scene.meshes) {
    Scene alone;
    alone.meshes.push_back(mesh);
    const double perTriangle = bytesPerTriangle(alone);
    std::printf("%s: %.1f bytes per triangle\n", mesh.file().c_str(), perTriangle);
    EXPECT_LE(perTriangle, 64.0) << mesh.file();
  }
  const double together = bytesPerTriangle(scene);
  std::printf("both in one BVH: %.1f bytes per triangle\n", together);
  EXPECT_LE(together, 64.0);
}

// A million copies of one triangle (an OFF listing it a million times) are
// two triangles to the BVH: a ray costs two triangle tests, not a million,
// and --stats says what was left out.
TEST(SceneBvh, AMillionCopiesOfATriangleCostTwoTestsARay) {
  MeshData m;
  m.vertices = {{-1.0, -1.0, 0.0}, {1.0, -1.0, 0.0}, {0.0, 1.0, 0.0}};
  m.triangles.assign(1000000, {0, 1, 2});
  Scene scene;
  scene.meshes.push_back(makeMesh("copies.off", std::move(m)));
  const SceneIntersector intersector(scene, {});
  const SceneBvhStats& stats = *intersector.bvhStats();
  EXPECT_EQ(stats.copiesLeftOut, 999998u);
  bool said = false;
  for (const std::string& item : stats.leftOut)
    said |= item.rfind("999998 triangles out of the triangle BVH: exact copies", 0) == 0;
  EXPECT_TRUE(said);
  Counters counters;
  std::size_t rays = 0, hits = 0;
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 40; ++x, ++rays) {
      const Ray ray{Vec3(-1.2 + 0.06 * x, -1.2 + 0.06 * y, 2.0), Vec3(0.0, 0.0, -1.0)};
      Hit hit;
      hits += intersector.closestHit(ray, 0.0, hit, counters);
      EXPECT_FALSE(hit.found() && hit.ref.triangle != 0);
      hits += intersector.occluded(ray, 0.0, kInfinity, counters);
    }
  EXPECT_GT(hits, rays / 2);
  EXPECT_LE(counters.triangleTests, 4 * rays);  // two queries a ray
}

}  // namespace
}  // namespace meshtrace
