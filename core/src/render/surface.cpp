#include "meshtrace/render/surface.h"

#include "meshtrace/render/spawn.h"

namespace meshtrace {

namespace {

constexpr double g(int n) { return roundingGamma<double>(n); }

// alpha A + beta B + gamma C evaluated in Real, with pbrt's bound
// gamma(7) * sum |b_i P_i|. The barycentrics need not be exact: any affine
// combination lies in the triangle's plane, and that is all the offset needs.
template <typename Real>
void barycentricPoint(const Vec3& a, const Vec3& b, const Vec3& c, double beta, double gamma,
                      SurfacePoint& sp) {
  using V = glm::vec<3, Real>;
  const Real b1 = static_cast<Real>(beta), b2 = static_cast<Real>(gamma), b0 = 1 - b1 - b2;
  const V pa = b0 * V(a), pb = b1 * V(b), pc = b2 * V(c);
  sp.point = Vec3(pa + pb + pc);
  sp.error = Vec3(roundingGamma<Real>(7) * (glm::abs(pa) + glm::abs(pb) + glm::abs(pc)));
}

SurfacePoint onSphere(const Sphere& s, const Vec3& p0) {
  // Reproject onto the sphere: q has error gamma(5)|q| (pbrt), the sum with
  // the centre one more rounding; one extra gamma of margin on each.
  Vec3 q = p0 - s.center;
  const double len = glm::length(q);
  if (len > 0.0) q *= s.radius / len;
  const Vec3 p = s.center + q;
  return {p, q / s.radius, &s.material, q / s.radius, g(6) * glm::abs(q) + g(2) * glm::abs(p)};
}

SurfacePoint onPlane(const Plane& pl, const Vec3& p0) {
  // Project onto the plane. Rounding in (p0 - P), the dot product and the
  // subtraction leaves the point off the plane by a few ulps of |p| + |P|,
  // plus the distance times the |n| = 1 +- eps normalisation error.
  const double dist = glm::dot(pl.normal, p0 - pl.point);
  const Vec3 p = p0 - dist * pl.normal;
  const Vec3 err = g(6) * (glm::abs(p) + glm::abs(pl.point) + Vec3(std::abs(dist)));
  return {p, normalAt(pl), &pl.material, pl.normal, err};
}

SurfacePoint onCylinder(const Cylinder& c, const Vec3& p0, const Vec3& rayDirection) {
  // Reproject the radial part onto the radius (pbrt: gamma(3)|radial| in
  // object space); rebuilding the world point adds roundings relative to the
  // centre, axial and radial parts.
  const Vec3 q = p0 - c.center;
  const Vec3 axial = glm::dot(q, c.axis) * c.axis;
  Vec3 radial = q - axial;
  const double len = glm::length(radial);
  if (len > 0.0) radial *= c.radius / len;
  const Vec3 p = c.center + axial + radial;
  const Vec3 err = g(8) * (glm::abs(c.center) + glm::abs(axial) + glm::abs(radial));
  const Vec3 n = normalAt(c, p, rayDirection);
  return {p, n, &c.material, n, err};
}

SurfacePoint surfaceOf(const Scene& scene, const Ray& ray, const Hit& hit, Precision precision) {
  const Vec3 p0 = ray.at(hit.t);
  const PrimitiveRef& ref = hit.ref;
  switch (ref.kind) {
    case ObjectKind::Sphere: return onSphere(scene.spheres[ref.object], p0);
    case ObjectKind::Plane: return onPlane(scene.planes[ref.object], p0);
    case ObjectKind::Cylinder: return onCylinder(scene.cylinders[ref.object], p0, ray.direction);
    case ObjectKind::Mesh: break;
  }
  const Mesh& m = scene.meshes[ref.object];
  const TriangleIndices& tri = m.triangles()[ref.triangle];
  const auto& v = m.vertices();
  const Vec3 flat = m.flatNormal(ref.triangle);
  SurfacePoint sp{Vec3(0.0),     m.shadingNormal(ref.triangle, hit.beta, hit.gamma, flat),
                  &m.material(), flat,
                  Vec3(0.0),     precision};
  if (precision == Precision::Double)
    barycentricPoint<double>(v[tri[0]], v[tri[1]], v[tri[2]], hit.beta, hit.gamma, sp);
  else
    barycentricPoint<float>(v[tri[0]], v[tri[1]], v[tri[2]], hit.beta, hit.gamma, sp);
  return sp;
}

}  // namespace

SurfacePoint surfaceAt(const Scene& scene, const Ray& ray, const Hit& hit, Precision precision) {
  SurfacePoint sp = surfaceOf(scene, ray, hit, precision);
  sp.primitive = hit.ref;
  return sp;
}

}  // namespace meshtrace
