#pragma once
// Where secondary (shadow and reflection) rays start, and the smallest ray
// parameter they accept. Kept in one place: every spawned ray goes through it.
#include "meshtrace/math.h"

namespace meshtrace {

// The origin of a ray leaving surface point p with unit normal n on the side
// that `direction` points to.
Vec3 spawnOrigin(const Vec3& p, const Vec3& n, const Vec3& direction);

// Lower bound on t for a spawned ray; hits closer than this are the surface
// the ray left.
inline constexpr double kSpawnTMin = 0.0;

}  // namespace meshtrace
