#include "viewer/model/projection.h"

#include <algorithm>
#include <cmath>

namespace meshtrace::viewer {

namespace {
// Corner i of a box: bit 0 picks max x, bit 1 max y, bit 2 max z.
Vec3 corner(const Aabb& box, int i) {
  return Vec3(i & 1 ? box.max.x : box.min.x, i & 2 ? box.max.y : box.min.y,
              i & 4 ? box.max.z : box.min.z);
}
}  // namespace

Projection::Projection(const Camera& camera) {
  const CameraSpec& spec = camera.spec();
  eye_ = spec.eye;
  const Vec3 offset = spec.center - spec.eye;
  planeDistance_ = glm::length(offset);
  view_ = offset / planeDistance_;
  near_ = 1e-6 * planeDistance_;
  // The image plane through the centre, found from the camera's own rays
  // (so that the mapping is exactly its inverse): where the rays through
  // (0, 0), (1, 0) and (0, 1) cross it.
  const auto onPlane = [&](double x, double y) {
    const Vec3 d = camera.primaryRay(x, y).direction;
    return eye_ + d * (planeDistance_ / glm::dot(d, view_));
  };
  lowerLeft_ = onPlane(0.0, 0.0);
  xDir_ = onPlane(1.0, 0.0) - lowerLeft_;
  yDir_ = onPlane(0.0, 1.0) - lowerLeft_;
}

double Projection::depth(const Vec3& p) const { return glm::dot(p - eye_, view_); }

std::optional<ImagePoint> Projection::project(const Vec3& p) const {
  const double d = depth(p);
  if (d < near_) return std::nullopt;
  const Vec3 q = eye_ + (p - eye_) * (planeDistance_ / d) - lowerLeft_;
  return ImagePoint{glm::dot(q, xDir_) / glm::dot(xDir_, xDir_),
                    glm::dot(q, yDir_) / glm::dot(yDir_, yDir_)};
}

std::optional<std::pair<ImagePoint, ImagePoint>> Projection::projectSegment(const Vec3& a,
                                                                            const Vec3& b) const {
  const double da = depth(a), db = depth(b);
  if (da < 2.0 * near_ && db < 2.0 * near_) return std::nullopt;
  Vec3 a2 = a, b2 = b;
  // Cut a little in front of the near plane, where it surely projects.
  const double cut = 2.0 * near_;
  if (da < cut) a2 = a + (b - a) * ((cut - da) / (db - da));
  if (db < cut) b2 = b + (a - b) * ((cut - db) / (da - db));
  const auto pa = project(a2), pb = project(b2);
  if (!pa || !pb) return std::nullopt;
  return std::make_pair(*pa, *pb);
}

double imageExtent(const Projection& projection, const Aabb& box) {
  double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
  for (int i = 0; i < 8; ++i) {
    const auto q = projection.project(corner(box, i));
    if (!q) return INFINITY;
    lo[0] = std::min(lo[0], q->x);
    lo[1] = std::min(lo[1], q->y);
    hi[0] = std::max(hi[0], q->x);
    hi[1] = std::max(hi[1], q->y);
  }
  return std::max(hi[0] - lo[0], hi[1] - lo[1]);
}

std::vector<std::pair<Vec3, Vec3>> boxEdges(const Aabb& box) {
  std::vector<std::pair<Vec3, Vec3>> edges;
  for (int i = 0; i < 8; ++i)
    for (int bit : {1, 2, 4})
      if (!(i & bit)) edges.emplace_back(corner(box, i), corner(box, i | bit));
  return edges;
}

}  // namespace meshtrace::viewer
