#pragma once
// The pinhole camera of the scene format: no half-pixel offset, y = 0 is the
// bottom row.
#include <string>

#include "meshtrace/util/math.h"

namespace meshtrace {

struct CameraSpec {
  Vec3 eye{0.0};
  Vec3 center{0.0, 0.0, -1.0};
  Vec3 up{0.0, 1.0, 0.0};
  double fovyDegrees = 45.0;
  int width = 0;
  int height = 0;
};

class Camera {
 public:
  Camera() = default;
  // Precondition: cameraProblem(spec) is empty. An up vector parallel to
  // the view is replaced by another axis; `upWasReplaced()` reports it so
  // callers can warn. Up may be of any length, 1e-200 as well as 1e200.
  explicit Camera(const CameraSpec& spec);

  const CameraSpec& spec() const { return spec_; }
  int width() const { return spec_.width; }
  int height() const { return spec_.height; }
  bool upWasReplaced() const { return upWasReplaced_; }

  // Ray through image position (x, y) in pixel units; integer values are the
  // reference pixel positions, fractions are used for extra samples.
  Ray primaryRay(double x, double y) const;

 private:
  CameraSpec spec_;
  Vec3 xDir_{0.0}, yDir_{0.0}, lowerLeft_{0.0};
  bool upWasReplaced_ = false;
};

// What makes `spec` unusable, or "" if nothing does. Besides a size, fovy
// or vector out of range, it is checked where it is used: the camera's rays
// at the image's corners and centre must be finite unit vectors, and
// neighbouring pixels must get rays as far apart as the pixels are. The
// message says which limit was met, for example "eye and center are
// 5e-324 apart: too close to define a view direction".
std::string cameraProblem(const CameraSpec& spec);

}  // namespace meshtrace
