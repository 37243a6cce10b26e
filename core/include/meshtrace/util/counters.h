#pragma once
// Work counters: what a render actually did, so that work left out is visible.
#include <cstdint>
#include <string>

namespace meshtrace {

struct Counters {
  std::uint64_t primaryRays = 0;
  std::uint64_t shadowRays = 0;
  std::uint64_t reflectionRays = 0;
  std::uint64_t boxTests = 0;
  std::uint64_t triangleTests = 0;
  std::uint64_t sphereTests = 0;
  std::uint64_t planeTests = 0;
  std::uint64_t cylinderTests = 0;
  std::uint64_t nodeVisits = 0;  // BVH nodes entered, top level and meshes
  // Shadow rays answered by the primitive that blocked the previous one
  // toward the same light (LastBlocker), without a traversal.
  std::uint64_t lastBlockerHits = 0;

  Counters& operator+=(const Counters& o);
  std::string describe() const;
};

}  // namespace meshtrace
