#pragma once
// Meshes for tests that build BVHs over them: generated geometry made a
// scene mesh, and the boxes of a mesh's triangles for the binary build.
#include <vector>

#include "meshtrace/geometry/aabb.h"
#include "meshtrace/geometry/mesh.h"

namespace meshtrace::test {

// `data` as a flat-shaded mesh named `name`, with the default material.
Mesh makeMesh(const char* name, MeshData data);

// The bounding box of each triangle of `m`, in triangle order.
std::vector<Aabb> triangleBoxes(const MeshData& m);

}  // namespace meshtrace::test
