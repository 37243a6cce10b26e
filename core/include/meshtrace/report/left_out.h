#pragma once
// The work a scene does not need, and why it is skipped: reported by
// `raytrace --stats` so that omissions are visible, and pinned by tests.
#include <string>
#include <vector>

#include "meshtrace/geometry/scene.h"

namespace meshtrace {

// Meshes too small for a BVH are listed by the BVH itself
// (SceneBvhStats::leftOut), which knows its threshold.
std::vector<std::string> leftOut(const Scene& scene);

// Vertex normals held by the scene's meshes (only PHONG meshes compute them).
std::size_t vertexNormalsComputed(const Scene& scene);

}  // namespace meshtrace
