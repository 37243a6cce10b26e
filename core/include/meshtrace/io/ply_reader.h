#pragma once
// Reader for PLY meshes, ASCII and binary (either byte order), streamed
// from the file as OFF's reader streams its text: the triangles are those
// of OFF's reader for the same polygons, and an ASCII file's coordinates
// are read in double as OFF's are.
#include <filesystem>
#include <optional>

#include "meshtrace/geometry/mesh.h"
#include "meshtrace/io/memory_budget.h"

namespace meshtrace {

// Reads a PLY file whose vertex element has x, y and z of any PLY number
// type (its other properties, lists too, skipped) and whose face elements
// (any number; their faces numbered on from one to the next) list their
// corners with integer indices; other elements and properties are skipped
// (a binary file's by their size; an ASCII file's values are checked
// against their types, one record to a line). Returns std::nullopt, having
// read only the header, for a PLY file it leaves to other readers: more
// than one vertex element, float corner indices. Faces may come before the
// vertices.
// Throws InputError naming the file and the element ("face 17"), and for
// ASCII the line, on bad input: a header readPlyHeader refuses, a
// truncated body, corner counts below 3 or above the vertex count, indices
// out of range, non-finite coordinates, a record of the wrong values. The
// arrays are reserved in `budget` before they are allocated.
std::optional<MeshData> readPly(const std::filesystem::path& file, MemoryBudget& budget);

}  // namespace meshtrace
