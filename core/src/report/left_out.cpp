#include "meshtrace/report/left_out.h"

namespace meshtrace {

std::vector<std::string> leftOut(const Scene& scene) {
  std::vector<std::string> out;
  if (!scene.meshes.empty() && !scene.hasPhongMeshes())
    out.push_back("vertex normals not computed: no PHONG mesh");
  for (const Mesh& m : scene.meshes) {
    if (m.shading() == Shading::Flat && scene.hasPhongMeshes())
      out.push_back("vertex normals not computed for " + m.file().filename().string() +
                    ": FLAT shaded");
  }
  if (scene.lights.empty()) out.push_back("no shadow rays: the scene has no lights");
  if (scene.depth == 0)
    out.push_back("no reflection rays: depth is 0");
  else if (!scene.hasMirrors())
    out.push_back("no reflection rays: no material has a mirror reflectivity above 0");
  if (!scene.meshes.empty())
    out.push_back(
        "OpenMesh cross-check of the normals not run: only the viewer runs it, on request");
  return out;
}

std::size_t vertexNormalsComputed(const Scene& scene) {
  std::size_t n = 0;
  for (const Mesh& m : scene.meshes) n += m.vertexNormals().size();
  return n;
}

}  // namespace meshtrace
