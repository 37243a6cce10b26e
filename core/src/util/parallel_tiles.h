#pragma once
// The one parallel loop over an image-shaped grid: whole renders, box-hit
// counts and the report's configurations all go through it.
#include <tbb/blocked_range2d.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "meshtrace/util/counters.h"

namespace meshtrace {

// Runs tile(rows, cols, counters) over a grid of `height` rows and `width`
// columns in tiles of about `grain` x `grain`, spread over `threads` workers
// (0: all cores); each worker adds to counters of its own, and their sum is
// returned. Every cell is visited once whatever the thread count.
template <typename Tile>
Counters forEachTile(int width, int height, int grain, int threads, const Tile& tile) {
  tbb::combinable<Counters> perThread;
  const auto run = [&] {
    tbb::parallel_for(
        tbb::blocked_range2d<int>(0, height, grain, 0, width, grain),
        [&](const tbb::blocked_range2d<int>& r) { tile(r.rows(), r.cols(), perThread.local()); });
  };
  if (threads > 0)
    tbb::task_arena(threads).execute(run);
  else
    run();
  Counters total;
  perThread.combine_each([&](const Counters& c) { total += c; });
  return total;
}

}  // namespace meshtrace
