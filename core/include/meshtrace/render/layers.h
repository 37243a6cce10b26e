#pragma once
// An image with what each pixel saw, as the channels of an EXR file: R, G,
// B (the colour before quantisation); Z (the primary hit's distance along
// its ray, infinite for the background); N.X, N.Y, N.Z (the shading
// normal); P.X, P.Y, P.Z (the hit point); objectId and triangleId
// (objectIndex order; 4294967295 where nothing was hit); barycentric.B and
// barycentric.C (the hit's barycentrics of the triangle's second and third
// corners); traversalCost (the closest-hit query's BVH nodes, boxes and
// primitives tested).
#include "meshtrace/accel/intersector.h"
#include "meshtrace/io/exr.h"

namespace meshtrace {

// The id channels' value where the primary ray hit nothing.
inline constexpr std::uint32_t kNoHitId = 0xffffffffu;

// Renders the image and probes each pixel's primary ray, on `threads`
// threads (0: all cores).
ExrImage renderLayers(const SceneIntersector& intersector, int threads);
// The same through `camera` instead of the scene's (the viewer's, once moved).
ExrImage renderLayers(const SceneIntersector& intersector, const Camera& camera, int threads);

}  // namespace meshtrace
