#pragma once
// One progressive render job (private to progressive.cpp): its passes and
// tiles, the work of one item (a tile in a pass), what it publishes, and
// the image-sized storage it borrows.
#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <vector>

#include "meshtrace/io/image.h"
#include "meshtrace/render/integrator.h"
#include "meshtrace/render/progressive.h"
#include "util/build_vector.h"

namespace meshtrace {

namespace progressive {
using Clock = std::chrono::steady_clock;

inline double msBetween(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

// A job's image-sized storage. It is allocated by a worker, not by start()
// on the caller's (a viewer's UI) thread, and once the job and the frames
// reading its probes let go of it, it serves the next job, which overwrites
// every element before anyone reads it: while a camera is dragged, a new
// job starts every frame. The first job at a size, or the first to need
// probes (48 bytes a pixel), gets new memory: BuildVector's huge pages make
// that a few page faults rather than one per 4 KiB, which where faults are
// dear held up the first image of a new size or view.
struct Buffers {
  BuildVector<Color> sum;          // worker side: sum of the samples per pixel, for AA passes
  BuildVector<PixelProbe> probes;  // written once per pixel, read where published
  BuildVector<std::uint8_t> rgba;  // published colours, under the tile's lock
  // With anti-aliasing passes: each tile's exact colours, copied from
  // `rgba` when its exact pass is published and never changed after.
  BuildVector<std::uint8_t> exactRgba;
};

class BufferPool : public std::enable_shared_from_this<BufferPool> {
 public:
  std::shared_ptr<Buffers> take() {
    std::unique_ptr<Buffers> buffers;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      buffers = spare_ ? std::move(spare_) : std::make_unique<Buffers>();
    }
    // The last owner hands the storage back instead of freeing it.
    return std::shared_ptr<Buffers>(buffers.release(), [pool = shared_from_this()](Buffers* b) {
      pool->give(std::unique_ptr<Buffers>(b));
    });
  }

 private:
  // One spare is enough: jobs overlap only while a replaced one winds down.
  void give(std::unique_ptr<Buffers> buffers) {
    std::lock_guard<std::mutex> lock(mutex_);
    spare_ = std::move(buffers);
  }

  std::mutex mutex_;
  std::unique_ptr<Buffers> spare_;
};

struct Job {
  std::uint64_t id = 0;
  std::shared_ptr<const PreparedScene> scene;
  Camera camera;
  ProgressiveSettings settings;
  Clock::time_point start = Clock::now();

  std::once_flag built;  // the integrator and the buffers, by the first worker
  std::unique_ptr<Integrator> integrator;
  std::shared_ptr<BufferPool> pool;
  std::shared_ptr<Buffers> buffers;

  int width = 0, height = 0, tile = 0, tilesX = 0, tilesY = 0, tileCount = 0;
  std::vector<int> steps;  // block size per level pass, coarse to 1
  int passCount = 0;
  int itemCount = 0;
  std::atomic<int> nextItem{0};
  std::atomic<bool> cancelled{false};
  std::unique_ptr<std::atomic<int>[]> tilePasses;  // passes finished per tile
  std::unique_ptr<std::atomic<int>[]> passTiles;   // tiles finished per pass
  std::atomic<int> itemsDone{0};
  std::atomic<long long> exactPixelsDone{0};

  // A tile's pixels are only ever written by the worker holding its current
  // pass, and passes of a tile run in order. A pass writes probes only at
  // pixels no coarser pass traced, so the published ones (at multiples of
  // the tile's step) never change: readers take those without copies.

  // Published per tile: its lock (shared by every kTileLocks-th tile, so
  // that two workers publishing rarely meet) guards its step and its
  // pixels of buffers->rgba; its version, bumped after, says it changed.
  static constexpr int kTileLocks = 64;
  mutable std::array<std::mutex, kTileLocks> tileLocks;
  std::vector<int> tileStep;
  std::unique_ptr<std::atomic<std::uint32_t>[]> tileVersion;
  std::mutex& tileLock(int t) const { return tileLocks[t % kTileLocks]; }

