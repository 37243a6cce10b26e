// The ray-triangle kernels (see triangle.h for the algorithms), written once
// for any scalar type and instantiated for double and float, and the
// triangle's other geometry: its normal and corner angles.
#include "meshtrace/geometry/triangle.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/type_ptr.hpp>
#include <numbers>
#include <optional>

#include "meshtrace/util/enum_names.h"
#include "util/atan2_pair.h"

namespace meshtrace {

namespace {

template <typename Real>
using V3 = glm::vec<3, Real>;
template <typename Real>
using Setup = TriangleRay::Setup<Real>;

template <typename Real>
bool accept(Real t, Real beta, Real gamma, TriangleHit& out) {
  out = {double(t), double(beta), double(gamma)};
  return true;
}

// Cramer's rule and Moller-Trumbore find beta, gamma and t as three
// quotients by one det. For a sliver, or a ray nearly in the triangle's
// plane, det is small against the rounding of the numerators, and the three
// need not describe one point: the kernel may report a hit far outside the
// triangle, where no box around the triangle holds it, so the BVH would
// miss what brute force finds. These two kernels therefore refuse a hit
// whose point o + t d lies outside the triangle's box by more than
// hitSlack, the same for every acceleration method. (In the kernel's
// precision: its roundings, and those of the float corners and ray against
// the double ones, are far inside the BVH's padding, twice the slack.) The
// watertight kernel's t is a convex combination of its corners' sheared
// depths, its point within a few roundings of the box; it needs no such
// test.
template <typename Real>
bool nearTheBox(const Setup<Real>& r, const V3<Real>& a, const V3<Real>& b, const V3<Real>& c,
                Real t) {
  constexpr HitSlack slack =
      hitSlack(sizeof(Real) == sizeof(double) ? Precision::Double : Precision::Single);
  const V3<Real> lo = glm::min(glm::min(a, b), c), hi = glm::max(glm::max(a, b), c);
  const V3<Real> o = r.origin, along = t * r.direction;
  const Real size = std::max({std::abs(o.x), std::abs(o.y), std::abs(o.z)}) +
                    std::max({std::abs(lo.x), std::abs(lo.y), std::abs(lo.z), std::abs(hi.x),
                              std::abs(hi.y), std::abs(hi.z)});
  const Real absolute = Real(slack.absolute) * size;
  for (int axis = 0; axis < 3; ++axis) {
    const Real p = o[axis] + along[axis];
    const Real room = absolute + Real(slack.relative) * std::abs(along[axis]);
    if (!(p >= lo[axis] - room && p <= hi[axis] + room)) return false;
  }
  return true;
}

// Cramer's rule: substituting alpha = 1 - beta - gamma gives the system
//   [B-A  C-A  -d] (beta, gamma, t)^T = o - A.
// Each determinant is a triple product; the numerators share s x d.
template <typename Real>
bool cramer(const Setup<Real>& r, const V3<Real>& a, const V3<Real>& b, const V3<Real>& c,
            Real tMin, Real tMax, TriangleHit& out) {
  const V3<Real> e1 = b - a, e2 = c - a, s = r.origin - a;
  const V3<Real> n = glm::cross(e1, e2);  // det[e1 e2 x] = n . x
  const Real det = -glm::dot(n, r.direction);
  if (det == 0) return false;  // ray parallel to the plane, or degenerate triangle
  const V3<Real> sxd = glm::cross(s, r.direction);
  const Real inv = 1 / det;
  // det[s e2 -d] = e2.(s x d) and det[e1 s -d] = -e1.(s x d).
  const Real beta = glm::dot(e2, sxd) * inv;
  if (beta < 0) return false;
  const Real gamma = -glm::dot(e1, sxd) * inv;
  if (gamma < 0 || beta + gamma > 1) return false;
  const Real t = glm::dot(n, s) * inv;
  if (!(t > tMin && t < tMax)) return false;  // also rejects NaN
  if (!nearTheBox(r, a, b, c, t)) return false;
  return accept(t, beta, gamma, out);
}

// Moller-Trumbore: the same system with det = e1 . (d x e2); beta is tested
// before the second cross product is formed.
template <typename Real>
bool mollerTrumbore(const Setup<Real>& r, const V3<Real>& a, const V3<Real>& b, const V3<Real>& c,
                    Real tMin, Real tMax, TriangleHit& out) {
  const V3<Real> e1 = b - a, e2 = c - a;
  const V3<Real> p = glm::cross(r.direction, e2);
  const Real det = glm::dot(e1, p);
  if (det == 0) return false;
  const Real inv = 1 / det;
  const V3<Real> s = r.origin - a;
  const Real beta = glm::dot(s, p) * inv;
  if (beta < 0 || beta > 1) return false;
  const V3<Real> q = glm::cross(s, e1);
  const Real gamma = glm::dot(r.direction, q) * inv;
  if (gamma < 0 || beta + gamma > 1) return false;
  const Real t = glm::dot(e2, q) * inv;
  if (!(t > tMin && t < tMax)) return false;
  if (!nearTheBox(r, a, b, c, t)) return false;
  return accept(t, beta, gamma, out);
}

// The 2D edge function px*qy - py*qx of the edge from p to q. Two triangles
// sharing an edge traverse it in opposite directions and so compute exactly
// the negated value (products commute and a - b == -(b - a) in IEEE
// arithmetic): the decision is consistent and the mesh watertight. Only when
// the rounded value is exactly 0 is it recomputed with Kahan's fma
// difference of products, whose relative error is below 2u, so the sign is
// exact. (This relies on the compiler not contracting the products into
// fmas on its own, which it does not for the baseline x86-64 target.)
template <typename Real>
Real edgeFunction(Real px, Real py, Real qx, Real qy) {
  const Real e = px * qy - py * qx;
  if (e != 0) return e;
  const Real w = py * qx;
  return std::fma(px, qy, -w) + std::fma(-py, qx, w);
}

// Woop, Benthin & Wald 2013: translate the vertices to the ray origin, shear
// so the ray is the +z axis, then test the 2D edge functions at (0, 0). Each
// vertex is transformed by the same expression whichever triangle it is in,
// so shared vertices get bit-identical coordinates.
//
// Components are picked through pointers: glm's operator[] is a switch on
// the index, three compares and jumps per access.
template <typename Real>
struct Sheared {
  Real x, y, z;
  Sheared(const Setup<Real>& r, const V3<Real>& p) {
    const Real* v = glm::value_ptr(p);
    const Real* o = glm::value_ptr(r.origin);
    z = v[r.kz] - o[r.kz];
    x = (v[r.kx] - o[r.kx]) - r.sx * z;
    y = (v[r.ky] - o[r.ky]) - r.sy * z;
  }
};

template <typename Real>
bool watertight(const Setup<Real>& r, const V3<Real>& a, const V3<Real>& b, const V3<Real>& c,
                Real tMin, Real tMax, TriangleHit& out) {
  const Sheared<Real> pa(r, a), pb(r, b), pc(r, c);
  const Real u = edgeFunction(pc.x, pc.y, pb.x, pb.y);  // opposite A: alpha * det
  const Real v = edgeFunction(pa.x, pa.y, pc.x, pc.y);  // opposite B: beta * det
  if ((u < 0 && v > 0) || (u > 0 && v < 0)) return false;
  const Real w = edgeFunction(pb.x, pb.y, pa.x, pa.y);  // opposite C: gamma * det
  if ((u < 0 || v < 0 || w < 0) && (u > 0 || v > 0 || w > 0)) return false;
  const Real det = u + v + w;
  if (det == 0) return false;
  const Real az = r.sz * pa.z, bz = r.sz * pb.z, cz = r.sz * pc.z;
  const Real tScaled = u * az + v * bz + w * cz;  // t * det
  // tMin < t < tMax without dividing: flip signs so that det > 0.
  const Real absDet = std::abs(det), tSigned = det < 0 ? -tScaled : tScaled;
  if (!(tSigned > tMin * absDet && tSigned < tMax * absDet)) return false;
  const Real inv = 1 / det;
  const Real t = tScaled * inv;
  const Real ax = pa.x, ay = pa.y, bx = pb.x, by = pb.y, cx = pc.x, cy = pc.y;
  // pbrt-v4 (6.8.4): a bound on the rounding error of t, propagated from the
  // error of the sheared coordinates through the edge functions. A t within
  // it is not provably positive, so it is no hit (in particular not the
  // surface a spawned ray has just left).
  const Real maxX = std::max({std::abs(ax), std::abs(bx), std::abs(cx)});
  const Real maxY = std::max({std::abs(ay), std::abs(by), std::abs(cy)});
  const Real maxZ = std::max({std::abs(az), std::abs(bz), std::abs(cz)});
  const Real deltaZ = roundingGamma<Real>(3) * maxZ;
  const Real deltaX = roundingGamma<Real>(5) * (maxX + maxZ);
  const Real deltaY = roundingGamma<Real>(5) * (maxY + maxZ);
  const Real deltaE = 2 * (roundingGamma<Real>(2) * maxX * maxY + deltaY * maxX + deltaX * maxY);
  const Real maxE = std::max({std::abs(u), std::abs(v), std::abs(w)});
  const Real deltaT =
      3 * (roundingGamma<Real>(3) * maxE * maxZ + deltaE * maxZ + deltaZ * maxE) * std::abs(inv);
  if (t <= deltaT) return false;
  return accept(t, v * inv, w * inv, out);
}

// Fills `s` where it stays: built elsewhere and copied in, its fields,
// written one at a time, were read back by wider loads that had to wait
// for the stores to land (a failed store-to-load forward).
template <typename Real>
void setUp(const Ray& ray, Setup<Real>& s) {
  s.origin = V3<Real>(ray.origin);
  s.direction = V3<Real>(ray.direction);
  const V3<Real> d = glm::abs(s.direction);
  s.kz = d.x > d.y ? (d.x > d.z ? 0 : 2) : (d.y > d.z ? 1 : 2);
  s.kx = (s.kz + 1) % 3;
  s.ky = (s.kx + 1) % 3;
  const Real* dir = glm::value_ptr(s.direction);
  if (dir[s.kz] < 0) std::swap(s.kx, s.ky);  // keep the winding
  s.sx = dir[s.kx] / dir[s.kz];
  s.sy = dir[s.ky] / dir[s.kz];
  s.sz = 1 / dir[s.kz];
}

template <typename Real>
bool dispatch(TriangleTest test, const Setup<Real>& r, const V3<Real>& a, const V3<Real>& b,
              const V3<Real>& c, Real tMin, Real tMax, TriangleHit& out) {
  switch (test) {
    case TriangleTest::Cramer: return cramer(r, a, b, c, tMin, tMax, out);
    case TriangleTest::MollerTrumbore: return mollerTrumbore(r, a, b, c, tMin, tMax, out);
    case TriangleTest::Watertight: break;
  }
  return watertight(r, a, b, c, tMin, tMax, out);
}

}  // namespace

TriangleRay::TriangleRay(const Ray& ray, TriangleKernel kernel) : kernel_(kernel) {
  if (kernel.precision == Precision::Double)
    setUp(ray, double_);
  else
    setUp(ray, single_);
}

bool TriangleRay::intersect(const Vec3& a, const Vec3& b, const Vec3& c, double tMin, double tMax,
                            TriangleHit& out) const {
  if (kernel_.precision == Precision::Double)
    return dispatch<double>(kernel_.test, double_, a, b, c, tMin, tMax, out);
  return dispatch<float>(kernel_.test, single_, glm::vec3(a), glm::vec3(b), glm::vec3(c),
                         static_cast<float>(tMin), static_cast<float>(tMax), out);
}

namespace {
constexpr EnumName<TriangleTest> kTests[] = {{TriangleTest::Cramer, "cramer"},
                                             {TriangleTest::MollerTrumbore, "mt"},
                                             {TriangleTest::Watertight, "watertight"}};
constexpr EnumName<Precision> kPrecisions[] = {{Precision::Double, "double"},
                                               {Precision::Single, "single"}};
}  // namespace

const char* toString(TriangleTest test) { return nameIn(kTests, test); }
const char* toString(Precision precision) { return nameIn(kPrecisions, precision); }
TriangleTest parseTriangleTest(std::string_view name) {
  return parseNamed(kTests, name, "triangle test");
}
Precision parsePrecision(std::string_view name) {
  return parseNamed(kPrecisions, name, "precision");
}

bool intersectTriangle(const Vec3& a, const Vec3& b, const Vec3& c, const Ray& ray, double tMin,
                       double tMax, TriangleHit& out) {
  return TriangleRay(ray, TriangleKernel{}).intersect(a, b, c, tMin, tMax, out);
}

Vec3 triangleNormal(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = glm::cross(b - a, c - a);
  const double len = glm::length(n);
  // From 2^-511 on, the squared length is a normal double and keeps its
  // digits; under it, or where it overflowed (edges under about 1e-77 or
  // over 1e77), n over its largest component has a length of 1 to sqrt(3)
  // to take instead. Triangles of ordinary size keep the bits of n / |n|.
  if (len >= 0x1p-511 && std::isfinite(len)) return n / len;
  if (!isFinite(n) || n == Vec3(0.0)) return Vec3(0.0);
  const Vec3 m = n / maxAbsComponent(n);
  return m / glm::length(m);
}

bool hasNormal(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = glm::cross(b - a, c - a);
  return isFinite(n) && n != Vec3(0.0);
}

namespace {

// The angles at corners P, Q and R of a triangle whose widest corner is P,
// from its edges P->Q, Q->R and R->P; nullopt when it has no area.
std::optional<Vec3> anglesWidestFirst(const Vec3& pq, const Vec3& qr, const Vec3& rp) {
  const double twiceArea = glm::length(glm::cross(pq, rp));
  if (!(twiceArea > 0.0) || !std::isfinite(twiceArea)) return std::nullopt;
  const auto [q, r] = atan2Pair(twiceArea, -glm::dot(pq, qr), -glm::dot(qr, rp));
  return Vec3(std::numbers::pi - q - r, q, r);
}

}  // namespace

Vec3 cornerAngles(const Vec3& a, const Vec3& b, const Vec3& c) {
  // Each angle is atan2(|u x v|, u . v) over the two edges at its corner,
  // accurate near 0 and pi where acos of a normalised dot product loses
  // digits. |u x v| is twice the area at every corner, so it is taken once,
  // at the widest corner (facing the longest edge), between the two shorter
  // edges: there its rounding error is smallest relative to its value. At a
  // needle's tip, between two long edges, the cross product cancels, and
  // the tip's angle would lose as many digits as the needle is thin.
  // The two narrower corners (each under pi/2) take their atan2 with it;
  // the widest is what is left of pi, at least pi/3, so that subtraction
  // loses nothing that matters.
  Vec3 ab = b - a, bc = c - b, ca = a - c;
  // The area and the dot products square the edges, and an area squares
  // them twice: for a triangle whose edges reach under 2^-200 or over
  // 2^200 across, the edges are first scaled by a power of two (exactly),
  // which changes no angle. Triangles of ordinary size are taken as they are.
  const double extent = std::max({maxAbsComponent(ab), maxAbsComponent(bc), maxAbsComponent(ca)});
  if (extent > 0.0 && std::isfinite(extent) && (extent < 0x1p-200 || extent > 0x1p200)) {
    int exponent = 0;
    std::frexp(extent, &exponent);
    const auto scaled = [&](const Vec3& v) {
      return Vec3(std::ldexp(v.x, -exponent), std::ldexp(v.y, -exponent),
                  std::ldexp(v.z, -exponent));
    };
    ab = scaled(ab), bc = scaled(bc), ca = scaled(ca);
  }
  const double facingA = glm::dot(bc, bc), facingB = glm::dot(ca, ca), facingC = glm::dot(ab, ab);
  std::optional<Vec3> w;
  if (facingA >= facingB && facingA >= facingC) {
    if ((w = anglesWidestFirst(ab, bc, ca))) return *w;
  } else if (facingB >= facingC) {
    if ((w = anglesWidestFirst(bc, ca, ab))) return {(*w)[2], (*w)[0], (*w)[1]};
  } else {
    if ((w = anglesWidestFirst(ca, ab, bc))) return {(*w)[1], (*w)[2], (*w)[0]};
  }
  // No area: each corner on its own, 0 where an edge has no length.
  const auto angle = [](const Vec3& u, const Vec3& v) {
    return std::atan2(glm::length(glm::cross(u, v)), glm::dot(u, v));
  };
  // 0 - v, not -v: an edge of no length gives +0 components, as c - a would.
  const auto reversed = [](const Vec3& v) { return Vec3(0.0) - v; };
  return {angle(ab, reversed(ca)), angle(bc, reversed(ab)), angle(ca, reversed(bc))};
}

}  // namespace meshtrace
