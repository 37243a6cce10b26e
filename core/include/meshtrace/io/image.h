#pragma once
// A linear RGB image, stored top row first as image files are, and its 8-bit
// encoding and file I/O.
#include <cstdint>
#include <filesystem>
#include <vector>

#include "meshtrace/io/output_file.h"
#include "meshtrace/util/math.h"

namespace meshtrace {

// Images are stored top row first, as image files are; the camera's y runs
// from the bottom (y = 0 is the bottom row). The one conversion between a
// storage row and a camera y, either way (it is its own inverse).
constexpr int flippedRow(int row, int height) { return height - 1 - row; }

struct Image {
  int width = 0;
  int height = 0;
  std::vector<Color> pixels;  // row-major, row 0 at the top

  Image() = default;
  Image(int w, int h, const Color& fill = Color(0.0))
      : width(w), height(h), pixels(static_cast<std::size_t>(w) * h, fill) {}

  Color& at(int x, int row) { return pixels[static_cast<std::size_t>(row) * width + x]; }
  const Color& at(int x, int row) const {
    return pixels[static_cast<std::size_t>(row) * width + x];
  }
};

// 8-bit RGB, top row first.
struct Image8 {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;

  std::uint8_t channel(int x, int row, int c) const {
    return rgb[(static_cast<std::size_t>(row) * width + x) * 3 + c];
  }
};

// floor(255 * min(c, 1)) per channel, negative values to 0, as the reference.
std::uint8_t toByte(double c);
Image8 quantize(const Image& image);

// Writes PNG, BMP, PPM or JPEG (by extension) through an OutputFile
// (output_file.h): a failure leaves any existing file untouched. Throws
// std::runtime_error naming the path on failure.
void writeImage(const Image8& image, const std::filesystem::path& path);
// The same into `out`, of the type its target's extension names, without
// committing it: for files that replace their targets together.
void writeImage(const Image8& image, OutputFile& out);
// Whether `path` names an OpenEXR file (.exr): written from float layers
// with writeExr (exr.h), not from an Image8.
bool isExrPath(const std::filesystem::path& path);
// Throws std::runtime_error naming the path if writeImage (or writeExr, for
// .exr) could not write there for a reason known before any image exists:
// an unknown image type,
// or what checkOutputDestination finds. Lets a long render be refused
// before it starts rather than after.
void checkImageDestination(const std::filesystem::path& path);
// Throws std::runtime_error naming the path if it cannot be read.
Image8 readImage(const std::filesystem::path& path);

// Encode as JPEG (quality, no chroma subsampling) and decode again.
Image8 jpegRoundTrip(const Image8& image, int quality);

}  // namespace meshtrace
