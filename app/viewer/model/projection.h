#pragma once
// Where points of the scene land in a camera's image: the inverse of
// Camera::primaryRay, for drawing rays and boxes over the image. Image
// positions are in pixels as primaryRay takes them (x to the right, y up,
// pixel (i, j) traced at exactly (i, j)).
#include <optional>
#include <utility>
#include <vector>

#include "meshtrace/geometry/aabb.h"
#include "meshtrace/geometry/camera.h"

namespace meshtrace::viewer {

struct ImagePoint {
  double x = 0.0, y = 0.0;
};

class Projection {
 public:
  explicit Projection(const Camera& camera);

  // The image position of a point in front of the camera (beyond a small
  // near distance); nothing for a point behind it.
  std::optional<ImagePoint> project(const Vec3& p) const;
  // The part of segment a-b in front of the camera, projected.
  std::optional<std::pair<ImagePoint, ImagePoint>> projectSegment(const Vec3& a,
                                                                  const Vec3& b) const;
  // The distance along the view direction (negative behind the camera).
  double depth(const Vec3& p) const;

 private:
  Vec3 eye_, view_, lowerLeft_, xDir_, yDir_;
  double planeDistance_ = 1.0, near_ = 1e-6;
};

// The larger side of the rectangle around a box's projected corners, in
// image pixels: how much of the image the box takes. Infinite for a box
// reaching behind the camera.
double imageExtent(const Projection& projection, const Aabb& box);

// The twelve edges of a box, as pairs of corners.
std::vector<std::pair<Vec3, Vec3>> boxEdges(const Aabb& box);

}  // namespace meshtrace::viewer
