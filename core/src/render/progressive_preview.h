#pragma once
// The Preview structure of a PreparedScene (progressive.h): a uniform grid
// over every mesh's triangles, walked cell by cell along the ray (Amanatides
// & Woo, "A Fast Voxel Traversal Algorithm", 1987). It is made in two
// parallel passes over the triangles (count per cell, then fill), so a
// viewer has something to trace while the BVH builds. Spheres, planes and
// cylinders are tested one by one on every query.
#include <cstdint>
#include <vector>

#include "meshtrace/accel/intersector.h"

namespace meshtrace {

class PreviewGrid final : public ExternalIntersector {
 public:
  PreviewGrid(const Scene& scene, TriangleKernel kernel);

  bool closestHit(const Ray& ray, double tMin, Hit& hit, Counters& counters) const override;
  bool occluded(const Ray& ray, double tMin, double tMax, Counters& counters) const override;

  // Cells along each axis (0 without triangles).
  int resolution(int axis) const { return res_[axis]; }
  // Triangle entries over all cells.
  std::size_t entries() const { return refs_.size(); }

 private:
  struct TriangleRef {
    std::uint32_t mesh, triangle;
  };

  // Offers the primitives the search's ray may meet to `search`
  // (accel/primitive_query.h); true if it ended early.
  template <typename Search>
  bool trace(Search& search, Counters& counters) const;
  // The cells whose box a triangle's box overlaps, as [lo, hi] per axis.
  void cellRange(const Aabb& box, int lo[3], int hi[3]) const;
  std::size_t cellIndex(int x, int y, int z) const {
    return (static_cast<std::size_t>(z) * res_[1] + y) * res_[0] + x;
  }

  const Scene& scene_;
  TriangleKernel kernel_;
  Aabb bounds_;
  int res_[3] = {0, 0, 0};
  Vec3 cellSize_{0.0}, inverseCell_{0.0};
  std::vector<std::uint32_t>
      cellStart_;  // per cell, its first entry in refs_ (one more at the end)
  std::vector<TriangleRef> refs_;
};

}  // namespace meshtrace
