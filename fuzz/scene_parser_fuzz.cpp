// Fuzzes the .sce reader: any input must either load or throw InputError
// (never crash, hang, leak or hit undefined behaviour). A scene that loads
// also has its centre pixel traced, so odd but valid values reach the
// intersection and shading code.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "meshtrace/io/input_error.h"
#include "meshtrace/io/scene_parser.h"
#include "meshtrace/render/integrator.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace meshtrace;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const Scene scene = parseScene(text, "fuzz-input.sce");
    const SceneIntersector intersector(scene, TraceOptions{});
    Counters counters;
    Integrator(intersector).pixel(scene.camera.width() / 2, scene.camera.height() / 2, counters);
  } catch (const InputError&) {
  }
  return 0;
}
