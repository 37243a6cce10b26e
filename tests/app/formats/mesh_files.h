#pragma once
// The same mesh written in each format, by hand from the formats' specs,
// independently of the readers under test; OM, OpenMesh's own binary
// halfedge format, by OpenMesh's writer.
#include <filesystem>
#include <string>
#include <vector>

#include "meshtrace/geometry/mesh.h"

namespace meshtrace::test {

enum class MeshFormat {
  Off,
  PlyAscii,
  PlyBinary,
  PlyBinaryBigEndian,
  Obj,
  StlAscii,
  StlBinary,
  Om
};

// Every format, and its name for test output ("ply-binary").
const std::vector<MeshFormat>& allMeshFormats();
std::string formatName(MeshFormat format);
// ".ply" and so on.
std::string formatExtension(MeshFormat format);

// Writes `mesh` as `format` to `path`. STL lists each triangle's three
// corners; the others are indexed. Coordinates are written as floats
// (exactly, in the text formats), so use meshes whose coordinates are
// floats (onFloatGrid) to compare formats.
void writeMeshFile(const MeshData& mesh, MeshFormat format, const std::filesystem::path& path);

// `mesh` with every coordinate rounded to a multiple of 1/1024: floats
// (for coordinates below 8192), written exactly by every format.
MeshData onFloatGrid(MeshData mesh);

}  // namespace meshtrace::test
