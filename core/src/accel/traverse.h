#pragma once
// Traversal of a Bvh8: two SSE slab tests per node check all eight child
// boxes in float. Closest hit visits the children a ray meets in the order
// its node keeps for the ray's octant; any-hit stops at the first blocker.
// The leaf work is a callback, as in the binary BVH.
#include <emmintrin.h>
#include <xmmintrin.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "accel/bvh8.h"
#include "accel/slab_ray.h"
#include "util/prefetch.h"

namespace meshtrace {

// The ray prepared for float slab tests that stay conservative: every box is
// tested as if widened by pad.absolute, with the distances scaled by
// 1 -/+ pad.relative (bvh_ray.h), whatever the float rounding does. The
// set-up runs in float on all three axes at once (u = 2^-24 below):
// - The origin is moved toward the far plane for the near distance (and the
//   other way for the far one) by shift = a + 2^-21 |o|, a = pad.absolute
//   (1 + 2^-20) rounded to float (2^-21 |o| is exact, a power of two).
//   Converting o and a, adding to form shift and adding it to o lose at most
//   2u |o| + 3u a; the 8u |o| and 16u a in shift cover that, so the float
//   origin is still on the widened side.
// - A reciprocal goes through five roundings (direction to float, the
//   division, the scale factor, the subtraction and the product of the slab
//   test), a relative error below 5u < 2^-21; the scale factors carry 2^-19
//   beyond pad.relative, which covers it with room for the factor's own
//   rounding (2^-24).
// - A zero or tiny component gets reciprocal +-1e30 rather than inf, so that
//   (plane - origin) * reciprocal is never 0 * inf = NaN.
class SlabRay {
 public:
  SlabRay(const Ray& ray, const SlabPadding& pad) {
    const __m128 signBit = _mm_set1_ps(-0.0f);
    const __m128 o = toFloats(ray.origin), d = toFloats(ray.direction);
    const __m128 dSign = _mm_and_ps(d, signBit);
    const __m128 absD = _mm_max_ps(_mm_andnot_ps(signBit, d), _mm_set1_ps(1e-30f));
    const __m128 inv = _mm_or_ps(_mm_div_ps(_mm_set1_ps(1.0f), absD), dSign);
    const __m128 absShift =
        _mm_add_ps(_mm_set1_ps(static_cast<float>(pad.absolute * (1.0 + 0x1p-20))),
                   _mm_mul_ps(_mm_set1_ps(0x1p-21f), _mm_andnot_ps(signBit, o)));
    const __m128 shift = _mm_or_ps(absShift, dSign);  // toward the far plane
    originNear = _mm_add_ps(o, shift);
    originFar = _mm_sub_ps(o, shift);
    invNear = _mm_mul_ps(inv, _mm_set1_ps(static_cast<float>(1.0 - pad.relative - 0x1p-19)));
    invFar = _mm_mul_ps(inv, _mm_set1_ps(static_cast<float>(1.0 + pad.relative + 0x1p-19)));
    // By the reciprocal's sign, so that -0.0 goes with the negative side,
    // as its reciprocal does.
    negative_ = _mm_cmplt_ps(invNear, _mm_setzero_ps());
    octant = _mm_movemask_ps(negative_) & 7;
  }

  // Whether the ray meets the widened box lo-hi within [tMin, tMax]: the
  // node test's arithmetic with the three axes side by side (lo and hi are
  // (x, y, z, z)), for a tree whose root is a leaf.
  bool meets(const float* lo, const float* hi, float tMin, float tMax) const {
    const __m128 low = _mm_load_ps(lo), high = _mm_load_ps(hi);
    const __m128 nearPlane = _mm_or_ps(_mm_and_ps(negative_, high), _mm_andnot_ps(negative_, low));
    const __m128 farPlane = _mm_or_ps(_mm_and_ps(negative_, low), _mm_andnot_ps(negative_, high));
    __m128 enter = _mm_mul_ps(_mm_sub_ps(nearPlane, originNear), invNear);
    __m128 exit = _mm_mul_ps(_mm_sub_ps(farPlane, originFar), invFar);
    enter = _mm_max_ps(enter, _mm_shuffle_ps(enter, enter, 0x4e));
    enter = _mm_max_ps(enter, _mm_shuffle_ps(enter, enter, 0xb1));
    exit = _mm_min_ps(exit, _mm_shuffle_ps(exit, exit, 0x4e));
    exit = _mm_min_ps(exit, _mm_shuffle_ps(exit, exit, 0xb1));
    const float in = _mm_cvtss_f32(enter), out = _mm_cvtss_f32(exit);
    return in <= out && in <= tMax && tMin <= out;
  }

