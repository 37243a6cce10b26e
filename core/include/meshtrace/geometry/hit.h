#pragma once
#include <cstdint>

#include "meshtrace/util/math.h"

namespace meshtrace {

enum class ObjectKind : std::uint8_t { Sphere, Plane, Cylinder, Mesh };

const char* toString(ObjectKind kind);

// Which primitive a ray hit: the object's kind and its index within that kind,
// plus the triangle for meshes.
struct PrimitiveRef {
  ObjectKind kind = ObjectKind::Sphere;
  std::uint32_t object = 0;
  std::uint32_t triangle = 0;
};

// The closest hit found so far. `t` doubles as the search limit: intersection
// routines only accept hits nearer than the current `t`.
struct Hit {
  double t = kInfinity;
  PrimitiveRef ref;
  double beta = 0.0, gamma = 0.0;  // barycentrics of B and C (triangles only)

  bool found() const { return t < kInfinity; }
  double alpha() const { return 1.0 - beta - gamma; }
};

}  // namespace meshtrace
