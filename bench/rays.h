#pragma once
// The rays every engine traces in the benchmark, and how they are timed.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <vector>

#include "meshtrace/accel/intersector.h"

namespace meshtrace::bench {

struct RaySet {
  std::vector<Ray> rays;
  std::vector<double> tMax;  // kInfinity for primary rays
  // Shadow rays: the primitive each leaves, which our queries are told (as
  // the integrator tells them); empty for primary rays.
  std::vector<PrimitiveRef> start;
  // Primary rays: the first 4 * packets rays are the 2x2 pixel quads the
  // renderer traces together (SceneIntersector::closestHitPacket); the
  // pixels of an odd last row or column follow one by one.
  std::size_t packets = 0;
  // What a packet-tracing engine calls per ray set: packets plus the rest.
  std::size_t packetCalls() const { return packets + (rays.size() - kPacketSize * packets); }

  const PrimitiveRef* startOf(std::size_t i) const { return start.empty() ? nullptr : &start[i]; }
};

// One ray through every pixel of the scene's camera, quad by quad.
RaySet primaryRays(const Scene& scene);
// From each primary hit whose normal faces the first light, the shadow ray
// the integrator would cast toward it (found with `intersector`).
RaySet shadowRays(const Scene& scene, const SceneIntersector& intersector, const RaySet& primary);
// From each primary hit, the ray a bounce off it would cast, spawned as the
// integrator spawns reflections: its mirror direction (coherent where the
// surface is flat, spread where it is curved), or a direction drawn
// uniformly over the hemisphere around the normal (incoherent: what a path
// tracer's diffuse bounce casts), from a fixed seed.
enum class Bounce { Mirror, Hemisphere };
RaySet bounceRays(const Scene& scene, const SceneIntersector& intersector, const RaySet& primary,
                  Bounce bounce);

// Seconds for trace(i) over every stride-th i < n, on `threads` threads,
// best of up to `passes` passes (stopping once a second has been spent).
template <typename Trace>
double timeRays(std::size_t n, std::size_t stride, int threads, int passes, const Trace& trace) {
  double best = 1e300, spent = 0.0;
  tbb::task_arena arena(threads);
  for (int p = 0; p < passes && spent < 1.0; ++p) {
    const auto start = std::chrono::steady_clock::now();
    arena.execute([&] {
      tbb::parallel_for(tbb::blocked_range<std::size_t>(0, (n + stride - 1) / stride, 256),
                        [&](const tbb::blocked_range<std::size_t>& r) {
                          for (std::size_t k = r.begin(); k < r.end(); ++k) trace(k * stride);
                        });
    });
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    best = std::min(best, s);
    spent += s;
  }
  return best;
}

}  // namespace meshtrace::bench