  // Lanes x, y, z (w: a copy of z, harmless in the reductions above).
  __m128 originNear, originFar, invNear, invFar;
  int octant;  // the direction's signs: bit a set if d[a] < 0

 private:
  // (x, y, z, z) in float.
  static __m128 toFloats(const Vec3& v) {
    const __m128 z = _mm_cvtpd_ps(_mm_load1_pd(&v[2]));
    return _mm_movelh_ps(_mm_cvtpd_ps(_mm_loadu_pd(&v[0])), z);
  }

  __m128 negative_;  // lanes whose direction component is negative
};

// The slab ray with each axis splatted over four lanes, for the node test.
// Made when a traversal reaches its first node: a ray that misses a tree
// whose root is a leaf never needs it.
class BoxRay8 {
 public:
  explicit BoxRay8(const SlabRay& ray) : octant_(ray.octant) {
    splat(ray.originNear, originNear_);
    splat(ray.originFar, originFar_);
    splat(ray.invNear, invNear_);
    splat(ray.invFar, invFar_);
    // The near and far planes of each axis in a node, by the direction's
    // signs, so that the slab test picks them without a branch.
    const auto& planes = kPlaneOffsets[octant_];
    std::copy(planes.begin(), planes.end(), planeOffset_);
  }

  int octant() const { return octant_; }

  // Bit i set if the ray meets child i's widened box within [tMin, tMax];
  // tEnter[i] receives its entry distance. Children 0-3 and 4-7 are tested
  // side by side, two independent chains of the same length as one.
  unsigned intersect(const Bvh8Node& node, __m128 tMin, __m128 tMax, float* tEnter) const {
    __m128 enterLow = tMin, enterHigh = tMin, exitLow = tMax, exitHigh = tMax;
    const char* base = reinterpret_cast<const char*>(&node);
    const auto slab = [](const float* plane, __m128 origin, __m128 inv, __m128& low,
                         __m128& high) {
      low = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(plane), origin), inv);
      high = _mm_mul_ps(_mm_sub_ps(_mm_load_ps(plane + 4), origin), inv);
    };
    for (int a = 0; a < 3; ++a) {
      __m128 low, high;
      slab(reinterpret_cast<const float*>(base + planeOffset_[a]), originNear_[a], invNear_[a],
           low, high);
      enterLow = _mm_max_ps(enterLow, low);
      enterHigh = _mm_max_ps(enterHigh, high);
      slab(reinterpret_cast<const float*>(base + planeOffset_[3 + a]), originFar_[a], invFar_[a],
           low, high);
      exitLow = _mm_min_ps(exitLow, low);
      exitHigh = _mm_min_ps(exitHigh, high);
    }
    _mm_store_ps(tEnter, enterLow);
    _mm_store_ps(tEnter + 4, enterHigh);
    return static_cast<unsigned>(_mm_movemask_ps(_mm_cmple_ps(enterLow, exitLow)) |
                                 _mm_movemask_ps(_mm_cmple_ps(enterHigh, exitHigh)) << 4);
  }

 private:
  static void splat(__m128 xyz, __m128 out[3]) {
    out[0] = _mm_shuffle_ps(xyz, xyz, 0x00);
    out[1] = _mm_shuffle_ps(xyz, xyz, 0x55);
    out[2] = _mm_shuffle_ps(xyz, xyz, 0xaa);
  }

  // Byte offsets in a Bvh8Node of the near planes (x, y, z), then the far
  // ones, for each sign pattern of the direction (bit a: d[a] < 0).
  static constexpr auto kPlaneOffsets = [] {
    std::array<std::array<std::uint32_t, 6>, 8> table{};
    for (int signs = 0; signs < 8; ++signs)
      for (int a = 0; a < 3; ++a) {
        const std::size_t axis = a * kBvhWidth * sizeof(float);
        const auto lo = static_cast<std::uint32_t>(offsetof(Bvh8Node, lo) + axis);
        const auto hi = static_cast<std::uint32_t>(offsetof(Bvh8Node, hi) + axis);
        const bool flip = (signs >> a) & 1;
        table[signs][a] = flip ? hi : lo;
        table[signs][3 + a] = flip ? lo : hi;
      }
    return table;
  }();

  __m128 originNear_[3], originFar_[3], invNear_[3], invFar_[3];
  std::uint32_t planeOffset_[6];
  int octant_;
};

