#pragma once
// The rays every engine traces in the benchmark, and how they are timed.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <vector>

#include "meshtrace/intersector.h"

namespace meshtrace::bench {

struct RaySet {
  std::vector<Ray> rays;
  std::vector<double> tMax;  // kInfinity for primary rays
  // Shadow rays: the primitive each leaves, which our queries are told (as
  // the integrator tells them); empty for primary rays.
  std::vector<PrimitiveRef> start;

  const PrimitiveRef* startOf(std::size_t i) const {
    return start.empty() ? nullptr : &start[i];
  }
};

// One ray through every pixel of the scene's camera.
RaySet primaryRays(const Scene& scene);
// From each primary hit whose normal faces the first light, the shadow ray
// the integrator would cast toward it (found with `intersector`).
RaySet shadowRays(const Scene& scene, const SceneIntersector& intersector,
                  const RaySet& primary);

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
