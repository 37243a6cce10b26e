#pragma once
// The generated meshes of our scenes/, each with the generator call that
// makes it: make_scenes writes them as OFF files, and the report's
// throughput measurement traces one without reading the source tree.
#include <string_view>
#include <vector>

#include "meshtrace/geometry/mesh.h"

namespace meshtrace {

struct SceneMesh {
  const char* path;  // relative to scenes/, e.g. "knot/knot.off"
  MeshData (*make)();
};

const std::vector<SceneMesh>& ourSceneMeshes();

// The mesh at `path` in ourSceneMeshes(); throws std::invalid_argument if
// none is.
MeshData makeOurSceneMesh(std::string_view path);

}  // namespace meshtrace
