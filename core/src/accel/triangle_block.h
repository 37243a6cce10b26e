#pragma once
// The triangles of one BVH leaf, up to four, stored together in float for a
// single SSE test of all four against a ray (Cramer's rule on the
// barycentric system, written with triple products as Moller-Trumbore does).
//
// That test is a conservative filter, not the answer: it rejects a triangle
// only when its error bound proves that the exact kernel (triangle.h) would
// reject it too; every other triangle goes on to the exact kernel, which
// alone decides hits and their t. So the triangle BVH finds exactly what brute
// force finds, while most triangles cost a quarter of one float test.
#include <emmintrin.h>
#include <xmmintrin.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "accel/bvh8.h"
#include "meshtrace/geometry/triangle.h"
#include "meshtrace/util/math.h"
#include "util/build_vector.h"

namespace meshtrace {

class TriangleSet;

// Coordinates are stored relative to the triangles' box centre and scaled by
// a power of two so the box fits in [-1, 1]^3: float then keeps its full
// relative precision however far the meshes are from the world origin, and
// the scaling itself is exact.
struct BlockFrame {
  Vec3 center{0.0};
  double scale = 1.0;      // local = (world - center) * scale
  double worldSize = 0.0;  // |center| + half extent, largest component
};

// The most triangles a block holds: one SSE lane each.
inline constexpr std::uint32_t kBlockLanes = 4;

// One leaf's block, as TriangleBlocks stores it: for its n triangles (1 to
// 4), their n ids in the TriangleSet the blocks were made from, then nine
// float arrays of n (v0, e1, e2 in local coordinates, x, y and z each, the
// edges v1 - v0 and v2 - v0 rounded once from double). No lane is kept
// empty: a leaf of three triangles takes 120 bytes, not a four-lane block's
// 160, and many of a BVH's leaves hold fewer than four.
class TriangleBlock {
 public:
  static constexpr std::size_t kWordsPerTriangle = 10;

  TriangleBlock(const std::uint32_t* words, int count) : words_(words), count_(count) {}

  // Where lane `lane` of float array `array` (0-8) lies in a block of
  // `count` triangles, in words from its start: after the ids. The one
  // statement of the layout, for the blocks' writer and their reader.
  static constexpr std::size_t wordOf(std::size_t array, std::size_t count, std::size_t lane) {
    return (array + 1) * count + lane;
  }

  int count() const { return count_; }
  std::uint32_t id(int lane) const { return words_[lane]; }
  // Four lanes of array k (0-2: v0, 3-5: e1, 6-8: e2). Lanes past count()
  // hold what follows the array in its block, the next arrays or the zeros
  // that pad the block (TriangleBlocks): never an id, which as a float
  // would be a denormal. The filter masks them off.
  __m128 lanes(int k) const {
    return _mm_loadu_ps(reinterpret_cast<const float*>(words_ + wordOf(k, count_, 0)));
  }
  const void* data() const { return words_; }
  std::size_t bytes() const { return 4 * kWordsPerTriangle * static_cast<std::size_t>(count_); }

 private:
  const std::uint32_t* words_;
  int count_;
};

// The blocks of every leaf of a triangle BVH, packed in one buffer, each
// starting on a 32-byte boundary: a block of four then has every array on
// 16 bytes, and the filter's loads stay inside their block for any count.
// (Blocks packed tighter made the filter slower than the bytes saved
// repay: docs/perf-log/2026-11-26-packed-blocks.md.) A leaf's block is
// found with no table, at kBlockAlignWords times the leaf's `first`, which
// the constructor moves from the leaf's place in the tree's order to its
// block's.
class TriangleBlocks {
 public:
  static constexpr std::size_t kBlockAlignWords = 8;

  TriangleBlocks() = default;
  // The blocks of the leaves of `tree`, at most four triangles of
  // `triangles` each (listed in tree.order, which is released). Throws
  // std::length_error for a larger leaf.
  TriangleBlocks(const TriangleSet& triangles, const BlockFrame& frame, Bvh8& tree);

