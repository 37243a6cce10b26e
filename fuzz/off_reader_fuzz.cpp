// Fuzzes the OFF reader: any input must either load or throw InputError.
// readOff takes a path, so each input is written to a scratch file first. A
// mesh that loads is built PHONG, computing its face and vertex normals.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "meshtrace/io/input_error.h"
#include "meshtrace/io/off_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace meshtrace;
  static const std::filesystem::path file = std::filesystem::temp_directory_path() /
                                            ("meshtrace-fuzz-" + std::to_string(getpid()) + ".off");
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    const Mesh mesh(file, readOff(file), Shading::Phong, Material{});
  } catch (const InputError&) {
  }
  return 0;
}