namespace bvh8 {

// A float no smaller than t (t * (1 + 2^-23) is above t by at least half a
// float ulp, so rounding to nearest cannot fall below t); inf stays inf.
inline float atLeast(double t) { return static_cast<float>(t * (1.0 + 0x1p-23)); }
inline float atMost(double t) { return t <= 0.0 ? static_cast<float>(t * (1.0 + 0x1p-23))
                                                : static_cast<float>(t * (1.0 - 0x1p-23)); }

struct Entry {
  std::uint32_t first, count;  // a node (count 0) or a leaf's primitive range
  float tEnter;
};
// Each level pushes at most seven entries besides the one it continues with;
// eight more slots take the writes of pushInOrder past the top.
inline constexpr int kStackSize = 7 * kMaxBvhDepth + kBvhWidth;

// What a traversal asks the memory for when a node shows which children a
// ray meets: by default nothing.
struct NoPrefetch {
  void operator()(const Bvh8Node*, const Bvh8Node&, unsigned) const {}
};

// Asks for the nodes, and through leafData(first) the leaf data, of the
// children in `mask`, before the traversal branches on them: on a tree far
// larger than the caches, each visit otherwise waits for memory in turn, and
// a mispredicted branch delays the next load further. Whether it pays is a
// matter of the tree's size (scene_bvh.h), so it is switched at run time.
template <typename LeafData>
class PrefetchChildren {
 public:
  PrefetchChildren(bool enabled, LeafData leafData) : enabled_(enabled), leafData_(leafData) {}

  [[gnu::always_inline]] void operator()(const Bvh8Node* nodes, const Bvh8Node& node,
                                         unsigned mask) const {
    if (!enabled_) return;
    for (; mask; mask &= mask - 1) {
      const int i = __builtin_ctz(mask);
      if (node.count[i] != 0)
        leafData_(node.first[i]);
      else
        prefetchObject(nodes[node.first[i]]);
    }
  }

 private:
  bool enabled_;
  LeafData leafData_;
};

// Pushes the children in `mask` farthest first by `childOrder`
// (Bvh8Node::childOrder), then pops and returns the nearest. Every slot is
// written and the top moves only past the children hit, so neither the
// number hit nor their distances cost a branch.
inline Entry pushInOrder(const Bvh8Node& node, unsigned mask, std::uint32_t childOrder,
                         const float* tEnter, Entry* stack, int& top) {
#pragma GCC unroll 8
  for (int k = kBvhWidth - 1; k >= 0; --k) {
    const unsigned slot = childOrder >> (3 * k) & 7;
    stack[top] = {node.first[slot], node.count[slot], tEnter[slot]};
    top += static_cast<int>(mask >> slot & 1);
  }
  return stack[--top];
}

}  // namespace bvh8

