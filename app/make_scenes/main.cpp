// make_scenes: writes the generated meshes that our scenes/ use. The .sce
// files themselves are written by hand; run this after changing a generator.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

#include "meshtrace/geometry/mesh_generators.h"

using namespace meshtrace;

int main(int argc, char** argv) {
  CLI::App cli{"Write the generated meshes of our scenes."};
  std::string dir = "scenes";
  cli.add_option("dir", dir, "The scenes folder")->capture_default_str();
  CLI11_PARSE(cli, argc, argv);

  struct Output {
    const char* path;
    std::function<MeshData()> make;
  };
  const std::vector<Output> outputs = {
      {"shading_modes/icosphere.off", [] { return makeIcosphere(Vec3(-1.4, 1.0, 0.0), 1.0, 2); }},
      {"shading_modes/torus.off",
       [] { return makeTorus(Vec3(1.5, 0.35, 0.3), 1.0, 0.35, 24, 12); }},
      {"shading_modes/floor.off", [] { return makeGrid(Vec3(0.0), 12.0, 8); }},
      {"knot/knot.off",
       [] { return makeTorusKnot(Vec3(0.0, 1.3, 0.0), 0.45, 2, 3, 0.42, 1024, 52); }},
      {"mirror_hall/torus.off", [] { return makeTorus(Vec3(0.0, 0.55, 0.0), 0.8, 0.3, 64, 32); }},
      {"everything/icosphere.off", [] { return makeIcosphere(Vec3(1.6, 0.7, 0.4), 0.7, 3); }},
      {"grid_room/room.off",
       [] {
         MeshData room = makeGriddedBox(Vec3(-4.0, 0.0, -4.0), Vec3(4.0, 5.0, 4.0), 16);
         reverseWinding(room);  // seen from inside
         return room;
       }},
      {"hall/hall.off", [] { return makeHall(40.0, 16.0, 8.0); }},
      {"sponge/sponge.off", [] { return makeMengerSponge(Vec3(0.0, 1.0, 0.0), 2.0, 2); }},
      {"grid_room/torus.off", [] { return makeTorus(Vec3(0.8, 1.0, -0.6), 0.9, 0.3, 48, 24); }},
  };
  try {
    for (const Output& o : outputs) {
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
