// Closest-hit and any-hit queries through the scene's two-level BVH.
#include "meshtrace/scene_bvh.h"
#include "primitive_query.h"

namespace meshtrace {

BoxRay4 SceneBvh::boxRay(const PrimitiveQuery& query) const {
  const bool single = query.kernel().precision == Precision::Single;
  return BoxRay4(query.ray(), slabPadding(single, query.ray().origin, sceneScale_));
}

void SceneBvh::closestHit(const PrimitiveQuery& query, ClosestHit& closest,
                          Counters& counters) const {
  for (std::uint32_t i = 0; i < scene_.planes.size(); ++i)
    query.offerShape(ObjectKind::Plane, i, closest);
  const BoxRay4 ray = boxRay(query);
  const double tMin = query.tMin();
  std::uint64_t visits = 0;
  traverseClosest(top_, ray, tMin, closest.t(), visits, [&](std::uint32_t first, std::uint32_t n) {
    for (std::uint32_t k = first; k < first + n; ++k) {
      const Object& o = objects_[top_.order[k]];
      if (o.kind != ObjectKind::Mesh) {
        query.offerShape(o.kind, o.index, closest);
        continue;
      }
      const Bvh4& bvh = meshBvhs_[o.index];
      if (bvh.empty()) {
        const auto count = static_cast<std::uint32_t>(scene_.meshes[o.index].triangles().size());
        for (std::uint32_t t = 0; t < count; ++t) query.offerTriangle(o.index, t, closest);
        continue;
      }
      traverseClosest(bvh, ray, tMin, closest.t(), visits,
                      [&](std::uint32_t tFirst, std::uint32_t tn) {
                        for (std::uint32_t j = tFirst; j < tFirst + tn; ++j)
                          query.offerTriangle(o.index, bvh.order[j], closest);
                      });
    }
  });
  counters.nodeVisits += visits;
}

bool SceneBvh::occluded(const PrimitiveQuery& query, double tMax, Counters& counters) const {
  for (std::uint32_t i = 0; i < scene_.planes.size(); ++i)
    if (query.shapeBlocks(ObjectKind::Plane, i, tMax)) return true;
  const BoxRay4 ray = boxRay(query);
  const double tMin = query.tMin();
  std::uint64_t visits = 0;
  const bool blocked =
      traverseAny(top_, ray, tMin, tMax, visits, [&](std::uint32_t first, std::uint32_t n) {
        for (std::uint32_t k = first; k < first + n; ++k) {
          const Object& o = objects_[top_.order[k]];
          if (o.kind != ObjectKind::Mesh) {
            if (query.shapeBlocks(o.kind, o.index, tMax)) return true;
            continue;
          }
          const Bvh4& bvh = meshBvhs_[o.index];
          if (bvh.empty()) {
            const auto count =
                static_cast<std::uint32_t>(scene_.meshes[o.index].triangles().size());
            for (std::uint32_t t = 0; t < count; ++t)
              if (query.triangleBlocks(o.index, t, tMax)) return true;
            continue;
          }
          const bool hit = traverseAny(bvh, ray, tMin, tMax, visits,
                                       [&](std::uint32_t tFirst, std::uint32_t tn) {
                                         for (std::uint32_t j = tFirst; j < tFirst + tn; ++j)
                                           if (query.triangleBlocks(o.index, bvh.order[j], tMax))
                                             return true;
                                         return false;
                                       });
          if (hit) return true;
        }
        return false;
      });
  counters.nodeVisits += visits;
  return blocked;
}

}  // namespace meshtrace
