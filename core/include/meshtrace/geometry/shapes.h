#pragma once
// The analytic primitives of the scene format and their ray intersections.
// Each intersect routine takes `t` as the nearest distance found so far,
// accepts a hit only with tMin < t_hit < t, and then sets t = t_hit.
#include "meshtrace/geometry/hit.h"
#include "meshtrace/geometry/material.h"

namespace meshtrace {

struct Sphere {
  Vec3 center{0.0};
  double radius = 1.0;
  Material material;
};

struct Plane {
  Vec3 point{0.0};
  Vec3 normal{0.0, 1.0, 0.0};  // unit length
  Material material;
};

// Open tube, no caps, centred on `center`, extending height/2 along ±axis.
struct Cylinder {
  Vec3 center{0.0};
  double radius = 1.0;
  Vec3 axis{0.0, 1.0, 0.0};  // unit length
  double height = 1.0;
  Material material;
};

bool intersect(const Sphere& s, const Ray& ray, double tMin, double& t);
bool intersect(const Plane& p, const Ray& ray, double tMin, double& t);
bool intersect(const Cylinder& c, const Ray& ray, double tMin, double& t);

// Geometric normals at a point known to lie on the surface.
Vec3 normalAt(const Sphere& s, const Vec3& p);
Vec3 normalAt(const Plane& p);
// The radial direction, turned to face the incoming ray.
Vec3 normalAt(const Cylinder& c, const Vec3& p, const Vec3& rayDirection);

}  // namespace meshtrace
