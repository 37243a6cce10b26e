#pragma once
// Ray-triangle intersection by Cramer's rule on the barycentric system
//   o + t d = alpha A + beta B + gamma C,  alpha + beta + gamma = 1.
#include "meshtrace/math.h"

namespace meshtrace {

struct TriangleHit {
  double t;
  double beta, gamma;  // alpha = 1 - beta - gamma
};

// Accepts a hit with alpha, beta, gamma >= 0 and tMin < t < tMax.
bool intersectTriangle(const Vec3& a, const Vec3& b, const Vec3& c, const Ray& ray,
                       double tMin, double tMax, TriangleHit& out);

// normalize((B - A) x (C - A)), or the zero vector for a degenerate triangle
// (so a zero-area triangle contributes nothing to vertex normals, and never a NaN).
Vec3 triangleNormal(const Vec3& a, const Vec3& b, const Vec3& c);

// Interior angles at A, B and C, in radians; zero for a degenerate corner.
Vec3 cornerAngles(const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace meshtrace
