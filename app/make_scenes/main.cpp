// make_scenes: writes the generated meshes that our scenes/ use. The .sce
// files themselves are written by hand; run this after changing a generator.
// --format writes them as PLY, OBJ or STL instead, to try the other readers
// on the same meshes (our scenes name the OFF files).
#include <CLI/CLI.hpp>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "meshtrace/geometry/scene_meshes.h"
#include "meshtrace/io/mesh_writer.h"

using namespace meshtrace;

int main(int argc, char** argv) {
  CLI::App cli{"Write the generated meshes of our scenes."};
  std::string dir = "scenes";
  std::string format = "off";
  cli.add_option("dir", dir, "The scenes folder")->capture_default_str();
  cli.add_option("--format", format, "File format of the meshes")
      ->check(CLI::IsMember({"off", "ply", "obj", "stl"}))
      ->capture_default_str();
  CLI11_PARSE(cli, argc, argv);

  try {
    for (const SceneMesh& o : ourSceneMeshes()) {
      const auto path = (std::filesystem::path(dir) / o.path).replace_extension("." + format);
      std::filesystem::create_directories(path.parent_path());
      const MeshData mesh = o.make();
      writeMesh(mesh, path);
      std::printf("wrote %s: %zu vertices, %zu triangles\n", path.string().c_str(),
                  mesh.vertices.size(), mesh.triangles.size());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
