#pragma once
// Where secondary (shadow and reflection) rays start, and the smallest ray
// parameter they accept. Kept in one place: every spawned ray goes through it.
//
// The offset follows pbrt-v4 (Pharr, Jakob & Humphreys, 4th ed., 6.8.6): every
// hit point carries a per-component bound on its rounding error (see
// surfaceAt); the origin moves along the geometric normal just far enough to
// leave that error box, and is then rounded one ulp further away. The true
// surface therefore lies strictly behind the new origin at any scale, and no
// fixed epsilon is needed.
//
// A flat primitive a ray leaves is then behind it altogether: the ray cannot
// meet that plane at t > 0. So the queries, told the triangle a spawned ray
// starts on (SurfacePoint::primitive), leave its test out; it is the one
// triangle a shadow or reflection ray's boxes always contain and the float
// filter can never rule out (its t is a rounding error from 0), so each
// such ray saves an exact test. The spawned-ray stability figures
// (stability.h) are measured without it, so they still show the offset
// alone keeps rays off their surface. Spheres and cylinders are curved, a
// ray may meet them again, and they are always tested.
#include "meshtrace/render/surface.h"
#include "meshtrace/util/math.h"

namespace meshtrace {

// The origin of a ray leaving `sp` on the side of its geometric normal that
// `direction` points to. With Precision::Single the origin is representable
// as float, rounded away from the surface, so a single-precision kernel sees
// the same point.
Vec3 spawnOrigin(const SurfacePoint& sp, const Vec3& direction);

// Lower bound on t for a spawned ray. Zero: the offset origin is already off
// the surface, so every hit at t > 0 is a real one.
inline constexpr double kSpawnTMin = 0.0;

}  // namespace meshtrace
