// Building the triangle blocks of the triangle BVH and preparing a ray for them.
#include "accel/triangle_block.h"

#include <tbb/parallel_for.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>
#include <string>

#include "accel/triangle_set.h"
#include "meshtrace/geometry/mesh.h"

namespace meshtrace {

BlockFrame blockFrame(const Aabb& box) {
  BlockFrame frame;
  if (box.empty()) return frame;
  frame.center = box.center();
  const double half = 0.5 * maxComponent(box.extent());
  // A power of two putting `half` in [0.5, 1): local coordinates are then
  // within [-1, 1] (a hair more after rounding, which the bounds allow for).
  frame.scale = half > 0.0 ? std::ldexp(1.0, -std::ilogb(half) - 1) : 1.0;
  frame.worldSize = maxAbsComponent(frame.center) + half;
  return frame;
}

namespace {

// The corner a block stores as v0, the one opposite the triangle's longest
// edge, so that e1 and e2 are its two shortest edges (the order of the
// corners turns, the winding stays). The filter's error bounds grow with
// the edges' lengths |e1| |e2|, its determinant with the area |e1 x e2|:
// from that corner the angle between them is the triangle's widest, at
// least 60 degrees, and a long sliver (two long edges, one short) keeps
// margins in proportion to its area. From a corner at the sliver's sharp
// tip, both edges would be long and the margins could exceed the whole
// determinant, passing every ray near the sliver's plane to the exact test.
int cornerOppositeLongestEdge(const std::vector<Vec3>& v, const TriangleIndices& idx) {
  const double opposite[3] = {glm::dot(v[idx[1]] - v[idx[2]], v[idx[1]] - v[idx[2]]),
                              glm::dot(v[idx[2]] - v[idx[0]], v[idx[2]] - v[idx[0]]),
                              glm::dot(v[idx[0]] - v[idx[1]], v[idx[0]] - v[idx[1]])};
  int longest = 0;
  for (int k = 1; k < 3; ++k)
    if (opposite[k] > opposite[longest]) longest = k;
  return longest;
}

// The words a block of `count` triangles takes, padded to a multiple of
// kBlockAlignWords.
constexpr std::size_t paddedWords(std::size_t count) {
  constexpr std::size_t kAlign = TriangleBlocks::kBlockAlignWords;
  return (TriangleBlock::kWordsPerTriangle * count + kAlign - 1) / kAlign * kAlign;
}

// The filter's last load, four lanes of array 8, reaches past the block's
// data by kBlockLanes - count words: into its padding, never into the next
// block, whatever the count.
static_assert([] {
  for (std::size_t count = 1; count <= kBlockLanes; ++count)
    if (TriangleBlock::wordOf(8, count, kBlockLanes - 1) >= paddedWords(count)) return false;
  return true;
}());

}  // namespace

TriangleBlocks::TriangleBlocks(const TriangleSet& triangles, const BlockFrame& frame, Bvh8& tree) {
  for (const Bvh8Leaf& leaf : leavesOf(tree))
    if (leaf.count > kBlockLanes)
      throw std::length_error("a triangle BVH leaf of " + std::to_string(leaf.count) +
                              " triangles, over a block's " + std::to_string(kBlockLanes));
  // The blocks go in the order the nodes list their leaves, not in the
  // tree's order, and each leaf's `first` moves to its block's place: the
  // leaf children of one node, which a ray meeting the node tests
  // together, then lie side by side, where the tree's order would put the
  // triangles of the node's other subtrees between them.
  struct Move {
    std::uint32_t from, to, count;
  };
  constexpr std::size_t kAlign = TriangleBlocks::kBlockAlignWords;
  std::vector<Move> moves;
  std::size_t packed = 0;  // words
  const auto place = [&](std::uint32_t& first, std::uint32_t count) {
    moves.push_back({first, static_cast<std::uint32_t>(packed / kAlign), count});
    first = static_cast<std::uint32_t>(packed / kAlign);
    packed += paddedWords(count);
  };
  if (tree.nodes.empty()) {
    std::uint32_t root = 0;
    if (tree.rootCount > 0) place(root, tree.rootCount);
  }
  for (Bvh8Node& node : tree.nodes)
    for (int i = 0; i < kBvhWidth; ++i)
      if (node.count[i] != 0) place(node.first[i], node.count[i]);
  units_.resize(packed / kAlign);  // written below, the padding as zeros
  const auto local = [&](const Vec3& p) { return (p - frame.center) * frame.scale; };
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, moves.size(), 4096),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t k = r.begin(); k < r.end(); ++k) {
                        // Not a structured binding: Clang 14 cannot capture
                        // one in the lambda below.
                        const std::uint32_t from = moves[k].from, count = moves[k].count;
                        const std::uint32_t to = moves[k].to;
                        std::uint32_t* words = this->words() + kAlign * to;
                        std::fill(words + TriangleBlock::kWordsPerTriangle * count,
                                  words + paddedWords(count), 0u);
                        const auto put = [&](std::size_t array, std::uint32_t lane, double x) {
                          words[TriangleBlock::wordOf(array, count, lane)] =
                              std::bit_cast<std::uint32_t>(static_cast<float>(x));
                        };
                        for (std::uint32_t lane = 0; lane < count; ++lane) {
                          const std::uint32_t t = tree.order[from + lane];
                          const TriangleSet::Member member = triangles[t];
                          const auto& v = member.mesh->vertices();
                          const TriangleIndices& idx = member.indices();
                          const int corner = cornerOppositeLongestEdge(v, idx);
                          const Vec3& v0 = v[idx[corner]];
                          const Vec3& v1 = v[idx[(corner + 1) % 3]];
                          const Vec3& v2 = v[idx[(corner + 2) % 3]];
                          const Vec3 a = local(v0);
                          const Vec3 e1 = (v1 - v0) * frame.scale;
                          const Vec3 e2 = (v2 - v0) * frame.scale;
                          for (int axis = 0; axis < 3; ++axis) {
                            put(axis, lane, a[axis]);
                            put(3 + axis, lane, e1[axis]);
                            put(6 + axis, lane, e2[axis]);
                          }
                          words[lane] = t;
                        }
                      }
                    });
  tree.order.clear();
  tree.order.shrink_to_fit();
}

