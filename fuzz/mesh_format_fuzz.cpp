// Fuzzes one of the formats the tools read besides OFF, through the readers
// registered for its extension (for PLY, the core's PLY reader, then for
// what it leaves the file checks, OpenMesh's reader and our importer; OBJ
// and STL, the core's readers; OM, its check):
// any input must either load or throw InputError. Built once per format, MESHTRACE_FUZZ_EXTENSION
// naming it
// (".ply", ".obj", ".stl", ".om"); each input is written to a scratch file
// of that extension. A mesh that loads is built PHONG, computing its normals.
// OpenMesh is the system's library, not instrumented: ASan sees only our
// code's accesses, and a wild access inside OpenMesh shows as a crash.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>

#include "formats/openmesh_reader.h"
#include "meshtrace/io/input_error.h"
#include "meshtrace/io/mesh_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace meshtrace;
  formats::registerOpenMeshFormats();
  // The scratch file, removed when the fuzzer exits.
  static const struct Scratch {
    std::filesystem::path path =
        std::filesystem::temp_directory_path() /
        ("meshtrace-fuzz-" + std::to_string(getpid()) + MESHTRACE_FUZZ_EXTENSION);
    ~Scratch() {
      std::error_code ignored;
      std::filesystem::remove(path, ignored);
    }
  } scratch;
  const std::filesystem::path& file = scratch.path;
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  try {
    MemoryBudget budget(std::uint64_t{1} << 30);
    const Mesh mesh(file, readMesh(file, budget), Shading::Phong, Material{});
  } catch (const InputError&) {
  } catch (const MemoryLimitError&) {
  }
  return 0;
}
