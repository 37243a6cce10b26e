#pragma once
// How closely a render must match a reference image, in the scene format's
// own words (../shared/SCENE_FORMAT.md, "How close is close enough"), for
// the tests that compare whole images.
#include <cstddef>
#include <filesystem>
#include <string>

#include "meshtrace/io/image.h"

namespace meshtrace::test {

// "A handful of pixels on silhouettes and shared triangle edges may differ
// more (which face a ray hits is a rounding decision there); whole regions
// may not": five pixels.
inline constexpr std::size_t kHandfulOfPixels = 5;

// The pixels of two images of one size that differ by more than `by` in
// some channel.
std::size_t pixelsDiffering(const Image8& a, const Image8& b, int by = 0);

// A render of a seed scene against its reference JPEG: encoded the same way
// (JPEG q95 4:4:4) and decoded, within RMSE 0.2 of it, and at most a
// handful of pixels off by more than 32. Prints the figures under `label`.
void expectWithinJpegNoise(const Image8& render, const std::filesystem::path& reference,
                           const std::string& label);

}  // namespace meshtrace::test
