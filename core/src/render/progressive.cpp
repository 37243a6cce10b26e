#include "meshtrace/render/progressive.h"

#include <atomic>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <mutex>
#include <thread>

#include "render/progressive_job.h"
#include "render/progressive_preview.h"

namespace meshtrace {

using progressive::BufferPool;
using progressive::Clock;
using progressive::Job;
using progressive::msBetween;

void sampleOffset(int k, double& dx, double& dy) {
  // R2 sequence (Roberts 2018): frac(0.5 + k * (1/phi2, 1/phi2^2)).
  constexpr double a1 = 0.7548776662466927, a2 = 0.5698402909980532;
  dx = std::fmod(0.5 + k * a1, 1.0) - 0.5;
  dy = std::fmod(0.5 + k * a2, 1.0) - 0.5;
}

struct PreparedScene::Lazy {
  std::once_flag once;
  std::atomic<bool> built{false};
  std::unique_ptr<PreviewGrid> grid;  // the Preview structure
  std::unique_ptr<SceneIntersector> intersector;
};

PreparedScene::PreparedScene(std::shared_ptr<const Scene> scene, const TraceOptions& options,
                             SceneStructure structure)
    : scene_(std::move(scene)),
      options_(options),
      structure_(structure),
      lazy_(std::make_unique<Lazy>()) {}

PreparedScene::~PreparedScene() = default;

const SceneIntersector& PreparedScene::intersector() const {
  std::call_once(lazy_->once, [&] {
    if (structure_ == SceneStructure::Preview) {
      lazy_->grid = std::make_unique<PreviewGrid>(*scene_, options_.triangle);
      lazy_->intersector = std::make_unique<SceneIntersector>(*scene_, options_, *lazy_->grid);
    } else {
      lazy_->intersector = std::make_unique<SceneIntersector>(*scene_, options_);
    }
    lazy_->built.store(true, std::memory_order_release);
  });
  return *lazy_->intersector;
}

bool PreparedScene::built() const { return lazy_->built.load(std::memory_order_acquire); }

// The workers and the job they share. Workers take the current job's items
// (a tile in a pass) in order; a new job replaces the current one, and the
// workers move to it between pixels.
class ProgressiveRenderer::Impl {
 public:
  Impl(int threads, std::function<void()> workerStart,
       std::function<void(const PassFinished&)> passFinished);
  ~Impl();

  std::uint64_t start(std::shared_ptr<const PreparedScene> scene, const Camera& camera,
                      const ProgressiveSettings& settings);
  void cancel();
  void pauseWorkers(int count);
  ProgressiveStatus status() const;
  std::vector<int> update(ProgressiveFrame& frame) const;
  int threads() const { return static_cast<int>(workers_.size()); }

 private:
  void workerLoop(int worker);
  // Between pixels: waits while `worker` is paused; false once `job` is cancelled.
  bool mayGoOn(const Job& job, int worker);
  // Until done() (part of `job` that other workers hold); false if the job
  // is cancelled first.
  bool waitFor(const Job& job, const std::function<bool()>& done);
  void resumeCancelled();

