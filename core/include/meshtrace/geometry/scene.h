#pragma once
// A loaded scene: camera, global settings, lights and objects, each object
// kind in its own array.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "meshtrace/geometry/camera.h"
#include "meshtrace/geometry/hit.h"
#include "meshtrace/geometry/mesh.h"
#include "meshtrace/geometry/shapes.h"

namespace meshtrace {

struct Scene {
  std::filesystem::path file;
  Camera camera;
  int depth = 0;
  Color background{0.0};
  Color ambience{0.0};
  std::vector<Light> lights;
  std::vector<Sphere> spheres;
  std::vector<Plane> planes;
  std::vector<Cylinder> cylinders;
  std::vector<Mesh> meshes;
  std::vector<std::string> warnings;

  std::size_t objectCount() const {
    return spheres.size() + planes.size() + cylinders.size() + meshes.size();
  }
  std::size_t triangleCount() const;
  const Material& material(const PrimitiveRef& ref) const;
  bool hasMirrors() const;
  bool hasPhongMeshes() const;
};

}  // namespace meshtrace
