#pragma once
// A/B inside the viewer: the render kept as "B" (with what it was made
// with), and the comparison of the current render "A" with it: RMSE, PSNR,
// the largest difference, and the difference image.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "meshtrace/geometry/camera.h"
#include "meshtrace/io/image.h"
#include "meshtrace/report/image_compare.h"

namespace meshtrace::viewer {

// How the image view shows A and B.
enum class AbMode { A, B, Wipe, Difference };
inline constexpr int kAbModeCount = 4;
const char* label(AbMode mode);
const char* name(AbMode mode);  // command-line name: a, b, wipe, difference
std::optional<AbMode> parseAbMode(std::string_view name);

struct KeptImage {
  Image8 image;        // RGB, top row first
  std::string label;   // what it was rendered with
  CameraSpec camera;   // through which camera
  bool exact = false;  // every pixel was traced exactly when it was kept
};

struct AbComparison {
  std::uint64_t job = 0;  // A's render
  ImageDifference difference;
  std::vector<std::uint8_t> differenceRgba;  // |A - B| x kAbDifferenceGain
};
inline constexpr int kAbDifferenceGain = 4;

// Compares A with B (the same size).
AbComparison compareWithB(std::uint64_t job, const Image8& a, const Image8& b);

// |a - b| x gain per channel, as RGBA with full alpha (the same size).
std::vector<std::uint8_t> differenceRgba(const Image8& a, const Image8& b, int gain);

// RGBA with full alpha, for a texture.
std::vector<std::uint8_t> toRgba(const Image8& image);

}  // namespace meshtrace::viewer
