#include "meshtrace/triangle.h"

namespace meshtrace {

bool intersectTriangle(const Vec3& a, const Vec3& b, const Vec3& c, const Ray& ray,
                       double tMin, double tMax, TriangleHit& out) {
  // Substituting alpha = 1 - beta - gamma gives the 3x3 system
  //   [B-A  C-A  -d] (beta, gamma, t)^T = o - A,
  // solved by Cramer's rule. Each determinant is a triple product; the three
  // numerators share the cross products below.
  const Vec3 e1 = b - a;
  const Vec3 e2 = c - a;
  const Vec3 s = ray.origin - a;
  const Vec3 n = glm::cross(e1, e2);  // det[e1 e2 x] = n . x
  const double det = -glm::dot(n, ray.direction);
  if (det == 0.0) return false;  // ray parallel to the plane, or degenerate triangle
  const Vec3 sxd = glm::cross(s, ray.direction);
  const double inv = 1.0 / det;
  // det[s e2 -d] = e2.(s x d) and det[e1 s -d] = -e1.(s x d).
  const double beta = glm::dot(e2, sxd) * inv;
  if (beta < 0.0) return false;
  const double gamma = -glm::dot(e1, sxd) * inv;
  if (gamma < 0.0 || beta + gamma > 1.0) return false;
  const double t = glm::dot(n, s) * inv;
  if (t <= tMin || t >= tMax) return false;
  out = {t, beta, gamma};
  return true;
}

Vec3 triangleNormal(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = glm::cross(b - a, c - a);
  const double len = glm::length(n);
  return len > 0.0 && std::isfinite(len) ? n / len : Vec3(0.0);
}

Vec3 cornerAngles(const Vec3& a, const Vec3& b, const Vec3& c) {
  // The angle between two edges as atan2(|u x v|, u . v): accurate for angles
  // near 0 and pi, where acos of a normalised dot product loses digits.
  const auto angle = [](const Vec3& u, const Vec3& v) {
    return std::atan2(glm::length(glm::cross(u, v)), glm::dot(u, v));
  };
  return {angle(b - a, c - a), angle(c - b, a - b), angle(a - c, b - c)};
}

}  // namespace meshtrace