  // Published totals, under `statsMutex`.
  mutable std::mutex statsMutex;
  Counters counters;
  double firstCoarseMs = -1.0, exactMs = -1.0, finishedMs = -1.0;
  std::vector<double> passMs;  // per pass, -1 until complete

  Job(std::uint64_t jobId, std::shared_ptr<const PreparedScene> s, const Camera& cam,
      const ProgressiveSettings& st, std::shared_ptr<BufferPool> buffersFrom)
      : id(jobId), scene(std::move(s)), camera(cam), settings(st), pool(std::move(buffersFrom)) {
    width = camera.width();
    height = camera.height();
    tile = powerOfTwoAtMost(std::max(1, settings.firstStep));
    tilesX = (width + tile - 1) / tile;
    tilesY = (height + tile - 1) / tile;
    tileCount = tilesX * tilesY;
    for (int s2 = tile; s2 >= 1; s2 /= 2) steps.push_back(s2);
    passCount = settings.firstPassOnly
                    ? 1
                    : static_cast<int>(steps.size()) + (settings.color ? settings.extraSamples : 0);
    itemCount = passCount * tileCount;
    tilePasses.reset(new std::atomic<int>[tileCount]);
    for (int i = 0; i < tileCount; ++i) tilePasses[i] = 0;
    passTiles.reset(new std::atomic<int>[passCount]);
    for (int i = 0; i < passCount; ++i) passTiles[i] = 0;
    passMs.assign(passCount, -1.0);
    tileStep.assign(tileCount, 0);
    tileVersion.reset(new std::atomic<std::uint32_t>[tileCount]);
    for (int i = 0; i < tileCount; ++i) tileVersion[i] = 0;
  }

  // On the first worker to pick the job up.
  void prepare() {
    integrator = std::make_unique<Integrator>(scene->intersector());
    buffers = pool->take();
    const std::size_t pixels = static_cast<std::size_t>(width) * height;
    // Sums only for anti-aliasing passes to add to.
    buffers->sum.resize(settings.color && settings.extraSamples > 0 ? pixels : 0);
    buffers->probes.resize(settings.probes ? pixels : 0);
    buffers->rgba.resize(settings.color ? pixels * 4 : 0);
    buffers->exactRgba.resize(passCount > levelCount() && settings.color ? pixels * 4 : 0);
  }

  // The largest power of two <= v, at least 1.
  static int powerOfTwoAtMost(int v) {
    int p = 1;
    while (p * 2 <= v) p *= 2;
    return p;
  }

  int levelCount() const { return static_cast<int>(steps.size()); }
  bool finished() const { return itemsDone.load() == itemCount; }
  std::size_t index(int col, int row) const { return static_cast<std::size_t>(row) * width + col; }

  Color tracePixel(double x, double y, Counters& work, LastBlockers& blockers) const {
    return integrator->pixel(camera, x, y, work, &blockers);
  }

  // Calls fn(col, row) for the pixels of tile [c0, c1) x [r0, r1) that
  // `pass` traces, until it returns false: in a level pass the points of its
  // step's grid that no coarser grid has (tile corners are multiples of
  // every step), in an anti-aliasing pass every pixel. False if stopped.
  template <typename Fn>
  bool forEachNewPixel(int pass, int step, int c0, int r0, int c1, int r1, const Fn& fn) const {
    const bool everyPoint = pass == 0 || pass >= levelCount();
    for (int r = r0; r < r1; r += step)
      for (int c = c0; c < c1; c += step) {
        if (!everyPoint && (c - c0) % (2 * step) == 0 && (r - r0) % (2 * step) == 0) continue;
        if (!fn(c, r)) return false;
      }
    return true;
  }

