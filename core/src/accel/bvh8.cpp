// Collapsing a binary BVH into an 8-wide one (see bvh8.h).
#include "accel/bvh8.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "util/build_vector.h"

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
    for (int a = 0; a < 3; ++a) centre2[i][a] = static_cast<double>(node.lo[a][i]) + node.hi[a][i];
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
    // heap buffer, whose allocations would cost more than the sort.
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

// Which binary nodes become 8-wide nodes. Every leaf of the binary tree
// ends up as the child of one 8-wide node whatever the choice, so what the
// choice changes is the set of 8-wide nodes, and by the surface area
// heuristic a ray's expected node visits are their areas' sum over the
// root's. The plan minimises that sum exactly (the dynamic programme of
// Ylitie et al. 2017, with the binary tree's leaves kept as they are): for
// each subtree it finds the least sum when the subtree takes at most j child
// slots of the node above, for j = 1 to 8, either as one child (an 8-wide
// node of its own, or a leaf) or split between its two children.
// Against the greedy collapse (opening the widest child first), it fills
// more of each node's slots, so the tree has fewer nodes and a ray visits
// fewer of them.
class CollapsePlan {
 public:
  explicit CollapsePlan(const Bvh& binary)
      : binary_(binary), split_(binary.nodes.size()), open_(binary.nodes.size()) {
    if (!binary.nodes[0].isLeaf()) plan(0, 0);
  }

  // Slots of an 8-wide node made from interior node n that go to its left
  // child (the rest to its right).
  int open(std::uint32_t n) const { return open_[n]; }
  // Slots of `slots` given to the left child of interior node n when it
  // takes at most `slots` child slots above; 0 if n takes one slot itself.
  int split(std::uint32_t n, int slots) const { return split_[n][slots - 1]; }

 private:
  using Costs = std::array<float, kBvhWidth>;  // [j - 1]: the least sum in j slots
  static constexpr int kParallelLevels = 6;

  Costs plan(std::uint32_t n, int level) {
    const BvhNode& node = binary_.nodes[n];
    if (node.isLeaf()) return Costs{};  // no 8-wide node below a leaf
    Costs left, right;
    if (level < kParallelLevels) {
      tbb::parallel_invoke([&] { left = plan(node.first, level + 1); },
                           [&] { right = plan(node.first + 1, level + 1); });
    } else {
      left = plan(node.first, level + 1);
      right = plan(node.first + 1, level + 1);
    }
    // Split between the children: the best share of j slots, j = 2..8. A
    // leaf costs nothing in one slot, so it takes one, and the search over
    // shares is left to nodes with two interior children.
    const bool leftLeaf = binary_.nodes[node.first].isLeaf();
    const bool rightLeaf = binary_.nodes[node.first + 1].isLeaf();
    float splitCost[kBvhWidth + 1];
    std::uint8_t splitLeft[kBvhWidth + 1];
#pragma GCC unroll 8
    for (int j = 2; j <= kBvhWidth; ++j) {
      splitCost[j] = left[0] + right[j - 2];
      splitLeft[j] = 1;
      if (leftLeaf) continue;
      if (rightLeaf) {
        splitCost[j] = left[j - 2];
        splitLeft[j] = static_cast<std::uint8_t>(j - 1);
        continue;
      }
      // Selects, not branches: which share wins depends on the subtrees'
      // areas, which no branch predictor can learn.
#pragma GCC unroll 8
      for (int k = 2; k < j; ++k) {
        const float c = left[k - 1] + right[j - k - 1];
        const bool better = c < splitCost[j];
        splitLeft[j] = better ? static_cast<std::uint8_t>(k) : splitLeft[j];
        splitCost[j] = better ? c : splitCost[j];
      }
    }
    Costs best;
    best[0] = static_cast<float>(halfArea(node)) + splitCost[kBvhWidth];  // a node of its own
    split_[n][0] = 0;
    for (int j = 2; j <= kBvhWidth; ++j) {
      const bool share = splitCost[j] < best[0];
      best[j - 1] = share ? splitCost[j] : best[0];
      split_[n][j - 1] = share ? splitLeft[j] : 0;
    }
    open_[n] = splitLeft[kBvhWidth];
    return best;
  }

  const Bvh& binary_;
  BuildVector<std::array<std::uint8_t, kBvhWidth>> split_;  // written for interior nodes
  BuildVector<std::uint8_t> open_;
};

