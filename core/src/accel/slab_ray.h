#pragma once
// How much a BVH's ray-box test must widen the boxes so that it never culls
// a box holding a hit that the primitive kernels would report (the test
// itself: BoxRay8 in bvh8_traverse.h).

#include "meshtrace/util/math.h"

namespace meshtrace {

// How much wider than exact a box test must be. Ize ("Robust BVH Ray
// Traversal", JCGT 2(2) 2013) pads the far distance by 1 + 2 gamma(3)
// (~7e-16) to cover the slab test's own rounding. Ours must be wider, because
// a box must hold not the exact hit but the one the kernels compute:
// - `relative` scales the near distance by 1 - relative and the far one by
//   1 + relative. A kernel's t is off by about u t / cos(theta) for a ray at
//   angle theta to a triangle, and a quadric's root by up to about sqrt(u) t
//   for a grazing ray (cancellation in the discriminant).
// - `absolute` widens every box by that distance on each side: the kernels'
//   rounding of the ray origin and of the vertices, about u (|o| + |v|), which
//   does not shrink with t (a float kernel rounds the origin to float).
struct SlabPadding {
  double relative;
  double absolute;
};

// The padding for kernels with unit roundoff `u` (2^-53 or 2^-24), a ray
// origin and a scene whose coordinates are at most `sceneScale` in size.
// Double: 2^-20 covers the quadrics' sqrt(u) ~ 1e-8 and cos(theta) down to
// ~1e-9; the absolute pad is 2^23 u. Float: 2^-12 and 2^-14, that is 2^12 u
// and 2^10 u.
inline SlabPadding slabPadding(bool singlePrecisionTriangles, const Vec3& origin,
                               double sceneScale) {
  const double scale = maxAbsComponent(origin) + sceneScale;
  return singlePrecisionTriangles ? SlabPadding{0x1p-12, 0x1p-14 * scale}
                                  : SlabPadding{0x1p-20, 0x1p-30 * scale};
}

}  // namespace meshtrace
