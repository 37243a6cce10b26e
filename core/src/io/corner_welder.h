#pragma once
// Corners given by position (STL) welded into a mesh's vertices: each
// position met for the first time becomes the next vertex; a position met
// again gets that vertex's index. Positions are equal when their
// coordinates compare equal, so -0 and +0 weld.
#include <cstdint>
#include <filesystem>
#include <span>
#include <vector>

#include "meshtrace/geometry/mesh.h"
#include "meshtrace/io/memory_budget.h"

namespace meshtrace {

class CornerWelder {
 public:
  // Appends to mesh.vertices, its growth and the welder's table planned in
  // `budget` (naming `file`); `expectedVertices` sizes them at first.
  CornerWelder(MeshData& mesh, MemoryBudget& budget, const std::filesystem::path& file,
               std::size_t expectedVertices);
  ~CornerWelder();
  CornerWelder(const CornerWelder&) = delete;
  CornerWelder& operator=(const CornerWelder&) = delete;

  // Welds the corners of facets, three at a time (finite coordinates), and
  // appends each facet's triangle to the mesh, unless two of its corners
  // weld into one vertex: a facet without area is left out, and recorded
  // as a face of two corners (PolygonFace) so that the faces after it keep
  // their file's numbers. The first facet is facet `firstFacet` of the
  // file.
  void addFacets(std::span<const Vec3> corners, std::uint64_t firstFacet);

 private:
  // The index of the vertex at `p`.
  std::uint32_t weld(const Vec3& p, std::uint64_t hash);
  // Records facet `facet` as left out, before the next triangle.
  void leaveOut(std::uint64_t facet);
  void growTable();

  MeshData& mesh_;
  MemoryBudget& budget_;
  std::filesystem::path file_;
  // Open addressing, linear probing: each slot a vertex index + 1, or 0 when
  // free. Kept at most half full.
  std::vector<std::uint32_t> slots_;
  std::size_t mask_ = 0;
  std::vector<std::uint64_t> hashes_;  // of the corners addFacets welds
};

}  // namespace meshtrace
