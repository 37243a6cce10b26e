#pragma once
// What shading needs to know about a hit: the point, the shading normal and
// the material.
#include "meshtrace/hit.h"
#include "meshtrace/scene.h"

namespace meshtrace {

struct SurfacePoint {
  Vec3 point;
  Vec3 normal;  // unit length
  const Material* material;
};

SurfacePoint surfaceAt(const Scene& scene, const Ray& ray, const Hit& hit);

}  // namespace meshtrace
