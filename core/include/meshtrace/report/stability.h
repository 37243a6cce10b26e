#pragma once
// Measurements of numerical robustness, shared by the stability tests (which
// state each case and assert on it) and by `raytrace --report` (which tables
// them against speed). Every measurement is deterministic: fixed seeds.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "meshtrace/geometry/hit.h"
#include "meshtrace/geometry/mesh.h"
#include "meshtrace/geometry/scene.h"
#include "meshtrace/geometry/triangle.h"
#include "meshtrace/util/counters.h"

namespace meshtrace {

// The closed surface of the box [-1, 1]^3, each face an n x n grid of squares
// split along a diagonal, facing outward: 12 n^2 triangles. Built here rather
// than read from a file so that every vertex is an exact binary fraction
// when n is a power of two.
MeshData makeClosedGridBox(int n);

// Watertightness: rays from `eye` (inside the box) aimed exactly at every grid
// vertex, edge midpoint and diagonal midpoint of makeClosedGridBox(n). A leak
// is a ray that hits nothing; a multiple hit a ray that more than one
// triangle accepts (harmless for the closest hit, but a double count).
struct WatertightResult {
  std::size_t rays = 0, leaks = 0, multipleHits = 0;
  double seconds = 0.0;  // the scan of every triangle for every ray
  double mraysPerSecond() const { return seconds > 0.0 ? rays / seconds * 1e-6 : 0.0; }
};
WatertightResult measureWatertightBox(TriangleKernel kernel, int n, const Vec3& eye);

// Self-intersection: a ray hits a primitive placed at `offset` (on every
// axis) with size `scale`; rays spawned from the hit (the mirror direction
// and random directions on both sides for flat primitives, on the outer
// side for spheres and cylinders, where no other hit is possible) must not
// hit it again. Counts only samples whose primary ray found the primitive.
struct SelfHitResult {
  std::size_t primaryHits = 0, spawned = 0, reHits = 0;
};
SelfHitResult measureSelfIntersection(ObjectKind kind, TriangleKernel kernel, double scale,
                                      double offset, int samples, std::uint64_t seed);

// Accuracy on ill-conditioned cases against a quad-precision (__float128)
// Cramer reference computed from the same double inputs.
enum class IllConditioned { Grazing, Sliver, Huge, Tiny };
const char* toString(IllConditioned family);
struct AccuracyResult {
  std::size_t cases = 0, wrongDecisions = 0;  // hit/miss differs from the reference
  double maxTError = 0.0;                     // max |t - t_ref| / t_ref
  double maxBaryError = 0.0;                  // max |beta - beta_ref|, |gamma - gamma_ref|
  // The same errors divided by their first-order bounds u*kappa*(2 + L/t) and
  // u*kappa, kappa = L^2 / |(e1 x e2) . d| the condition number of the system
  // and L the longest of the edges and o - A: the constant K the bound needs.
  double maxTErrorOverBound = 0.0;
  double maxBaryErrorOverBound = 0.0;
};
AccuracyResult measureAccuracy(IllConditioned family, TriangleKernel kernel, int samples,
                               std::uint64_t seed);

// Speed where a reader meets a triangle test: the closest hits of primary
// rays on scenes/knot's knot (106,496 triangles, generated as make_scenes
// writes it), seen from that scene's eye with the knot filling a view of
// 256x256 rays, through the BVH, on one core, one ray at a time; the
// fastest of several passes.
struct ThroughputResult {
  std::size_t rays = 0, hits = 0, triangles = 0;
  Counters counters;     // what the queries did: node visits, triangle tests
  double seconds = 0.0;  // the queries of one pass alone, not the BVH's build
  double mraysPerSecond() const { return seconds > 0.0 ? rays / seconds * 1e-6 : 0.0; }
};
// The knot as a scene of its own, to build once and measure every test on.
Scene knotThroughputScene();
ThroughputResult measureThroughput(const Scene& knot, TriangleKernel kernel);

// The table for the report: one row per algorithm and precision.
struct StabilityRow {
  TriangleKernel kernel;
  WatertightResult watertight;  // n = 16 box, off-centre eye
  SelfHitResult selfHits;       // triangles, all scales and offsets
  AccuracyResult accuracy;      // all four families together
  ThroughputResult throughput;  // the knot through the BVH
};
std::vector<StabilityRow> measureStabilityTable(int samplesPerCase);
std::string stabilityMarkdown(const std::vector<StabilityRow>& rows);

// All algorithm and precision pairs, the default first.
std::vector<TriangleKernel> allTriangleKernels();

}  // namespace meshtrace
