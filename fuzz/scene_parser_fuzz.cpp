// Fuzzes the .sce reader and what a scene that loads goes through. Any
// input must either load or throw InputError (never crash, hang, leak or
// hit undefined behaviour). Mesh paths are read relative to fuzz/meshes/,
// which holds small meshes of the kinds found in the wild (polygons,
// colours, CRLF, shared edges, repeated triangles); the dictionary names
// them and the larger meshes of scenes/. A scene that loads is rendered in
// quads with packets through its BVH, and each pixel must equal brute
// force's (packets_match.h).
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "meshtrace/io/input_error.h"
#include "meshtrace/io/scene_parser.h"
#include "packets_match.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace meshtrace;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const Scene scene =
        parseScene(text, std::filesystem::path(MESHTRACE_FUZZ_MESHES) / "input.sce");
    fuzz::expectPacketsMatchBruteForce(scene);
  } catch (const InputError&) {
  }
  return 0;
}
