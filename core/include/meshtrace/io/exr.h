#pragma once
// OpenEXR files of named channels: the colour before quantisation and what
// each pixel saw (depth, normal, hit point, ids, cost), one multi-layer
// scan-line file. A channel's name before its last '.' is its layer, as
// EXR viewers such as tev group them ("N.X", "N.Y", "N.Z" make layer N).
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace meshtrace {

struct ExrChannel {
  std::string name;
  // One value per pixel, row 0 at the top: floats, or (when `floats` is
  // empty) unsigned integers, for ids and counts.
  std::vector<float> floats;
  std::vector<std::uint32_t> uints;
};

struct ExrImage {
  int width = 0;
  int height = 0;
  std::vector<ExrChannel> channels;

  // The channel named `name`, or null.
  const ExrChannel* find(const std::string& name) const;
};

// Writes `image` ZIP-compressed through an OutputFile (output_file.h): a
// failure leaves any existing file untouched. Throws std::runtime_error
// naming the path on failure.
void writeExr(const ExrImage& image, const std::filesystem::path& path);
// Throws std::runtime_error naming the path if it cannot be read.
ExrImage readExr(const std::filesystem::path& path);

}  // namespace meshtrace
