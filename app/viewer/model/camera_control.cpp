#include "viewer/model/camera_control.h"

#include <charconv>
#include <glm/gtc/matrix_transform.hpp>

#include "meshtrace/io/scene_parser.h"

namespace meshtrace::viewer {

namespace {
Vec3 rotate(const Vec3& v, const Vec3& axis, double radians) {
  return Vec3(glm::rotate(glm::dmat4(1.0), radians, glm::normalize(axis)) * glm::dvec4(v, 0.0));
}

std::string number(double v) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}
}  // namespace

CameraSpec orbit(const CameraSpec& camera, double dxPixels, double dyPixels) {
  CameraSpec out = camera;
  Vec3 offset = camera.eye - camera.center;
  const Vec3 up = glm::normalize(camera.up);
  offset = rotate(offset, up, glm::radians(-0.5 * dxPixels));
  const Vec3 side = glm::cross(glm::normalize(-offset), up);
  if (glm::length(side) > 1e-9) {
    const Vec3 pitched = rotate(offset, side, glm::radians(-0.5 * dyPixels));
    // Keep away from the poles, where up and view become parallel.
    if (std::abs(glm::dot(glm::normalize(pitched), up)) < 0.995) offset = pitched;
  }
  out.eye = camera.center + offset;
  return out;
}

CameraSpec pan(const CameraSpec& camera, double dxPixels, double dyPixels) {
  CameraSpec out = camera;
  const Vec3 offset = camera.center - camera.eye;
  const double dist = glm::length(offset);
  const Vec3 view = offset / dist;
  Vec3 side = glm::cross(view, camera.up);
  if (glm::length(side) < 1e-12) return out;
  side = glm::normalize(side);
  const Vec3 up = glm::normalize(glm::cross(side, view));
  const double pixel =
      2.0 * dist * std::tan(glm::radians(camera.fovyDegrees) / 2.0) / camera.height;
  const Vec3 move = -dxPixels * pixel * side - dyPixels * pixel * up;
  out.eye += move;
  out.center += move;
  return out;
}

CameraSpec zoom(const CameraSpec& camera, double steps) {
  CameraSpec out = camera;
  out.eye = camera.center + (camera.eye - camera.center) * std::pow(0.9, steps);
  return out;
}

bool sameCamera(const CameraSpec& a, const CameraSpec& b) {
  return a.eye == b.eye && a.center == b.center && a.up == b.up && a.fovyDegrees == b.fovyDegrees &&
         a.width == b.width && a.height == b.height;
}

std::string cameraLine(const CameraSpec& c) {
  std::string s = "camera";
  // Appending piece by piece (GCC 12 warns falsely about " " + string).
  const auto add = [&s](const std::string& word) { s.append(1, ' ').append(word); };
  for (const Vec3& v : {c.eye, c.center, c.up})
    for (int k = 0; k < 3; ++k) add(number(v[k]));
  add(number(c.fovyDegrees));
  add(std::to_string(c.width));
  add(std::to_string(c.height));
  return s;
}

CameraSpec parseCameraLine(const std::string& line) {
  return parseScene(line, "pasted").camera.spec();
}

}  // namespace meshtrace::viewer
