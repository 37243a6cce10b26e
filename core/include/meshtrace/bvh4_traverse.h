#pragma once
// Traversal of a Bvh4: one SSE slab test per node checks all four child
// boxes in float. Closest hit visits the children a ray meets in the order
// its node keeps for the ray's octant; any-hit stops at the first blocker. The leaf work is a callback, as in the binary BVH.
#include <emmintrin.h>
#include <xmmintrin.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

#include "meshtrace/bvh4.h"
#include "meshtrace/bvh_ray.h"

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
class BoxRay4 {
 public:
  BoxRay4(const Ray& ray, const SlabPadding& pad) {
    const __m128 signBit = _mm_set1_ps(-0.0f);
    const __m128 o = toFloats(ray.origin), d = toFloats(ray.direction);
    const __m128 dSign = _mm_and_ps(d, signBit);
    const __m128 absD = _mm_max_ps(_mm_andnot_ps(signBit, d), _mm_set1_ps(1e-30f));
    const __m128 inv = _mm_or_ps(_mm_div_ps(_mm_set1_ps(1.0f), absD), dSign);
    const __m128 absShift =
        _mm_add_ps(_mm_set1_ps(static_cast<float>(pad.absolute * (1.0 + 0x1p-20))),
                   _mm_mul_ps(_mm_set1_ps(0x1p-21f), _mm_andnot_ps(signBit, o)));
    const __m128 shift = _mm_or_ps(absShift, dSign);  // toward the far plane
    splat(_mm_add_ps(o, shift), originNear_);
    splat(_mm_sub_ps(o, shift), originFar_);
    splat(_mm_mul_ps(inv, _mm_set1_ps(static_cast<float>(1.0 - pad.relative - 0x1p-19))),
          invNear_);
    splat(_mm_mul_ps(inv, _mm_set1_ps(static_cast<float>(1.0 + pad.relative + 0x1p-19))),
          invFar_);
    // The near and far planes of each axis in a node, by the direction's
    // signs, so that the slab test picks them without a branch.
    octant_ = _mm_movemask_ps(d) & 7;
    const auto& planes = kPlaneOffsets[octant_];
    std::copy(planes.begin(), planes.end(), planeOffset_);
  }

  // The direction's signs: bit a set if d[a] < 0.
  int octant() const { return octant_; }

  // Bit i set if the ray meets child i's widened box within [tMin, tMax];
  // tEnter holds the entry distances.
  int intersect(const Bvh4Node& node, __m128 tMin, __m128 tMax, __m128& tEnter) const {
    __m128 enter = tMin, exit = tMax;
    const char* base = reinterpret_cast<const char*>(&node);
    for (int a = 0; a < 3; ++a) {
      const __m128 nearPlane = _mm_load_ps(reinterpret_cast<const float*>(base + planeOffset_[a]));
      const __m128 farPlane =
          _mm_load_ps(reinterpret_cast<const float*>(base + planeOffset_[3 + a]));
      enter = _mm_max_ps(enter, _mm_mul_ps(_mm_sub_ps(nearPlane, originNear_[a]), invNear_[a]));
      exit = _mm_min_ps(exit, _mm_mul_ps(_mm_sub_ps(farPlane, originFar_[a]), invFar_[a]));
    }
    tEnter = enter;
    return _mm_movemask_ps(_mm_cmple_ps(enter, exit));
  }

 private:
  // (x, y, z, 0) in float.
  static __m128 toFloats(const Vec3& v) {
    return _mm_movelh_ps(_mm_cvtpd_ps(_mm_loadu_pd(&v[0])), _mm_cvtpd_ps(_mm_load_sd(&v[2])));
  }
  static void splat(__m128 xyz, __m128 out[3]) {
    out[0] = _mm_shuffle_ps(xyz, xyz, 0x00);
    out[1] = _mm_shuffle_ps(xyz, xyz, 0x55);
    out[2] = _mm_shuffle_ps(xyz, xyz, 0xaa);
  }

