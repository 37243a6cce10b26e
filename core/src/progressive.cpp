#include "meshtrace/progressive.h"

#include <chrono>
#include <cmath>

#include "meshtrace/image.h"
#include "meshtrace/integrator.h"

namespace meshtrace {

namespace {
using Clock = std::chrono::steady_clock;

double msBetween(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double, std::milli>(b - a).count();
}

// The largest power of two <= v, at least 1.
int powerOfTwoAtMost(int v) {
  int p = 1;
  while (p * 2 <= v) p *= 2;
  return p;
}
}  // namespace

void sampleOffset(int k, double& dx, double& dy) {
  // R2 sequence (Roberts 2018): frac(0.5 + k * (1/phi2, 1/phi2^2)).
  constexpr double a1 = 0.7548776662466927, a2 = 0.5698402909980532;
  dx = std::fmod(0.5 + k * a1, 1.0) - 0.5;
  dy = std::fmod(0.5 + k * a2, 1.0) - 0.5;
}

PreparedScene::PreparedScene(std::shared_ptr<const Scene> scene, const TraceOptions& options)
    : scene_(std::move(scene)), options_(options) {}

PreparedScene::~PreparedScene() = default;

const SceneIntersector& PreparedScene::intersector() const {
  std::call_once(built_,
                 [&] { intersector_ = std::make_unique<SceneIntersector>(*scene_, options_); });
  return *intersector_;
}

const PixelProbe* ProgressiveFrame::probeAt(int col, int row) const {
  if (probes.empty() || col < 0 || row < 0 || col >= width || row >= height) return nullptr;
  const int step = tileStep[(row / tileSize) * tilesX + col / tileSize];
  if (step == 0) return nullptr;
  return &probes[static_cast<std::size_t>(row - row % step) * width + (col - col % step)];
}

struct ProgressiveRenderer::Job {
  std::uint64_t id = 0;
  std::shared_ptr<const PreparedScene> scene;
  Camera camera;
  ProgressiveSettings settings;
  Clock::time_point start = Clock::now();

  std::once_flag built;
  std::unique_ptr<Integrator> integrator;

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

  // Worker-side data: a tile is only ever touched by the worker holding its
  // current pass, and passes of a tile run in order.
  std::vector<Color> sum;
  std::vector<PixelProbe> probeSamples;

  // Published data, under `mutex`.
  mutable std::mutex mutex;
  std::vector<std::uint8_t> rgba;
  std::vector<PixelProbe> probes;
  std::vector<int> tileStep;
  std::vector<std::uint32_t> tileVersion;
  Counters counters;
  double firstCoarseMs = -1.0, exactMs = -1.0, finishedMs = -1.0;

  Job(std::uint64_t jobId, std::shared_ptr<const PreparedScene> s, const Camera& cam,
      const ProgressiveSettings& st)
      : id(jobId), scene(std::move(s)), camera(cam), settings(st) {
    width = camera.width();
    height = camera.height();
    tile = powerOfTwoAtMost(std::max(1, settings.firstStep));
    tilesX = (width + tile - 1) / tile;
    tilesY = (height + tile - 1) / tile;
    tileCount = tilesX * tilesY;
    for (int s2 = tile; s2 >= 1; s2 /= 2) steps.push_back(s2);
    passCount = static_cast<int>(steps.size()) + (settings.color ? settings.extraSamples : 0);
    itemCount = passCount * tileCount;
    tilePasses.reset(new std::atomic<int>[tileCount]);
    for (int i = 0; i < tileCount; ++i) tilePasses[i] = 0;
    passTiles.reset(new std::atomic<int>[passCount]);
    for (int i = 0; i < passCount; ++i) passTiles[i] = 0;
    const std::size_t pixels = static_cast<std::size_t>(width) * height;
    if (settings.color) sum.assign(pixels, Color(0.0));
    if (settings.probes) {
      probeSamples.assign(pixels, PixelProbe{});
      probes.assign(pixels, PixelProbe{});
    }
    rgba.assign(pixels * 4, 0);
    tileStep.assign(tileCount, 0);
    tileVersion.assign(tileCount, 0);
  }

  int levelCount() const { return static_cast<int>(steps.size()); }
  bool finished() const { return itemsDone.load() == itemCount; }
  std::size_t index(int col, int row) const { return static_cast<std::size_t>(row) * width + col; }

