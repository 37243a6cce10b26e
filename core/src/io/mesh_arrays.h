#pragma once
// The arrays of a mesh being read, each planned in the memory budget
// before it is allocated, with messages naming the file.
#include <cstddef>
#include <filesystem>

#include "meshtrace/geometry/mesh.h"
#include "meshtrace/io/memory_budget.h"

namespace meshtrace::mesh_arrays {

// `mesh`'s vertex array, `count` vertices of `file` (a count checked
// against the file's size).
void sizeVertices(MeshData& mesh, MemoryBudget& budget, std::size_t count,
                  const std::filesystem::path& file);

// Room for `capacity` triangles, planned before it is allocated: the new
// array, and the old one until it is copied.
void growTriangles(MeshData& mesh, MemoryBudget& budget, std::size_t capacity,
                   const std::filesystem::path& file);

}  // namespace meshtrace::mesh_arrays
