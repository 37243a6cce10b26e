// Collapsing a binary BVH into an 8-wide one (see bvh8.h).
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "meshtrace/bvh8.h"

namespace meshtrace {

namespace {

double halfArea(const BvhNode& n) {
  const double x = n.bounds[3] - n.bounds[0], y = n.bounds[4] - n.bounds[1],
               z = n.bounds[5] - n.bounds[2];
  return x * y + y * z + z * x;
}

// Orders the used children of each octant by their box centres projected
// on the octant's diagonal: a direction-only estimate of which box a ray
// enters first, free of per-ray work. Used slots come first; an unused one
// has an empty box (lo > hi). Opposite octants (o and o ^ 7) have opposite
// diagonals, so one sort serves both: the other takes the used slots in
// reverse (children at equal distance then come in the other order, which
// no ray can tell apart).
void setChildOrders(Bvh8Node& node) {
  int n = 0;
  while (n < kBvhWidth && node.lo[0][n] <= node.hi[0][n]) ++n;
  double centre2[kBvhWidth][3];  // twice each used child's box centre
  for (int i = 0; i < n; ++i)
    for (int a = 0; a < 3; ++a)
      centre2[i][a] = static_cast<double>(node.lo[a][i]) + node.hi[a][i];
  const auto store = [&node](int octant, const int* slots) {
    std::uint32_t packed = 0;
    for (int k = 0; k < kBvhWidth; ++k) packed |= static_cast<std::uint32_t>(slots[k]) << (3 * k);
    for (int byte = 0; byte < 3; ++byte)
      node.order[octant][byte] = static_cast<std::uint8_t>(packed >> (8 * byte));
  };
  for (int octant = 0; octant < 4; ++octant) {
    double key[kBvhWidth];
    int slots[kBvhWidth];
    for (int i = 0; i < kBvhWidth; ++i) {
      slots[i] = i;
      if (i >= n) continue;
      key[i] = 0.0;
      for (int a = 0; a < 3; ++a) key[i] += (octant >> a & 1) ? -centre2[i][a] : centre2[i][a];
    }
    // A stable insertion sort of the used slots: std::stable_sort takes a
    // heap buffer, and with its allocations it was half of the collapse's
    // instructions.
    for (int k = 1; k < n; ++k) {
      const int slot = slots[k];
      int j = k;
      for (; j > 0 && key[slot] < key[slots[j - 1]]; --j) slots[j] = slots[j - 1];
      slots[j] = slot;
    }
    store(octant, slots);
    std::reverse(slots, slots + n);
    store(octant ^ 7, slots);
  }
}

class Collapser {
 public:
  Collapser(const Bvh& binary, Bvh8& out)
      : in_(binary), out_(out), leaves_(binary.nodes.size(), 1) {
    // Children come after their parent in the binary tree.
    for (std::size_t i = binary.nodes.size(); i-- > 0;) {
      const BvhNode& node = binary.nodes[i];
      if (!node.isLeaf()) leaves_[i] = leaves_[node.first] + leaves_[node.first + 1];
    }
  }

  // Fills a new 8-wide node from binary interior node `b`; returns its index.
  std::uint32_t node(std::uint32_t b, int depth) {
    out_.depth = std::max(out_.depth, depth);
    std::uint32_t children[kBvhWidth] = {in_.nodes[b].first, in_.nodes[b].first + 1};
    int n = 2;
    while (n < kBvhWidth) {
      // The widest interior child, or the widest of those whose whole
      // subtree still fits in this node: a small subtree left as a child of
      // its own would make a node with few children.
      int widest = -1;
      bool widestFits = false;
      for (int i = 0; i < n; ++i) {
        if (in_.nodes[children[i]].isLeaf()) continue;
        const bool fits = leaves_[children[i]] - 1 <= static_cast<std::uint32_t>(kBvhWidth - n);
        if (widest < 0 || (fits && !widestFits) ||
            (fits == widestFits &&
             halfArea(in_.nodes[children[i]]) > halfArea(in_.nodes[children[widest]]))) {
          widest = i;
          widestFits = fits;
        }
      }
      if (widest < 0) break;
      const std::uint32_t split = children[widest];
      children[widest] = in_.nodes[split].first;
      children[n++] = in_.nodes[split].first + 1;
    }
    const auto index = static_cast<std::uint32_t>(out_.nodes.size());
    out_.nodes.emplace_back();
    for (int i = 0; i < kBvhWidth; ++i) {
      const bool used = i < n;
      const BvhNode* c = used ? &in_.nodes[children[i]] : nullptr;
      for (int a = 0; a < 3; ++a) {
        out_.nodes[index].lo[a][i] = used ? c->bounds[a] : kEmptyLo;
        out_.nodes[index].hi[a][i] = used ? c->bounds[a + 3] : kEmptyHi;
      }
      out_.nodes[index].first[i] = used && c->isLeaf() ? c->first : 0;
      if (used && c->count > kMaxBvh8Leaf)
        throw std::length_error("BVH leaf of " + std::to_string(c->count) +
                                " primitives, more than a node can hold");
      out_.nodes[index].count[i] = static_cast<std::uint8_t>(used ? c->count : 0);
    }
    // Interior children after the node itself (depth-first order).
    for (int i = 0; i < n; ++i)
      if (!in_.nodes[children[i]].isLeaf()) {
        const std::uint32_t child = node(children[i], depth + 1);
        out_.nodes[index].first[i] = child;
      }
    return index;
  }

 private:
  static constexpr float kEmptyLo = std::numeric_limits<float>::infinity();
  static constexpr float kEmptyHi = -std::numeric_limits<float>::infinity();
  const Bvh& in_;
  Bvh8& out_;
  std::vector<std::uint32_t> leaves_;  // leaves under each binary node
};

}  // namespace

Bvh8 collapseToBvh8(const Bvh& binary) {
  Bvh8 out;
  if (binary.empty()) return out;
  out.order = binary.order;
  const BvhNode& root = binary.nodes[0];
  for (int k = 0; k < 4; ++k) {
    out.rootLo[k] = root.bounds[std::min(k, 2)];
    out.rootHi[k] = root.bounds[3 + std::min(k, 2)];
  }
  if (root.isLeaf()) {
    out.rootCount = root.count;
    out.depth = 1;
    return out;
  }
  out.nodes.reserve(binary.nodes.size() / 6 + 1);
  Collapser(binary, out).node(0, 1);
  // The child orders read only each node's own boxes, so they are filled
  // in afterwards, in parallel.
  tbb::parallel_for(tbb::blocked_range<std::size_t>(0, out.nodes.size(), 256),
                    [&](const tbb::blocked_range<std::size_t>& r) {
                      for (std::size_t i = r.begin(); i < r.end(); ++i)
                        setChildOrders(out.nodes[i]);
                    });
  return out;
}

}  // namespace meshtrace
