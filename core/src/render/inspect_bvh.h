#pragma once
// The scene BVH's nodes for the inspector (inspect.h): those a ray enters.
#include <vector>

#include "meshtrace/render/inspect.h"

namespace meshtrace {

// The nodes of both levels whose box `ray` meets at 0 <= t <= tMax (plus a
// relative margin of kEnteredMargin), each level from its root down (a node
// whose box the ray misses hides its children); empty without a BVH.
inline constexpr double kEnteredMargin = 1e-6;
std::vector<BvhNodeBox> bvhNodesEntered(const SceneIntersector& intersector, const Ray& ray,
                                        double tMax);

}  // namespace meshtrace
