#pragma once
// Mesh files written from MeshData, each whole or not at all
// (writeFileAtomically): what make_scenes and the bench write. Throws
// std::runtime_error naming the path when it cannot write.
#include <filesystem>

#include "meshtrace/geometry/mesh.h"

namespace meshtrace {

// OFF text whose coordinates read back exactly (shortest round-trip form).
void writeOff(const MeshData& mesh, const std::filesystem::path& path);

// ASCII PLY with OFF's lines: "x y z" (double, read back exactly) and
// "3 a b c" ("list uchar int vertex_indices").
void writeAsciiPly(const MeshData& mesh, const std::filesystem::path& path);

// ASCII STL, one solid: each triangle's normal and corners in double, read
// back exactly.
void writeAsciiStl(const MeshData& mesh, const std::filesystem::path& path);

// Binary little-endian PLY: a vertex element of x, y, z and a face element
// of "list uchar int vertex_indices". Double coordinates read back exactly;
// float ones are what scanners and exporters write, rounded to nearest.
enum class PlyCoordinates { Double, Float };
void writeBinaryPly(const MeshData& mesh, const std::filesystem::path& path,
                    PlyCoordinates coordinates);

// By the extension of `path`: .off, .ply (double coordinates), .obj
// ("v" and "f" lines, exact coordinates) or .stl (binary; each triangle's
// corners as floats, with its normal). std::invalid_argument for another.
void writeMesh(const MeshData& mesh, const std::filesystem::path& path);

}  // namespace meshtrace
