#pragma once
// OM (refused after its check) and the PLY layouts the core's reader
// leaves, through OpenMesh's readers; OFF, OBJ, PLY and STL have readers
// of their own in the core. A library of its own, so that the core never depends on
// OpenMesh: the tools link it and register its readers at start.
#include <filesystem>

#include "meshtrace/geometry/mesh.h"
#include "meshtrace/io/memory_budget.h"

namespace meshtrace::formats {

// Registers readOpenMeshFile for .om, and for .ply the
// core's PLY reader (readPly), with readOpenMeshFile for the PLY files it
// leaves (registerMeshReader); only the first call does, so
// every loader may call it first.
void registerOpenMeshFormats();

// Reads a mesh with the OpenMesh reader of its extension (.ply, .stl or
// .om; PLY and OM checked first, file_checks.h; other formats go
// unchecked, for comparisons in the tests), polygons triangulated as OFF's
// are (polygon.h). Only the faces' corners are taken: no topology is
// built, so a non-manifold mesh keeps every face. STL lists each
// triangle's corners apart; its reader merges equal points, so the
// vertices are shared as in an indexed mesh. Throws InputError naming the
// file (and the element where known) on bad input; reserves its arrays in
// `budget` before allocating them.
MeshData readOpenMeshFile(const std::filesystem::path& file, MemoryBudget& budget);

}  // namespace meshtrace::formats
