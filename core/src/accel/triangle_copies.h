#pragma once
// Exact copies of a triangle: triangles that every kernel, in either
// precision, computes with the same arithmetic on the same numbers, so that
// no ray can tell them apart except by their index.
//
// A kernel reads a triangle as its three corner positions in the order the
// triangle lists them (TriangleRay::intersect takes a, b, c): the edges it
// forms, the products it sums and the order of its roundings follow from
// that order, and in single precision from the floats of those doubles.
// So two triangles are copies when their corners are equal bit for bit
// (-0 and +0 apart, as the signs of zero can take different paths), in the
// same order; which vertex indices hold those positions does not matter.
// The same corners listed in another order are not copies: they are the
// same surface, but a kernel may round their hit differently.
//
// Every member of a set of copies hits where the others do, at the same t,
// and a tie goes to the lowest index (primitive_query.h). A query leaves
// out at most one triangle, the one its ray starts on (spawn.h): so of a
// set, the lowest index answers for all of them, or, for a ray leaving it,
// the second lowest. The members past the two lowest can never be a hit or
// a blocker that those two are not, and the BVH leaves them out.
#include <array>
#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

#include "meshtrace/geometry/mesh.h"

namespace meshtrace {

// Whether triangle `a` of mesh `ma` and triangle `b` of mesh `mb` are
// copies (the meshes may be the same).
inline bool sameCorners(const Mesh& ma, std::uint32_t a, const Mesh& mb, std::uint32_t b) {
  const TriangleIndices &ia = ma.triangles()[a], &ib = mb.triangles()[b];
  for (int k = 0; k < 3; ++k)
    if (std::memcmp(&ma.vertices()[ia[k]], &mb.vertices()[ib[k]], sizeof(Vec3)) != 0) return false;
  return true;
}

// For each entry of `triangles` (indices into `mesh`, each at most once),
// whether it is a spare copy: a copy of two other entries with lower
// indices. Time O(n log n).
std::vector<char> markSpareCopies(const Mesh& mesh, std::span<const std::uint32_t> triangles);

// A triangle's corners as bits (x, y, z of each corner in order), and a
// hash of them.
using CornerBits = std::array<std::uint64_t, 9>;
using CornerHash = std::uint64_t (*)(const CornerBits&);
// markSpareCopies with another hash than its own: tests pass one that
// collides.
std::vector<char> markSpareCopies(const Mesh& mesh, std::span<const std::uint32_t> triangles,
                                  CornerHash hash);

}  // namespace meshtrace
