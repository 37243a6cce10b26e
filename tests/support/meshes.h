#pragma once
// Meshes for tests that build BVHs over them: generated geometry made a
// scene mesh, and the boxes of a mesh's triangles for the binary build.
#include <vector>

#include "meshtrace/geometry/aabb.h"
#include "meshtrace/geometry/mesh.h"
#include "meshtrace/geometry/scene.h"

namespace meshtrace::test {

// `data` as a flat-shaded mesh named `name`, with the default material.
Mesh makeMesh(const char* name, MeshData data);

// The bounding box of each triangle of `m`, in triangle order.
std::vector<Aabb> triangleBoxes(const MeshData& m);

// `m` with, for every `every`-th triangle, appended: `copies` exact copies
// (triangle_copies.h) listing its vertices, `copies` listing new vertices
// at the same positions, and triangles that are not copies though they
// have the same box: its five other corner orders, and its corners with
// the first moved by one ulp.
MeshData withCopies(MeshData m, std::size_t every, int copies);

// The hall of scenes/hall (makeHall) with its two lights, the sun through
// the windows and a lamp under the ceiling, seen by its camera at
// `width` x `height` pixels: most shadow rays are blocked by walls, beams
// and bars, which neighbouring pixels share.
Scene hallScene(int width, int height);

}  // namespace meshtrace::test
