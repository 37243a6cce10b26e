// The float block filter in front of the exact triangle kernels: it may pass
// triangles on that the exact kernel then rejects, but it must never drop one
// the exact kernel hits, for any kernel, at any scale or distance, with rays
// aimed exactly at vertices and edges.
#include "accel/triangle_block.h"

#include <gtest/gtest.h>

#include <random>

#include "accel/binary_bvh.h"
#include "accel/triangle_set.h"
#include "meshtrace/geometry/mesh.h"
#include "meshtrace/geometry/mesh_generators.h"

namespace meshtrace {
namespace {

struct Blocks {
  Mesh mesh;
  BlockFrame frame;
  Bvh8 tree;
  BuildVector<TriangleBlock4> blocks;
  std::vector<int> counts;  // valid lanes per block
};

Blocks makeBlocks(MeshData data) {
  Blocks b{Mesh("filtered.off", std::move(data), Shading::Flat, Material{}), {}, {}, {}, {}};
  std::vector<Aabb> boxes;
  for (const auto& t : b.mesh.triangles()) {
    Aabb box;
    for (auto k : t) box.extend(b.mesh.vertices()[k]);
    boxes.push_back(box);
  }
  b.tree = collapseToBvh8(buildBvh(boxes, {.leafBlock = 4}));
  TriangleSet set;
  set.add(b.mesh, 0);
  b.frame = blockFrame(set.bounds());
  b.blocks = makeTriangleBlocks(set, b.frame, b.tree);
  for (const TriangleBlock4& block : b.blocks) {
    int n = 0;
    while (n < 4 && block.id[n] != kNoTriangle) ++n;
    b.counts.push_back(n);
  }
  return b;
}

MeshData transformed(MeshData m, double scale, const Vec3& offset) {
  for (Vec3& v : m.vertices) v = v * scale + offset;
  return m;
}

// Rays from around the mesh toward a point of one of its triangles: inside
// it, on an edge (a barycentric exactly 0) or on a vertex.
Ray aimedRay(const Mesh& mesh, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto& t = mesh.triangles()[rng() % mesh.triangles().size()];
  const auto& v = mesh.vertices();
  double b = u(rng), g = u(rng);
  if (b + g > 1.0) b = 1.0 - b, g = 1.0 - g;
  if (u(rng) < 0.2) b = 0.0;
  if (u(rng) < 0.2) g = 0.0;
  const Vec3 target = (1.0 - b - g) * v[t[0]] + b * v[t[1]] + g * v[t[2]];
  const Vec3 e = mesh.bounds().extent();
  const Vec3 origin = mesh.bounds().min - e + 3.0 * Vec3(u(rng), u(rng), u(rng)) * e;
  Vec3 d = target - origin;
  if (u(rng) < 0.1) d = Vec3(0.0, 0.0, u(rng) < 0.5 ? 1.0 : -1.0);  // axis-parallel
  if (d == Vec3(0.0)) d = Vec3(1.0, 0.0, 0.0);
  return {origin, glm::normalize(d)};
}

struct FilterCount {
  std::uint64_t lanes = 0, candidates = 0, hits = 0, dropped = 0;
};

// Every lane of every block against `rays` rays; counts exact hits the
// filter dropped (with no upper limit on t, with the hit's own t as the
// limit, and with a lower limit just below it).
FilterCount checkFilter(const Blocks& b, TriangleKernel kernel, int rays, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  FilterCount c;
  const auto& v = b.mesh.vertices();
  for (int r = 0; r < rays; ++r) {
    const Ray ray = aimedRay(b.mesh, rng);
    const BlockRay blockRay(ray, b.frame, kernel);
    const TriangleRay exact(ray, kernel);
    for (std::size_t k = 0; k < b.blocks.size(); ++k) {
      const TriangleBlock4& block = b.blocks[k];
      const int mask = blockRay.candidates(block, b.counts[k], 0.0, kInfinity);
      c.lanes += b.counts[k];
      for (int lane = 0; lane < b.counts[k]; ++lane) {
        const bool passed = (mask >> lane) & 1;
        c.candidates += passed;
        const auto& t = b.mesh.triangles()[block.id[lane]];
        TriangleHit hit;
        if (!exact.intersect(v[t[0]], v[t[1]], v[t[2]], 0.0, kInfinity, hit)) continue;
        ++c.hits;
        const bool atHit = (blockRay.candidates(block, b.counts[k], 0.0, hit.t) >> lane) & 1;
        const bool fromBelow =
            (blockRay.candidates(block, b.counts[k], hit.t * 0.999, kInfinity) >> lane) & 1;
        if (!passed || !atHit || !fromBelow) ++c.dropped;
      }
      EXPECT_EQ(mask >> b.counts[k], 0) << "a lane past the block's triangles was reported";
    }
  }
  return c;
}

const TriangleKernel kKernels[] = {{TriangleTest::Watertight, Precision::Double},
                                   {TriangleTest::Cramer, Precision::Double},
                                   {TriangleTest::MollerTrumbore, Precision::Double},
                                   {TriangleTest::Watertight, Precision::Single},
                                   {TriangleTest::Cramer, Precision::Single},
                                   {TriangleTest::MollerTrumbore, Precision::Single}};

TEST(TriangleBlockFilter, NeverDropsAHitOfAnyKernelAtAnyScaleOrDistance) {
  const MeshData sphere = makeIcosphere(Vec3(0.3, -0.2, 0.1), 1.0, 2);
  const struct {
    const char* name;
    MeshData data;
  } meshes[] = {
      {"icosphere", sphere},
      {"knot", makeTorusKnot(Vec3(0.0), 1.0, 2, 3, 0.2, 48, 6)},
      {"far away (1e6)", transformed(sphere, 1.0, Vec3(1e6, -2e6, 5e5))},
      {"tiny (1e-4)", transformed(sphere, 1e-4, Vec3(0.0))},
      {"tiny and far", transformed(sphere, 1e-3, Vec3(1e3, 0.0, -1e3))},
      {"huge (1e8)", transformed(sphere, 1e8, Vec3(0.0))},
  };
  for (const auto& m : meshes) {
    const Blocks b = makeBlocks(m.data);
    for (const TriangleKernel& kernel : kKernels) {
      const FilterCount c = checkFilter(b, kernel, 300, 42);
      EXPECT_GT(c.hits, 0u) << m.name;
      EXPECT_EQ(c.dropped, 0u) << m.name << ", " << toString(kernel.test) << " "
                               << toString(kernel.precision) << ": " << c.dropped << " of "
                               << c.hits << " exact hits dropped";
    }
  }
}

// The filter must also pay: for double kernels, nearly every triangle a ray
// misses is dropped in float. Those within rounding of the ray pass: with
// rays aimed exactly at edges and vertices, the neighbours sharing them
// (about six around a vertex), so a few per exact hit.
TEST(TriangleBlockFilter, DropsNearlyAllMissedTrianglesForDoubleKernels) {
  const Blocks b = makeBlocks(makeIcosphere(Vec3(0.0), 1.0, 3));
  const FilterCount c = checkFilter(b, {}, 200, 7);
  const std::uint64_t passedMisses = c.candidates - c.hits;
  std::printf("lanes %llu, exact hits %llu, passed without a hit %llu\n",
              static_cast<unsigned long long>(c.lanes), static_cast<unsigned long long>(c.hits),
              static_cast<unsigned long long>(passedMisses));
  EXPECT_LT(double(passedMisses), 0.005 * double(c.lanes));
  EXPECT_LT(passedMisses, 3 * c.hits);
}

// With tMin = 0, as every query of a render has, a triangle the ray's line
// crosses behind its origin is no candidate: from the centre of a sphere,
// the triangle straight behind is dropped, not passed on to be rejected.
TEST(TriangleBlockFilter, DropsTheTriangleBehindTheOrigin) {
  const Blocks b = makeBlocks(makeIcosphere(Vec3(0.0), 1.0, 2));
  const auto& v = b.mesh.vertices();
  std::mt19937_64 rng(3);
  std::normal_distribution<double> n;
  int behind = 0, passedBehind = 0;
  for (int r = 0; r < 200; ++r) {
    const Vec3 d = glm::normalize(Vec3(n(rng), n(rng), n(rng)));
    const BlockRay blockRay({Vec3(0.0), d}, b.frame, {});
    const TriangleRay backward({Vec3(0.0), -d}, {});
    for (std::size_t k = 0; k < b.blocks.size(); ++k) {
      const int mask = blockRay.candidates(b.blocks[k], b.counts[k], 0.0, kInfinity);
      for (int lane = 0; lane < b.counts[k]; ++lane) {
        const auto& t = b.mesh.triangles()[b.blocks[k].id[lane]];
        TriangleHit hit;
        if (!backward.intersect(v[t[0]], v[t[1]], v[t[2]], 0.0, kInfinity, hit)) continue;
        ++behind;
        passedBehind += mask >> lane & 1;
      }
    }
  }
  EXPECT_GE(behind, 200);
  EXPECT_EQ(passedBehind, 0);
}

TEST(TriangleBlockFilter, AbsurdlyFarOriginPassesEveryLaneToTheExactKernel) {
  const Blocks b = makeBlocks(makeIcosphere(Vec3(0.0), 1.0, 1));
  const Ray ray{Vec3(1e30, 0.0, 0.0), Vec3(-1.0, 0.0, 0.0)};
  const BlockRay blockRay(ray, b.frame, {});
  for (std::size_t k = 0; k < b.blocks.size(); ++k)
    EXPECT_EQ(blockRay.candidates(b.blocks[k], b.counts[k], 0.0, kInfinity),
              (1 << b.counts[k]) - 1);
}

TEST(TriangleBlocks, HoldEveryTriangleOnceInItsLeaf) {
  const Blocks b = makeBlocks(makeTorus(Vec3(0.0), 1.0, 0.3, 24, 12));
  std::vector<int> seen(b.mesh.triangles().size(), 0);
  for (std::size_t k = 0; k < b.blocks.size(); ++k)
    for (int lane = 0; lane < b.counts[k]; ++lane) ++seen[b.blocks[k].id[lane]];
  for (std::size_t t = 0; t < seen.size(); ++t) EXPECT_EQ(seen[t], 1) << "triangle " << t;
  EXPECT_TRUE(b.tree.order.empty());
}

}  // namespace
}  // namespace meshtrace
