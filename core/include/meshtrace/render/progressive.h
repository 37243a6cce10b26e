#pragma once
// Progressive rendering on background threads, for an interactive viewer.
//
// A job renders the image coarse to fine, tile by tile: the first pass traces
// one pixel per block of `firstStep` x `firstStep` pixels, each later pass
// halves the block and traces only the pixels the earlier passes did not,
// down to every pixel (the exact image, each pixel traced once, exactly as
// `render` traces it). Optional passes then add one jittered sample per pixel
// each (anti-aliasing). Each finished tile is published at once; a viewer
// copies the tiles that changed since its last look. Starting a new job
// cancels the one in flight: workers check between pixels.
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "meshtrace/accel/intersector.h"
#include "meshtrace/render/inspect.h"
#include "meshtrace/util/counters.h"

namespace meshtrace {

// What a PreparedScene traces through.
enum class SceneStructure {
  Full,  // the intersector of options.accel (the BVH by default): the exact image
  // A uniform grid over every mesh's triangles, made in one pass over them
  // (tens of ms for a million triangles, where the BVH takes hundreds):
  // for a first coarse pass while the BVH builds. It tests the same
  // triangle kernel and keeps the same nearest hit, but a spawned ray is
  // not told the triangle it leaves (spawn.h), so a pixel can differ from
  // the exact image: show its passes as a preview only.
  Preview,
};

// A scene with its intersector (and so its BVH), built once on first use by
// whichever thread needs it first (or by build()), and shared by every job
// and inspector query on that scene: moving the camera does not rebuild it.
class PreparedScene {
 public:
  PreparedScene(std::shared_ptr<const Scene> scene, const TraceOptions& options,
                SceneStructure structure = SceneStructure::Full);
  ~PreparedScene();
  const Scene& scene() const { return *scene_; }
  const std::shared_ptr<const Scene>& sharedScene() const { return scene_; }
  const TraceOptions& options() const { return options_; }
  SceneStructure structure() const { return structure_; }
  // Builds the intersector on the first call; later calls wait for it.
  const SceneIntersector& intersector() const;
  // True once the intersector is built: a caller that must not wait (a
  // viewer's UI thread) asks this first.
  bool built() const;

 private:
  struct Lazy;  // the intersector and the flag that builds it once
  std::shared_ptr<const Scene> scene_;
  TraceOptions options_;
  SceneStructure structure_;
  std::unique_ptr<Lazy> lazy_;
};

struct ProgressiveSettings {
  int firstStep = 32;    // block size of the first pass: a power of two, also the tile size
  int extraSamples = 0;  // anti-aliasing samples per pixel beyond the exact one
  bool color = true;     // trace colours (the Integrator)
  bool probes = false;   // record a PixelProbe per pixel for the false-colour views
  // Only the first pass: a quick look (e.g. through a preview structure)
  // that a full job replaces.
  bool firstPassOnly = false;
};

struct ProgressiveStatus {
  std::uint64_t job = 0;
  bool running = false;  // a job exists and has work left
  int passesDone = 0, passCount = 0;
  double exactFraction = 0.0;  // share of the exact image's pixels traced
  bool coarseDone = false, exactDone = false, finished = false;
  int samplesPerPixel = 0;  // complete samples in every pixel
  double elapsedMs = 0.0;   // since start; stops when the job finishes
  double firstCoarseMs = -1.0, exactMs = -1.0, finishedMs = -1.0;  // -1 until reached
  std::vector<double> passMs;  // per pass, when it was complete (ms since start); -1 until then
  Counters counters;           // work of the published tiles
};

// What a pass that just completed brings: the first (coarse) image, the
// exact one, the end of the job.
struct PassFinished {
  int pass = 0;
  bool coarse = false, exact = false, last = false;
};

// The viewer's copy of a job's image: colours as RGBA8 (when the job traces
// colours), the job's probes (when it records them) and per tile the step
// of the last pass that reached it (1 once exact). Both hold a pixel only
// where a pass traced it: at multiples of its tile's step, each standing
// for the step x step block it is the corner of (probeAt and rgbaAt).
struct ProgressiveFrame {
  std::uint64_t job = 0;
  int width = 0, height = 0, tileSize = 0, tilesX = 0, tilesY = 0;
  std::vector<std::uint8_t> rgba;      // row 0 at the top
  std::span<const PixelProbe> probes;  // the job's own
  // With anti-aliasing passes, which change `rgba`, the exact colours of
  // each tile from its exact pass on (the job's own; empty without them).
  std::span<const std::uint8_t> exactRgba;
  std::shared_ptr<const void> storage;  // keeps `probes` and `exactRgba` alive
  std::vector<int> tileStep;            // 0 while a tile has nothing yet
  std::vector<std::uint32_t> tileVersion;

  // What stands for storage pixel (col, row) at its tile's step; null
  // where nothing was traced yet.
  const PixelProbe* probeAt(int col, int row) const;
  const std::uint8_t* rgbaAt(int col, int row) const;
  // The index of that pixel.
  std::optional<std::size_t> cornerOf(int col, int row) const;
};

class ProgressiveRenderer {
 public:
  // threads = 0: one worker per core. `workerStart` runs first on each
  // worker thread (a viewer lowers their priority there, to keep drawing).
  // `passFinished` runs on the worker that completes a pass of a job, so a
  // viewer waiting for events can wake and show it at once; it must be
  // quick and must not call back into the renderer.
  explicit ProgressiveRenderer(int threads = 0, std::function<void()> workerStart = {},
                               std::function<void(const PassFinished&)> passFinished = {});
  ~ProgressiveRenderer();
  ProgressiveRenderer(const ProgressiveRenderer&) = delete;
  ProgressiveRenderer& operator=(const ProgressiveRenderer&) = delete;

  // Cancels the job in flight and starts rendering `scene` through `camera`
  // (the scene's own camera is not used). Returns the new job's id.
  std::uint64_t start(std::shared_ptr<const PreparedScene> scene, const Camera& camera,
                      const ProgressiveSettings& settings);
  void cancel();
  // Until called again with a smaller count, workers 0 .. count-1 wait
  // between pixels (except while another worker needs the tile they hold):
  // a viewer lends itself a core for the time it draws a frame, without
  // lowering the render's priority against other programs.
  void pauseWorkers(int count);

  ProgressiveStatus status() const;
  // Brings `frame` up to date with the current job (resizing it for a new
  // job) and returns the indices of the tiles that changed.
  std::vector<int> update(ProgressiveFrame& frame) const;
  // Blocks until the current job finishes, or the timeout; true if finished.
  bool waitUntilFinished(double timeoutMs) const;

  int threads() const;

 private:
  class Impl;  // the workers, the current job and their locks (progressive.cpp)
  std::unique_ptr<Impl> impl_;
};

// The offset in [-0.5, 0.5)^2 of anti-aliasing sample k >= 1 (an R2
// low-discrepancy sequence), so sample 0 is the exact pixel position.
void sampleOffset(int k, double& dx, double& dy);

}  // namespace meshtrace
