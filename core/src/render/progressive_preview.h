#pragma once
// The Preview structure of a PreparedScene (progressive.h): a uniform grid
// over runs of consecutive triangles ("chunks"), walked cell by cell along
// the ray (Amanatides & Woo, "A Fast Voxel Traversal Algorithm", 1987).
// Most meshes list their triangles in an order that follows the surface (a
// sweep, a scan's strips, a subdivision), so a run of 16 has a small box:
// the grid is made over those boxes, a pass over the triangles and one
// over the chunks, where a grid of single triangles would sort every
// triangle into its cells. A mesh in no such order gets chunks of one
// triangle. Spheres, planes and cylinders are tested one by one on every
// query.
#include <cstdint>
#include <vector>

#include "meshtrace/accel/intersector.h"
#include "util/build_vector.h"

namespace meshtrace {

class PreviewGrid final : public ExternalIntersector {
 public:
  PreviewGrid(const Scene& scene, TriangleKernel kernel);

  bool closestHit(const Ray& ray, double tMin, Hit& hit, Counters& counters) const override;
  bool occluded(const Ray& ray, double tMin, double tMax, Counters& counters) const override;

  // Cells along each axis (0 without triangles).
  int resolution(int axis) const { return res_[axis]; }
  // Chunk entries over all cells, and triangles per chunk (the last of a
  // mesh may have fewer).
  std::size_t entries() const { return refs_.size(); }
  std::uint32_t chunkSize() const { return chunkSize_; }

 private:
  struct Chunk {
    std::uint32_t mesh, first, count;
    float lo[3], hi[3];  // rounded outward: the box holds the triangles
  };

  // Makes the chunks of `size` triangles, then a grid of about
  // `cellsWanted` cells over them; false (and nothing kept) if the chunks
  // are so spread out that they would need more than kMaxEntriesPerChunk
  // entries each, unless the grid is a single cell.
  bool build(std::uint32_t size, double cellsWanted);
  // Offers the primitives the search's ray may meet to `search`
  // (accel/primitive_query.h); true if it ended early.
  template <typename Search>
  bool trace(Search& search, Counters& counters) const;
  // The cells a box overlaps, as [lo, hi] per axis.
  void cellRange(const Aabb& box, int lo[3], int hi[3]) const;
  std::size_t cellIndex(int x, int y, int z) const {
    return (static_cast<std::size_t>(z) * res_[1] + y) * res_[0] + x;
  }

  const Scene& scene_;
  TriangleKernel kernel_;
  Aabb bounds_;
  std::uint32_t chunkSize_ = 0;
  // chunks_ and refs_ are new memory that a scene's first look waits for:
  // on huge pages (BuildVector), they are a few page faults, not hundreds.
  BuildVector<Chunk> chunks_;
  int res_[3] = {0, 0, 0};
  Vec3 cellSize_{0.0}, inverseCell_{0.0};
  std::vector<std::uint32_t>
      cellStart_;                    // per cell, its first entry in refs_ (one more at the end)
  BuildVector<std::uint32_t> refs_;  // chunk indices, cell by cell
};

}  // namespace meshtrace
