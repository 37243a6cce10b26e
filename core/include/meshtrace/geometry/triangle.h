#pragma once
// Ray-triangle intersection. Three algorithms, each in double or single
// precision, all solving
//   o + t d = alpha A + beta B + gamma C,  alpha + beta + gamma = 1
// and reporting the same quantities (t, beta, gamma):
// - Cramer: Cramer's rule on the 3x3 system (the reference tools' method);
// - MollerTrumbore: Moller & Trumbore 1997, the same system in the form that
//   tests beta before computing the remaining cross product;
// - Watertight: Woop, Benthin & Wald, "Watertight Ray/Triangle Intersection",
//   JCGT 2(1) 2013. Edges shared by two triangles are tested with bit-identical
//   values, so a ray can never slip between them. Also rejects hits whose t is
//   not provably positive (the error bound of pbrt-v4), so a ray spawned off a
//   surface by spawnOrigin never re-hits it.
#include <cstdint>
#include <string_view>

#include "meshtrace/util/math.h"

namespace meshtrace {

enum class TriangleTest : std::uint8_t { Cramer, MollerTrumbore, Watertight };
// The arithmetic the kernels run in: Single converts the vertices and the ray
// to float first, as a single-precision tracer would store them.
enum class Precision : std::uint8_t { Double, Single };

// "cramer", "mt", "watertight"; "double", "single".
const char* toString(TriangleTest test);
const char* toString(Precision precision);
// Throw std::invalid_argument for an unknown name.
TriangleTest parseTriangleTest(std::string_view name);
Precision parsePrecision(std::string_view name);

// The triangle kernel choice, part of TraceOptions.
struct TriangleKernel {
  TriangleTest test = TriangleTest::Watertight;
  Precision precision = Precision::Double;
};

// How far outside its triangle's bounding box a kernel's hit point may lie:
// on each axis, `relative` of the hit's distance along that axis (t |d|),
// plus `absolute` times the largest coordinate of the ray's origin plus
// that of the triangle. Cramer and Moller-Trumbore refuse hits beyond it (see
// triangle.cpp); the watertight kernel's hits lie within a few
// roundings of the box. The BVH pads its boxes by twice as much
// (slab_ray.h), so it holds every hit a kernel reports.
struct HitSlack {
  double relative;
  double absolute;
};
constexpr HitSlack hitSlack(Precision precision) {
  return precision == Precision::Double ? HitSlack{0x1p-21, 0x1p-31} : HitSlack{0x1p-13, 0x1p-15};
}

struct TriangleHit {
  double t;
  double beta, gamma;  // alpha = 1 - beta - gamma
};

// A ray prepared once for many triangle tests: holds the chosen kernel and
// its per-ray set-up (the watertight test's shear, the float copy).
class TriangleRay {
 public:
  TriangleRay(const Ray& ray, TriangleKernel kernel);

  // Accepts a hit with alpha, beta, gamma >= 0 and tMin < t < tMax (for
  // Cramer and Moller-Trumbore, at a point within hitSlack of the
  // triangle's box).
  bool intersect(const Vec3& a, const Vec3& b, const Vec3& c, double tMin, double tMax,
                 TriangleHit& out) const;

  // Per-ray constants of one precision (filled in triangle.cpp).
  template <typename Real>
  struct Setup {
    glm::vec<3, Real> origin, direction;
    int kx, ky, kz;   // watertight: axis permutation, kz the largest |d|
    Real sx, sy, sz;  // watertight: shear constants
  };

 private:
  TriangleKernel kernel_;
  Setup<double> double_;
  Setup<float> single_;
};

// One-off test with the default kernel (prefer TriangleRay in loops).
bool intersectTriangle(const Vec3& a, const Vec3& b, const Vec3& c, const Ray& ray, double tMin,
                       double tMax, TriangleHit& out);

// normalize((B - A) x (C - A)), or the zero vector for a degenerate triangle
// (so a zero-area triangle contributes nothing to vertex normals, and never a NaN).
Vec3 triangleNormal(const Vec3& a, const Vec3& b, const Vec3& c);
// Whether triangleNormal(a, b, c) is not the zero vector, without its
// square root and division: the same cross product, its squared length
// positive and finite exactly when the length is.
bool hasNormal(const Vec3& a, const Vec3& b, const Vec3& c);

// Interior angles at A, B and C, in radians; zero for a degenerate corner.
Vec3 cornerAngles(const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace meshtrace