  // Byte offsets in a Bvh4Node of the near planes (x, y, z), then the far
  // ones, for each sign pattern of the direction (bit a: d[a] < 0).
  static constexpr auto kPlaneOffsets = [] {
    std::array<std::array<std::uint32_t, 6>, 8> table{};
    for (int signs = 0; signs < 8; ++signs)
      for (int a = 0; a < 3; ++a) {
        const auto lo = static_cast<std::uint32_t>(offsetof(Bvh4Node, lo) + a * sizeof(__m128));
        const auto hi = static_cast<std::uint32_t>(offsetof(Bvh4Node, hi) + a * sizeof(__m128));
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

namespace bvh4 {

// A float no smaller than t (t * (1 + 2^-23) is above t by at least half a
// float ulp, so rounding to nearest cannot fall below t); inf stays inf.
inline float atLeast(double t) { return static_cast<float>(t * (1.0 + 0x1p-23)); }
inline float atMost(double t) { return t <= 0.0 ? static_cast<float>(t * (1.0 + 0x1p-23))
                                                : static_cast<float>(t * (1.0 - 0x1p-23)); }

struct Entry {
  std::uint32_t first, count;  // a node (count 0) or a leaf's primitive range
  float tEnter;
};
// Each level pushes at most three entries besides the one it continues with;
// two more slots take the unused writes of pushFarther.
inline constexpr int kStackSize = 3 * kMaxBvhDepth + 3;

// What the closest-hit traversal does at a node, for each child order
// (kChildOrders) and mask of children hit: with the hit children c0 .. c(n-1)
// in that order, bits 0-1 hold c0 (visited next), bits 2-4 n, and bits 5-10
// the others farthest first, c(n-1) .. c1 (two bits each, 0 past the end).
inline constexpr auto kVisitPlans = [] {
  std::array<std::array<std::uint16_t, 16>, kChildOrderCount> plans{};
  for (int o = 0; o < kChildOrderCount; ++o)
    for (int mask = 1; mask < 16; ++mask) {
      int hit[4], n = 0;
      for (int k = 0; k < 4; ++k) {
        const int slot = kChildOrders[o] >> (2 * k) & 3;
        if (mask >> slot & 1) hit[n++] = slot;
      }
      int plan = hit[0] | n << 2;
      for (int k = 0; k < n - 1; ++k) plan |= hit[n - 1 - k] << (5 + 2 * k);
      plans[o][mask] = static_cast<std::uint16_t>(plan);
    }
  return plans;
}();

// Pushes the hit children other than the first of `plan`, farthest first.
// Three entries are always written and `top` then moves past the real ones,
// so the number of children hit costs no branch.
inline void pushFarther(const Bvh4Node& node, unsigned plan, __m128 tEnter, Entry* stack,
                        int& top) {
  alignas(16) float t[4];
  _mm_store_ps(t, tEnter);
  for (int k = 0; k < 3; ++k) {
    const unsigned slot = plan >> (5 + 2 * k) & 3;
    stack[top + k] = {node.first[slot], node.count[slot], t[slot]};
  }
  top += static_cast<int>(plan >> 2 & 7) - 1;
}

}  // namespace bvh4

// Calls leaf(first, count) for the leaves whose boxes the ray meets at
// tMin <= t <= tBest, nearer boxes first as the nodes' octant orders
// estimate them. The leaf may lower tBest (it is read again after every
// call); a box entered exactly at tBest is still visited, so that a later
// primitive at the same distance can win a tie.
// Sorting the children by entry distance instead, with its branches that
// depend on each ray's data, made primary rays 2-4% slower than this fixed
// order, although the fixed order visits up to 7% more nodes (armadillo).
// (Both traversals are forced inline: see scene_bvh_query.cpp.)
template <typename Leaf>
[[gnu::always_inline]] inline void traverseClosest(const Bvh4& bvh, const BoxRay4& ray,
                                                   double tMin, const double& tBest,
                                                   std::uint64_t& visits, Leaf&& leaf) {
  if (bvh.empty()) return;
  if (bvh.nodes.empty()) return leaf(0, bvh.rootCount);
  bvh4::Entry stack[bvh4::kStackSize];
  int top = 0;
  // Locals, not the members and the caller's counter: the leaf call may
  // write anywhere, and the compiler would reload them after each one.
  const Bvh4Node* nodes = bvh.nodes.data();
  std::uint64_t visited = 0;
  const __m128 tMinV = _mm_set1_ps(bvh4::atMost(tMin));
  float tMax = bvh4::atLeast(tBest);  // refreshed after every leaf
  bvh4::Entry next{0, 0, 0.0f};       // the root
  for (;;) {
    if (next.count == 0) {
      // An interior node: continue with its nearest child hit, if any.
      const Bvh4Node& node = nodes[next.first];
      ++visited;
      __m128 tEnter;
      const int mask = ray.intersect(node, tMinV, _mm_set1_ps(tMax), tEnter);
      if (mask) {
        const unsigned plan = bvh4::kVisitPlans[node.order[ray.octant()]][mask];
        bvh4::pushFarther(node, plan, tEnter, stack, top);
        const unsigned nearest = plan & 3;
        next = {node.first[nearest], node.count[nearest], 0.0f};
        continue;
      }
    } else {
      leaf(next.first, next.count);
      tMax = bvh4::atLeast(tBest);
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
template <typename Leaf>
[[gnu::always_inline]] inline bool traverseAny(const Bvh4& bvh, const BoxRay4& ray, double tMin,
                                               double tMax, std::uint64_t& visits,
                                               Leaf&& blocked) {
  if (bvh.empty()) return false;
  if (bvh.nodes.empty()) return blocked(0, bvh.rootCount);
  std::uint32_t stack[bvh4::kStackSize];
  int top = 0;
  stack[top++] = 0;
  const Bvh4Node* nodes = bvh.nodes.data();
  std::uint64_t visited = 0;
  const __m128 tMinV = _mm_set1_ps(bvh4::atMost(tMin));
  const __m128 tMaxV = _mm_set1_ps(bvh4::atLeast(tMax));
  bool found = false;
  while (top > 0 && !found) {
    const Bvh4Node& node = nodes[stack[--top]];
    ++visited;
    __m128 tEnter;
    int mask = ray.intersect(node, tMinV, tMaxV, tEnter);
    for (; mask; mask &= mask - 1) {
      const int i = __builtin_ctz(static_cast<unsigned>(mask));
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
