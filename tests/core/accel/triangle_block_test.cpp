// The float block filter in front of the exact triangle kernels: it may pass
// triangles on that the exact kernel then rejects, but it must never drop one
// the exact kernel hits, for any kernel, at any scale or distance, with rays
// aimed exactly at vertices and edges.
#include "accel/triangle_block.h"

#include <gtest/gtest.h>

#include <cmath>
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
  TriangleBlocks store;
  std::vector<TriangleBlock> blocks;  // one per leaf of the tree
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
  b.store = TriangleBlocks(set, b.frame, b.tree);
  for (const auto& [first, count] : leavesOf(b.tree))
    b.blocks.push_back(b.store.block(first, count));
  return b;
}

MeshData transformed(MeshData m, double scale, const Vec3& offset) {
  for (Vec3& v : m.vertices) v = v * scale + offset;
  return m;
}

// A point of a random triangle of the mesh, and that triangle's unit
// normal; `onEdges`: each of two barycentrics is exactly 0 a fifth of the
// time (the point is on an edge or a vertex).
struct MeshPoint {
  Vec3 point, normal;
};
MeshPoint pointOn(const Mesh& mesh, std::mt19937_64& rng, bool onEdges) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto& t = mesh.triangles()[rng() % mesh.triangles().size()];
  const auto& v = mesh.vertices();
  double b = u(rng), g = u(rng);
  if (b + g > 1.0) b = 1.0 - b, g = 1.0 - g;
  if (onEdges && u(rng) < 0.2) b = 0.0;
  if (onEdges && u(rng) < 0.2) g = 0.0;
  return {(1.0 - b - g) * v[t[0]] + b * v[t[1]] + g * v[t[2]],
          glm::normalize(glm::cross(v[t[1]] - v[t[0]], v[t[2]] - v[t[0]]))};
}

// Rays from around the mesh toward a point of one of its triangles: inside
// it, on an edge (a barycentric exactly 0) or on a vertex.
Ray aimedRay(const Mesh& mesh, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const Vec3 target = pointOn(mesh, rng, true).point;
  const Vec3 e = mesh.bounds().extent();
  const Vec3 origin = mesh.bounds().min - e + 3.0 * Vec3(u(rng), u(rng), u(rng)) * e;
  Vec3 d = target - origin;
  if (u(rng) < 0.1) d = Vec3(0.0, 0.0, u(rng) < 0.5 ? 1.0 : -1.0);  // axis-parallel
  if (d == Vec3(0.0)) d = Vec3(1.0, 0.0, 0.0);
  return {origin, glm::normalize(d)};
}

// Rays that graze a triangle: from a point of it (inside, on an edge or on
// a vertex), along its plane tilted by 1e-2 to 1e-12 radians, from up to
// twice the mesh's size away. Their det is within the filter's margin, so
// the filter cannot tell which way the triangle faces.
Ray grazingRay(const Mesh& mesh, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto [p, n] = pointOn(mesh, rng, true);
  Vec3 along = glm::cross(n, Vec3(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5));
  if (glm::length(along) == 0.0) along = glm::cross(n, Vec3(1.0, 0.0, 0.0));
  const double tilt = (u(rng) < 0.5 ? -1.0 : 1.0) * std::pow(10.0, -2.0 - 10.0 * u(rng));
  const Vec3 d = glm::normalize(glm::normalize(along) + tilt * n);
  const double away = (0.01 + 2.0 * u(rng)) * maxAbsComponent(mesh.bounds().extent());
  return {p - away * d, d};
}

// The lanes the filter passes on to the exact kernel, as a closest-hit
// search asks for them.
int candidates(const BlockRay& ray, TriangleBlock block, double tMin, double tMax) {
  return ray.rank(block, tMin, tMax).candidates;
}

struct FilterCount {
  std::uint64_t lanes = 0, candidates = 0, hits = 0, dropped = 0;
};

