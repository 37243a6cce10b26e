#pragma once
// Reader for Wavefront OBJ meshes: the vertices (`v x y z`, further values
// ignored) and the faces (`f` with corners `i`, `i/t`, `i//n` or `i/t/n`,
// indices from 1, or negative for the vertices just above), polygons
// triangulated by polygon.h. Every other statement (texture coordinates,
// normals, groups, materials, lines) is skipped; comments, blank lines and
// CRLF line ends are allowed. Coordinates are read as doubles.
#include <filesystem>

#include "meshtrace/geometry/mesh.h"
#include "meshtrace/io/memory_budget.h"

namespace meshtrace {

// Throws InputError naming the file and the line on bad input: a vertex
// without three finite numbers, a face of fewer than three corners or more
// corners than there are vertices above it, a corner naming no vertex
// defined above it, a NUL byte, no vertex at all. The vertex and triangle
// arrays are planned in `budget` before they are allocated
// (MemoryLimitError beyond its limit).
MeshData readObj(const std::filesystem::path& file, MemoryBudget& budget);

}  // namespace meshtrace
