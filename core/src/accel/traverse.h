#pragma once
// Traversal of a Bvh8, written once per width: traverse() for one ray and
// traversePacket() for kPacketSize rays, each for either kind of hit
// (HitKind). Two SSE slab tests per node check all eight child boxes in
// float (slab_ray.h). The leaf work is a callback; it answers whether the
// search is over, so the same loop serves closest hits (never over before the
// tree is) and any hit (over at the first blocker).
//
// Closest hits visit the children a ray meets in the order its node keeps
// for the ray's octant (Bvh8Node::order), nearest first, instead of sorting
// their entry distances: the fixed order costs no branch that depends on the
// ray. A single ray that meets exactly two children takes them by their
// entry distances instead, at the cost of one comparison (TwoChildren).
// Any-hit searches take the children in slot order and test the leaves
// among them at once, since any blocker will do.
//
// Every traversal, packets included, tests each ray's boxes with its own
// conservative slab test and calls the leaves each ray alone would reach (at
// least), so a packet finds the hits each of its rays would find alone. What
// a packet saves is the chain of dependent node visits that bounds a single
// ray (a node load, the slab test, the choice of the next node): the four
// rays' tests of a node are independent and overlap.
#include <emmintrin.h>
#include <xmmintrin.h>

#include <cstdint>
#include <limits>

#include "accel/bvh8.h"
#include "accel/hit_kind.h"
#include "accel/slab_ray.h"
#include "meshtrace/accel/intersector.h"
#include "util/prefetch.h"

namespace meshtrace {

namespace bvh8 {

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

// Asks for the nodes, and through leafData(first, count) the leaf data, of the
// children in `mask`, before the traversal branches on them: on a tree far
// larger than the caches, each visit otherwise waits for memory in turn, and
// a mispredicted branch delays the next load further. Whether it pays is a
// matter of the tree's size (kPrefetchBvhBytes), so it is switched at run
// time.
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
        leafData_(node.first[i], node.count[i]);
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
[[gnu::always_inline]] inline Entry pushInOrder(const Bvh8Node& node, unsigned mask,
                                                std::uint32_t childOrder, const float* tEnter,
                                                Entry* stack, int& top) {
#pragma GCC unroll 8
  for (int k = kBvhWidth - 1; k >= 0; --k) {
    const unsigned slot = childOrder >> (3 * k) & 7;
    stack[top] = {node.first[slot], node.count[slot], tEnter[slot]};
    top += static_cast<int>(mask >> slot & 1);
  }
  return stack[--top];
}

// When a closest-hit ray meets exactly two children, the slots of the one
// it enters first and of the other: one comparison of their entry
// distances, where the octant order is often wrong for long boxes side by
// side (a hall's floor stripes, walls and beams). Three or more keep the
// octant order: sorting them gained nothing on the hall and cost the
// meshes' bounces. Nor do packets use it: ordered by their rays' nearest
// entries, the meshes' quads lost. `mask` has two bits or more.
struct TwoChildren {
  [[gnu::always_inline]] TwoChildren(unsigned mask, const float* tEnter) {
    const unsigned rest = mask & (mask - 1);
    met = (rest & (rest - 1)) == 0;
    const int i = __builtin_ctz(mask), j = __builtin_ctz(rest);
    const bool iFirst = tEnter[i] <= tEnter[j];
    near = iFirst ? i : j;
    far = iFirst ? j : i;
  }
  explicit operator bool() const { return met; }

