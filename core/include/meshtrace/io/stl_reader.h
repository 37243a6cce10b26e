#pragma once
// Reader for STL meshes, binary and ASCII. STL lists each facet's three
// corners by position; corners at equal positions are welded into one
// vertex (numbered in the order they first occur), so that PHONG normals
// are those of the same mesh indexed. Binary coordinates are floats;
// ASCII ones are read in double as OFF's are.
#include <filesystem>

#include "meshtrace/geometry/mesh.h"
#include "meshtrace/io/memory_budget.h"

namespace meshtrace {

// A file is binary when its size is 84 + 50 n bytes, n the little-endian
// count at byte 80; otherwise ASCII: "solid" and its name, then facets
// ("facet normal nx ny nz", "outer loop", three "vertex x y z", "endloop",
// "endfacet"), then "endsolid" and its name, and any further solids alike.
// Corners are equal when their coordinates compare equal (-0 and +0 too).
// A facet two of whose corners weld into one vertex has no area and is
// left out, recorded in MeshData::polygons so that the facets after it
// keep their numbers (Mesh::faceOf). Facet normals are not read. Throws InputError naming the file
// and the facet (and for ASCII the line) on bad input: a file neither
// binary nor ASCII, an unexpected word, a value that is no number, a
// non-finite coordinate, a file that ends inside a solid. The arrays are
// planned in `budget` before they are allocated (MemoryLimitError beyond
// its limit).
MeshData readStl(const std::filesystem::path& file, MemoryBudget& budget);

}  // namespace meshtrace