  TriangleBlock block(std::uint32_t first, std::uint32_t count) const {
    return {words() + kBlockAlignWords * first, static_cast<int>(count)};
  }
  bool empty() const { return units_.empty(); }
  std::size_t bytes() const { return units_.size() * sizeof(Unit); }

 private:
  struct alignas(4 * kBlockAlignWords) Unit {
    std::uint32_t words[kBlockAlignWords];
  };
  const std::uint32_t* words() const {
    return reinterpret_cast<const std::uint32_t*>(units_.data());
  }
  std::uint32_t* words() { return reinterpret_cast<std::uint32_t*>(units_.data()); }

  BuildVector<Unit> units_;
};

// The frame that fits `box` (the set's bounds) in [-1, 1]^3.
BlockFrame blockFrame(const Aabb& box);

// One ray prepared for the blocks made in one frame.
class BlockRay {
 public:
  BlockRay(const Ray& ray, const BlockFrame& frame, TriangleKernel kernel);

  // What the filter finds in a block's lanes. `candidates`: bit i set if
  // lane i of the block may hold a hit at tMin <= t <= tMax (world
  // distances) for the exact kernel; lanes past its count are clear.
  struct Lanes {
    int candidates, certain;
  };
  // The candidates, and beside them the lanes the exact kernel is sure to
  // hit at tMin < t < tMax (`certain`, a subset): an any-hit search needs
  // no exact test of those. Only double-precision kernels are ever sure.
  Lanes classify(TriangleBlock block, double tMin, double tMax) const {
    return test<Mode::Certain>(block, tMin, tMax);
  }
  // The candidates (none certain), and beside them, when there are two or
  // more, a lower bound
  // on each one's distance (`near`, in the ray's local units; -inf for a
  // lane the filter cannot bound): a closest-hit search tests them nearest
  // first and leaves out those that lie beyond() the hit it has found.
  struct Ranked : Lanes {
    alignas(16) float near[kBlockLanes];
  };
  Ranked rank(TriangleBlock block, double tMin, double tMax) const {
    Ranked ranked;
    static_cast<Lanes&>(ranked) = test<Mode::Ranked>(block, tMin, tMax, ranked.near);
    return ranked;
  }
  // Whether a lane of bound `near` (rank) is one the filter drops for a
  // limit of tMax: the filter's own far test, rearranged.
  bool beyond(float near, double tMax) const { return near > farLimit(tMax); }

 private:
  enum class Mode { Certain, Ranked };
  // Mode::Ranked also writes rank()'s bounds to `near`.
  template <Mode kMode>
  [[gnu::always_inline]] Lanes test(TriangleBlock block, double tMin, double tMax,
                                    float* near = nullptr) const;
  // The lanes where one of the three edge functions (beta det, gamma det,
  // det - beta det - gamma det) is clearly positive and another clearly
  // negative, given their margins (the third's is mBetaGammaDet plus its
  // own roundings): the ray passes outside whichever way the triangle
  // faces. Out of line: only the rare lanes whose det is within its margin
  // need it, and inlined it would crowd the filter.
  [[gnu::noinline]] static int outsideEitherWay(__m128 det, __m128 bet, __m128 gam, __m128 mBeta,
                                                __m128 mGamma, __m128 mBetaGammaDet);
  // tMax in local units, rounded up with room for the filter's roundings.
  float farLimit(double tMax) const {
    return std::min(static_cast<float>(tMax * tScale_ * (1 + 0x1p-20)), 0x1p127f);
  }

