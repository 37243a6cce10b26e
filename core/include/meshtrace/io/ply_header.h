#pragma once
// A PLY file's header as it declares it: the format, and each element with
// its count and properties. Read strictly, by the PLY reader and by the
// check run before OpenMesh's reader alike, so that both refuse the same
// headers with the same words.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace meshtrace {

// The most bytes a header may take: it must end within them.
inline constexpr std::size_t kMaxPlyHeaderBytes = 64 * 1024;

struct PlyProperty {
  std::string name;
  int size = 0;       // bytes of a value, or of a list's items
  int countSize = 0;  // bytes of a list's count; 0 for a single value
  bool countSigned = false;
  bool isFloat = false;   // of a value or of a list's items
  bool isSigned = false;  // of an integer value or of a list's integer items
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
  std::size_t line = 0;  // the header line that declares it
};

struct PlyHeader {
  std::string format;  // "ascii", "binary_little_endian" or "binary_big_endian"
  std::vector<PlyElement> elements;
  std::size_t bodyStart = 0;   // the offset of the first byte after end_header's line
  std::size_t lines = 0;       // the header's lines, end_header's included
  std::uint64_t vertices = 0;  // the vertex element's count
};

// Reads the header at the start of `bytes` (the file's first bytes; the
// header must end in its first 64 KiB) of a file of `fileSize` bytes:
// "ply", a format line (version 1.0), elements and their properties, and
// end_header; a vertex element with x, y and z, and any face element with
// a list vertex_indices (or vertex_index); counts whose smallest records
// (a value of each property, three corners per face) fit in the file.
// Throws InputError naming `file` and the line of what is wrong.
PlyHeader readPlyHeader(const std::filesystem::path& file, std::string_view bytes,
                        std::uint64_t fileSize);

// Whether `p` is the list a face takes its corners from.
bool isPlyCornerList(const PlyElement& e, const PlyProperty& p);

}  // namespace meshtrace
