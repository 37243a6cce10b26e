#include "meshtrace/intersector.h"

#include <stdexcept>
#include <string>

#include "meshtrace/triangle.h"

namespace meshtrace {

const char* toString(AccelMethod method) {
  switch (method) {
    case AccelMethod::None: return "none";
    case AccelMethod::BoundingBox: return "aabb";
  }
  return "?";
}

AccelMethod parseAccelMethod(std::string_view name) {
  if (name == "none") return AccelMethod::None;
  if (name == "aabb") return AccelMethod::BoundingBox;
  throw std::invalid_argument("unknown acceleration method '" + std::string(name) +
                              "' (use none or aabb)");
}

SceneIntersector::SceneIntersector(const Scene& scene, const TraceOptions& options)
    : scene_(scene), options_(options) {}

bool SceneIntersector::intersectMesh(std::uint32_t index, const Ray& ray,
                                     const RayInverse& inverse, double tMin, Hit& hit,
                                     bool anyHit, Counters& counters) const {
  const Mesh& mesh = scene_.meshes[index];
  if (options_.accel == AccelMethod::BoundingBox) {
    ++counters.boxTests;
    double tEnter, tExit;
    if (!intersectSlabs(mesh.bounds(), inverse, tMin, hit.t, tEnter, tExit)) return false;
  }
  const auto& v = mesh.vertices();
  const auto& tris = mesh.triangles();
  bool found = false;
  for (std::uint32_t i = 0; i < tris.size(); ++i) {
    ++counters.triangleTests;
    TriangleHit th;
    if (intersectTriangle(v[tris[i][0]], v[tris[i][1]], v[tris[i][2]], ray, tMin, hit.t, th)) {
      hit.t = th.t;
      hit.ref = {ObjectKind::Mesh, index, i};
      hit.beta = th.beta;
      hit.gamma = th.gamma;
      found = true;
      if (anyHit) return true;
    }
  }
  return found;
}

bool SceneIntersector::closestHit(const Ray& ray, double tMin, Hit& hit,
                                  Counters& counters) const {
  bool found = false;
  const auto test = [&](ObjectKind kind, std::uint32_t i, bool hitIt) {
    if (hitIt) {
      hit.ref = {kind, i, 0};
      found = true;
    }
  };
  for (std::uint32_t i = 0; i < scene_.spheres.size(); ++i) {
    ++counters.sphereTests;
    test(ObjectKind::Sphere, i, intersect(scene_.spheres[i], ray, tMin, hit.t));
  }
  for (std::uint32_t i = 0; i < scene_.planes.size(); ++i) {
    ++counters.planeTests;
    test(ObjectKind::Plane, i, intersect(scene_.planes[i], ray, tMin, hit.t));
  }
  for (std::uint32_t i = 0; i < scene_.cylinders.size(); ++i) {
    ++counters.cylinderTests;
    test(ObjectKind::Cylinder, i, intersect(scene_.cylinders[i], ray, tMin, hit.t));
  }
  if (!scene_.meshes.empty()) {
    const RayInverse inverse(ray);
    for (std::uint32_t i = 0; i < scene_.meshes.size(); ++i)
      found |= intersectMesh(i, ray, inverse, tMin, hit, false, counters);
  }
  return found;
}

bool SceneIntersector::occluded(const Ray& ray, double tMin, double tMax,
                                Counters& counters) const {
  double t = tMax;
  for (const Sphere& s : scene_.spheres) {
    ++counters.sphereTests;
    if (intersect(s, ray, tMin, t)) return true;
  }
  for (const Plane& p : scene_.planes) {
    ++counters.planeTests;
    if (intersect(p, ray, tMin, t)) return true;
  }
  for (const Cylinder& c : scene_.cylinders) {
    ++counters.cylinderTests;
    if (intersect(c, ray, tMin, t)) return true;
  }
  if (!scene_.meshes.empty()) {
    const RayInverse inverse(ray);
    Hit hit;
    hit.t = tMax;
    for (std::uint32_t i = 0; i < scene_.meshes.size(); ++i)
      if (intersectMesh(i, ray, inverse, tMin, hit, true, counters)) return true;
  }
  return false;
}

}  // namespace meshtrace
