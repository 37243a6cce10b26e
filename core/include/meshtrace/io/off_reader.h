#pragma once
// Reader for OFF meshes as found in the wild: comments, blank lines, CRLF,
// counts on the header line, polygons (fan-triangulated) and trailing
// per-face values such as colours.
#include <filesystem>

#include "meshtrace/geometry/mesh.h"

namespace meshtrace {

// Throws InputError naming the file and the line or element on bad input.
MeshData readOff(const std::filesystem::path& file);

}  // namespace meshtrace
