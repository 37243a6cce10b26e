// The stability table's speed column: each triangle test's rays per second
// on a real mesh (scenes/knot's generated knot) through the BVH, the speed
// a reader choosing --triangle and --precision meets, not that of a
// brute-force loop over a small box.
#include <gtest/gtest.h>

#include <cstdio>

#include "meshtrace/geometry/scene_meshes.h"
#include "meshtrace/report/stability.h"

namespace meshtrace {
namespace {

TEST(StabilityThroughput, TracesTheKnotOfOurScenesThroughTheBvh) {
  const Scene knot = knotThroughputScene();
  // The same mesh make_scenes writes to scenes/knot/knot.off.
  EXPECT_EQ(knot.triangleCount(), 106496u);
  EXPECT_EQ(knot.triangleCount(), makeOurSceneMesh("knot/knot.off").triangles.size());
  for (const TriangleKernel& k : allTriangleKernels()) {
    const ThroughputResult r = measureThroughput(knot, k);
    std::printf(
        "[ figures  ] %-10s %-6s %zu rays, %zu hits, %.1f triangle tests a ray: %.2f "
        "Mrays/s\n",
        toString(k.test), toString(k.precision), r.rays, r.hits,
        double(r.counters.triangleTests) / r.rays, r.mraysPerSecond());
    EXPECT_EQ(r.rays, 256u * 256u);
    // The knot, a thin tube, fills the view's width: one ray in seven
    // meets it, the others pass through its BVH's root box or beside it.
    EXPECT_GT(r.hits, r.rays / 10) << toString(k.test);
    // Through the BVH: a ray tests a few dozen triangles, not all 106,496
    // as brute force would.
    EXPECT_GT(r.counters.nodeVisits, 0u);
    EXPECT_LT(r.counters.triangleTests, 200 * r.rays) << toString(k.test);
    EXPECT_GT(r.mraysPerSecond(), 0.0);
  }
}

TEST(StabilityThroughput, TheTablesSpeedColumnIsTheKnotsThroughTheBvh) {
  StabilityRow row{TriangleKernel{}, {}, {}, {}, {}};
  row.watertight.rays = 1000000;
  row.watertight.seconds = 1.0;  // the box's brute force: 1 Mray/s
  row.throughput.rays = 7000000;
  row.throughput.seconds = 1.0;  // the knot through the BVH: 7 Mrays/s
  const std::string table = stabilityMarkdown({row});
  EXPECT_NE(table.find("Mrays/s (knot, BVH, 1 core)"), std::string::npos) << table;
  EXPECT_NE(table.find("| 7.00 |"), std::string::npos) << table;
  EXPECT_EQ(table.find("1.00"), std::string::npos) << table;
}

}  // namespace
}  // namespace meshtrace
