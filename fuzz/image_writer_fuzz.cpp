// Fuzzes image writing: an image of fuzzed size and pixels, written as PNG,
// BMP, PPM or JPEG under a fuzzed name in an empty scratch folder, half the
// time over an older image of that name. Afterwards the folder must hold
// that one file: the new image if the write succeeded (the same pixels for
// the lossless formats, the same size for JPEG), the old one untouched if
// it threw, and no temporary file either way.
//
// Input: format (low two bits of byte 0; bit 2: over an older file), width
// and height (bytes 1 and 2, 1 to 64), the name's length (byte 3, up to
// 200 bytes of the input, without '/' or NUL), then pixel bytes, repeated
// to fill the image.
#include <unistd.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

#include "meshtrace/io/image.h"

namespace {

namespace fs = std::filesystem;
using meshtrace::Image8;

const fs::path& scratch() {
  static const fs::path dir =
      fs::temp_directory_path() / ("meshtrace-fuzz-image-" + std::to_string(getpid()));
  return dir;
}

[[noreturn]] void fail(const char* what, const fs::path& file) {
  std::fprintf(stderr, "%s: %s\n", file.c_str(), what);
  std::abort();
}

std::size_t filesIn(const fs::path& dir) {
  std::size_t n = 0;
  for (const auto& e : fs::directory_iterator(dir)) n += e.exists();
  return n;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 4) return 0;
  static const char* const kExtensions[] = {".png", ".bmp", ".ppm", ".jpg"};
  const bool lossless = (data[0] & 3) != 3;
  const bool overOld = data[0] & 4;
  Image8 image;
  image.width = 1 + data[1] % 64;
  image.height = 1 + data[2] % 64;
  const std::size_t nameLength = std::min<std::size_t>({data[3], size - 4, 200});
  std::string stem(reinterpret_cast<const char*>(data + 4), nameLength);
  std::replace(stem.begin(), stem.end(), '/', '_');
  std::replace(stem.begin(), stem.end(), '\0', '_');
  const std::size_t pixelsAt = 4 + nameLength;
  image.rgb.resize(std::size_t{3} * image.width * image.height);
  for (std::size_t i = 0; i < image.rgb.size(); ++i)
    image.rgb[i] = pixelsAt < size ? data[pixelsAt + i % (size - pixelsAt)] : 0;

  fs::remove_all(scratch());
  fs::create_directories(scratch());
  const fs::path file = scratch() / (stem + kExtensions[data[0] & 3]);
  // The older image, where one can be written under that name.
  const Image8 old{2, 1, {1, 2, 3, 4, 5, 6}};
  bool hasOld = false;
  if (overOld) try {
      meshtrace::writeImage(old, file);
      hasOld = true;
    } catch (const std::runtime_error&) {
    }
  try {
    meshtrace::writeImage(image, file);
  } catch (const std::runtime_error&) {
    if (filesIn(scratch()) != (hasOld ? 1u : 0u)) fail("a failed write left files behind", file);
    if (hasOld && lossless && meshtrace::readImage(file).rgb != old.rgb)
      fail("a failed write changed the older file", file);
    return 0;
  }
  if (filesIn(scratch()) != 1) fail("the write left other files beside the image", file);
  const Image8 back = meshtrace::readImage(file);
  if (back.width != image.width || back.height != image.height) fail("size changed", file);
  if (lossless && back.rgb != image.rgb) fail("pixels changed", file);
  return 0;
}