  std::function<void(const PassFinished&)> passFinished_;
  std::shared_ptr<BufferPool> pool_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::shared_ptr<Job> current_;
  std::uint64_t generation_ = 0;
  bool stopping_ = false;
  std::mutex pauseMutex_;
  std::condition_variable resumed_;
  alignas(64) std::atomic<int> paused_{0};          // read between pixels: a line of its own
  alignas(64) std::atomic<int> waitingForWork_{0};  // workers waiting for work others hold
  std::vector<std::thread> workers_;
};

ProgressiveRenderer::ProgressiveRenderer(int threads, std::function<void()> workerStart,
                                         std::function<void(const PassFinished&)> passFinished)
    : impl_(std::make_unique<Impl>(threads, std::move(workerStart), std::move(passFinished))) {}
ProgressiveRenderer::~ProgressiveRenderer() = default;
std::uint64_t ProgressiveRenderer::start(std::shared_ptr<const PreparedScene> scene,
                                         const Camera& camera,
                                         const ProgressiveSettings& settings) {
  return impl_->start(std::move(scene), camera, settings);
}
void ProgressiveRenderer::cancel() { impl_->cancel(); }
void ProgressiveRenderer::pauseWorkers(int count) { impl_->pauseWorkers(count); }
ProgressiveStatus ProgressiveRenderer::status() const { return impl_->status(); }
std::vector<int> ProgressiveRenderer::update(ProgressiveFrame& frame) const {
  return impl_->update(frame);
}
int ProgressiveRenderer::threads() const { return impl_->threads(); }

std::optional<std::size_t> ProgressiveFrame::cornerOf(int col, int row) const {
  if (col < 0 || row < 0 || col >= width || row >= height) return std::nullopt;
  const int step = tileStep[(row / tileSize) * tilesX + col / tileSize];
  if (step == 0) return std::nullopt;
  return static_cast<std::size_t>(row - row % step) * width + (col - col % step);
}

const PixelProbe* ProgressiveFrame::probeAt(int col, int row) const {
  const auto i = probes.empty() ? std::nullopt : cornerOf(col, row);
  return i ? &probes[*i] : nullptr;
}

const std::uint8_t* ProgressiveFrame::rgbaAt(int col, int row) const {
  const auto i = rgba.empty() ? std::nullopt : cornerOf(col, row);
  return i ? &rgba[*i * 4] : nullptr;
}

ProgressiveRenderer::Impl::Impl(int threads, std::function<void()> workerStart,
                                std::function<void(const PassFinished&)> passFinished)
    : passFinished_(std::move(passFinished)), pool_(std::make_shared<BufferPool>()) {
  if (threads <= 0) threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  for (int i = 0; i < threads; ++i)
    workers_.emplace_back([this, workerStart, i] {
      if (workerStart) workerStart();
      workerLoop(i);
    });
}

ProgressiveRenderer::Impl::~Impl() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
    if (current_) current_->cancelled = true;
  }
  wake_.notify_all();
  resumeCancelled();
  for (std::thread& w : workers_) w.join();
}

std::uint64_t ProgressiveRenderer::Impl::start(std::shared_ptr<const PreparedScene> scene,
                                               const Camera& camera,
                                               const ProgressiveSettings& settings) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (current_) current_->cancelled = true;
  ++generation_;
  current_ = std::make_shared<Job>(generation_, std::move(scene), camera, settings, pool_);
  wake_.notify_all();
  resumeCancelled();
  return generation_;
}

void ProgressiveRenderer::Impl::cancel() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (current_) current_->cancelled = true;
    current_.reset();
  }
  resumeCancelled();
}

void ProgressiveRenderer::Impl::pauseWorkers(int count) {
  {
    std::lock_guard<std::mutex> lock(pauseMutex_);
    paused_.store(count, std::memory_order_relaxed);
  }
  resumed_.notify_all();
}

void ProgressiveRenderer::Impl::resumeCancelled() {
  // Taking the lock orders the cancellation before a paused worker's check.
  { std::lock_guard<std::mutex> lock(pauseMutex_); }
  resumed_.notify_all();
}

bool ProgressiveRenderer::Impl::mayGoOn(const Job& job, int worker) {
  if (worker < paused_.load(std::memory_order_relaxed) && waitingForWork_.load() == 0) {
    std::unique_lock<std::mutex> lock(pauseMutex_);
    resumed_.wait(lock, [&] {
      return worker >= paused_.load(std::memory_order_relaxed) || waitingForWork_.load() > 0 ||
             job.cancelled.load();
    });
  }
  return !job.cancelled.load(std::memory_order_relaxed);
}

