#include "meshtrace/geometry/scene.h"

#include "meshtrace/util/enum_names.h"

namespace meshtrace {

namespace {
constexpr EnumName<ObjectKind> kObjectKinds[] = {{ObjectKind::Sphere, "sphere"},
                                                 {ObjectKind::Plane, "plane"},
                                                 {ObjectKind::Cylinder, "cylinder"},
                                                 {ObjectKind::Mesh, "mesh"}};
}  // namespace

const char* toString(ObjectKind kind) { return nameIn(kObjectKinds, kind); }

std::size_t Scene::triangleCount() const {
  std::size_t n = 0;
  for (const Mesh& m : meshes) n += m.triangles().size();
  return n;
}

const Material& Scene::material(const PrimitiveRef& ref) const {
  switch (ref.kind) {
    case ObjectKind::Sphere: return spheres[ref.object].material;
    case ObjectKind::Plane: return planes[ref.object].material;
    case ObjectKind::Cylinder: return cylinders[ref.object].material;
    case ObjectKind::Mesh: break;
  }
  return meshes[ref.object].material();
}

bool Scene::hasMirrors() const {
  const auto mirrored = [](const auto& objects) {
    for (const auto& o : objects)
      if (o.material.mirror > 0.0) return true;
    return false;
  };
  for (const Mesh& m : meshes)
    if (m.material().mirror > 0.0) return true;
  return mirrored(spheres) || mirrored(planes) || mirrored(cylinders);
}

bool Scene::hasPhongMeshes() const {
  for (const Mesh& m : meshes)
    if (m.shading() == Shading::Phong) return true;
  return false;
}

}  // namespace meshtrace
