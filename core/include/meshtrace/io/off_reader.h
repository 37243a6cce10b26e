#pragma once
// Reader for OFF meshes as found in the wild: comments, blank lines, CRLF,
// counts on the header line, polygons (triangulated by polygon.h) and trailing
// per-face values such as colours.
#include <filesystem>

#include "meshtrace/geometry/mesh.h"
#include "meshtrace/io/memory_budget.h"

namespace meshtrace {

// Throws InputError naming the file and the line or element on bad input
// (a polygon lists each corner once: a face with more corners than the mesh
// has vertices is refused). The vertex and triangle arrays are reserved in
// `budget` before they are allocated (MemoryLimitError beyond its limit).
MeshData readOff(const std::filesystem::path& file, MemoryBudget& budget);
// With a budget of defaultMemoryLimit().
MeshData readOff(const std::filesystem::path& file);

}  // namespace meshtrace
