#pragma once
// Procedural meshes for our scenes, tests and benchmarks. Every generator is
// deterministic and outward-facing (counter-clockwise seen from outside).
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

// Interiors: scenes of large, long and thin triangles spanning the scene
// beside small parts, where a BVH over whole triangles is weakest
// (architecture_generators.cpp). Both are unions of boxes (12 triangles
// each, with corners of their own), axis-aligned and facing outward.

// A hall of `length` along z, `width` along x and `height`, its floor at
// y = 0 centred on the origin: a floor of stripes running its length, walls
// with window openings crossed by bars, a ceiling carried by beams across
// the width, two rows of columns and a flight of stairs at the far end.
MeshData makeHall(double length, double width, double height);

// A Menger sponge of `level` (0 is the cube) filling the cube of side
// `size` at `center`: 20^level cubes, touching face to face, so that
// neighbours' faces are coplanar.
MeshData makeMengerSponge(const Vec3& center, double size, int level);

// Adds `part`'s vertices and triangles to `mesh`.
void appendMesh(MeshData& mesh, const MeshData& part);

// Turns every triangle to face the other way (e.g. a box seen from inside).
void reverseWinding(MeshData& mesh);

}  // namespace meshtrace