  Color tracePixel(double x, double y, Counters& work) const {
    return integrator->pixel(camera, x, y, work);
  }

  // Runs work item `item`; false if cancelled part way.
  bool run(int item) {
    const int pass = item / tileCount;
    const int t = item % tileCount;
    // The tile's previous pass may still be running on another worker.
    while (tilePasses[t].load(std::memory_order_acquire) < pass) {
      if (cancelled.load(std::memory_order_relaxed)) return false;
      std::this_thread::yield();
    }
    const int c0 = (t % tilesX) * tile, r0 = (t / tilesX) * tile;
    const int c1 = std::min(c0 + tile, width), r1 = std::min(r0 + tile, height);
    Counters work;
    const int step = pass < levelCount() ? steps[pass] : 1;
    long long traced = 0;
    if (pass >= levelCount()) {
      double dx, dy;
      sampleOffset(pass - levelCount() + 1, dx, dy);
      for (int r = r0; r < r1; ++r)
        for (int c = c0; c < c1; ++c) {
          if (cancelled.load(std::memory_order_relaxed)) return false;
          sum[index(c, r)] += tracePixel(c + dx, height - 1 - r + dy, work);
        }
    } else {
      // The pixels on this pass's grid that the coarser grids did not trace
      // (tile corners are multiples of every step).
      for (int r = r0; r < r1; r += step)
        for (int c = c0; c < c1; c += step) {
          if (pass > 0 && (c - c0) % (2 * step) == 0 && (r - r0) % (2 * step) == 0) continue;
          if (cancelled.load(std::memory_order_relaxed)) return false;
          ++traced;
          const double x = c, y = height - 1 - r;
          if (settings.color) sum[index(c, r)] = tracePixel(x, y, work);
          if (settings.probes) {
            probeSamples[index(c, r)] = probePixel(scene->intersector(), camera, x, y);
            if (!settings.color) ++work.primaryRays;
          }
        }
    }
    publish(t, pass, step, c0, r0, c1, r1, work);
    exactPixelsDone += traced;
    tilePasses[t].store(pass + 1, std::memory_order_release);
    const int tilesDone = ++passTiles[pass];
    ++itemsDone;
    if (tilesDone == tileCount) {
      const double ms = msBetween(start, Clock::now());
      std::lock_guard<std::mutex> lock(mutex);
      if (pass == 0) firstCoarseMs = ms;
      if (pass == levelCount() - 1) exactMs = ms;
      if (pass == passCount - 1) finishedMs = ms;
    }
    return true;
  }

  void publish(int t, int pass, int step, int c0, int r0, int c1, int r1, const Counters& work) {
    const double samples = pass < levelCount() ? 1.0 : double(pass - levelCount() + 2);
    std::lock_guard<std::mutex> lock(mutex);
    // Each traced pixel stands for the step x step block it is the corner of.
    for (int br = r0; br < r1; br += step) {
      for (int bc = c0; bc < c1; bc += step) {
        std::uint8_t value[4] = {0, 0, 0, 255};
        if (settings.color) {
          const Color v = samples == 1.0 ? sum[index(bc, br)] : sum[index(bc, br)] / samples;
          for (int k = 0; k < 3; ++k) value[k] = toByte(v[k]);
        }
        for (int r = br; r < std::min(br + step, r1); ++r)
          for (int c = bc; c < std::min(bc + step, c1); ++c)
            std::copy(value, value + 4, &rgba[index(c, r) * 4]);
        if (settings.probes) probes[index(bc, br)] = probeSamples[index(bc, br)];
      }
    }
    tileStep[t] = step;
    ++tileVersion[t];
    counters += work;
  }
};

ProgressiveRenderer::ProgressiveRenderer(int threads, std::function<void()> workerStart) {
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  for (int i = 0; i < threads; ++i)
    workers_.emplace_back([this, workerStart] {
      if (workerStart) workerStart();
      workerLoop();
    });
}

ProgressiveRenderer::~ProgressiveRenderer() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
    if (current_) current_->cancelled = true;
  }
  wake_.notify_all();
  for (std::thread& w : workers_) w.join();
}

