#pragma once
// The arrays of a mesh being read, each planned in the memory budget
// before it is allocated, with messages naming the file.
#include <cstddef>
#include <cstdint>
#include <exception>
#include <filesystem>
#include <string_view>
#include <vector>

#include "io/line_pieces.h"
#include "meshtrace/geometry/mesh.h"
#include "meshtrace/io/memory_budget.h"

namespace meshtrace::mesh_arrays {

// `mesh`'s vertex array, `count` vertices of `file` (a count checked
// against the file's size).
void sizeVertices(MeshData& mesh, MemoryBudget& budget, std::size_t count,
                  const std::filesystem::path& file);

// Room for `capacity` vertices, for a reader that learns their number as it
// reads: planned before it is allocated, the new array and the old one
// until it is copied.
void growVertices(MeshData& mesh, MemoryBudget& budget, std::size_t capacity,
                  const std::filesystem::path& file);

// Room for `capacity` triangles, planned before it is allocated: the new
// array, and the old one until it is copied.
void growTriangles(MeshData& mesh, MemoryBudget& budget, std::size_t capacity,
                   const std::filesystem::path& file);

// Room for `capacity` face records (MeshData::polygons), planned alike.
void growPolygons(MeshData& mesh, MemoryBudget& budget, std::size_t capacity,
                  const std::filesystem::path& file);

// What a piece of a text mesh (OFF, OBJ, ASCII PLY) holds whatever the
// format, as it goes through text::streamPieces: the triangles its faces
// were cut into.
struct MeshChunk : text::PieceChunk {
  std::vector<TriangleIndices> triangles;
  std::vector<PolygonFace> polygons;   // among `triangles`, numbered from its first face
  std::vector<std::uint32_t> corners;  // of the face being read
  std::exception_ptr error;            // of its first bad line
};

// Appends `chunk`'s triangles and polygon records to `mesh`, its first face
// being face `firstFace` of the file, the triangle array grown first as
// growTriangles grows it (at least doubling). Throws MemoryLimitError.
void appendTriangles(MeshData& mesh, MemoryBudget& budget, const MeshChunk& chunk,
                     std::uint32_t firstFace, const std::filesystem::path& file);

}  // namespace meshtrace::mesh_arrays
