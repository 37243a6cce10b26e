#pragma once
// PNG encoding through libpng and zlib. stb's encoder, which the reader
// still uses for decoding, compressed an 800x600 render in 14-27 ms; zlib's
// fastest level with the Sub filter takes 3-4 ms and writes smaller files
// (58 against 66 KB for refined_elephant's frame; BENCHMARKS.md).
#include <cstdint>
#include <vector>

#include "meshtrace/io/image.h"

namespace meshtrace::png {

// Throws std::runtime_error if libpng reports an error.
std::vector<std::uint8_t> encode(const Image8& image);

}  // namespace meshtrace::png
