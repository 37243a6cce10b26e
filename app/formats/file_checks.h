#pragma once
// Checks of a mesh file before OpenMesh's readers see it. Those readers
// trust what a file says: a PLY header without end_header or a face list
// of 2^31 corners keeps them reading forever, counts in headers go to
// reserve() unchecked. Each check
// walks the file's structure (no values are kept, nothing is allocated per
// element) and throws InputError naming the file, the line or the element,
// and what is wrong.
#include <cstdint>
#include <filesystem>
#include <string_view>

namespace meshtrace::formats {

// The elements a checked file holds, for the progress of its read: its
// vertices and its faces.
struct ElementCounts {
  std::uint64_t vertices = 0, faces = 0;
};

// The whole header: the format, elements, properties and end_header in
// the first 64 KiB; a vertex element with x, y and z and a face element
// with a list of vertex indices; counts a file of this size can hold; then
// every element of the body, each face listing 3 to (vertex count) corners.
ElementCounts checkPly(const std::filesystem::path& file, std::string_view bytes);
// The header's counts against the file's size; then refused (README).
[[noreturn]] void checkOm(const std::filesystem::path& file, std::string_view bytes);

}  // namespace meshtrace::formats