bool ProgressiveRenderer::Impl::waitFor(const Job& job, const std::function<bool()>& done) {
  if (done()) return true;
  // A worker still at it may be paused: it goes on while anyone waits.
  {
    std::lock_guard<std::mutex> lock(pauseMutex_);
    ++waitingForWork_;
  }
  resumed_.notify_all();
  bool ready = true;
  while (!done()) {
    if (job.cancelled.load(std::memory_order_relaxed)) {
      ready = false;
      break;
    }
    std::this_thread::yield();
  }
  --waitingForWork_;
  return ready;
}

void ProgressiveRenderer::Impl::workerLoop(int worker) {
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
    std::call_once(job->built, [&] { job->prepare(); });
    for (int item = job->nextItem++; item < job->itemCount; item = job->nextItem++) {
      const auto tileReady = [&](int t, int pass) {
        return waitFor(*job, [&] { return job->tilePasses[t].load() >= pass; });
      };
      const auto goOn = [&] {
        if (worker < paused_.load(std::memory_order_relaxed)) return mayGoOn(*job, worker);
        return !job->cancelled.load(std::memory_order_relaxed);
      };
      if (!job->run(item, tileReady, goOn, passFinished_)) break;
    }
    // The last items may be held by paused workers: they finish them now.
    if (paused_.load() > 0) waitFor(*job, [&] { return job->finished(); });
  }
}

ProgressiveStatus ProgressiveRenderer::Impl::status() const {
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
  std::lock_guard<std::mutex> lock(job->statsMutex);
  s.firstCoarseMs = job->firstCoarseMs;
  s.exactMs = job->exactMs;
  s.finishedMs = job->finishedMs;
  s.passMs = job->passMs;
  s.elapsedMs =
      s.finished && job->finishedMs >= 0 ? job->finishedMs : msBetween(job->start, Clock::now());
  s.counters = job->counters;
  return s;
}

std::vector<int> ProgressiveRenderer::Impl::update(ProgressiveFrame& frame) const {
  std::shared_ptr<Job> job;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    job = current_;
  }
  std::vector<int> changed;
  if (!job) return changed;
  if (frame.job != job->id) {
    const std::size_t pixels = static_cast<std::size_t>(job->width) * job->height;
    frame.job = job->id;
    frame.width = job->width;
    frame.height = job->height;
    frame.tileSize = job->tile;
    frame.tilesX = job->tilesX;
    frame.tilesY = job->tilesY;
    frame.rgba.resize(job->settings.color ? pixels * 4 : 0);
    frame.probes = {};
    frame.exactRgba = {};
    frame.storage.reset();
    frame.tileStep.assign(job->tileCount, 0);
    frame.tileVersion.assign(job->tileCount, 0);
  }
  for (int t = 0; t < job->tileCount; ++t) {
    if (frame.tileVersion[t] == job->tileVersion[t].load(std::memory_order_acquire)) continue;
    std::lock_guard<std::mutex> lock(job->tileLock(t));
    frame.tileVersion[t] = job->tileVersion[t].load(std::memory_order_relaxed);
    frame.tileStep[t] = job->tileStep[t];
    changed.push_back(t);
    if (!frame.storage) {
      // Published probes and exact colours never change again: the frame
      // reads the job's.
      frame.storage = job->buffers;
      frame.probes = job->buffers->probes;
      frame.exactRgba = job->buffers->exactRgba;
    }
    if (frame.rgba.empty()) continue;
    const int c0 = (t % job->tilesX) * job->tile, r0 = (t / job->tilesX) * job->tile;
    const int c1 = std::min(c0 + job->tile, job->width);
    const int r1 = std::min(r0 + job->tile, job->height);
    const auto& rgba = job->buffers->rgba;
    for (int r = r0; r < r1; ++r) {
      const std::size_t a = job->index(c0, r), b = job->index(c1, r);
      std::copy(rgba.begin() + a * 4, rgba.begin() + b * 4, frame.rgba.begin() + a * 4);
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