  bool met;
  int near, far;
};

// A postponed child of a packet's traversal. Its rays are kept as the node
// test's result shifted right by the child's slot (bit 8r: ray r meets it)
// and gathered only when it is popped: a push writes all eight slots, met
// or not, and gathering the rays of each there costs more than the pops.
struct PacketEntry {
  std::uint32_t first, count;  // as Entry
  float tEnter;                // the nearest entry among the packet's rays
  std::uint32_t meets;         // bit 8r: ray r meets the box
};

// The rays of a PacketEntry's `meets` (bit r: ray r). The multiply gathers
// bits 0, 8, 16 and 24 into bits 28-31; no two of the partial products land
// on the same bit, so nothing carries.
[[gnu::always_inline]] inline std::uint32_t raysOf(std::uint32_t meets) {
  const std::uint64_t bits = meets & 0x01010101u;
  return static_cast<std::uint32_t>((bits * 0x10204080u) >> 28) & 0xfu;
}

// atLeast of the four rays' limits, lane r for ray r: the same double
// product and rounding to float, two rays at a time.
[[gnu::always_inline]] inline __m128 atLeast4(const double* const* t) {
  static_assert(kPacketSize == 4, "one SSE lane per ray");
  const __m128d up = _mm_set1_pd(1.0 + 0x1p-23);
  const __m128 low = _mm_cvtpd_ps(_mm_mul_pd(_mm_set_pd(*t[1], *t[0]), up));
  const __m128 high = _mm_cvtpd_ps(_mm_mul_pd(_mm_set_pd(*t[3], *t[2]), up));
  return _mm_movelh_ps(low, high);
}

}  // namespace bvh8

// Calls leaf(first, count) for the leaves whose boxes the ray meets at
// tMin <= t <= tLimit until one returns true, and returns whether one did.
// Closest: nearer boxes first; the leaf may lower tLimit (it is read again
// after every call), and a box entered exactly at tLimit is still visited,
// so that a later primitive at the same distance can win a tie. Any: the
// first leaf that returns true ends it. `prefetch` is shown each node's
// children met before they are taken (NoPrefetch, PrefetchChildren).
// (The traversals are forced inline into the queries, with their leaf
// callbacks: see scene_bvh.cpp.)
template <HitKind kKind, typename Leaf, typename Prefetch = bvh8::NoPrefetch>
[[gnu::always_inline]] inline bool traverse(const Bvh8& bvh, const SlabRay& slab, double tMin,
                                            const double& tLimit, std::uint64_t& visits,
                                            Leaf&& leaf, const Prefetch& prefetch = {}) {
  if (bvh.empty()) return false;
  if (bvh.nodes.empty())
    return slab.meets(bvh.rootLo, bvh.rootHi, bvh8::atMost(tMin), bvh8::atLeast(tLimit)) &&
           leaf(0, bvh.rootCount);
  const BoxRay8 ray(slab);
  bvh8::Entry stack[bvh8::kStackSize];
  int top = 0;
  // Locals, not the members and the caller's counter: the leaf call may
  // write anywhere, and the compiler would reload them after each one.
  const Bvh8Node* nodes = bvh.nodes.data();
  std::uint64_t visited = 0;
  const __m128 tMinV = _mm_set1_ps(bvh8::atMost(tMin));
  float tMax = bvh8::atLeast(tLimit);  // closest hits: refreshed after every leaf
  bool found = false;
  bvh8::Entry next{0, 0, 0.0f};  // the root
  for (;;) {
    if (next.count == 0) {
      const Bvh8Node& node = nodes[next.first];
      ++visited;
      alignas(16) float tEnter[kBvhWidth];
      unsigned mask = ray.intersect(node, tMinV, _mm_set1_ps(tMax), tEnter);
      prefetch(nodes, node, mask);
      if constexpr (kKind == HitKind::Any) {
        // The leaves met are tested at once; inner children wait.
        for (; mask && !found; mask &= mask - 1) {
          const int i = __builtin_ctz(mask);
          if (node.count[i] == 0)
            stack[top++] = {node.first[i], 0, 0.0f};
          else
            found = leaf(node.first[i], node.count[i]);
        }
        if (found) break;
      } else if (mask) {
        // Continue with the nearest child met.
        if ((mask & (mask - 1)) == 0) {
          const int i = __builtin_ctz(mask);
          next = {node.first[i], node.count[i], 0.0f};
        } else if (bvh8::TwoChildren two(mask, tEnter); two) {
          stack[top++] = {node.first[two.far], node.count[two.far], tEnter[two.far]};
          next = {node.first[two.near], node.count[two.near], 0.0f};
        } else {
          next = bvh8::pushInOrder(node, mask, node.childOrder(ray.octant()), tEnter, stack, top);
        }
        continue;
      }
    } else {
      // Only closest-hit searches postpone leaves.
      leaf(next.first, next.count);
      tMax = bvh8::atLeast(tLimit);
    }
    // Resume with the nearest postponed child that may still hold a hit
    // (for an any-hit search, any postponed child).
    do {
      if (top == 0) {
        visits += visited;
        return found;
      }
      next = stack[--top];
    } while (kKind == HitKind::Closest && next.tEnter > tMax);
  }
  visits += visited;
  return found;
}

// Calls leaf(first, count, rays) for the leaves whose boxes meet some of the
// packet's rays that are still searching; `rays` names those (bit r: ray r,
// met within its own [tMin[r], *tLimit[r]]), and the call returns those of
// them whose search it ended. Returns every ray whose search a leaf ended.
// Closest: the active rays must share an octant, and *tLimit[r] is read
// again after every leaf, as in traverse(). Any: the rays need not share
// one (children are taken in slot order). `prefetch` as in traverse().
template <HitKind kKind, typename Leaf, typename Prefetch = bvh8::NoPrefetch>
[[gnu::always_inline]] inline std::uint32_t traversePacket(
    const Bvh8& bvh, const SlabRay* slab, const double* tMin, const double* const* tLimit,
    std::uint32_t active, std::uint64_t& visits, Leaf&& leaf, const Prefetch& prefetch = {}) {
  if (bvh.empty() || active == 0) return 0;
  if (bvh.nodes.empty()) {
    std::uint32_t meeting = 0;
    for (int r = 0; r < kPacketSize; ++r)
      if ((active >> r & 1) &&
          slab[r].meets(bvh.rootLo, bvh.rootHi, bvh8::atMost(tMin[r]), bvh8::atLeast(*tLimit[r])))
        meeting |= 1u << r;
    return meeting ? leaf(0, bvh.rootCount, meeting) : 0;
  }
  const BoxRay8 ray[kPacketSize] = {BoxRay8(slab[0]), BoxRay8(slab[1]), BoxRay8(slab[2]),
                                    BoxRay8(slab[3])};
  __m128 tMinV[kPacketSize];
  for (int r = 0; r < kPacketSize; ++r) tMinV[r] = _mm_set1_ps(bvh8::atMost(tMin[r]));
  // Lane r: ray r's upper bound; closest hits refresh it after every leaf.
  __m128 tMaxV = bvh8::atLeast4(tLimit);
  alignas(16) float tMax[kPacketSize];
  _mm_store_ps(tMax, tMaxV);
  // An any-hit search's bounds never change: splat them once.
  __m128 fixedMax[kPacketSize];
  for (int r = 0; r < kPacketSize; ++r) fixedMax[r] = _mm_set1_ps(tMax[r]);
  const int octant = ray[__builtin_ctz(active)].octant();
  bvh8::PacketEntry stack[bvh8::kStackSize];
  int top = 0;
  const Bvh8Node* nodes = bvh.nodes.data();
  std::uint64_t visited = 0;
  std::uint32_t open = active, done = 0;  // rays still searching, rays whose search ended
  bvh8::PacketEntry next{0, 0, 0.0f, 0};
  std::uint32_t rays = active;  // next's rays
  for (;;) {
    if (next.count == 0) {
      const Bvh8Node& node = nodes[next.first];
      ++visited;
      alignas(16) float tEnter[kPacketSize][kBvhWidth];
      std::uint32_t perRay = 0;  // bit 8r + i: ray r meets child i
      __m128 nearLow = _mm_set1_ps(std::numeric_limits<float>::infinity()), nearHigh = nearLow;
      for (int r = 0; r < kPacketSize; ++r) {
        if (!(rays >> r & 1)) continue;
        const __m128 limit = kKind == HitKind::Any ? fixedMax[r] : _mm_set1_ps(tMax[r]);
        perRay |= ray[r].intersect(node, tMinV[r], limit, tEnter[r]) << (8 * r);
        if constexpr (kKind == HitKind::Closest) {
          // Rays that miss a child lower its entry too: still a bound below
          // the rays that meet it, which is all the culling below needs.
          nearLow = _mm_min_ps(nearLow, _mm_load_ps(tEnter[r]));
          nearHigh = _mm_min_ps(nearHigh, _mm_load_ps(tEnter[r] + 4));
        }
      }
      std::uint32_t any = (perRay | perRay >> 8 | perRay >> 16 | perRay >> 24) & 0xffu;
      prefetch(nodes, node, any);
      if constexpr (kKind == HitKind::Any) {
        // The leaves met are tested at once; inner children wait.
        for (; any && open; any &= any - 1) {
          const int i = __builtin_ctz(any);
          const std::uint32_t meeting = bvh8::raysOf(perRay >> i) & open;
          if (!meeting) continue;
          if (node.count[i] == 0) {
            stack[top++] = {node.first[i], 0, 0.0f, perRay >> i};
          } else {
            const std::uint32_t ended = leaf(node.first[i], node.count[i], meeting);
            done |= ended;
            open &= ~ended;
          }
        }
        if (!open) break;
      } else if (any) {
        // Continue with the nearest child met by some ray.
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
      // Only closest-hit searches postpone leaves.
      leaf(next.first, next.count, rays);
      tMaxV = bvh8::atLeast4(tLimit);
      _mm_store_ps(tMax, tMaxV);
    }
    // Resume with the nearest postponed child that may still hold a hit for
    // one of its rays (for an any-hit search, any postponed child with a ray
    // still searching).
    for (;;) {
      if (top == 0) {
        visits += visited;
        return done;
      }
      next = stack[--top];
      if constexpr (kKind == HitKind::Any) {
        rays = bvh8::raysOf(next.meets) & open;
      } else {
        const auto still = static_cast<std::uint32_t>(
            _mm_movemask_ps(_mm_cmple_ps(_mm_set1_ps(next.tEnter), tMaxV)));
        rays = bvh8::raysOf(next.meets) & still;
      }
      if (rays) break;
    }
  }
  visits += visited;
  return done;
}

}  // namespace meshtrace