// Calls leaf(first, count) for the leaves whose boxes the ray meets at
// tMin <= t <= tBest, nearer boxes first as the nodes' octant orders
// estimate them. The leaf may lower tBest (it is read again after every
// call); a box entered exactly at tBest is still visited, so that a later
// primitive at the same distance can win a tie. `prefetch` is shown each
// node's children met before they are taken (NoPrefetch, PrefetchChildren).
// Sorting the children by entry distance instead takes branches that depend
// on each ray's data: measured on fandisk's hitting primary rays, the
// traversal alone took 139 ns with an insertion sort of the children hit
// and 95 ns with this fixed order, for the same 5.3 node visits.
// (Both traversals are forced inline: see scene_bvh_query.cpp.)
template <typename Leaf, typename Prefetch = bvh8::NoPrefetch>
[[gnu::always_inline]] inline void traverseClosest(const Bvh8& bvh, const SlabRay& slab,
                                                   double tMin, const double& tBest,
                                                   std::uint64_t& visits, Leaf&& leaf,
                                                   const Prefetch& prefetch = {}) {
  if (bvh.empty()) return;
  if (bvh.nodes.empty()) {
    if (slab.meets(bvh.rootLo, bvh.rootHi, bvh8::atMost(tMin), bvh8::atLeast(tBest)))
      leaf(0, bvh.rootCount);
    return;
  }
  const BoxRay8 ray(slab);
  bvh8::Entry stack[bvh8::kStackSize];
  int top = 0;
  // Locals, not the members and the caller's counter: the leaf call may
  // write anywhere, and the compiler would reload them after each one.
  const Bvh8Node* nodes = bvh.nodes.data();
  std::uint64_t visited = 0;
  const __m128 tMinV = _mm_set1_ps(bvh8::atMost(tMin));
  float tMax = bvh8::atLeast(tBest);  // refreshed after every leaf
  bvh8::Entry next{0, 0, 0.0f};       // the root
  for (;;) {
    if (next.count == 0) {
      // An interior node: continue with its nearest child hit, if any.
      const Bvh8Node& node = nodes[next.first];
      ++visited;
      alignas(16) float tEnter[kBvhWidth];
      const unsigned mask = ray.intersect(node, tMinV, _mm_set1_ps(tMax), tEnter);
      prefetch(nodes, node, mask);
      if (mask) {
        if ((mask & (mask - 1)) == 0) {
          const int i = __builtin_ctz(mask);
          next = {node.first[i], node.count[i], 0.0f};
        } else {
          next = bvh8::pushInOrder(node, mask, node.childOrder(ray.octant()), tEnter, stack, top);
        }
        continue;
      }
    } else {
      leaf(next.first, next.count);
      tMax = bvh8::atLeast(tBest);
    }
    // Resume with the nearest postponed child that may still hold a hit.
    do {
      if (top == 0) {
        visits += visited;
        return;
      }
      next = stack[--top];
    } while (next.tEnter > tMax);
  }
}

// Calls blocked(first, count) for the leaves whose boxes the ray meets at
// tMin <= t <= tMax until one returns true; returns whether one did.
// `prefetch` as for traverseClosest.
template <typename Leaf, typename Prefetch = bvh8::NoPrefetch>
[[gnu::always_inline]] inline bool traverseAny(const Bvh8& bvh, const SlabRay& slab, double tMin,
                                               double tMax, std::uint64_t& visits,
                                               Leaf&& blocked, const Prefetch& prefetch = {}) {
  if (bvh.empty()) return false;
  if (bvh.nodes.empty())
    return slab.meets(bvh.rootLo, bvh.rootHi, bvh8::atMost(tMin), bvh8::atLeast(tMax)) &&
           blocked(0, bvh.rootCount);
  const BoxRay8 ray(slab);
  std::uint32_t stack[bvh8::kStackSize];
  int top = 0;
  stack[top++] = 0;
  const Bvh8Node* nodes = bvh.nodes.data();
  std::uint64_t visited = 0;
  const __m128 tMinV = _mm_set1_ps(bvh8::atMost(tMin));
  const __m128 tMaxV = _mm_set1_ps(bvh8::atLeast(tMax));
  bool found = false;
  while (top > 0 && !found) {
    const Bvh8Node& node = nodes[stack[--top]];
    ++visited;
    alignas(16) float tEnter[kBvhWidth];
    unsigned mask = ray.intersect(node, tMinV, tMaxV, tEnter);
    prefetch(nodes, node, mask);
    for (; mask; mask &= mask - 1) {
      const int i = __builtin_ctz(mask);
      if (node.count[i] == 0) {
        stack[top++] = node.first[i];
      } else if (blocked(node.first[i], node.count[i])) {
        found = true;
        break;
      }
    }
  }
  visits += visited;
  return found;
}

}  // namespace meshtrace
