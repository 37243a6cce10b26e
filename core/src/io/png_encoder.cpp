#include "io/png_encoder.h"

#include <png.h>
#include <zlib.h>

#include <csetjmp>
#include <cstdio>
#include <new>
#include <stdexcept>
#include <string>

namespace meshtrace::png {

namespace {

struct Output {
  std::vector<std::uint8_t> bytes;
  char error[256] = "cannot set up libpng";  // kept where nothing can throw
};

// libpng reports fatal errors through a callback that must not return; it
// keeps the message and jumps back to encode(), which throws it.
void onError(png_structp png, png_const_charp message) {
  auto* out = static_cast<Output*>(png_get_error_ptr(png));
  std::snprintf(out->error, sizeof out->error, "%s", message);
  png_longjmp(png, 1);
}
void onWarning(png_structp, png_const_charp) {}

void append(png_structp png, png_bytep data, png_size_t size) {
  auto* out = static_cast<Output*>(png_get_io_ptr(png));
  bool stored = true;
  try {
    out->bytes.insert(out->bytes.end(), data, data + size);
  } catch (const std::bad_alloc&) {
    stored = false;
  }
  // Outside the handler: png_error jumps, and jumping out of a handler
  // would skip the exception's own clean-up.
  if (!stored) png_error(png, "out of memory");
}

}  // namespace

std::vector<std::uint8_t> encode(const Image8& image) {
  Output out;
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &out, onError, onWarning);
  if (!png) throw std::runtime_error("PNG encoding failed: cannot set up libpng");
  png_infop info = png_create_info_struct(png);
  if (!info || setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    throw std::runtime_error(std::string("PNG encoding failed: ") + out.error);
  }
  png_set_write_fn(png, &out, append, nullptr);
  // Sub predicts each byte from the pixel to its left, which suits smooth
  // shading and flat backgrounds; trying all five filters per row (libpng's
  // default) tripled the time for 3-8% smaller files.
  png_set_compression_level(png, Z_BEST_SPEED);
  png_set_filter(png, PNG_FILTER_TYPE_BASE, PNG_FILTER_SUB);
  png_set_IHDR(png, info, static_cast<png_uint_32>(image.width),
               static_cast<png_uint_32>(image.height), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
               PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
  png_write_info(png, info);
  for (int row = 0; row < image.height; ++row)
    png_write_row(png, image.rgb.data() + static_cast<std::size_t>(row) * image.width * 3);
  png_write_end(png, info);
  png_destroy_write_struct(&png, &info);
  return std::move(out.bytes);
}

}  // namespace meshtrace::png
