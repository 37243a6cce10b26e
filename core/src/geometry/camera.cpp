#include "meshtrace/geometry/camera.h"

#include <algorithm>
#include <cmath>

#include "meshtrace/util/quoted.h"

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
  // The view and up directions come from their vectors scaled by a power of
  // two, so that eye and center 1e-300 apart, or an up of 1e-200, give
  // directions; dist is scaled back exactly.
  int exponent = 0;
  const Vec3 offset = scaledToUnitRange(spec.center - spec.eye, &exponent);
  const double scaledDist = glm::length(offset);
  const Vec3 view = offset / scaledDist;
  const double dist = std::ldexp(scaledDist, exponent);
  const double imageHeight = 2.0 * dist * std::tan(glm::radians(spec.fovyDegrees) / 2.0);
  const double imageWidth = imageHeight * spec.width / spec.height;

  const Vec3 up = scaledToUnitRange(spec.up);
  Vec3 side = glm::cross(view, up);
  // Parallel when the sine of the angle between up and view is negligible.
  if (glm::length(side) <= 1e-12 * glm::length(up)) {
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

std::string cameraProblem(const CameraSpec& spec) {
  if (spec.width < 1 || spec.height < 1) return "the image size must be positive";
  if (!(spec.fovyDegrees > 0.0 && spec.fovyDegrees < 180.0))
    return "the camera fovy must lie strictly between 0 and 180 degrees";
  if (!isFinite(spec.eye) || !isFinite(spec.center) || !isFinite(spec.up))
    return "the camera's eye, center and up vector must be finite";
  if (spec.up == Vec3(0.0)) return "the camera up vector is the zero vector";
  const Vec3 offset = spec.center - spec.eye;
  if (offset == Vec3(0.0)) return "the camera eye and center are the same point";
  // The distance, even where its square would underflow or overflow.
  int exponent = 0;
  const Vec3 scaled = scaledToUnitRange(offset, &exponent);
  const double apart = std::ldexp(glm::length(scaled), exponent);
  if (!std::isfinite(apart))
    return "eye and center are too far apart: their difference overflows double precision";
  const std::string between = "eye and center are " + shortestText(apart) + " apart";

  // The rays as rendering takes them: at the corners (the longest) and the
  // centre (the shortest), each a finite unit vector.
  const Camera camera(spec);
  const double w = spec.width, h = spec.height;
  for (const auto& [x, y] : {std::pair{0.0, 0.0}, {w, 0.0}, {0.0, h}, {w, h}, {w / 2, h / 2}}) {
    const Vec3 d = camera.primaryRay(x, y).direction;
    if (isFinite(d) && std::abs(glm::length(d) - 1.0) < 1e-9) continue;
    // Their squared lengths overflow, or underflow: they are at least as
    // long as eye and center are apart.
    if (apart >= 1.0) {
      return between + " with fovy " + shortestText(spec.fovyDegrees) +
             ": the image plane is too large for double precision";
    }
    return between + ": too close to define a view direction";
  }
  // Neighbouring pixels at the centre: their rays as far apart as those of
  // the same camera moved to the origin, not lost in the rounding of
  // coordinates far larger than the distance.
  CameraSpec atOrigin = spec;
  atOrigin.eye = Vec3(0.0);
  atOrigin.center = offset;
  const Camera reference(atOrigin);
  const double cx = std::floor(w / 2), cy = std::floor(h / 2);
  for (const auto& [x, y] : {std::pair{cx + 1, cy}, {cx, cy + 1}}) {
    const double step =
        glm::length(camera.primaryRay(x, y).direction - camera.primaryRay(cx, cy).direction);
    const double expected =
        glm::length(reference.primaryRay(x, y).direction - reference.primaryRay(cx, cy).direction);
    if (!(std::abs(step - expected) <= 0.01 * expected)) {
      return between + " at coordinates up to " +
             shortestText(std::max(maxAbsComponent(spec.eye), maxAbsComponent(spec.center))) +
             ": too close to tell neighbouring pixels apart";
    }
  }
  return "";
}

}  // namespace meshtrace