// Collapses subtrees of the binary tree into 8-wide nodes, depth first.
// Each subtree's nodes are counted first, so that it is written straight
// into the tree's one array: grown node by node in a vector of its own and
// then copied, a large tree's nodes would be written three times over, each
// time to pages never touched before.
class Collapser {
 public:
  Collapser(const Bvh& binary, const CollapsePlan& plan) : in_(binary), plan_(plan) {}

  // The 8-wide nodes that binary interior node `b` becomes with its subtree.
  std::uint32_t count(std::uint32_t b) const {
    std::uint32_t children[kBvhWidth];
    const int n = chooseChildren(b, children);
    std::uint32_t total = 1;
    for (int i = 0; i < n; ++i)
      if (!in_.nodes[children[i]].isLeaf()) total += count(children[i]);
    return total;
  }

  // Fills `b`'s 8-wide node at nodes[index] and its subtree's after it;
  // returns the index past them and raises `depth` to the deepest level.
  std::uint32_t node(std::uint32_t b, std::uint32_t index, int level, Bvh8Node* nodes,
                     int& depth) const {
    depth = std::max(depth, level);
    std::uint32_t children[kBvhWidth];
    const int n = chooseChildren(b, children);
    fill(nodes[index], children, n);
    std::uint32_t next = index + 1;
    // Interior children after the node itself (depth-first order).
    for (int i = 0; i < n; ++i)
      if (!in_.nodes[children[i]].isLeaf()) {
        nodes[index].first[i] = next;
        next = node(children[i], next, level + 1, nodes, depth);
      }
    return next;
  }

  // The binary nodes that become the children of `b`'s 8-wide node; returns
  // how many.
  int chooseChildren(std::uint32_t b, std::uint32_t (&children)[kBvhWidth]) const {
    int n = 0;
    const std::uint32_t first = in_.nodes[b].first;
    const int k = plan_.open(b);
    take(first, k, children, n);
    take(first + 1, kBvhWidth - k, children, n);
    return n;
  }

  // Appends the children that binary node `b` becomes when it may take up
  // to `slots` slots.
  void take(std::uint32_t b, int slots, std::uint32_t* children, int& n) const {
    const int k = in_.nodes[b].isLeaf() ? 0 : plan_.split(b, slots);
    if (k == 0) {
      children[n++] = b;
      return;
    }
    const std::uint32_t first = in_.nodes[b].first;
    take(first, k, children, n);
    take(first + 1, slots - k, children, n);
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
  const CollapsePlan& plan_;
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
  // collapsed in parallel in slot order: the depth-first order of one
  // serial pass, so the tree is the same whatever the threads do.
  const CollapsePlan plan(binary);
  const Collapser collapser(binary, plan);
  std::uint32_t children[kBvhWidth];
  const int n = collapser.chooseChildren(0, children);
  std::vector<std::uint32_t> interior;
  for (int i = 0; i < n; ++i)
    if (!binary.nodes[children[i]].isLeaf()) interior.push_back(static_cast<std::uint32_t>(i));
  std::vector<std::uint32_t> base(interior.size());
  tbb::parallel_for(std::size_t(0), interior.size(),
                    [&](std::size_t k) { base[k] = collapser.count(children[interior[k]]); });
  std::uint32_t total = 1;
  for (std::uint32_t& b : base) total += std::exchange(b, total);
  out.nodes.resize(total);  // every node is assigned below
  collapser.fill(out.nodes[0], children, n);
  for (std::size_t k = 0; k < interior.size(); ++k) out.nodes[0].first[interior[k]] = base[k];
  std::vector<int> depth(interior.size(), 1);
  tbb::parallel_for(std::size_t(0), interior.size(), [&](std::size_t k) {
    collapser.node(children[interior[k]], base[k], 2, out.nodes.data(), depth[k]);
  });
  out.depth = 1;
  for (int d : depth) out.depth = std::max(out.depth, d);
  return out;
}

std::vector<Bvh8Leaf> leavesOf(const Bvh8& tree) {
  std::vector<Bvh8Leaf> leaves;
  if (tree.nodes.empty()) {
    if (tree.rootCount > 0) leaves.push_back({0, tree.rootCount});
    return leaves;
  }
  for (const Bvh8Node& node : tree.nodes)
    for (int i = 0; i < kBvhWidth; ++i)
      if (node.count[i] != 0) leaves.push_back({node.first[i], node.count[i]});
  return leaves;
}

}  // namespace meshtrace