std::uint64_t ProgressiveRenderer::start(std::shared_ptr<const PreparedScene> scene,
                                         const Camera& camera,
                                         const ProgressiveSettings& settings) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (current_) current_->cancelled = true;
  ++generation_;
  current_ = std::make_shared<Job>(generation_, std::move(scene), camera, settings);
  wake_.notify_all();
  return generation_;
}

void ProgressiveRenderer::cancel() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (current_) current_->cancelled = true;
  current_.reset();
}

void ProgressiveRenderer::workerLoop() {
  std::uint64_t seen = 0;
  for (;;) {
    std::shared_ptr<Job> job;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, [&] { return stopping_ || (current_ && generation_ != seen); });
      if (stopping_) return;
      job = current_;
      seen = generation_;
    }
    std::call_once(job->built, [&] {
      job->integrator = std::make_unique<Integrator>(job->scene->intersector());
    });
    for (int item = job->nextItem++; item < job->itemCount; item = job->nextItem++) {
      if (!job->run(item)) break;
    }
  }
}

ProgressiveStatus ProgressiveRenderer::status() const {
  std::shared_ptr<Job> job;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    job = current_;
  }
  ProgressiveStatus s;
  if (!job) return s;
  s.job = job->id;
  s.passCount = job->passCount;
  int done = 0;
  while (done < job->passCount && job->passTiles[done].load() == job->tileCount) ++done;
  s.passesDone = done;
  const double pixels = double(job->width) * job->height;
  s.exactFraction = pixels > 0 ? double(job->exactPixelsDone.load()) / pixels : 1.0;
  s.coarseDone = done >= 1;
  s.exactDone = done >= job->levelCount();
  s.finished = job->finished();
  s.running = !s.finished;
  s.samplesPerPixel = s.exactDone ? 1 + (done - job->levelCount()) : 0;
  std::lock_guard<std::mutex> lock(job->mutex);
  s.firstCoarseMs = job->firstCoarseMs;
  s.exactMs = job->exactMs;
  s.finishedMs = job->finishedMs;
  s.elapsedMs =
      s.finished && job->finishedMs >= 0 ? job->finishedMs : msBetween(job->start, Clock::now());
  s.counters = job->counters;
  return s;
}

std::vector<int> ProgressiveRenderer::update(ProgressiveFrame& frame) const {
  std::shared_ptr<Job> job;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    job = current_;
  }
  std::vector<int> changed;
  if (!job) return changed;
  if (frame.job != job->id) {
    frame = ProgressiveFrame{};
    frame.job = job->id;
    frame.width = job->width;
    frame.height = job->height;
    frame.tileSize = job->tile;
    frame.tilesX = job->tilesX;
    frame.tilesY = job->tilesY;
    frame.rgba.assign(job->rgba.size(), 0);
    if (job->settings.probes) frame.probes.assign(job->probes.size(), PixelProbe{});
    frame.tileStep.assign(job->tileCount, 0);
    frame.tileVersion.assign(job->tileCount, 0);
  }
  std::lock_guard<std::mutex> lock(job->mutex);
  for (int t = 0; t < job->tileCount; ++t) {
    if (frame.tileVersion[t] == job->tileVersion[t]) continue;
    frame.tileVersion[t] = job->tileVersion[t];
    frame.tileStep[t] = job->tileStep[t];
    changed.push_back(t);
    const int c0 = (t % job->tilesX) * job->tile, r0 = (t / job->tilesX) * job->tile;
    const int c1 = std::min(c0 + job->tile, job->width);
    const int r1 = std::min(r0 + job->tile, job->height);
    for (int r = r0; r < r1; ++r) {
      const std::size_t a = job->index(c0, r), b = job->index(c1, r);
      std::copy(job->rgba.begin() + a * 4, job->rgba.begin() + b * 4, frame.rgba.begin() + a * 4);
      if (!frame.probes.empty())
        std::copy(job->probes.begin() + a, job->probes.begin() + b, frame.probes.begin() + a);
    }
  }
  return changed;
}

bool ProgressiveRenderer::waitUntilFinished(double timeoutMs) const {
  const auto start = Clock::now();
  for (;;) {
    const ProgressiveStatus s = status();
    if (s.job == 0 || s.finished) return true;
    if (msBetween(start, Clock::now()) > timeoutMs) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
}

}  // namespace meshtrace