// The filter's error bounds are in local lengths, as multiples of float's
// u = 2^-24:
// - originError bounds the error of s = o' - v0 in float: the roundings of
//   o' (u |o'|), of v0 (u, as |v0| <= 1) and of the subtraction
//   (u (|o'| + 1)), plus the kernel's.
// - kernelError is how far the exact kernel's own arithmetic may move the
//   vertices and the origin, in world terms k u_kernel (|o| + |v|), scaled to
//   local lengths; the filter treats it as extra input error. k = 2^10 for
//   double kernels is far above their few roundings; single-precision
//   kernels round the world coordinates to float, so their k is 32 u_float.
// The beta and gamma margins take kernelError differently for dropping a
// lane and for calling it certain. As an error of the edges, it would be
// multiplied by the origin's distance S, the whole way to the triangle,
// and a single-precision kernel's lanes near the ray would all pass. To
// drop a lane a dilation is enough: the kernel acts as the exact test on a
// triangle whose corners, relative to the origin, moved by at most
// r = 2 sqrt(3) kernelError, so its shadow across the ray lies within r of
// the triangle's own; beta det is |d x e2| times the ray's signed distance
// from the edge v0 v2, and a ray more than r outside an edge misses every
// such triangle. r |d x e2| <= 6 sqrt(3) D E2 kernelError lies within the
// margin's dS E2 term (dS includes kernelError), so S multiplies only the
// edges' roundings. To call a lane certain the kernel must hit every such
// triangle, which a dilation does not show: there the S term keeps
// kernelError.
//
// The same margins, in outsideEitherWay, drop lanes whose det is too close
// to 0 to tell which way they face (a triangle the ray sees edge-on), for
// the kernels never sure of a lane: a single-precision kernel's wide det
// margin makes many such lanes, a double kernel's few.

