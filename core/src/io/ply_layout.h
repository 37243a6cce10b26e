#pragma once
// Which PLY files our readers take (ply_reader.cpp, ply_ascii_reader.cpp):
// the others go on to OpenMesh's reader.
#include "meshtrace/io/ply_header.h"

namespace meshtrace {

// One vertex element (readPlyHeader has seen its x, y and z, single
// values), and face elements (any number, their faces numbered on from one
// to the next) each with exactly one corner list of integers.
bool readablePlyLayout(const PlyHeader& header);

}  // namespace meshtrace
