#pragma once
// Procedural meshes for our scenes, tests and benchmarks. Every generator is
// deterministic and outward-facing (counter-clockwise seen from outside).
#include <filesystem>

#include "meshtrace/geometry/mesh.h"

namespace meshtrace {

// Icosahedron subdivided `level` times, projected onto the sphere:
// 20 * 4^level triangles.
MeshData makeIcosphere(const Vec3& center, double radius, int level);

// Torus around the y axis: 2 * ringSegments * tubeSegments triangles.
MeshData makeTorus(const Vec3& center, double ringRadius, double tubeRadius, int ringSegments,
                   int tubeSegments);

// A (p, q) torus knot swept by a circular tube: 2 * segments * tubeSegments
// triangles.
MeshData makeTorusKnot(const Vec3& center, double scale, int p, int q, double tubeRadius,
                       int segments, int tubeSegments);

// A square grid in the y = height plane facing +y, 2 * n * n triangles.
MeshData makeGrid(const Vec3& center, double size, int n);

// The closed surface of an axis-aligned box, each face an n x n grid,
// facing outward: 12 * n * n triangles.
MeshData makeGriddedBox(const Vec3& min, const Vec3& max, int n);

// Turns every triangle to face the other way (e.g. a box seen from inside).
void reverseWinding(MeshData& mesh);

// Writes OFF text whose coordinates read back exactly (shortest round-trip
// form). Throws std::runtime_error naming the path on failure.
void writeOff(const MeshData& mesh, const std::filesystem::path& path);

}  // namespace meshtrace
