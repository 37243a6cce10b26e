#pragma once
// Error against run time: `raytrace --report DIR SCENE...` renders each scene
// under a set of configurations (progressive coarse passes, samples per
// pixel, single or double precision, triangle algorithm, acceleration),
// times each, measures its error against a reference, and writes
// DIR/report.md, DIR/report.csv and one PNG plot of error against time per
// scene.
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "meshtrace/accel/intersector.h"
#include "meshtrace/io/image.h"
#include "meshtrace/util/shard.h"

namespace meshtrace {

struct ReportConfig {
  std::string group;  // "progressive", "samples", "precision", "triangle", "accel"
  std::string name;
  TraceOptions trace;
  int step = 1;     // > 1: a coarse pass, one traced pixel per step x step block
  int samples = 1;  // samples per pixel (sample 0 at the exact pixel position)
};

struct ReportRow {
  ReportConfig config;
  double seconds = 0.0;
  double rmse = 0.0, psnr = 0.0;  // against the reference, 8-bit units
  double hitDiffers = 0.0;        // share of pixels whose primary hit differs
  double maxNormalDegrees = 0.0;  // worst shading-normal angle on the same primitive
  // What the errors are against: "reference" (SceneReport::reference) or
  // "converged" (SceneReport::converged, for the samples sweep).
  std::string against = "reference";
};

inline constexpr int kConvergedSamples = 256;

struct SceneReport {
  std::filesystem::path scene;
  std::string reference;       // what the errors are measured against
  double jpegNoiseRmse = 0.0;  // "within JPEG noise" threshold
  // The samples sweep's reference: the same scene rendered with
  // kConvergedSamples samples per pixel, which the sweep's RMSE falls towards
  // (a 1-sample reference would favour 1 sample). Pixel-exact configurations
  // keep `reference`.
  std::string converged;
  // The slope of log RMSE against log samples over the sweep (-0.5 for
  // independent random samples).
  double samplesSlope = 0.0;
  std::vector<ReportRow> rows;
  std::vector<std::string> leftOut;
};

// The configurations run for `scene`; brute force is left out (with the
// reason added to `leftOut`) when it would trace more than `maxBruteForceTests`
// triangle tests for primary rays alone.
std::vector<ReportConfig> reportConfigs(const Scene& scene, std::vector<std::string>& leftOut,
                                        double maxBruteForceTests = 4e9);

// The image of a configuration: coarse passes upsampled by repeating the
// traced pixel over its block; several samples averaged.
Image renderConfig(const Scene& scene, const ReportConfig& config, int threads = 0);

// The scene's stored reference image (findReference: the seed's
// expected_results/<stem>.jpg, our expected_results/<stem>.png), if it has
// the scene's size; empty if not.
std::filesystem::path findReferenceImage(const Scene& scene);

// Told before each configuration is measured: how many are done, of how
// many, and the next one's group and name.
using ReportProgress =
    std::function<void(std::size_t done, std::size_t total, const std::string& next)>;

SceneReport measureScene(const Scene& scene, int threads = 0, const ReportProgress& progress = {});

// Which share of a run a report holds (raytrace --report --shard I/N):
// the scenes whose index in `scenes`, every scene of the run sorted, is
// shard.index modulo shard.count.
struct ReportShare {
  Shard shard;
  std::vector<std::filesystem::path> scenes;
};

// Writes report.md, report.csv and plot_<scene>.png into `dir`, with the
// data the report is made from (scenes.csv, stability.md, share.txt) for
// mergeReports; `stability` is the markdown table of stability.h, included
// verbatim. Without a share's scenes, the report is the whole run of
// `scenes`. The files replace the folder's old ones together or not at all.
void writeReport(const std::filesystem::path& dir, const std::vector<SceneReport>& scenes,
                 const std::string& stability, const ReportShare& share = {});

}  // namespace meshtrace