// Every lane of every block against `rays` rays; counts exact hits the
// filter dropped (with no upper limit on t, with the hit's own t as the
// limit, and with a lower limit just below it), and those a closest-hit
// search would leave out as beyond a nearer hit at their own t (rank).
FilterCount checkFilter(const Blocks& b, TriangleKernel kernel, int rays, std::uint64_t seed,
                        Ray (*makeRay)(const Mesh&, std::mt19937_64&) = aimedRay) {
  std::mt19937_64 rng(seed);
  FilterCount c;
  const auto& v = b.mesh.vertices();
  for (int r = 0; r < rays; ++r) {
    const Ray ray = makeRay(b.mesh, rng);
    const BlockRay blockRay(ray, b.frame, kernel);
    const TriangleRay exact(ray, kernel);
    for (const TriangleBlock& block : b.blocks) {
      const BlockRay::Ranked ranked = blockRay.rank(block, 0.0, kInfinity);
      const int mask = ranked.candidates;
      c.lanes += block.count();
      for (int lane = 0; lane < block.count(); ++lane) {
        const bool passed = (mask >> lane) & 1;
        c.candidates += passed;
        const auto& t = b.mesh.triangles()[block.id(lane)];
        TriangleHit hit;
        if (!exact.intersect(v[t[0]], v[t[1]], v[t[2]], 0.0, kInfinity, hit)) continue;
        ++c.hits;
        const bool atHit = (candidates(blockRay, block, 0.0, hit.t) >> lane) & 1;
        const bool fromBelow = (candidates(blockRay, block, hit.t * 0.999, kInfinity) >> lane) & 1;
        const bool leftOut = blockRay.beyond(ranked.near[lane], hit.t);
        if (!passed || !atHit || !fromBelow || leftOut) ++c.dropped;
      }
      EXPECT_EQ(mask >> block.count(), 0) << "a lane past the block's triangles was reported";
    }
  }
  return c;
}

struct NamedMesh {
  const char* name;
  MeshData data;
};

// Meshes at every scale and distance, and one of needles (a knot's tube
// 1e-5 wide): where the filter's bounds are tightest.
std::vector<NamedMesh> scaledMeshes() {
  const MeshData sphere = makeIcosphere(Vec3(0.3, -0.2, 0.1), 1.0, 2);
  return {
      {"icosphere", sphere},
      {"knot", makeTorusKnot(Vec3(0.0), 1.0, 2, 3, 0.2, 48, 6)},
      {"needles", makeTorusKnot(Vec3(0.0), 1.0, 2, 3, 1e-5, 400, 3)},
      {"far away (1e6)", transformed(sphere, 1.0, Vec3(1e6, -2e6, 5e5))},
      {"tiny (1e-4)", transformed(sphere, 1e-4, Vec3(0.0))},
      {"tiny and far", transformed(sphere, 1e-3, Vec3(1e3, 0.0, -1e3))},
      {"huge (1e8)", transformed(sphere, 1e8, Vec3(0.0))},
  };
}

const TriangleKernel kKernels[] = {{TriangleTest::Watertight, Precision::Double},
                                   {TriangleTest::Cramer, Precision::Double},
                                   {TriangleTest::MollerTrumbore, Precision::Double},
                                   {TriangleTest::Watertight, Precision::Single},
                                   {TriangleTest::Cramer, Precision::Single},
                                   {TriangleTest::MollerTrumbore, Precision::Single}};

