#pragma once
// The pipeline a text mesh's body streams through (off_reader.cpp,
// obj_reader.cpp), in pieces of whole lines, several pieces in flight:
// read in order; counted in parallel (the lines, and the elements they
// hold); numbered in order (the line number and the first element of each
// piece); parsed in parallel; and gathered in order, where the first bad
// line of the file ends the reading, as a serial reader would report it.
// Only the pieces in flight are in memory, never the whole file.
#include <tbb/parallel_pipeline.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <cstddef>
#include <memory>
#include <mutex>
#include <vector>

#include "io/line_pieces.h"

namespace meshtrace::text {

// The bytes of a piece, a little over which a pipeline's pieces are read.
inline constexpr std::size_t kPieceBytes = std::size_t{1} << 18;

// Streams `pieces` through the stages, each a callable on a Chunk&, a
// PieceChunk or one derived from it. `first`, if any, is the first chunk,
// its piece already read (a header may have taken its start).
// `gather(chunk, done)` sets `done` to end the reading (after an error); it
// also leaves the chunk ready for another piece, as chunks are reused
// rather than allocated again.
template <typename Chunk, typename Count, typename Number, typename Parse, typename Gather>
void streamPieces(LinePieces& pieces, std::unique_ptr<Chunk> first, Count&& count, Number&& number,
                  Parse&& parse, Gather&& gather) {
  const auto tokens = static_cast<std::size_t>(4 * tbb::this_task_arena::max_concurrency());
  std::vector<std::unique_ptr<Chunk>> spare;
  std::mutex spareLock;
  std::atomic<bool> done = false;  // set by the last stage, read by the first
  tbb::parallel_pipeline(
      tokens,
      tbb::make_filter<
          void, Chunk*>(tbb::filter_mode::serial_in_order, [&](tbb::flow_control& fc) -> Chunk* {
        if (first) return first.release();
        if (done) {
          fc.stop();
          return nullptr;
        }
        std::unique_ptr<Chunk> c;
        {
          const std::lock_guard<std::mutex> lock(spareLock);
          if (!spare.empty()) c = std::move(spare.back()), spare.pop_back();
        }
        if (!c) c = std::make_unique<Chunk>();
        if (!pieces.next(c->piece) && !c->piece.nulAfter()) {
          fc.stop();
          return nullptr;
        }
        c->begin = 0;
        return c.release();
      }) & tbb::make_filter<Chunk*, Chunk*>(tbb::filter_mode::parallel, [&](Chunk* c) {
        count(*c);
        return c;
      }) & tbb::make_filter<Chunk*, Chunk*>(tbb::filter_mode::serial_in_order, [&](Chunk* c) {
        number(*c);
        return c;
      }) & tbb::make_filter<Chunk*, Chunk*>(tbb::filter_mode::parallel, [&](Chunk* c) {
        parse(*c);
        return c;
      }) & tbb::make_filter<Chunk*, void>(tbb::filter_mode::serial_in_order, [&](Chunk* chunk) {
        std::unique_ptr<Chunk> c(chunk);
        gather(*c, done);
        const std::lock_guard<std::mutex> lock(spareLock);
        spare.push_back(std::move(c));
      }));
}

}  // namespace meshtrace::text
