#include "io/corner_welder.h"

#include <bit>
#include <cstring>
#include <string>

#include "io/mesh_arrays.h"

namespace meshtrace {

namespace {
// A hash of the position's coordinates as they compare: adding +0 turns -0
// into +0 and leaves every other value as it is.
std::uint64_t hashOf(const Vec3& p) {
  std::uint64_t h = 0;
  for (int k = 0; k < 3; ++k) {
    h = (h ^ std::bit_cast<std::uint64_t>(p[k] + 0.0)) * 0x9e3779b97f4a7c15u;
    h ^= h >> 29;
  }
  return h;
}
}  // namespace

CornerWelder::CornerWelder(MeshData& mesh, MemoryBudget& budget, const std::filesystem::path& file,
                           std::size_t expectedVertices)
    : mesh_(mesh), budget_(budget), file_(file) {
  mesh_arrays::growVertices(mesh_, budget_, expectedVertices, file_);
  std::size_t slots = 16;
  while (slots < 2 * expectedVertices) slots *= 2;
  budget_.reserve(slots * sizeof(std::uint32_t), "load",
                  "the vertex table of " + file_.filename().string());
  slots_.assign(slots, 0);
  mask_ = slots - 1;
}

CornerWelder::~CornerWelder() { budget_.release(slots_.size() * sizeof(std::uint32_t)); }

std::uint32_t CornerWelder::weld(const Vec3& p, std::uint64_t hash) {
  for (std::size_t i = hash & mask_;; i = (i + 1) & mask_) {
    const std::uint32_t slot = slots_[i];
    if (slot == 0) {
      const auto index = static_cast<std::uint32_t>(mesh_.vertices.size());
      if (mesh_.vertices.size() == mesh_.vertices.capacity())
        mesh_arrays::growVertices(mesh_, budget_, 2 * mesh_.vertices.capacity(), file_);
      mesh_.vertices.push_back(p);
      slots_[i] = index + 1;
      if (2 * mesh_.vertices.size() > slots_.size()) growTable();
      return index;
    }
    if (mesh_.vertices[slot - 1] == p) return slot - 1;
  }
}

void CornerWelder::addFacets(std::span<const Vec3> corners, std::uint64_t firstFacet) {
  // Welding a corner reads its table slot, then the vertex the slot names:
  // two dependent reads far apart, each a likely cache miss in a large
  // mesh. The slot is prefetched kSlotAhead corners ahead and the vertex
  // kVertexAhead ahead (its slot then in the cache), so that the misses of
  // several corners overlap instead of following one another. A prefetch
  // only guesses: a slot taken or a table grown meanwhile makes it useless,
  // not wrong.
  constexpr std::size_t kSlotAhead = 64, kVertexAhead = 32;
  hashes_.resize(corners.size());
  for (std::size_t i = 0; i < corners.size(); ++i) hashes_[i] = hashOf(corners[i]);
  TriangleIndices t;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    if (i + kSlotAhead < corners.size())
      __builtin_prefetch(&slots_[hashes_[i + kSlotAhead] & mask_]);
    if (i + kVertexAhead < corners.size()) {
      const std::uint32_t slot = slots_[hashes_[i + kVertexAhead] & mask_];
      if (slot != 0) __builtin_prefetch(&mesh_.vertices[slot - 1]);
    }
    t[i % 3] = weld(corners[i], hashes_[i]);
    if (i % 3 < 2) continue;
    if (t[0] == t[1] || t[0] == t[2] || t[1] == t[2]) {
      leaveOut(firstFacet + i / 3);
      continue;
    }
    if (mesh_.triangles.size() == mesh_.triangles.capacity())
      mesh_arrays::growTriangles(mesh_, budget_, 2 * mesh_.triangles.capacity() + 1, file_);
    mesh_.triangles.push_back(t);
  }
}

void CornerWelder::leaveOut(std::uint64_t facet) {
  if (mesh_.polygons.size() == mesh_.polygons.capacity())
    mesh_arrays::growPolygons(mesh_, budget_, 2 * mesh_.polygons.capacity() + 1, file_);
  // Facet numbers fit 32 bits as triangle numbers do: a file of more is
  // refused by its size.
  mesh_.polygons.push_back(
      {static_cast<std::uint32_t>(mesh_.triangles.size()), 2, static_cast<std::uint32_t>(facet)});
}

void CornerWelder::growTable() {
  const std::size_t slots = 2 * slots_.size();
  budget_.reserve(slots * sizeof(std::uint32_t), "load",
                  "the vertex table of " + file_.filename().string());
  std::vector<std::uint32_t> grown(slots, 0);
  mask_ = slots - 1;
  for (std::uint32_t v = 0; v < mesh_.vertices.size(); ++v) {
    std::size_t i = hashOf(mesh_.vertices[v]) & mask_;
    while (grown[i] != 0) i = (i + 1) & mask_;
    grown[i] = v + 1;
  }
  budget_.release(slots_.size() * sizeof(std::uint32_t));
  slots_ = std::move(grown);
}

}  // namespace meshtrace