BlockRay::BlockRay(const Ray& ray, const BlockFrame& frame, TriangleKernel kernel) {
  const Vec3 o = (ray.origin - frame.center) * frame.scale;
  const double dSize = maxAbsComponent(ray.direction);
  const double oSize = maxAbsComponent(o);
  const double world = (maxAbsComponent(ray.origin) + frame.worldSize) * frame.scale;
  const double kernelError =
      kernel.precision == Precision::Double ? 0x1p10 * 0x1p-53 * world : 32 * 0x1p-24 * world;
  // d' = d / 2^k has its largest component in [1, 2): t' = t 2^k scale.
  // The power of two is read off dSize's exponent bits (ldexp is a call).
  const auto exponent = (std::bit_cast<std::uint64_t>(dSize) >> 52) & 0x7ff;
  filter_ = exponent != 0 && exponent != 0x7ff && oSize < 0x1p40 && kernelError < 0x1p20;
  if (!filter_) return;
  const double twoToK = std::bit_cast<double>(exponent << 52);
  const double twoToMinusK = std::bit_cast<double>((2046 - exponent) << 52);
  for (int a = 0; a < 3; ++a) {
    origin_[a] = _mm_set1_ps(static_cast<float>(o[a]));
    direction_[a] = _mm_set1_ps(static_cast<float>(ray.direction[a] * twoToMinusK));
  }
  tScale_ = frame.scale * twoToK;
  const double up = 1.0 + 0x1p-20;
  directionSize_ = static_cast<float>(dSize * twoToMinusK * up);
  // 1 / dSize <= 2^-k, since dSize = |d'| 2^k with |d'| >= 1: a bound with
  // no division.
  inverseDirection_ = static_cast<float>(twoToMinusK);
  sure_ = kernel.precision == Precision::Double && inverseDirection_ < 0x1p60f;
  kernelError_ = static_cast<float>(kernelError * up);
  originError_ = static_cast<float>((0x1p-24 * (2 * oSize + 3) + kernelError) * up);
}

int BlockRay::outsideEitherWay(__m128 det, __m128 bet, __m128 gam, __m128 mBeta, __m128 mGamma,
                               __m128 mBetaGammaDet) {
  const __m128 signBit = _mm_set1_ps(-0.0f);
  const auto abs = [&](__m128 x) { return _mm_andnot_ps(signBit, x); };
  const __m128 alpha = _mm_sub_ps(_mm_sub_ps(det, bet), gam);
  // Its two subtractions round by at most 2u of |det| + |beta det| + |gamma
  // det| (with room).
  const __m128 mAlpha = _mm_add_ps(
      mBetaGammaDet,
      _mm_mul_ps(_mm_set1_ps(0x1p-22f), _mm_add_ps(_mm_add_ps(abs(det), abs(bet)), abs(gam))));
  const __m128 positive = _mm_or_ps(_mm_or_ps(_mm_cmpgt_ps(bet, mBeta), _mm_cmpgt_ps(gam, mGamma)),
                                    _mm_cmpgt_ps(alpha, mAlpha));
  const __m128 negative = _mm_or_ps(_mm_or_ps(_mm_cmplt_ps(bet, _mm_xor_ps(mBeta, signBit)),
                                              _mm_cmplt_ps(gam, _mm_xor_ps(mGamma, signBit))),
                                    _mm_cmplt_ps(alpha, _mm_xor_ps(mAlpha, signBit)));
  return _mm_movemask_ps(_mm_and_ps(positive, negative));
}

}  // namespace meshtrace
