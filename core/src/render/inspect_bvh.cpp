// The scene BVH's nodes as boxes, for drawing: those a ray enters, and the
// cut through a level at a depth. Reads the 8-wide trees of both levels
// (accel/bvh8.h); the node layout stays private to the library.
#include "render/inspect_bvh.h"

#include "accel/scene_bvh.h"
#include "meshtrace/util/enum_names.h"

namespace meshtrace {

namespace {
constexpr EnumName<BvhLevel> kLevels[] = {{BvhLevel::Objects, "objects"},
                                          {BvhLevel::Triangles, "triangles"}};

const Bvh8* treeOf(const SceneIntersector& intersector, BvhLevel level) {
  const SceneBvh* bvh = intersector.bvh();
  if (!bvh) return nullptr;
  const Bvh8& tree = level == BvhLevel::Objects ? bvh->topLevel() : bvh->meshBvh().tree;
  return tree.empty() ? nullptr : &tree;
}

// A node's child slot: its box, or an empty box for an unused slot.
Aabb childBox(const Bvh8Node& node, int k) {
  Aabb box;
  if (node.lo[0][k] > node.hi[0][k]) return box;
  for (int a = 0; a < 3; ++a) {
    box.min[a] = node.lo[a][k];
    box.max[a] = node.hi[a][k];
  }
  return box;
}

// Calls visit(box, depth, leaf) for the root and, for each node visit
// returns true for, for its children (depth first, in slot order).
template <typename Visit>
void walk(const Bvh8& tree, const Visit& visit) {
  if (tree.rootCount > 0) {
    Aabb root;
    for (int a = 0; a < 3; ++a) {
      root.min[a] = tree.rootLo[a];
      root.max[a] = tree.rootHi[a];
    }
    visit(root, 0, true);
    return;
  }
  Aabb root;
  for (int k = 0; k < kBvhWidth; ++k) root.extend(childBox(tree.nodes[0], k));
  if (!visit(root, 0, false)) return;
  struct Entry {
    std::uint32_t node;
    int depth;
  };
  std::vector<Entry> stack{{0, 0}};
  while (!stack.empty()) {
    const Entry e = stack.back();
    stack.pop_back();
    const Bvh8Node& node = tree.nodes[e.node];
    // Slots pushed last to first, so they are visited in order.
    for (int k = kBvhWidth - 1; k >= 0; --k) {
      const Aabb box = childBox(node, k);
      if (box.empty()) continue;
      const bool leaf = node.count[k] > 0;
      if (visit(box, e.depth + 1, leaf) && !leaf) stack.push_back({node.first[k], e.depth + 1});
    }
  }
}
}  // namespace

const char* toString(BvhLevel level) { return nameIn(kLevels, level); }

std::vector<BvhNodeBox> bvhNodesEntered(const SceneIntersector& intersector, const Ray& ray,
                                        double tMax) {
  std::vector<BvhNodeBox> out;
  const RayInverse inverse(ray);
  // A leaf's box may be as thin as the face the ray hits, where rounding
  // can put its entry just past the hit: a little margin keeps it, as the
  // traversal's own padded box test does.
  tMax *= 1.0 + kEnteredMargin;
  for (BvhLevel level : {BvhLevel::Objects, BvhLevel::Triangles}) {
    const Bvh8* tree = treeOf(intersector, level);
    if (!tree) continue;
    walk(*tree, [&](const Aabb& box, int depth, bool leaf) {
      double tEnter, tExit;
      if (!intersectSlabs(box, inverse, 0.0, tMax, tEnter, tExit)) return false;
      out.push_back({box, depth, level, leaf});
      return true;
    });
  }
  return out;
}

BvhCut bvhCut(const SceneIntersector& intersector, BvhLevel level, int depth, std::size_t limit) {
  BvhCut out;
  const Bvh8* tree = treeOf(intersector, level);
  if (!tree) return out;
  out.levelDepth = tree->rootCount > 0 ? 0 : tree->depth;
  walk(*tree, [&](const Aabb& box, int d, bool leaf) {
    if (d < depth && !leaf) return true;  // go down to the cut
    if (out.boxes.size() < limit)
      out.boxes.push_back({box, d, level, leaf});
    else
      out.truncated = true;
    return false;
  });
  return out;
}

}  // namespace meshtrace
