#include "meshtrace/io/image.h"

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>

#include "io/jpeg.h"
#include "io/png_encoder.h"
#include "meshtrace/io/output_file.h"

namespace meshtrace {

std::uint8_t toByte(double c) {
  if (!(c > 0.0)) return 0;  // negative, zero and NaN
  if (c >= 1.0) return 255;
  return static_cast<std::uint8_t>(255.0 * c);  // truncation, as the reference
}

Image8 quantize(const Image& image) {
  Image8 out{image.width, image.height, {}};
  out.rgb.resize(image.pixels.size() * 3);
  for (std::size_t i = 0; i < image.pixels.size(); ++i)
    for (int c = 0; c < 3; ++c) out.rgb[i * 3 + c] = toByte(image.pixels[i][c]);
  return out;
}

namespace {
std::string lowerExtension(const std::filesystem::path& path) {
  std::string ext = path.extension().string();
  for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// stb's BMP encoder appends to the vector through this callback.
void appendBytes(void* context, void* data, int size) {
  auto* out = static_cast<std::vector<std::uint8_t>*>(context);
  const auto* bytes = static_cast<const std::uint8_t*>(data);
  out->insert(out->end(), bytes, bytes + size);
}

std::vector<std::uint8_t> encodePpm(const Image8& image) {
  const std::string header =
      "P6\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n255\n";
  std::vector<std::uint8_t> out(header.begin(), header.end());
  out.insert(out.end(), image.rgb.begin(), image.rgb.end());
  return out;
}

bool knownType(const std::string& ext) {
  return ext == ".png" || ext == ".bmp" || ext == ".ppm" || ext == ".jpg" || ext == ".jpeg";
}

[[noreturn]] void throwUnknownType(const std::filesystem::path& path, const std::string& ext) {
  throw std::runtime_error(path.string() + ": unknown image type '" + ext +
                           "' (use .png, .bmp, .ppm, .jpg or .exr)");
}

// The bytes of `image` in the known type `ext` names. A codec's error
// comes without the file's name; encode() adds it, once for every codec.
std::vector<std::uint8_t> encodeAs(const Image8& image, const std::string& ext) {
  if (ext == ".png") return png::encode(image);
  if (ext == ".jpg" || ext == ".jpeg") return jpeg::encode(image, 95);
  if (ext == ".ppm") return encodePpm(image);
  std::vector<std::uint8_t> bytes;  // .bmp
  if (!stbi_write_bmp_to_func(appendBytes, &bytes, image.width, image.height, 3, image.rgb.data()))
    throw std::runtime_error("cannot encode the image");
  return bytes;
}

// The file's bytes for the type named by `ext`. Encoding in memory and
// writing separately lets every write error be seen: stb's file writers
// ignore failed writes and report success for a truncated file.
std::vector<std::uint8_t> encode(const Image8& image, const std::string& ext,
                                 const std::filesystem::path& path) {
  if (!knownType(ext)) throwUnknownType(path, ext);
  try {
    return encodeAs(image, ext);
  } catch (const std::runtime_error& e) {
    throw std::runtime_error(path.string() + ": " + e.what());
  }
}

std::vector<std::uint8_t> readBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot open image for reading");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
}  // namespace

void writeImage(const Image8& image, OutputFile& out) {
  const std::vector<std::uint8_t> bytes = encode(image, lowerExtension(out.target()), out.target());
  out.write(bytes.data(), bytes.size());
}

void writeImage(const Image8& image, const std::filesystem::path& path) {
  // Encoded before the temporary file exists: a codec's error leaves nothing.
  const std::vector<std::uint8_t> bytes = encode(image, lowerExtension(path), path);
  OutputFile out(path);
  out.write(bytes.data(), bytes.size());
  out.commit();
}

bool isExrPath(const std::filesystem::path& path) { return lowerExtension(path) == ".exr"; }

void checkImageDestination(const std::filesystem::path& path) {
  const std::string ext = lowerExtension(path);
  if (!knownType(ext) && !isExrPath(path)) throwUnknownType(path, ext);
  checkOutputDestination(path);
}

Image8 readImage(const std::filesystem::path& path) {
  const std::vector<std::uint8_t> bytes = readBytes(path);
  if (jpeg::hasJpegSignature(bytes)) {
    try {
      return jpeg::decode(bytes);
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(path.string() + ": " + e.what());
    }
  }
  int w = 0, h = 0, n = 0;
  unsigned char* data =
      stbi_load_from_memory(bytes.data(), static_cast<int>(bytes.size()), &w, &h, &n, 3);
  if (!data) {
    throw std::runtime_error(path.string() + ": cannot read image (" + stbi_failure_reason() + ")");
  }
  Image8 out{w, h, std::vector<std::uint8_t>(data, data + static_cast<std::size_t>(w) * h * 3)};
  stbi_image_free(data);
  return out;
}

Image8 jpegRoundTrip(const Image8& image, int quality) {
  return jpeg::decode(jpeg::encode(image, quality));
}

}  // namespace meshtrace