  __m128 origin_[3], direction_[3];
  float originError_ = 0.0f;    // bound on the error of o' - v0 (see the .cpp)
  float kernelError_ = 0.0f;    // the exact kernel's own input error, as a length
  float directionSize_ = 0.0f;  // largest |d'| component, rounded up
  float inverseDirection_ = 0.0f;  // at least 1 / |d| (largest world component)
  double tScale_ = 1.0;            // local t = world t * tScale_
  bool filter_ = true;             // false: every lane is a candidate (absurd magnitudes)
  bool sure_ = false;              // whether classify() may call lanes certain
};

// Cramer's rule in triple products: with s = o - v0, p = d x e2, q = s x e1,
//   det = e1.p,  beta det = s.p,  gamma det = d.q,  t det = e2.q.
// Each computed triple product x.(y x z) is within
//   m = 2 * 6 (dx Y Z + X dy Z + X Y dz + 5u X Y Z)
// of the exact one, where X, Y, Z bound the components and dx, dy, dz their
// input errors (six products, five roundings deep; the factor 2 covers the
// second-order terms and the rounding of m itself). A lane is dropped only
// if, with every quantity moved by its m against it, it still fails a
// condition: so a triangle the exact kernel accepts is never dropped.
//
// Conversely a lane is certain only if, with every quantity moved by its m
// against it, it still passes every condition with room to spare: the
// exact kernel, whose arithmetic the bounds treat as input error, then
// accepts it too. The watertight kernel also refuses a t within its own
// rounding bound (pbrt-v4's deltaT); with R bounding |v - o| (local), D the
// world direction's largest component and gamma_n = n u_double / (1 - n
// u_double), working that bound through the sheared coordinates gives
//   deltaT det < 3 R (2 gamma_3 det + 8 gamma_5 R^2 (3 + 1/D)),
// which a certain lane's t det must exceed as well.
template <BlockRay::Mode kMode>
inline BlockRay::Lanes BlockRay::test(TriangleBlock b, double tMin, double tMax,
                                      float* near) const {
  const int valid = (1 << b.count()) - 1;
  const auto unbounded = [] { return _mm_set1_ps(-std::numeric_limits<float>::infinity()); };
  if (!filter_) {
    if constexpr (kMode == Mode::Ranked) _mm_store_ps(near, unbounded());
    return {valid, 0};
  }
  constexpr float u = 0x1p-24f;
  const __m128 signBit = _mm_set1_ps(-0.0f);
  const auto abs = [&](__m128 x) { return _mm_andnot_ps(signBit, x); };
  const auto mul = [](__m128 x, __m128 y) { return _mm_mul_ps(x, y); };
  const auto add = [](__m128 x, __m128 y) { return _mm_add_ps(x, y); };
  const auto sub = [](__m128 x, __m128 y) { return _mm_sub_ps(x, y); };
  const auto splat = [](float x) { return _mm_set1_ps(x); };

  __m128 s[3], e1[3], e2[3];
  for (int a = 0; a < 3; ++a) {
    s[a] = sub(origin_[a], b.lanes(a));
    e1[a] = b.lanes(3 + a);
    e2[a] = b.lanes(6 + a);
  }
  const __m128* d = direction_;
  const __m128 p0 = sub(mul(d[1], e2[2]), mul(d[2], e2[1]));
  const __m128 p1 = sub(mul(d[2], e2[0]), mul(d[0], e2[2]));
  const __m128 p2 = sub(mul(d[0], e2[1]), mul(d[1], e2[0]));
  const __m128 q0 = sub(mul(s[1], e1[2]), mul(s[2], e1[1]));
  const __m128 q1 = sub(mul(s[2], e1[0]), mul(s[0], e1[2]));
  const __m128 q2 = sub(mul(s[0], e1[1]), mul(s[1], e1[0]));
  const __m128 det = add(add(mul(e1[0], p0), mul(e1[1], p1)), mul(e1[2], p2));
  const __m128 bet = add(add(mul(s[0], p0), mul(s[1], p1)), mul(s[2], p2));
  const __m128 gam = add(add(mul(d[0], q0), mul(d[1], q1)), mul(d[2], q2));
  const __m128 tee = add(add(mul(e2[0], q0), mul(e2[1], q1)), mul(e2[2], q2));

  // Bounds: S on s (plus its error dS), E1 and E2 on the edges (plus dE1,
  // dE2), D on d (its error, 4u D, is folded into the 9u terms). Each edge
  // keeps its own bound: a long, thin triangle's short edge would otherwise
  // be taken as long as its long one, and its margins be larger than its
  // whole determinant.
  const auto max3 = [](const __m128* x) { return _mm_max_ps(_mm_max_ps(x[0], x[1]), x[2]); };
  const __m128 absS[3] = {abs(s[0]), abs(s[1]), abs(s[2])};
  const __m128 absE1[3] = {abs(e1[0]), abs(e1[1]), abs(e1[2])};
  const __m128 absE2[3] = {abs(e2[0]), abs(e2[1]), abs(e2[2])};
  const __m128 dS = splat(originError_), kernelError = splat(kernelError_);
  const __m128 e1Max = max3(absE1), e2Max = max3(absE2);
  const __m128 e1Rounding = mul(splat(u), e1Max), e2Rounding = mul(splat(u), e2Max);
  const __m128 dE1 = add(e1Rounding, kernelError), dE2 = add(e2Rounding, kernelError);
  const __m128 sB = add(max3(absS), dS), e1B = add(e1Max, dE1), e2B = add(e2Max, dE2);
  const __m128 dB = splat(directionSize_);
  const __m128 twelve = splat(12.0f), floor = splat(0x1p-120f);
  const __m128 nineU = splat(9 * u);
  const __m128 twelveD = mul(twelve, dB);
  // beta det: x = s, y = d, z = e2; gamma det: x = d, y = s, z = e1. The
  // edges' errors that S multiplies are their roundings alone: the
  // kernel's error is a dilation of the triangle, within the dS terms (see
  // the .cpp). A certain lane needs it as an edge error too (below).
  const __m128 mBeta =
      add(mul(twelveD, add(mul(dS, e2B), mul(sB, add(mul(nineU, e2B), e2Rounding)))), floor);
  const __m128 mGamma =
      add(mul(twelveD, add(mul(dS, e1B), mul(sB, add(mul(nineU, e1B), e1Rounding)))), floor);
  // det: x = e1, y = d, z = e2.
  const __m128 mDet =
      add(mul(twelveD, add(add(mul(dE1, e2B), mul(e1B, dE2)), mul(mul(nineU, e1B), e2B))), floor);
  // t det: x = e2, y = s, z = e1.
  const __m128 e1e2 = mul(e1B, e2B);
  const __m128 mT =
      add(mul(twelve, add(add(mul(sB, add(mul(dE2, e1B), mul(e2B, dE1))), mul(dS, e1e2)),
                          mul(mul(splat(5 * u), sB), e1e2))),
          floor);

  // Flip signs so that det > 0.
  const __m128 detSign = _mm_and_ps(det, signBit);
  const __m128 absDet = abs(det);
  const __m128 betS = _mm_xor_ps(bet, detSign), gamS = _mm_xor_ps(gam, detSign);
  const __m128 teeS = _mm_xor_ps(tee, detSign);
  const __m128 undecided = _mm_cmple_ps(absDet, mDet);
  __m128 inside = _mm_and_ps(_mm_cmpge_ps(betS, _mm_xor_ps(mBeta, signBit)),
                             _mm_cmpge_ps(gamS, _mm_xor_ps(mGamma, signBit)));
  const __m128 mBary = add(mBeta, mGamma);
  inside = _mm_and_ps(inside, _mm_cmple_ps(add(betS, gamS), add(add(absDet, mBary), mDet)));
  // tMin' det - m <= t det <= tMax' det + m, with t' rounded outward.
  const __m128 farV = splat(farLimit(tMax));
  inside = _mm_and_ps(inside, _mm_cmple_ps(teeS, add(add(mul(farV, absDet), mT), mul(farV, mDet))));
  // tMin = 0 too: every query of a render has it, and without this test
  // the triangles a leaf holds behind the ray's origin would all pass.
  if (tMin >= 0) {
    const __m128 nearV = splat(static_cast<float>(tMin * tScale_ * (1 - 0x1p-20)));
    inside =
        _mm_and_ps(inside, _mm_cmpge_ps(teeS, sub(sub(mul(nearV, absDet), mT), mul(nearV, mDet))));
  }
  int candidates = _mm_movemask_ps(_mm_or_ps(undecided, inside)) & valid;
  // A lane whose det is within its margin faces no known way, so the tests
  // above cannot drop it. One edge function clearly positive and another
  // clearly negative still put the ray outside it, whichever way it faces.
  // Only single-precision kernels, whose det margin is wide, have many
  // such lanes.
  if (!sure_) {
    if (const int undecidedOnly = candidates & ~_mm_movemask_ps(inside))
      candidates &=
          ~(undecidedOnly & outsideEitherWay(det, bet, gam, mBeta, mGamma, add(mBary, mDet)));
  }
  if constexpr (kMode == Mode::Ranked) {
    // The far test above is t det <= far (det + mDet) + mT: a lane stays
    // for exactly the limits whose far is at least (t det - mT) / (det +
    // mDet), rounded down here by one float ulp for the division's own
    // rounding (far carries 2^-20 of room for the test's). Only worth its
    // division when there is a choice of order.
    if ((candidates & (candidates - 1)) == 0) {
      _mm_store_ps(near, unbounded());
      return {candidates, 0};
    }
    __m128 bound = _mm_div_ps(sub(teeS, mT), add(absDet, mDet));
    bound = sub(bound, mul(abs(bound), splat(2 * u)));
    _mm_store_ps(near,
                 _mm_or_ps(_mm_and_ps(undecided, unbounded()), _mm_andnot_ps(undecided, bound)));
    return {candidates, 0};
  }
  // A lane whose t det is not clearly above 0 cannot be certain: the
  // triangle a spawned ray leaves, met by nearly every such ray, is
  // answered here.
  if (!sure_ || !(_mm_movemask_ps(_mm_cmpgt_ps(teeS, add(mT, mT))) & candidates))
    return {candidates, 0};

  // Sums of positive terms, each rounded; so scaled they stay bounds.
  const __m128 up = splat(1 + 0x1p-20f), down = splat(1 - 0x1p-20f);
  const __m128 detLow = sub(absDet, mDet), detHigh = add(absDet, mDet);
  // The beta and gamma margins with the kernel's error as an error of the
  // edges, which S multiplies: the kernel must hit every triangle within
  // its error, not just one.
  const __m128 edgeKernel = mul(mul(twelveD, sB), kernelError);
  const __m128 mBetaSure = add(mBeta, edgeKernel), mGammaSure = add(mGamma, edgeKernel);
  __m128 sure =
      _mm_and_ps(_mm_cmpgt_ps(detLow, _mm_setzero_ps()),
                 _mm_and_ps(_mm_cmpgt_ps(betS, mBetaSure), _mm_cmpgt_ps(gamS, mGammaSure)));
  const __m128 baryHigh = add(add(betS, gamS), add(add(mBetaSure, mGammaSure), mDet));
  sure = _mm_and_ps(sure, _mm_cmplt_ps(mul(baryHigh, up), detLow));
  // t det above tMin det and the watertight kernel's deltaT det.
  const __m128 r = add(sB, _mm_max_ps(e1B, e2B));
  const __m128 deltaT =
      mul(mul(splat(3.0f), r),
          add(mul(splat(0x1p-50f), detHigh),
              mul(mul(mul(splat(0x1p-47f), r), r), add(splat(3.0f), splat(inverseDirection_)))));
  const float nearSure = static_cast<float>(std::max(tMin, 0.0) * tScale_ * (1 + 0x1p-20));
  const __m128 teeLow = add(add(mT, mul(splat(nearSure), detHigh)), deltaT);
  sure = _mm_and_ps(sure, _mm_cmpgt_ps(teeS, mul(teeLow, up)));
  // t det below tMax det.
  const double farSure = tMax * tScale_ * (1 - 0x1p-20);
  if (!(farSure >= 0x1p127))  // NaN included: then nothing is certain
    sure =
        _mm_and_ps(sure, _mm_cmplt_ps(mul(add(teeS, mT), up),
                                      mul(mul(splat(static_cast<float>(farSure)), detLow), down)));
  return {candidates, _mm_movemask_ps(sure) & candidates};
}

}  // namespace meshtrace
