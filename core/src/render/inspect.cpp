#include "meshtrace/render/inspect.h"

#include <algorithm>

#include "meshtrace/render/render.h"
#include "meshtrace/render/surface.h"
#include "render/inspect_bvh.h"
#include "render/whitted.h"

namespace meshtrace {

namespace {

double angleDegrees(const Vec3& a, const Vec3& b) {
  return glm::degrees(std::acos(std::clamp(glm::dot(a, b), -1.0, 1.0)));
}

SurfaceRecord describeSurface(const Scene& scene, const Hit& hit, const SurfacePoint& sp) {
  SurfaceRecord s;
  s.ref = hit.ref;
  s.t = hit.t;
  s.point = sp.point;
  s.shadingNormal = sp.normal;
  s.geometricNormal = sp.normal;
  if (hit.ref.kind == ObjectKind::Mesh) {
    const Mesh& mesh = scene.meshes[hit.ref.object];
    s.face = mesh.faceOf(hit.ref.triangle);
    s.alpha = hit.alpha();
    s.beta = hit.beta;
    s.gamma = hit.gamma;
    s.geometricNormal = mesh.flatNormal(hit.ref.triangle);
    s.phong = mesh.shading() == Shading::Phong;
    if (!mesh.vertexNormals().empty()) {
      s.hasVertexNormals = true;
      for (int k = 0; k < 3; ++k)
        s.vertexNormals[k] = mesh.vertexNormals()[mesh.triangles()[hit.ref.triangle][k]];
    }
  }
  s.normalAngleDegrees = angleDegrees(s.geometricNormal, s.shadingNormal);
  return s;
}

std::vector<BoxRecord> boxesEntered(const Scene& scene, const Ray& ray) {
  std::vector<BoxRecord> boxes;
  const RayInverse inverse(ray);
  for (std::uint32_t i = 0; i < scene.meshes.size(); ++i) {
    BoxRecord b{i, 0.0, 0.0};
    if (intersectSlabs(scene.meshes[i].bounds(), inverse, 0.0, kInfinity, b.tEnter, b.tExit))
      boxes.push_back(b);
  }
  std::sort(boxes.begin(), boxes.end(),
            [](const BoxRecord& a, const BoxRecord& b) { return a.tEnter < b.tEnter; });
  return boxes;
}

// Records each step of whittedTrace into a PixelInspection.
class Recorder {
 public:
  Recorder(const SceneIntersector& intersector, PixelInspection& out)
      : intersector_(intersector), out_(out) {}

  void beginBounce(int level, const Ray& ray) {
    BounceRecord b;
    b.level = level;
    b.ray = ray;
    if (!open_.empty()) {
      const BounceRecord& parent = out_.bounces[open_.back()];
      b.weight = parent.weight * parent.mirror;
    }
    b.boxes = boxesEntered(intersector_.scene(), ray);
    open_.push_back(out_.bounces.size());
    out_.bounces.push_back(std::move(b));
  }
  void surface(const Hit& hit, const SurfacePoint& sp) {
    current().hit = true;
    current().surface = describeSurface(intersector_.scene(), hit, sp);
  }
  void ambient(const Color& c) { current().ambient = c; }
  void lightBehind(std::size_t light, const Vec3& l, double nl) {
    current().lights.push_back(lightRecord(light, l, nl));
  }
  void lightShadowed(std::size_t light, const Vec3& l, double nl, const SurfacePoint& sp) {
    LightRecord rec = lightRecord(light, l, nl);
    rec.shadowed = true;
    // The nearest blocker, found with a closest-hit query limited to the
    // light; its counters are not the render's, so they are kept apart.
    Counters scratch;
    Hit blocker;
    const Ray shadow = shadowRayToward(intersector_.scene().lights[light], sp, l, blocker.t);
    if (intersector_.closestHit(shadow, kSpawnTMin, blocker, scratch, &sp.primitive)) {
      rec.blocker = blocker.ref;
      rec.blockerT = blocker.t;
    }
    current().lights.push_back(rec);
  }
  void lightLit(std::size_t light, const Vec3& l, double nl, const Color& diffuse,
                const Color& specular) {
    LightRecord rec = lightRecord(light, l, nl);
    rec.diffuse = diffuse;
    rec.specular = specular;
    current().lights.push_back(rec);
  }
  void local(const Color& c, double mirror, bool reflects) {
    current().local = c;
    current().mirror = mirror;
    current().reflects = reflects;
  }
  void endBounce(const Color& c) {
    BounceRecord& b = current();
    b.color = c;
    b.nodes = bvhNodesEntered(intersector_, b.ray, b.hit ? b.surface.t : kInfinity);
    open_.pop_back();
  }

 private:
  // The record of the innermost bounce still being traced. Looked up by index
  // each time: a deeper bounce appends to the vector and may move it.
  BounceRecord& current() { return out_.bounces[open_.back()]; }

  static LightRecord lightRecord(std::size_t light, const Vec3& l, double nl) {
    LightRecord rec;
    rec.light = light;
    rec.toLight = l;
    rec.nDotL = nl;
    rec.facing = nl > 0.0;
    return rec;
  }

  const SceneIntersector& intersector_;
  PixelInspection& out_;
  std::vector<std::size_t> open_;  // indices of the bounces being traced, outermost first
};

}  // namespace

PixelInspection inspectPixel(const SceneIntersector& intersector, const Camera& camera, double x,
                             double y) {
  PixelInspection out;
  out.x = x;
  out.y = y;
  ++out.counters.primaryRays;
  Recorder recorder(intersector, out);
  out.color = whittedTrace(intersector, camera.primaryRay(x, y), 0, out.counters, recorder);
  return out;
}

std::int32_t objectIndex(const Scene& scene, const PrimitiveRef& ref) {
  std::size_t base = 0;
  switch (ref.kind) {
    case ObjectKind::Mesh: base += scene.cylinders.size(); [[fallthrough]];
    case ObjectKind::Cylinder: base += scene.planes.size(); [[fallthrough]];
    case ObjectKind::Plane: base += scene.spheres.size(); [[fallthrough]];
    case ObjectKind::Sphere: break;
  }
  return static_cast<std::int32_t>(base + ref.object);
}

std::uint64_t traversalCost(const Counters& counters) {
  return counters.nodeVisits + counters.boxTests + counters.triangleTests + counters.sphereTests +
         counters.planeTests + counters.cylinderTests;
}

PixelProbe probePixel(const SceneIntersector& intersector, const Camera& camera, double x,
                      double y) {
  const Scene& scene = intersector.scene();
  const Ray ray = camera.primaryRay(x, y);
  PixelProbe p;
  p.boxHits = static_cast<std::uint16_t>(std::min(boxHitCount(scene, ray), 65535));
  Counters counters;
  Hit hit;
  const bool found = intersector.closestHit(ray, kSpawnTMin, hit, counters);
  p.cost =
      static_cast<std::uint32_t>(std::min<std::uint64_t>(traversalCost(counters), 0xffffffffu));
  if (!found) return p;
  const SurfacePoint sp = surfaceAt(scene, ray, hit, intersector.options().triangle.precision);
  p.depth = static_cast<float>(hit.t);
  for (int k = 0; k < 3; ++k) p.normal[k] = static_cast<float>(sp.normal[k]);
  p.object = objectIndex(scene, hit.ref);
  p.kind = hit.ref.kind;
  p.index = hit.ref.object;
  p.triangle = hit.ref.triangle;
  p.beta = static_cast<float>(hit.beta);
  p.gamma = static_cast<float>(hit.gamma);
  return p;
}

}  // namespace meshtrace
