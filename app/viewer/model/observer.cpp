#include "viewer/model/observer.h"

#include <algorithm>
#include <cmath>

namespace meshtrace::viewer {

Aabb sceneBounds(const Scene& scene) {
  Aabb box;
  for (const Mesh& m : scene.meshes)
    if (!m.triangles().empty()) box.extend(m.bounds());
  for (const Sphere& s : scene.spheres) {
    box.extend(s.center - Vec3(std::abs(s.radius)));
    box.extend(s.center + Vec3(std::abs(s.radius)));
  }
  for (const Cylinder& c : scene.cylinders) {
    const double r = std::abs(c.radius) + 0.5 * std::abs(c.height);
    box.extend(c.center - Vec3(r));
    box.extend(c.center + Vec3(r));
  }
  return box;
}

CameraSpec observerCamera(const CameraSpec& main, const Scene& scene) {
  // What must be in view: the main eye, what it looks at, and the objects.
  Aabb box = sceneBounds(scene);
  box.extend(main.eye);
  box.extend(main.center);
  const Vec3 target = box.center();
  const double radius = std::max(0.5 * glm::length(box.extent()), 1e-6);
  const Vec3 view = glm::normalize(main.center - main.eye);
  const Vec3 up = glm::length(main.up) > 0 ? glm::normalize(main.up) : Vec3(0, 1, 0);
  Vec3 side = glm::cross(view, up);
  side = glm::length(side) > 1e-9 ? glm::normalize(side) : Vec3(1, 0, 0);
  // Aside, back and up from the main camera's view, far enough for the
  // whole sphere around the box to fit the field of view.
  const Vec3 direction = glm::normalize(-0.8 * view + 0.9 * side + 0.6 * up);
  CameraSpec out = main;
  out.fovyDegrees = 45.0;
  const double fit = radius / std::sin(glm::radians(out.fovyDegrees) / 2.0);
  out.center = target;
  out.eye = target + direction * (1.05 * fit);
  out.up = up;
  return out;
}

std::vector<std::pair<Vec3, Vec3>> frustumLines(const CameraSpec& main, double reach) {
  const Camera camera(main);
  const Vec3 view = glm::normalize(main.center - main.eye);
  reach = std::max(reach, glm::length(main.center - main.eye));
  const double w = main.width, h = main.height;
  // The corners of the image: pixel edges half a pixel past the outer
  // pixels' positions.
  const double xs[2] = {-0.5, w - 0.5}, ys[2] = {-0.5, h - 0.5};
  Vec3 corners[4];
  for (int i = 0; i < 4; ++i) {
    const Vec3 d = camera.primaryRay(xs[i & 1], ys[i >> 1]).direction;
    corners[i] = main.eye + d * (reach / glm::dot(d, view));
  }
  std::vector<std::pair<Vec3, Vec3>> lines;
  for (const Vec3& c : corners) lines.emplace_back(main.eye, c);
  lines.emplace_back(corners[0], corners[1]);
  lines.emplace_back(corners[1], corners[3]);
  lines.emplace_back(corners[3], corners[2]);
  lines.emplace_back(corners[2], corners[0]);
  return lines;
}

}  // namespace meshtrace::viewer
