#pragma once
// The pinhole camera of the scene format: no half-pixel offset, y = 0 is the
// bottom row.
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
  // Precondition: the spec was validated (eye != center, 0 < fovy < 180,
  // positive size). An up vector parallel to the view is replaced by another
  // axis; `upWasReplaced()` reports it so callers can warn.
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

}  // namespace meshtrace