  // Runs work item `item`; false if cancelled part way. `waitForTile(t,
  // pass)` returns once tile t has finished `pass` passes (false if
  // cancelled first); `mayGoOn()` is asked between pixels and may wait too.
  // `passFinished` is told when this item completes a pass.
  template <typename WaitForTile, typename MayGoOn>
  bool run(int item, const WaitForTile& waitForTile, const MayGoOn& mayGoOn,
           const std::function<void(const PassFinished&)>& passFinished) {
    const int pass = item / tileCount;
    const int t = item % tileCount;
    // The tile's previous pass may still be running on another worker.
    if (!waitForTile(t, pass)) return false;
    const int c0 = (t % tilesX) * tile, r0 = (t / tilesX) * tile;
    const int c1 = std::min(c0 + tile, width), r1 = std::min(r0 + tile, height);
    Counters work;
    LastBlockers blockers(scene->scene());
    const bool antiAliasing = pass >= levelCount();
    const int step = antiAliasing ? 1 : steps[pass];
    const double samples = antiAliasing ? double(pass - levelCount() + 2) : 1.0;
    long long traced = 0;
    double dx = 0.0, dy = 0.0;
    if (antiAliasing) sampleOffset(pass - levelCount() + 1, dx, dy);
    // This pass's colours as bytes, until they are published.
    thread_local std::vector<std::array<std::uint8_t, 4>> fresh;
    fresh.resize(static_cast<std::size_t>(tile) * tile);
    const bool complete = forEachNewPixel(pass, step, c0, r0, c1, r1, [&](int c, int r) {
      if (!mayGoOn()) return false;
      const double x = c + dx, y = flippedRow(r, height) + dy;
      if (antiAliasing) {
        const Color sum = buffers->sum[index(c, r)] += tracePixel(x, y, work, blockers);
        fresh[(r - r0) * tile + (c - c0)] = rgbaOf(sum / samples);
        return true;
      }
      ++traced;
      if (settings.color) {
        const Color v = tracePixel(x, y, work, blockers);
        if (!buffers->sum.empty()) buffers->sum[index(c, r)] = v;
        fresh[(r - r0) * tile + (c - c0)] = rgbaOf(v);
      }
      if (settings.probes) {
        buffers->probes[index(c, r)] = probePixel(scene->intersector(), camera, x, y);
        if (!settings.color) ++work.primaryRays;
      }
      return true;
    });
    if (!complete) return false;
    publish(t, pass, step, c0, r0, c1, r1, fresh, work);
    exactPixelsDone += traced;
    // Read before the tile's next pass may start elsewhere: a later pass
    // never gets an earlier time than this one.
    const double ms = msBetween(start, Clock::now());
    tilePasses[t].store(pass + 1, std::memory_order_release);
    const int tilesDone = ++passTiles[pass];
    ++itemsDone;
    if (tilesDone == tileCount) {
      std::lock_guard<std::mutex> lock(statsMutex);
      passMs[pass] = ms;
      if (pass == 0) firstCoarseMs = ms;
      if (pass == levelCount() - 1) exactMs = ms;
      if (pass == passCount - 1) finishedMs = ms;
    }
    if (tilesDone == tileCount && passFinished)
      passFinished({pass, pass == 0, pass == levelCount() - 1, pass == passCount - 1});
    return true;
  }

  static std::array<std::uint8_t, 4> rgbaOf(const Color& c) {
    return {toByte(c.r), toByte(c.g), toByte(c.b), 255};
  }

  // `fresh`: the colours `pass` traced, by position in the tile.
  void publish(int t, int pass, int step, int c0, int r0, int c1, int r1,
               const std::vector<std::array<std::uint8_t, 4>>& fresh, const Counters& work) {
    auto& rgba = buffers->rgba;
    std::unique_lock<std::mutex> lock(tileLock(t));
    // Only the pixels just traced: a reader takes each coarser pixel for the
    // block it is the corner of, as the tile's step says.
    if (settings.color)
      forEachNewPixel(pass, step, c0, r0, c1, r1, [&](int c, int r) {
        const auto& v = fresh[(r - r0) * tile + (c - c0)];
        std::copy(v.begin(), v.end(), &rgba[index(c, r) * 4]);
        return true;
      });
    if (pass == levelCount() - 1 && !buffers->exactRgba.empty())
      for (int r = r0; r < r1; ++r)
        std::copy(&rgba[index(c0, r) * 4], &rgba[index(c1, r) * 4],
                  &buffers->exactRgba[index(c0, r) * 4]);
    tileStep[t] = step;
    tileVersion[t].fetch_add(1, std::memory_order_release);
    lock.unlock();
    std::lock_guard<std::mutex> statsLock(statsMutex);
    counters += work;
  }
};

}  // namespace progressive

}  // namespace meshtrace
