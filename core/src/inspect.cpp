#include "meshtrace/inspect.h"

#include <algorithm>

#include "meshtrace/spawn.h"
#include "meshtrace/surface.h"

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
    s.alpha = hit.alpha();
    s.beta = hit.beta;
    s.gamma = hit.gamma;
    s.geometricNormal = mesh.triangleNormals()[hit.ref.triangle];
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

class Inspector {
 public:
  Inspector(const SceneIntersector& intersector, PixelInspection& out)
      : intersector_(intersector), scene_(intersector.scene()), out_(out) {}

  // Mirrors Integrator::trace, operation for operation, so the colours agree
  // to the bit.
  Color trace(const Ray& ray, int level, double weight) {
    out_.bounces.emplace_back();
    const std::size_t index = out_.bounces.size() - 1;
    {
      BounceRecord& b = out_.bounces[index];
      b.level = level;
      b.ray = ray;
      b.weight = weight;
      b.boxes = boxesEntered(scene_, ray);
    }
    Hit hit;
    if (!intersector_.closestHit(ray, kSpawnTMin, hit, out_.counters)) {
      out_.bounces[index].color = scene_.background;
      return scene_.background;
    }
    const SurfacePoint sp = surfaceAt(scene_, ray, hit, intersector_.options().triangle.precision);
    BounceRecord& b = out_.bounces[index];
    b.hit = true;
    b.surface = describeSurface(scene_, hit, sp);
    b.local = localColor(-ray.direction, sp, b);
    b.mirror = sp.material->mirror;
    if (b.mirror <= 0.0 || level >= scene_.depth) {
      b.color = b.local;
      return b.local;
    }
    b.reflects = true;
    const Vec3 d = ray.direction;
    const Vec3 reflected = d - 2.0 * glm::dot(d, sp.normal) * sp.normal;
    const Ray bounce{spawnOrigin(sp, reflected), glm::normalize(reflected)};
    ++out_.counters.reflectionRays;
    const double mirror = b.mirror;
    const Color local = b.local;
    // `b` may move when the next level appends its record.
    const Color color = (1.0 - mirror) * local + mirror * trace(bounce, level + 1, weight * mirror);
    out_.bounces[index].color = color;
    return color;
  }

 private:
  Color localColor(const Vec3& viewDir, const SurfacePoint& sp, BounceRecord& b) {
    const Material& m = *sp.material;
    Color color = scene_.ambience * m.ambient;
    b.ambient = color;
    for (std::size_t i = 0; i < scene_.lights.size(); ++i) {
      const Light& light = scene_.lights[i];
      LightRecord rec;
      rec.light = i;
      const Vec3 toLight = light.position - sp.point;
      const Vec3 l = glm::normalize(toLight);
      const double nl = glm::dot(sp.normal, l);
      rec.toLight = l;
      rec.nDotL = nl;
      rec.facing = nl > 0.0;
      if (!rec.facing) {
        b.lights.push_back(rec);
        continue;
      }
      const Ray shadow{spawnOrigin(sp, l), l};
      ++out_.counters.shadowRays;
      const double lightDistance = glm::length(light.position - shadow.origin);
      if (intersector_.occluded(shadow, kSpawnTMin, lightDistance, out_.counters)) {
        rec.shadowed = true;
        // The nearest blocker, found with a closest-hit query limited to the
        // light; its counters are not the render's, so they are kept apart.
        Counters scratch;
        Hit blocker;
        blocker.t = lightDistance;
        if (intersector_.closestHit(shadow, kSpawnTMin, blocker, scratch)) {
          rec.blocker = blocker.ref;
          rec.blockerT = blocker.t;
        }
        b.lights.push_back(rec);
        continue;
      }
      rec.diffuse = light.color * m.diffuse * nl;
      color += rec.diffuse;
      const Vec3 r = 2.0 * nl * sp.normal - l;
      const double rv = glm::dot(r, viewDir);
      if (rv > 0.0) {
        rec.specular = light.color * m.specular * std::pow(rv, m.shininess);
        color += rec.specular;
      }
      b.lights.push_back(rec);
    }
    return color;
  }

  const SceneIntersector& intersector_;
  const Scene& scene_;
  PixelInspection& out_;
};

}  // namespace

PixelInspection inspectPixel(const SceneIntersector& intersector, const Camera& camera, double x,
                             double y) {
  PixelInspection out;
  out.x = x;
  out.y = y;
  ++out.counters.primaryRays;
  Inspector inspector(intersector, out);
  out.color = inspector.trace(camera.primaryRay(x, y), 0, 1.0);
  return out;
}

std::int32_t objectIndex(const Scene& scene, const PrimitiveRef& ref) {
  std::size_t base = 0;
  switch (ref.kind) {
    case ObjectKind::Mesh:
      base += scene.cylinders.size();
      [[fallthrough]];
    case ObjectKind::Cylinder:
      base += scene.planes.size();
      [[fallthrough]];
    case ObjectKind::Plane:
      base += scene.spheres.size();
      [[fallthrough]];
    case ObjectKind::Sphere:
      break;
  }
  return static_cast<std::int32_t>(base + ref.object);
}

std::uint64_t traversalCost(const Counters& counters) {
  return counters.nodeVisits + counters.boxTests + counters.triangleTests + counters.sphereTests +
         counters.planeTests + counters.cylinderTests;
}

int boxHitCount(const Scene& scene, const Ray& ray) {
  const RayInverse inverse(ray);
  int n = 0;
  for (const Mesh& mesh : scene.meshes) {
    double tEnter, tExit;
    n += intersectSlabs(mesh.bounds(), inverse, 0.0, kInfinity, tEnter, tExit);
  }
  return n;
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
