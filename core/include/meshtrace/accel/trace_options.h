#pragma once
// Every choice that changes how rays are intersected: the acceleration
// method, the triangle kernel and the BVH's build settings. Accelerated and
// brute-force queries use the same triangle kernel and the same
// order-independent choice among equal distances, so they find the same
// hits: the acceleration method changes the speed, never the image.
#include <cstddef>
#include <string_view>

#include "meshtrace/geometry/triangle.h"

namespace meshtrace {

enum class AccelMethod {
  None,         // every triangle of every mesh
  BoundingBox,  // a mesh's triangles only when the ray meets its box
  Bvh,          // a two-level bounding volume hierarchy
};

// "none", "aabb", "bvh".
const char* toString(AccelMethod method);
// Throws std::invalid_argument for an unknown name.
AccelMethod parseAccelMethod(std::string_view name);

// The binned SAH build of one BVH level.
struct BvhBuildOptions {
  int bins = 16;               // candidate split planes per axis (fewer for small nodes)
  int maxLeafSize = 4;         // larger sets are always split
  double nodeCost = 1.0;       // SAH: cost of one node visit (two box tests) ...
  double primitiveCost = 1.0;  // ... relative to one primitive test
  int leafBlock = 1;  // primitives tested together: a leaf of n costs ceil(n / leafBlock) tests
};

// Meshes with fewer triangles stay out of the triangle BVH: testing their
// few triangles after their top-level box is faster (`bench --crossover`
// measures where a BVH starts to pay; see BENCHMARKS.md).
inline constexpr std::size_t kMinBvhTriangles = 3;

// From this size of nodes and blocks on, the triangle BVH's traversals ask
// for the children a ray meets before visiting them: on a tree far larger
// than the caches that hides memory latency, on a smaller one it only costs
// instructions (see BENCHMARKS.md).
inline constexpr std::size_t kPrefetchBvhBytes = std::size_t{24} << 20;

// The build choices of --accel bvh (they change the speed only).
struct SceneBvhOptions {
  std::size_t minMeshTriangles = kMinBvhTriangles;
  // A leaf is one block of up to four triangles, tested at once.
  BvhBuildOptions mesh{
      .bins = 16, .maxLeafSize = 4, .nodeCost = 1.0, .primitiveCost = 1.0, .leafBlock = 4};
  BvhBuildOptions top{.bins = 16, .maxLeafSize = 2, .nodeCost = 1.0, .primitiveCost = 2.0};
  // A triangle BVH of this many bytes or more fetches children ahead.
  std::size_t prefetchBytes = kPrefetchBvhBytes;
};

struct TraceOptions {
  AccelMethod accel = AccelMethod::Bvh;
  TriangleKernel triangle;  // algorithm and precision of the triangle test
  SceneBvhOptions bvh;      // build choices for --accel bvh (speed only)
};

}  // namespace meshtrace
