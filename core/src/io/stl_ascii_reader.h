#pragma once
// ASCII STL, read in parallel pieces: each piece's words are found and its
// numbers parsed in parallel (text::streamPieces); the grammar, which spans
// lines, and the welding of corners into vertices run on the words in file
// order as the pieces are gathered.
#include "io/file_source.h"
#include "meshtrace/geometry/mesh.h"
#include "meshtrace/io/memory_budget.h"

namespace meshtrace {

// Reads `source` as readStl describes an ASCII STL (stl_reader.h): the
// first bad word of the file is the one reported, as a serial reader would
// find it.
MeshData readAsciiStl(text::FileSource& source, MemoryBudget& budget);

}  // namespace meshtrace
