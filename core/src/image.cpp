#include "meshtrace/image.h"

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <cstdio>
#include <fstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <unistd.h>

#include "jpeg.h"

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

bool writePpm(const Image8& image, const char* path) {
  std::ofstream out(path, std::ios::binary);
  out << "P6\n" << image.width << ' ' << image.height << "\n255\n";
  out.write(reinterpret_cast<const char*>(image.rgb.data()),
            static_cast<std::streamsize>(image.rgb.size()));
  return static_cast<bool>(out.flush());
}

bool writeBytes(const std::vector<std::uint8_t>& bytes, const char* path) {
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
  return static_cast<bool>(out.flush());
}

std::vector<std::uint8_t> readBytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path.string() + ": cannot open image for reading");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
}  // namespace

void writeImage(const Image8& image, const std::filesystem::path& path) {
  const std::string ext = lowerExtension(path);
  // The temporary file sits beside the target so the rename stays on one
  // file system and is atomic.
  std::filesystem::path tmp = path;
  tmp += ".tmp" + std::to_string(::getpid());
  const std::string t = tmp.string();
  bool ok = false;
  if (ext == ".png") {
    ok = stbi_write_png(t.c_str(), image.width, image.height, 3, image.rgb.data(), image.width * 3);
  } else if (ext == ".bmp") {
    ok = stbi_write_bmp(t.c_str(), image.width, image.height, 3, image.rgb.data());
  } else if (ext == ".ppm") {
    ok = writePpm(image, t.c_str());
  } else if (ext == ".jpg" || ext == ".jpeg") {
    ok = writeBytes(jpeg::encode(image, 95), t.c_str());
  } else {
    throw std::runtime_error(path.string() + ": unknown image type '" + ext +
                             "' (use .png, .bmp, .ppm or .jpg)");
  }
  std::error_code ec;
  if (!ok) {
    std::filesystem::remove(tmp, ec);
    throw std::runtime_error(path.string() + ": cannot write the image file");
  }
  std::filesystem::rename(tmp, path, ec);
  if (ec) {
    std::filesystem::remove(tmp, ec);
    throw std::runtime_error(path.string() + ": cannot write the image file (" + ec.message() + ")");
  }
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
