// make_scenes: writes the generated meshes that our scenes/ use. The .sce
// files themselves are written by hand; run this after changing a generator.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "meshtrace/geometry/mesh_generators.h"
#include "meshtrace/geometry/scene_meshes.h"

using namespace meshtrace;

int main(int argc, char** argv) {
  CLI::App cli{"Write the generated meshes of our scenes."};
  std::string dir = "scenes";
  cli.add_option("dir", dir, "The scenes folder")->capture_default_str();
  CLI11_PARSE(cli, argc, argv);

  try {
    for (const SceneMesh& o : ourSceneMeshes()) {
      const auto path = std::filesystem::path(dir) / o.path;
      std::filesystem::create_directories(path.parent_path());
      const MeshData mesh = o.make();
      writeOff(mesh, path);
      std::printf("wrote %s: %zu vertices, %zu triangles\n", path.string().c_str(),
                  mesh.vertices.size(), mesh.triangles.size());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
