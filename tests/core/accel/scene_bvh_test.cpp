// The scene's two-level BVH (scene_bvh): which meshes get a triangle BVH
// and which are said to be left out, the large ones sharing one triangle BVH
// that the top level holds as one object, each triangle block holding one
// mesh's triangles, at most 64 bytes of nodes and blocks per triangle, and
// a mesh of one triangle listed a million times costing two triangles, and
// one face of 100k corners a few.
#include "accel/scene_bvh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <numeric>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "meshtrace/accel/intersector.h"
#include "meshtrace/geometry/mesh_generators.h"
#include "meshtrace/geometry/polygon.h"
#include "meshtrace/io/input_error.h"
#include "support/meshes.h"

namespace meshtrace {
namespace {

using test::makeMesh;

// A closest-hit and an any-hit query for each of 40 x 40 rays straight
// down onto the plane z = 0, over [-1.2, 1.2]^2.
struct DownwardQueries {
  std::size_t queries = 0, hits = 0;
  std::set<std::uint32_t> trianglesHit;
  Counters counters;
};

DownwardQueries queryDownOntoTheUnitSquare(const SceneIntersector& intersector) {
  DownwardQueries q;
  for (int y = 0; y < 40; ++y)
    for (int x = 0; x < 40; ++x) {
      const Ray ray{Vec3(-1.2 + 0.06 * x, -1.2 + 0.06 * y, 2.0), Vec3(0.0, 0.0, -1.0)};
      Hit hit;
      if (intersector.closestHit(ray, 0.0, hit, q.counters)) {
        ++q.hits;
        q.trianglesHit.insert(hit.ref.triangle);
      }
      q.hits += intersector.occluded(ray, 0.0, kInfinity, q.counters);
      q.queries += 2;
    }
  return q;
}

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
  for (const auto& [first, count] : leavesOf(shared.tree)) {
    const TriangleBlock block = shared.blocks.block(first, count);
    for (int lane = 0; lane < block.count(); ++lane) {
      ++lanes;
      mixed +=
          shared.triangles[block.id(lane)].sceneIndex != shared.triangles[block.id(0)].sceneIndex;
    }
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
  const DownwardQueries q = queryDownOntoTheUnitSquare(intersector);
  EXPECT_GT(q.hits, q.queries / 4);  // the triangle covers 35% of the square
  EXPECT_EQ(q.trianglesHit, std::set<std::uint32_t>{0});
  EXPECT_LE(q.counters.triangleTests, 2 * q.queries);
}

// One face of 100k corners (a disc), triangulated as every reader does,
// costs a query a few triangle tests, where a fan of slivers meeting at one
// corner cost 3,800. The bound is the polygon test's 3 log2(n) boxes at a
// point.
TEST(SceneBvh, AFaceOfAHundredThousandCornersCostsFewTestsARay) {
  constexpr std::uint32_t kCorners = 100000;
  MeshData disc;
  std::vector<std::uint32_t> corners;
  for (std::uint32_t i = 0; i < kCorners; ++i) {
    const double a = 2.0 * M_PI * i / kCorners;
    disc.vertices.emplace_back(std::cos(a), std::sin(a), 0.0);
    corners.push_back(i);
  }
  appendPolygonTriangles(corners, disc.triangles);
  Scene scene;
  scene.meshes.push_back(makeMesh("disc.off", std::move(disc)));
  const SceneIntersector intersector(scene, {});
  const DownwardQueries q = queryDownOntoTheUnitSquare(intersector);
  EXPECT_GT(q.hits, q.queries / 2);  // the disc covers 55% of the square
  const double testsAQuery =
      static_cast<double>(q.counters.triangleTests) / static_cast<double>(q.queries);
  EXPECT_LE(testsAQuery, 3.0 * std::log2(static_cast<double>(kCorners)));
  std::printf("%.2f triangle tests a query\n", testsAQuery);
}

// An L-shaped face whose bottom edge is a row of 10,000 corners, on a line
// and on a slight outward arc, cut by ear clipping as the readers cut it:
// a query costs a few triangle tests, where the ears cut in a run from the
// L's top-left corner made a fan whose slivers' boxes all held the points
// near it (about 3,000 tests a query).
TEST(SceneBvh, ANonConvexFaceWithARowOfManyCornersCostsFewTestsARay) {
  constexpr std::uint32_t kRow = 10000;
  for (const double bulge : {0.0, 0.05}) {
    MeshData l;
    l.vertices.emplace_back(-1.0, -1.0, 0.0);
    for (std::uint32_t i = 1; i <= kRow; ++i) {
      const double s = static_cast<double>(i) / (kRow + 1);
      l.vertices.emplace_back(-1.0 + 2.0 * s, -1.0 - bulge * std::sin(M_PI * s), 0.0);
    }
    for (const auto& [x, y] :
         {std::pair{1.0, -1.0}, {1.0, 0.0}, {0.0, 0.0}, {0.0, 1.0}, {-1.0, 1.0}})
      l.vertices.emplace_back(x, y, 0.0);
    std::vector<std::uint32_t> corners(l.vertices.size());
    std::iota(corners.begin(), corners.end(), 0u);
    appendPolygonTriangles(corners, l.triangles, &l.polygons);
    const PolygonTiling tiling = tileNonConvexPolygons(l.vertices, l.polygons, l.triangles);
    ASSERT_EQ(tiling.recut, 1u) << "bulge " << bulge;
    Scene scene;
    scene.meshes.push_back(makeMesh("l.off", std::move(l)));
    const SceneIntersector intersector(scene, {});
    const DownwardQueries q = queryDownOntoTheUnitSquare(intersector);
    EXPECT_GT(q.hits, q.queries / 2) << "bulge " << bulge;  // the L covers 52% of the square
    const double testsAQuery =
        static_cast<double>(q.counters.triangleTests) / static_cast<double>(q.queries);
    EXPECT_LE(testsAQuery, 3.0 * std::log2(static_cast<double>(kRow))) << "bulge " << bulge;
    std::printf("bulge %g: %.2f triangle tests a query\n", bulge, testsAQuery);
  }
}

// The BVH's boxes and ray origins are single precision. Up to its limit
// (2^126) it answers as brute force at any scale, deep in float's
// denormals included; a scene beyond it is refused by name, where its rays
// would round to infinity and miss what brute force hits.
TEST(SceneBvh, AnswersAsBruteForceAtAnyScaleUpToSinglePrecisionAndRefusesBeyond) {
  TraceOptions bvh, none;
  none.accel = AccelMethod::None;
  const auto sceneAt = [](double scale) {
    Scene scene;
    scene.meshes.push_back(makeMesh("grid.off", makeGrid(Vec3(0.0), 2.0 * scale, 8)));
    scene.meshes.push_back(
        makeMesh("ball.off", makeIcosphere(Vec3(0.0, 0.5 * scale, 0.0), 0.4 * scale, 2)));
    return scene;
  };
  for (const double scale : {0x1p-300, 0x1p-140, 1.0, 0x1p100, 0x1p125}) {
    const Scene scene = sceneAt(scale);
    const SceneIntersector withBvh(scene, bvh), bruteForce(scene, none);
    Counters counters;
    int hits = 0;
    for (int y = 0; y < 30; ++y)
      for (int x = 0; x < 30; ++x) {
        const Ray ray{Vec3((-1.2 + 0.08 * x) * scale, 1.9 * scale, (-1.2 + 0.08 * y) * scale),
                      glm::normalize(Vec3(0.1, -1.0, 0.05))};
        Hit a, b;
        const bool foundA = withBvh.closestHit(ray, 0.0, a, counters);
        const bool foundB = bruteForce.closestHit(ray, 0.0, b, counters);
        ASSERT_EQ(foundA, foundB) << "scale " << scale << ", ray " << x << ", " << y;
        if (!foundA) continue;
        ++hits;
        EXPECT_EQ(a.ref.object, b.ref.object);
        EXPECT_EQ(a.ref.triangle, b.ref.triangle);
        EXPECT_EQ(a.t, b.t);
        EXPECT_EQ(withBvh.occluded(ray, 0.0, kInfinity, counters),
                  bruteForce.occluded(ray, 0.0, kInfinity, counters));
      }
    EXPECT_GT(hits, 400) << "scale " << scale;
  }
  const Scene far = sceneAt(0x1p127);
  try {
    const SceneIntersector refused(far, bvh);
    ADD_FAILURE() << "a scene beyond single precision was taken";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("mesh grid.off reaches"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("single precision"), std::string::npos) << e.what();
  }
  EXPECT_NO_THROW(SceneIntersector(far, none));
}

}  // namespace
}  // namespace meshtrace
