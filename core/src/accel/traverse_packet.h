#pragma once
// Traversal of a Bvh8 by a packet of four rays: closest hit for rays that
// share an octant of directions, such as the primary rays of a 2x2 pixel
// quad, and any hit for the shadow rays from their hits. Each node is
// fetched (and, for closest hits, ordered) once for the packet; every ray
// still runs its own conservative slab test (BoxRay8) and its own leaf
// tests, so each ray visits at least the leaves it would visit alone and
// finds the same hit.
// What a packet saves is the chain of dependent node visits that bounds a
// single ray (a node load, the slab test, the choice of the next node): the
// four rays' tests of a node are independent of each other and overlap.
// Primary rays of 2x2 quads, 1 thread: 1.17x (knot1m, where a hitting ray
// waits on memory) to 1.38x (armadillo) the speed of ray by ray; shadow
// rays from the quads' hits, 1.09-1.27x (BENCHMARKS.md).
#include <emmintrin.h>
#include <xmmintrin.h>

#include <cstdint>
#include <limits>

#include "accel/traverse.h"
#include "meshtrace/accel/intersector.h"

namespace meshtrace {

namespace bvh8 {

// A postponed child. Its rays are kept as the node test's result shifted
// right by the child's slot (bit 8r: ray r meets it) and gathered only when
// it is popped: a push writes all eight slots, met or not, and gathering
// the rays of each there took 370 instructions a hitting primary quad on
// knot1m.
struct PacketEntry {
  std::uint32_t first, count;  // as Entry
  float tEnter;                // the nearest entry among the packet's rays
  std::uint32_t meets;         // bit 8r: ray r meets the box
};

// The rays of a PacketEntry's `meets` (bit r: ray r). The multiply gathers
// bits 0, 8, 16 and 24 into bits 28-31; no two of the partial products land
// on the same bit, so nothing carries.
inline std::uint32_t raysOf(std::uint32_t meets) {
  const std::uint64_t bits = meets & 0x01010101u;
  return static_cast<std::uint32_t>((bits * 0x10204080u) >> 28) & 0xfu;
}

// atLeast (bvh8_traverse.h) of the four rays' best distances, lane r for
// ray r: the same double product and rounding to float, two rays at a time.
inline __m128 atLeast4(const double* const* t) {
  const __m128d up = _mm_set1_pd(1.0 + 0x1p-23);
  const __m128 low = _mm_cvtpd_ps(_mm_mul_pd(_mm_set_pd(*t[1], *t[0]), up));
  const __m128 high = _mm_cvtpd_ps(_mm_mul_pd(_mm_set_pd(*t[3], *t[2]), up));
  return _mm_movelh_ps(low, high);
}

}  // namespace bvh8

// Calls leaf(first, count, rays) for the leaves whose boxes meet some of the
// packet's rays; `rays` names those that do (within their own [tMin, tBest]).
// The active rays must share an octant. tBest[r] is read again after every
// leaf call, and `prefetch` is used, as in traverseClosest.
template <typename Leaf, typename Prefetch = bvh8::NoPrefetch>
[[gnu::always_inline]] inline void traverseClosestPacket(
    const Bvh8& bvh, const SlabRay* slab, const double* tMin, const double* const* tBest,
    std::uint32_t active, std::uint64_t& visits, Leaf&& leaf, const Prefetch& prefetch = {}) {
  if (bvh.empty() || active == 0) return;
  if (bvh.nodes.empty()) {
    std::uint32_t meeting = 0;
    for (int r = 0; r < kPacketSize; ++r)
      if ((active >> r & 1) &&
          slab[r].meets(bvh.rootLo, bvh.rootHi, bvh8::atMost(tMin[r]), bvh8::atLeast(*tBest[r])))
        meeting |= 1u << r;
    if (meeting) leaf(0, bvh.rootCount, meeting);
    return;
  }
  const BoxRay8 ray[kPacketSize] = {BoxRay8(slab[0]), BoxRay8(slab[1]), BoxRay8(slab[2]),
                                    BoxRay8(slab[3])};
  __m128 tMinV[kPacketSize];
  for (int r = 0; r < kPacketSize; ++r) tMinV[r] = _mm_set1_ps(bvh8::atMost(tMin[r]));
  // Lane r: ray r's upper bound, refreshed after every leaf.
  __m128 tMaxV = bvh8::atLeast4(tBest);
  alignas(16) float tMax[kPacketSize];
  _mm_store_ps(tMax, tMaxV);
  const int octant = ray[__builtin_ctz(active)].octant();
  bvh8::PacketEntry stack[bvh8::kStackSize];
  int top = 0;
  const Bvh8Node* nodes = bvh.nodes.data();
  std::uint64_t visited = 0;
  bvh8::PacketEntry next{0, 0, 0.0f, 0};
  std::uint32_t rays = active;  // next's rays
  for (;;) {
    if (next.count == 0) {
      const Bvh8Node& node = nodes[next.first];
      ++visited;
      alignas(16) float tEnter[kPacketSize][kBvhWidth];
      std::uint32_t perRay = 0;
      __m128 nearLow = _mm_set1_ps(std::numeric_limits<float>::infinity()), nearHigh = nearLow;
      for (int r = 0; r < kPacketSize; ++r) {
        if (!(rays >> r & 1)) continue;
        perRay |= ray[r].intersect(node, tMinV[r], _mm_set1_ps(tMax[r]), tEnter[r]) << (8 * r);
        // Rays that miss a child lower its entry too: still a bound below
        // the rays that meet it, which is all the culling below needs.
        nearLow = _mm_min_ps(nearLow, _mm_load_ps(tEnter[r]));
        nearHigh = _mm_min_ps(nearHigh, _mm_load_ps(tEnter[r] + 4));
      }
      const std::uint32_t any = (perRay | perRay >> 8 | perRay >> 16 | perRay >> 24) & 0xffu;
      prefetch(nodes, node, any);
      if (any) {
        alignas(16) float nearest[kBvhWidth];
        _mm_store_ps(nearest, nearLow);
        _mm_store_ps(nearest + 4, nearHigh);
        if ((any & (any - 1)) == 0) {
          const int i = __builtin_ctz(any);
          next = {node.first[i], node.count[i], nearest[i], perRay >> i};
        } else {
          // Farthest first, so that the nearest is popped next.
          const std::uint32_t order = node.childOrder(octant);
#pragma GCC unroll 8
          for (int k = kBvhWidth - 1; k >= 0; --k) {
            const unsigned slot = order >> (3 * k) & 7;
            stack[top] = {node.first[slot], node.count[slot], nearest[slot], perRay >> slot};
            top += static_cast<int>(any >> slot & 1);
          }
          next = stack[--top];
        }
        rays = bvh8::raysOf(next.meets);
        continue;
      }
    } else {
      leaf(next.first, next.count, rays);
      tMaxV = bvh8::atLeast4(tBest);
      _mm_store_ps(tMax, tMaxV);
    }
    // Resume with the nearest postponed child that may still hold a hit for
    // one of its rays.
    for (;;) {
      if (top == 0) {
        visits += visited;
        return;
      }
      next = stack[--top];
      const auto still = static_cast<std::uint32_t>(
          _mm_movemask_ps(_mm_cmple_ps(_mm_set1_ps(next.tEnter), tMaxV)));
      rays = bvh8::raysOf(next.meets) & still;
      if (rays) break;
    }
  }
}

// Calls blocked(first, count, rays) for the leaves whose boxes meet some of
// the packet's rays that are not yet blocked, at tMin <= t <= tMax; `rays`
// names them, and the call returns those of them it found blocked. Returns
// every ray found blocked. The rays need not share an octant (children are
// taken in slot order, as in traverseAny; `prefetch` as there).
template <typename Leaf, typename Prefetch = bvh8::NoPrefetch>
[[gnu::always_inline]] inline std::uint32_t traverseAnyPacket(
    const Bvh8& bvh, const SlabRay* slab, const double* tMin, const double* tMax,
    std::uint32_t active, std::uint64_t& visits, Leaf&& blocked, const Prefetch& prefetch = {}) {
  if (bvh.empty() || active == 0) return 0;
  if (bvh.nodes.empty()) {
    std::uint32_t meeting = 0;
    for (int r = 0; r < kPacketSize; ++r)
      if ((active >> r & 1) &&
          slab[r].meets(bvh.rootLo, bvh.rootHi, bvh8::atMost(tMin[r]), bvh8::atLeast(tMax[r])))
        meeting |= 1u << r;
    return meeting ? blocked(0, bvh.rootCount, meeting) : 0;
  }
  const BoxRay8 ray[kPacketSize] = {BoxRay8(slab[0]), BoxRay8(slab[1]), BoxRay8(slab[2]),
                                    BoxRay8(slab[3])};
  __m128 tMinV[kPacketSize], tMaxV[kPacketSize];
  for (int r = 0; r < kPacketSize; ++r) {
    tMinV[r] = _mm_set1_ps(bvh8::atMost(tMin[r]));
    tMaxV[r] = _mm_set1_ps(bvh8::atLeast(tMax[r]));
  }
  struct Entry {
    std::uint32_t node, rays;
  };
  Entry stack[bvh8::kStackSize];
  int top = 0;
  stack[top++] = {0, active};
  const Bvh8Node* nodes = bvh.nodes.data();
  std::uint64_t visited = 0;
  std::uint32_t open = active, found = 0;
  while (top > 0 && open) {
    const Entry e = stack[--top];
    const std::uint32_t rays = e.rays & open;
    if (!rays) continue;
    const Bvh8Node& node = nodes[e.node];
    ++visited;
    alignas(16) float tEnter[kBvhWidth];
    std::uint32_t perRay = 0;
    for (int r = 0; r < kPacketSize; ++r)
      if (rays >> r & 1) perRay |= ray[r].intersect(node, tMinV[r], tMaxV[r], tEnter) << (8 * r);
    std::uint32_t any = (perRay | perRay >> 8 | perRay >> 16 | perRay >> 24) & 0xffu;
    prefetch(nodes, node, any);
    for (; any; any &= any - 1) {
      const int i = __builtin_ctz(any);
      const std::uint32_t meeting = bvh8::raysOf(perRay >> i) & open;
      if (!meeting) continue;
      if (node.count[i] == 0) {
        stack[top++] = {node.first[i], meeting};
      } else {
        const std::uint32_t now = blocked(node.first[i], node.count[i], meeting);
        found |= now;
        open &= ~now;
        if (!open) break;
      }
    }
  }
  visits += visited;
  return found;
}

}  // namespace meshtrace
