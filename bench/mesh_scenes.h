#pragma once
// Benchmark inputs made by our own code: a scene file framing a mesh, and a
// large generated mesh.
#include <cstddef>
#include <filesystem>

namespace meshtrace::bench {

// Writes a .sce that frames the OFF mesh (read for its bounding box) from
// an oblique view at 800x600, one light, PHONG shading. The mesh is referred
// to by file name, so the scene must sit beside it.
void writeMeshScene(const std::filesystem::path& off, const std::filesystem::path& sce);

// Writes a (2, 3) torus knot with at least `triangles` triangles as OFF.
void writeKnot(const std::filesystem::path& off, std::size_t triangles);

}  // namespace meshtrace::bench
