#include "meshtrace/surface.h"

namespace meshtrace {

SurfacePoint surfaceAt(const Scene& scene, const Ray& ray, const Hit& hit) {
  const Vec3 p = ray.at(hit.t);
  const PrimitiveRef& ref = hit.ref;
  switch (ref.kind) {
    case ObjectKind::Sphere: {
      const Sphere& s = scene.spheres[ref.object];
      return {p, normalAt(s, p), &s.material};
    }
    case ObjectKind::Plane: {
      const Plane& pl = scene.planes[ref.object];
      return {p, normalAt(pl), &pl.material};
    }
    case ObjectKind::Cylinder: {
      const Cylinder& c = scene.cylinders[ref.object];
      return {p, normalAt(c, p, ray.direction), &c.material};
    }
    case ObjectKind::Mesh: break;
  }
  const Mesh& m = scene.meshes[ref.object];
  return {p, m.shadingNormal(ref.triangle, hit.beta, hit.gamma), &m.material()};
}

}  // namespace meshtrace
