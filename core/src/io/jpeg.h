#pragma once
// JPEG through libjpeg(-turbo), the codec the reference images were made
// with: stb's encoder and decoder round differently and would add their own
// noise to every comparison.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "meshtrace/io/image.h"

namespace meshtrace::jpeg {

// Baseline JPEG at `quality`, no chroma subsampling (4:4:4).
std::vector<std::uint8_t> encode(const Image8& image, int quality);
// Throws std::runtime_error on corrupt data.
Image8 decode(const std::vector<std::uint8_t>& data);

bool hasJpegSignature(const std::vector<std::uint8_t>& data);

}  // namespace meshtrace::jpeg
