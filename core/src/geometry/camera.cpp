#include "meshtrace/geometry/camera.h"

namespace meshtrace {

namespace {
// An up vector that is not parallel to `view`: the world axis least aligned
// with it.
Vec3 fallbackUp(const Vec3& view) {
  const Vec3 a = glm::abs(view);
  if (a.x <= a.y && a.x <= a.z) return {1.0, 0.0, 0.0};
  if (a.y <= a.z) return {0.0, 1.0, 0.0};
  return {0.0, 0.0, 1.0};
}
}  // namespace

Camera::Camera(const CameraSpec& spec) : spec_(spec) {
  const Vec3 offset = spec.center - spec.eye;
  const double dist = glm::length(offset);
  const Vec3 view = offset / dist;
  const double imageHeight = 2.0 * dist * std::tan(glm::radians(spec.fovyDegrees) / 2.0);
  const double imageWidth = imageHeight * spec.width / spec.height;

  Vec3 side = glm::cross(view, spec.up);
  // Parallel when the sine of the angle between up and view is negligible.
  if (glm::length(side) <= 1e-12 * glm::length(spec.up)) {
    upWasReplaced_ = true;
    side = glm::cross(view, fallbackUp(view));
  }
  xDir_ = glm::normalize(side) * (imageWidth / spec.width);
  yDir_ = glm::normalize(glm::cross(xDir_, view)) * (imageHeight / spec.height);
  lowerLeft_ = spec.center - 0.5 * spec.width * xDir_ - 0.5 * spec.height * yDir_;
}

Ray Camera::primaryRay(double x, double y) const {
  const Vec3 target = lowerLeft_ + x * xDir_ + y * yDir_;
  return {spec_.eye, glm::normalize(target - spec_.eye)};
}

}  // namespace meshtrace
