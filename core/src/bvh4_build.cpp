// Collapsing a binary BVH into a 4-wide one (see bvh4.h).
#include <algorithm>
#include <limits>
#include <stdexcept>

#include "meshtrace/bvh4.h"

namespace meshtrace {

namespace {

double halfArea(const BvhNode& n) {
  const double x = n.bounds[3] - n.bounds[0], y = n.bounds[4] - n.bounds[1],
               z = n.bounds[5] - n.bounds[2];
  return x * y + y * z + z * x;
}

class Collapser {
 public:
  Collapser(const Bvh& binary, Bvh4& out) : in_(binary), out_(out) {}

  // Fills a new 4-wide node from binary interior node `b`; returns its index.
  std::uint32_t node(std::uint32_t b, int depth) {
    out_.depth = std::max(out_.depth, depth);
    std::uint32_t children[4] = {in_.nodes[b].first, in_.nodes[b].first + 1, 0, 0};
    int n = 2;
    while (n < 4) {
      int widest = -1;
      for (int i = 0; i < n; ++i)
        if (!in_.nodes[children[i]].isLeaf() &&
            (widest < 0 || halfArea(in_.nodes[children[i]]) >
                               halfArea(in_.nodes[children[widest]])))
          widest = i;
      if (widest < 0) break;
      const std::uint32_t split = children[widest];
      children[widest] = in_.nodes[split].first;
      children[n++] = in_.nodes[split].first + 1;
    }
    const auto index = static_cast<std::uint32_t>(out_.nodes.size());
    out_.nodes.emplace_back();
    for (int i = 0; i < 4; ++i) {
      const bool used = i < n;
      const BvhNode* c = used ? &in_.nodes[children[i]] : nullptr;
      for (int a = 0; a < 3; ++a) {
        out_.nodes[index].lo[a][i] = used ? c->bounds[a] : kEmptyLo;
        out_.nodes[index].hi[a][i] = used ? c->bounds[a + 3] : kEmptyHi;
      }
      out_.nodes[index].first[i] = used && c->isLeaf() ? c->first : 0;
      if (used && c->count > std::numeric_limits<std::uint16_t>::max())
        throw std::length_error("BVH leaf larger than a 4-wide node can hold");
      out_.nodes[index].count[i] = static_cast<std::uint16_t>(used ? c->count : 0);
    }
    setChildOrders(out_.nodes[index], children, n);
    // Interior children after the node itself (depth-first order).
    for (int i = 0; i < n; ++i)
      if (!in_.nodes[children[i]].isLeaf()) {
        const std::uint32_t child = node(children[i], depth + 1);
        out_.nodes[index].first[i] = child;
      }
    return index;
  }

 private:
  // Orders the used children of each octant by their box centres projected
  // on the octant's diagonal: a direction-only estimate of which box a ray
  // enters first, free of per-ray work.
  void setChildOrders(Bvh4Node& node, const std::uint32_t* children, int n) const {
    for (int octant = 0; octant < 8; ++octant) {
      double key[4];
      int slots[4] = {0, 1, 2, 3};
      for (int i = 0; i < 4; ++i) {
        key[i] = std::numeric_limits<double>::infinity();  // unused slots go last
        if (i >= n) continue;
        const float* b = in_.nodes[children[i]].bounds;
        key[i] = 0.0;
        for (int a = 0; a < 3; ++a) {
          const double centre2 = static_cast<double>(b[a]) + b[a + 3];
          key[i] += (octant >> a & 1) ? -centre2 : centre2;
        }
      }
      std::stable_sort(slots, slots + 4, [&](int x, int y) { return key[x] < key[y]; });
      const auto packed =
          static_cast<std::uint8_t>(slots[0] | slots[1] << 2 | slots[2] << 4 | slots[3] << 6);
      const auto* found = std::find(kChildOrders.begin(), kChildOrders.end(), packed);
      node.order[octant] = static_cast<std::uint8_t>(found - kChildOrders.begin());
    }
  }

  static constexpr float kEmptyLo = std::numeric_limits<float>::infinity();
  static constexpr float kEmptyHi = -std::numeric_limits<float>::infinity();
  const Bvh& in_;
  Bvh4& out_;
};

}  // namespace

Bvh4 collapseToBvh4(const Bvh& binary) {
  Bvh4 out;
  if (binary.empty()) return out;
  out.order = binary.order;
  const BvhNode& root = binary.nodes[0];
  std::copy(root.bounds, root.bounds + 6, out.rootBounds);
  if (root.isLeaf()) {
    out.rootCount = root.count;
    out.depth = 1;
    return out;
  }
  out.nodes.reserve(binary.nodes.size() / 3 + 1);
  Collapser(binary, out).node(0, 1);
  return out;
}

}  // namespace meshtrace
