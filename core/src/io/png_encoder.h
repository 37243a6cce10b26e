#pragma once
// PNG encoding through libpng and zlib at its fastest level with the Sub
// filter: several times faster than stb's encoder (which the reader still
// uses for decoding), with smaller files (BENCHMARKS.md).
#include <cstdint>
#include <vector>

#include "meshtrace/io/image.h"

namespace meshtrace::png {

// Throws std::runtime_error if libpng reports an error.
std::vector<std::uint8_t> encode(const Image8& image);

}  // namespace meshtrace::png
