// Collapsing a binary BVH into an 8-wide one (see bvh8.h).
#include <tbb/parallel_for.h>

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
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

// Leaves under each binary node. Children come after their parent in the
// binary tree.
std::vector<std::uint32_t> leafCounts(const Bvh& binary) {
  std::vector<std::uint32_t> leaves(binary.nodes.size(), 1);
  for (std::size_t i = binary.nodes.size(); i-- > 0;) {
    const BvhNode& node = binary.nodes[i];
    if (!node.isLeaf()) leaves[i] = leaves[node.first] + leaves[node.first + 1];
  }
  return leaves;
}

// Collapses subtrees of the binary tree into 8-wide nodes, depth first, into
// a vector of its own: node indices count from that vector's start.
class Collapser {
 public:
  Collapser(const Bvh& binary, const std::vector<std::uint32_t>& leaves)
      : in_(binary), leaves_(leaves) {}

  BuildVector<Bvh8Node> nodes;
  int depth = 0;

  // Fills a new 8-wide node from binary interior node `b`; returns its index.
  std::uint32_t node(std::uint32_t b, int level) {
    depth = std::max(depth, level);
    std::uint32_t children[kBvhWidth];
    const int n = chooseChildren(b, children);
    const auto index = static_cast<std::uint32_t>(nodes.size());
    nodes.emplace_back();
    fill(nodes[index], children, n);
    // Interior children after the node itself (depth-first order).
    for (int i = 0; i < n; ++i)
      if (!in_.nodes[children[i]].isLeaf()) {
        const std::uint32_t child = node(children[i], level + 1);
        nodes[index].first[i] = child;
      }
    return index;
  }

  // The binary nodes that become the children of `b`'s 8-wide node; returns
  // how many.
  int chooseChildren(std::uint32_t b, std::uint32_t (&children)[kBvhWidth]) const {
    // Per child: whether it can be opened, its leaf count and its area,
    // each read once rather than at every comparison (knot1m's collapse, 2
    // threads, medians of seven, three rounds: 27.8-28.0 -> 22.4-25.9 ms;
    // the same trees).
    bool interior[kBvhWidth];
    std::uint32_t leafCount[kBvhWidth];
    double area[kBvhWidth];
    const auto set = [&](int i, std::uint32_t c) {
      const BvhNode& node = in_.nodes[c];
      children[i] = c;
      interior[i] = !node.isLeaf();
      if (interior[i]) {
        leafCount[i] = leaves_[c];
        area[i] = halfArea(node);
      }
    };
    set(0, in_.nodes[b].first);
    set(1, in_.nodes[b].first + 1);
    int n = 2;
    while (n < kBvhWidth) {
      // The widest interior child, or the widest of those whose whole
      // subtree still fits in this node: a small subtree left as a child of
      // its own would make a node with few children.
      int widest = -1;
      bool widestFits = false;
      for (int i = 0; i < n; ++i) {
        if (!interior[i]) continue;
        const bool fits = leafCount[i] - 1 <= static_cast<std::uint32_t>(kBvhWidth - n);
        if (widest < 0 || (fits && !widestFits) || (fits == widestFits && area[i] > area[widest])) {
          widest = i;
          widestFits = fits;
        }
      }
      if (widest < 0) break;
      const std::uint32_t first = in_.nodes[children[widest]].first;
      set(widest, first);
      set(n++, first + 1);
    }
    return n;
  }

  // The boxes, leaf ranges and child orders of `children` (interior
  // children's indices are set by the caller).
  void fill(Bvh8Node& out, const std::uint32_t* children, int n) const {
    for (int i = 0; i < kBvhWidth; ++i) {
      const bool used = i < n;
      const BvhNode* c = used ? &in_.nodes[children[i]] : nullptr;
      for (int a = 0; a < 3; ++a) {
        out.lo[a][i] = used ? c->bounds[a] : kEmptyLo;
        out.hi[a][i] = used ? c->bounds[a + 3] : kEmptyHi;
      }
      out.first[i] = used && c->isLeaf() ? c->first : 0;
      if (used && c->count > kMaxBvh8Leaf)
        throw std::length_error("BVH leaf of " + std::to_string(c->count) +
                                " primitives, more than a node can hold");
      out.count[i] = static_cast<std::uint8_t>(used ? c->count : 0);
    }
    setChildOrders(out);
  }

 private:
  static constexpr float kEmptyLo = std::numeric_limits<float>::infinity();
  static constexpr float kEmptyHi = -std::numeric_limits<float>::infinity();
  const Bvh& in_;
  const std::vector<std::uint32_t>& leaves_;
};

}  // namespace

Bvh8 collapseToBvh8(Bvh binary) {
  Bvh8 out;
  if (binary.empty()) return out;
  out.order = std::move(binary.order);
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
  // The root's node, then the subtree of each of its interior children,
  // collapsed in parallel and appended in slot order: the depth-first order
  // of one serial pass, so the tree is the same whatever the threads do.
  const std::vector<std::uint32_t> leaves = leafCounts(binary);
  const Collapser top(binary, leaves);
  std::uint32_t children[kBvhWidth];
  const int n = top.chooseChildren(0, children);
  std::vector<int> interior;
  for (int i = 0; i < n; ++i)
    if (!binary.nodes[children[i]].isLeaf()) interior.push_back(i);
  std::vector<Collapser> parts(interior.size(), top);
  tbb::parallel_for(std::size_t(0), parts.size(), [&](std::size_t k) {
    parts[k].nodes.reserve(leaves[children[interior[k]]] / 3 + 1);
    parts[k].node(children[interior[k]], 2);
  });
  std::vector<std::uint32_t> base(parts.size());
  std::size_t total = 1;
  out.depth = 1;
  for (std::size_t k = 0; k < parts.size(); ++k) {
    base[k] = static_cast<std::uint32_t>(total);
    total += parts[k].nodes.size();
    out.depth = std::max(out.depth, parts[k].depth);
  }
  out.nodes.resize(total);  // every node is assigned below
  top.fill(out.nodes[0], children, n);
  for (std::size_t k = 0; k < parts.size(); ++k) out.nodes[0].first[interior[k]] = base[k];
  tbb::parallel_for(std::size_t(0), parts.size(), [&](std::size_t k) {
    Bvh8Node* to = out.nodes.data() + base[k];
    for (const Bvh8Node& node : parts[k].nodes) {
      *to = node;
      // Interior children (a used slot, lo <= hi, with no primitives).
      for (int i = 0; i < kBvhWidth; ++i)
        if (to->count[i] == 0 && to->lo[0][i] <= to->hi[0][i]) to->first[i] += base[k];
      ++to;
    }
  });
  return out;
}

}  // namespace meshtrace
