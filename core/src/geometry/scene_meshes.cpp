#include "meshtrace/geometry/scene_meshes.h"

#include <stdexcept>
#include <string>

#include "meshtrace/geometry/mesh_generators.h"

namespace meshtrace {

const std::vector<SceneMesh>& ourSceneMeshes() {
  static const std::vector<SceneMesh> kMeshes = {
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
      {"grid_room/torus.off", [] { return makeTorus(Vec3(0.8, 1.0, -0.6), 0.9, 0.3, 48, 24); }},
      {"hall/hall.off", [] { return makeHall(40.0, 16.0, 8.0); }},
      {"sponge/sponge.off", [] { return makeMengerSponge(Vec3(0.0, 1.0, 0.0), 2.0, 2); }},
  };
  return kMeshes;
}

MeshData makeOurSceneMesh(std::string_view path) {
  for (const SceneMesh& m : ourSceneMeshes())
    if (path == m.path) return m.make();
  throw std::invalid_argument("no generated mesh of our scenes is at " + std::string(path));
}

}  // namespace meshtrace
