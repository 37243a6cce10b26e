#include "meshtrace/geometry/shapes.h"

namespace meshtrace {

namespace {
// Real roots of a t^2 + b t + c = 0 in ascending order, computed without the
// cancellation of the textbook formula (q = -(b + sign(b) sqrt(disc)) / 2).
int solveQuadratic(double a, double b, double c, double roots[2]) {
  const double disc = b * b - 4.0 * a * c;
  if (disc < 0.0 || a == 0.0) return 0;
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  if (q == 0.0) {  // b == 0 and c == 0: a double root at 0
    roots[0] = roots[1] = 0.0;
    return 2;
  }
  roots[0] = q / a;
  roots[1] = c / q;
  if (roots[0] > roots[1]) std::swap(roots[0], roots[1]);
  return 2;
}

// The smallest root in (tMin, t), if any; updates t.
bool acceptNearest(const double* roots, int n, double tMin, double& t) {
  for (int i = 0; i < n; ++i) {
    if (roots[i] > tMin && roots[i] < t) {
      t = roots[i];
      return true;
    }
  }
  return false;
}
}  // namespace

bool intersect(const Sphere& s, const Ray& ray, double tMin, double& t) {
  const Vec3 oc = ray.origin - s.center;
  double roots[2];
  const int n =
      solveQuadratic(glm::dot(ray.direction, ray.direction), 2.0 * glm::dot(ray.direction, oc),
                     glm::dot(oc, oc) - s.radius * s.radius, roots);
  return acceptNearest(roots, n, tMin, t);
}

bool intersect(const Plane& p, const Ray& ray, double tMin, double& t) {
  const double denom = glm::dot(p.normal, ray.direction);
  if (denom == 0.0) return false;  // parallel rays miss
  const double tHit = glm::dot(p.normal, p.point - ray.origin) / denom;
  if (tHit > tMin && tHit < t) {
    t = tHit;
    return true;
  }
  return false;
}

bool intersect(const Cylinder& c, const Ray& ray, double tMin, double& t) {
  // Work with the components perpendicular to the axis.
  const Vec3 oc = ray.origin - c.center;
  const Vec3 dPerp = ray.direction - glm::dot(ray.direction, c.axis) * c.axis;
  const Vec3 oPerp = oc - glm::dot(oc, c.axis) * c.axis;
  double roots[2];
  const int n = solveQuadratic(glm::dot(dPerp, dPerp), 2.0 * glm::dot(dPerp, oPerp),
                               glm::dot(oPerp, oPerp) - c.radius * c.radius, roots);
  for (int i = 0; i < n; ++i) {
    if (roots[i] <= tMin || roots[i] >= t) continue;
    const double along = glm::dot(ray.at(roots[i]) - c.center, c.axis);
    if (std::abs(along) <= 0.5 * c.height) {
      t = roots[i];
      return true;
    }
  }
  return false;
}

Vec3 normalAt(const Sphere& s, const Vec3& p) { return (p - s.center) / s.radius; }

Vec3 normalAt(const Plane& p) { return p.normal; }

Vec3 normalAt(const Cylinder& c, const Vec3& p, const Vec3& rayDirection) {
  const Vec3 r = p - c.center;
  Vec3 n = glm::normalize(r - glm::dot(r, c.axis) * c.axis);
  if (glm::dot(n, rayDirection) > 0.0) n = -n;
  return n;
}

}  // namespace meshtrace