TEST(TriangleBlockFilter, NeverDropsAHitOfAnyKernelAtAnyScaleOrDistance) {
  for (const auto& m : scaledMeshes()) {
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

// A grazing ray meets lanes whose facing the filter cannot tell: it may
// drop them only where the ray passes outside whichever way they face.
TEST(TriangleBlockFilter, NeverDropsAGrazingHitOfAnyKernelAtAnyScaleOrDistance) {
  for (const auto& m : scaledMeshes()) {
    const Blocks b = makeBlocks(m.data);
    for (const TriangleKernel& kernel : kKernels) {
      const FilterCount c = checkFilter(b, kernel, 300, 43, grazingRay);
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

// Single-precision kernels round the world coordinates to float, so the
// filter lets triangles within that rounding of the ray pass too: a
// dilation of each triangle by the kernel's error, not a margin that
// grows with the ray's distance from it. Nearly every triangle a ray
// misses is still dropped.
TEST(TriangleBlockFilter, DropsNearlyAllMissedTrianglesForSingleKernels) {
  const Blocks b = makeBlocks(makeIcosphere(Vec3(0.0), 1.0, 5));
  for (const TriangleKernel& kernel : kKernels) {
    if (kernel.precision != Precision::Single) continue;
    const FilterCount c = checkFilter(b, kernel, 200, 7);
    const std::uint64_t passedMisses = c.candidates - c.hits;
    std::printf("%s single: lanes %llu, exact hits %llu, passed without a hit %llu\n",
                toString(kernel.test), static_cast<unsigned long long>(c.lanes),
                static_cast<unsigned long long>(c.hits),
                static_cast<unsigned long long>(passedMisses));
    EXPECT_LT(double(passedMisses), 0.005 * double(c.lanes)) << toString(kernel.test);
    EXPECT_LT(passedMisses, 3 * c.hits) << toString(kernel.test);
  }
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
    for (const TriangleBlock& block : b.blocks) {
      const int mask = candidates(blockRay, block, 0.0, kInfinity);
      for (int lane = 0; lane < block.count(); ++lane) {
        const auto& t = b.mesh.triangles()[block.id(lane)];
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

// A sliver 40 long and 0.05 wide, listed from its sharp tip as a box's side
// face may be: rays whose line crosses it a few centimetres behind their
// origin are dropped. The margins follow the sliver's area, not the
// product of its two long edges.
TEST(TriangleBlockFilter, DropsTheSliverBehindTheOrigin) {
  MeshData sliver;
  sliver.vertices = {Vec3(1.0, -0.05, -20.0), Vec3(1.0, 0.0, 20.0), Vec3(1.0, -0.05, 20.0)};
  sliver.triangles = {{0, 1, 2}};
  const Blocks b = makeBlocks(sliver);
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int passed = 0;
  for (int r = 0; r < 1000; ++r) {
    double beta = u(rng), gamma = u(rng);
    if (beta + gamma > 1.0) beta = 1.0 - beta, gamma = 1.0 - gamma;
    const auto& v = sliver.vertices;
    const Vec3 p = (1.0 - beta - gamma) * v[0] + beta * v[1] + gamma * v[2];
    Vec3 d = glm::normalize(Vec3(-0.1 - u(rng), u(rng) - 0.5, u(rng) - 0.5));
    const Ray ray{p + (0.01 + 0.09 * u(rng)) * d, d};
    passed += candidates(BlockRay(ray, b.frame, {}), b.blocks[0], 0.0, kInfinity) & 1;
  }
  EXPECT_EQ(passed, 0);
}

// The two faces of a thin wall in one block, the far one first: a ray
// through both ranks the near face first, and once it has hit it, the far
// face lies beyond that hit and needs no exact test.
TEST(TriangleBlockFilter, RanksTheFarFaceOfAWallBeyondTheNearFacesHit) {
  MeshData wall;
  wall.vertices = {Vec3(-1.0, -1.0, 0.1), Vec3(3.0, -1.0, 0.1), Vec3(-1.0, 3.0, 0.1),
                   Vec3(-1.0, -1.0, 0.0), Vec3(3.0, -1.0, 0.0), Vec3(-1.0, 3.0, 0.0)};
  wall.triangles = {{0, 1, 2}, {3, 4, 5}};
  const Blocks b = makeBlocks(wall);
  ASSERT_EQ(b.blocks.size(), 1u);
  const TriangleBlock& block = b.blocks[0];
  const int nearLane = block.id(0) == 1 ? 0 : 1, farLane = 1 - nearLane;
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  for (int r = 0; r < 1000; ++r) {
    const Vec3 target(u(rng), u(rng), 0.05);
    const Vec3 origin(u(rng) - 0.5, u(rng) - 0.5, -2.0 - 3.0 * u(rng));
    const Ray ray{origin, glm::normalize(target - origin)};
    const BlockRay blockRay(ray, b.frame, {});
    const BlockRay::Ranked ranked = blockRay.rank(block, 0.0, kInfinity);
    ASSERT_EQ(ranked.candidates, 3);
    EXPECT_LT(ranked.near[nearLane], ranked.near[farLane]);
    TriangleHit hit;
    ASSERT_TRUE(TriangleRay(ray, {}).intersect(wall.vertices[3], wall.vertices[4], wall.vertices[5],
                                               0.0, kInfinity, hit));
    EXPECT_FALSE(blockRay.beyond(ranked.near[nearLane], hit.t));
    EXPECT_TRUE(blockRay.beyond(ranked.near[farLane], hit.t));
  }
}

// A ray from a hair off a triangle's surface, on either side, in any
// direction: its hits lie at t within rounding of 0, where the exact
// kernels' own cut-offs decide.
Ray nearSurfaceRay(const Mesh& mesh, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const auto [p, n] = pointOn(mesh, rng, false);
  const double offset =
      std::ldexp(u(rng) - 0.5, -40 - static_cast<int>(rng() % 16)) * (1.0 + maxAbsComponent(p));
  Vec3 d(u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5);
  if (d == Vec3(0.0)) d = n;
  return {p + offset * n, glm::normalize(d)};
}

struct CertainCount {
  std::uint64_t hits = 0, certainHits = 0, wrong = 0;
  std::string example;
};

// classify()'s certain lanes against the exact kernel, for every lane and
// several limits around each exact hit's t (a certain lane must be an
// exact hit inside the limits, a lane at exactly tMax or tMin is not).
CertainCount checkCertain(const Blocks& b, TriangleKernel kernel, int rays, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  CertainCount c;
  const auto& v = b.mesh.vertices();
  for (int r = 0; r < rays; ++r) {
    const Ray ray = r % 2 ? aimedRay(b.mesh, rng) : nearSurfaceRay(b.mesh, rng);
    const BlockRay blockRay(ray, b.frame, kernel);
    const TriangleRay exact(ray, kernel);
    for (const TriangleBlock& block : b.blocks) {
      const auto certainIn = [&](int lane, double tMin, double tMax) {
        const BlockRay::Lanes lanes = blockRay.classify(block, tMin, tMax);
        EXPECT_EQ(lanes.certain & ~lanes.candidates, 0) << "a certain lane is no candidate";
        return (lanes.certain >> lane & 1) != 0;
      };
      for (int lane = 0; lane < block.count(); ++lane) {
        const auto& t = b.mesh.triangles()[block.id(lane)];
        TriangleHit hit;
        const bool found = exact.intersect(v[t[0]], v[t[1]], v[t[2]], 0.0, kInfinity, hit);
        const double th = found ? hit.t : 1.0;
        const double limits[][2] = {{0.0, kInfinity},
                                    {0.0, th},
                                    {0.0, th * (1 + 1e-12)},
                                    {th * (1 - 1e-12), kInfinity},
                                    {th, kInfinity}};
        for (const auto& [tMin, tMax] : limits) {
          if (!certainIn(lane, tMin, tMax)) continue;
          TriangleHit within;
          if (exact.intersect(v[t[0]], v[t[1]], v[t[2]], tMin, tMax, within)) continue;
          if (++c.wrong == 1)
            c.example = "certain in (" + std::to_string(tMin) + ", " + std::to_string(tMax) +
                        ") but the exact kernel " +
                        (found ? "hits at " + std::to_string(th) : std::string("misses"));
        }
        c.hits += found;
        c.certainHits += found && certainIn(lane, 0.0, kInfinity);
      }
    }
  }
  return c;
}

// An any-hit search takes a certain lane as its blocker without the exact
// test: each must be a hit the exact kernel finds inside the search's
// limits, for every kernel, at every scale, from near the surfaces too.
TEST(TriangleBlockFilter, CertainLanesAreExactHitsOfEveryKernelAtAnyScaleOrDistance) {
  for (const auto& m : scaledMeshes()) {
    const Blocks b = makeBlocks(m.data);
    for (const TriangleKernel& kernel : kKernels) {
      const std::string label =
          std::string(m.name) + ", " + toString(kernel.test) + " " + toString(kernel.precision);
      const CertainCount c = checkCertain(b, kernel, 300, 11);
      EXPECT_GT(c.hits, 0u) << label;
      EXPECT_EQ(c.wrong, 0u) << label << ": " << c.example;
      if (kernel.precision == Precision::Single) {
        EXPECT_EQ(c.certainHits, 0u) << label << ": a single-precision kernel is never sure";
      }
    }
  }
}

// And it must pay: most hits of rays aimed anywhere at a triangle (a third
// of them exactly at an edge or a vertex, which are never certain) are
// certain for the double kernels.
TEST(TriangleBlockFilter, FindsMostHitsCertainForDoubleKernels) {
  const Blocks b = makeBlocks(makeIcosphere(Vec3(0.0), 1.0, 3));
  for (const TriangleKernel& kernel : kKernels) {
    if (kernel.precision != Precision::Double) continue;
    const CertainCount c = checkCertain(b, kernel, 200, 5);
    std::printf("%s: %llu exact hits, %llu certain\n", toString(kernel.test),
                static_cast<unsigned long long>(c.hits),
                static_cast<unsigned long long>(c.certainHits));
    EXPECT_GT(double(c.certainHits), 0.5 * double(c.hits)) << toString(kernel.test);
  }
}

TEST(TriangleBlockFilter, AbsurdlyFarOriginPassesEveryLaneToTheExactKernel) {
  const Blocks b = makeBlocks(makeIcosphere(Vec3(0.0), 1.0, 1));
  const Ray ray{Vec3(1e30, 0.0, 0.0), Vec3(-1.0, 0.0, 0.0)};
  const BlockRay blockRay(ray, b.frame, {});
  for (const TriangleBlock& block : b.blocks)
    EXPECT_EQ(candidates(blockRay, block, 0.0, kInfinity), (1 << block.count()) - 1);
}

TEST(TriangleBlocks, HoldEveryTriangleOnceInItsLeaf) {
  const Blocks b = makeBlocks(makeTorus(Vec3(0.0), 1.0, 0.3, 24, 12));
  std::vector<int> seen(b.mesh.triangles().size(), 0);
  for (const TriangleBlock& block : b.blocks)
    for (int lane = 0; lane < block.count(); ++lane) ++seen[block.id(lane)];
  for (std::size_t t = 0; t < seen.size(); ++t) EXPECT_EQ(seen[t], 1) << "triangle " << t;
  EXPECT_TRUE(b.tree.order.empty());
}

// A block of n triangles takes 40 n bytes, padded to 32, and no empty
// lanes: each lane holds its triangle's corners (v0, v0 + e1, v0 + e2, the
// corners in turn from one of them) to float precision, in blocks of every
// count.
TEST(TriangleBlocks, PackEachLeafWithoutEmptyLanes) {
  for (const int segments : {5, 7, 24}) {
    const Blocks b = makeBlocks(makeTorus(Vec3(0.5, -1.0, 2.0), 1.0, 0.3, segments, 3));
    const auto& v = b.mesh.vertices();
    std::size_t padded = 0;
    int withCount[5] = {};
    for (const TriangleBlock& block : b.blocks) {
      padded += (40 * block.count() + 31) / 32 * 32;
      ++withCount[block.count()];
      alignas(16) float x[9][4];
      for (int k = 0; k < 9; ++k) _mm_store_ps(x[k], block.lanes(k));
      for (int lane = 0; lane < block.count(); ++lane) {
        const auto& t = b.mesh.triangles()[block.id(lane)];
        const auto local = [&](int k) { return Vec3(x[k][lane], x[k + 1][lane], x[k + 2][lane]); };
        const Vec3 v0 = local(0) / b.frame.scale + b.frame.center;
        const Vec3 stored[3] = {v0, v0 + local(3) / b.frame.scale, v0 + local(6) / b.frame.scale};
        bool matched = false;
        for (int turn = 0; turn < 3 && !matched; ++turn) {
          matched = true;
          for (int c = 0; c < 3; ++c)
            matched = matched && glm::length(stored[c] - v[t[(turn + c) % 3]]) < 1e-6;
        }
        EXPECT_TRUE(matched) << "triangle " << block.id(lane);
      }
    }
    EXPECT_GT(withCount[1] + withCount[2] + withCount[3], 0) << segments << " segments";
    EXPECT_EQ(b.store.bytes(), padded);
    EXPECT_LT(b.store.bytes(), 160 * b.blocks.size());
  }
}

TEST(TriangleBlocks, RefuseALeafOfMoreThanFourTriangles) {
  const Mesh mesh("eight.off", makeTorus(Vec3(0.0), 1.0, 0.3, 2, 2), Shading::Flat, Material{});
  ASSERT_EQ(mesh.triangles().size(), 8u);
  std::vector<Aabb> boxes;
  for (const auto& t : mesh.triangles()) {
    Aabb box;
    for (auto k : t) box.extend(mesh.vertices()[k]);
    boxes.push_back(box);
  }
  Bvh8 tree = collapseToBvh8(buildBvh(boxes, {.maxLeafSize = 8, .nodeCost = 1e9}));
  ASSERT_EQ(tree.rootCount, 8u);
  TriangleSet set;
  set.add(mesh, 0);
  EXPECT_THROW(TriangleBlocks(set, blockFrame(set.bounds()), tree), std::length_error);
}

}  // namespace
}  // namespace meshtrace
