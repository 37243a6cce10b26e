// raytrace --report: configurations, measurements and the written report.
#include "meshtrace/report/report.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <system_error>

#include "meshtrace/io/output_file.h"
#include "meshtrace/io/reference_lookup.h"
#include "meshtrace/render/integrator.h"
#include "meshtrace/render/progressive.h"
#include "meshtrace/render/surface.h"
#include "meshtrace/report/image_compare.h"
#include "meshtrace/report/left_out.h"
#include "meshtrace/report/plot.h"
#include "report/report_files.h"
#include "util/parallel_tiles.h"

namespace meshtrace {

namespace {

// The primary hit of every storage pixel (of its block's traced pixel for a
// coarse pass), with its shading normal.
struct PixelHit {
  bool found = false;
  PrimitiveRef ref;
  Vec3 normal{0.0};
};

std::vector<PixelHit> primaryHits(const Scene& scene, const TraceOptions& options, int step,
                                  int threads) {
  const SceneIntersector intersector(scene, options);
  const int w = scene.camera.width(), h = scene.camera.height();
  std::vector<PixelHit> out(static_cast<std::size_t>(w) * h);
  forEachTile(w, h, 16, threads, [&](const auto& rows, const auto& cols, Counters& counters) {
    for (int row = rows.begin(); row < rows.end(); ++row)
      for (int x = cols.begin(); x < cols.end(); ++x) {
        const int cx = x - x % step, crow = row - row % step;  // the block's traced pixel
        const Ray ray = scene.camera.primaryRay(cx, flippedRow(crow, h));
        Hit hit;
        PixelHit& p = out[static_cast<std::size_t>(row) * w + x];
        if (!intersector.closestHit(ray, 0.0, hit, counters)) continue;
        p = {true, hit.ref, surfaceAt(scene, ray, hit, options.triangle.precision).normal};
      }
  });
  return out;
}

bool sameRef(const PrimitiveRef& a, const PrimitiveRef& b) {
  return a.kind == b.kind && a.object == b.object && a.triangle == b.triangle;
}

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Least-squares slope of log RMSE against log samples over the sweep's rows
// with an error (0 where fewer than two).
double samplesSlope(const std::vector<ReportRow>& rows) {
  double n = 0, sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (const ReportRow& r : rows) {
    if (r.config.group != "samples" || !(r.rmse > 0.0)) continue;
    const double x = std::log(double(r.config.samples)), y = std::log(r.rmse);
    n += 1;
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  const double d = n * sxx - sx * sx;
  return n >= 2 && d > 0 ? (n * sxy - sx * sy) / d : 0.0;
}

std::string configLabel(const TraceOptions& t) {
  return std::string(toString(t.triangle.test)) + " " + toString(t.triangle.precision) + " " +
         toString(t.accel);
}

}  // namespace

std::vector<ReportConfig> reportConfigs(const Scene& scene, std::vector<std::string>& leftOut,
                                        double maxBruteForceTests) {
  const TraceOptions base;
  std::vector<ReportConfig> out;
  // The viewer's progressive passes, coarse to exact to anti-aliased.
  for (int step : {16, 4, 2})
    out.push_back({"progressive", "coarse 1/" + std::to_string(step), base, step, 1});
  out.push_back({"progressive", "exact (default)", base, 1, 1});
  for (int spp : {1, 4, 16, 64})
    out.push_back({"samples", std::to_string(spp) + " samples/pixel", base, 1, spp});
  for (Precision p : {Precision::Double, Precision::Single})
    for (TriangleTest t :
         {TriangleTest::Cramer, TriangleTest::MollerTrumbore, TriangleTest::Watertight}) {
      TraceOptions o = base;
      o.triangle = {t, p};
      if (t == base.triangle.test && p == base.triangle.precision) continue;
      out.push_back({p == Precision::Double ? "triangle" : "precision", configLabel(o), o, 1, 1});
    }
  const double bruteTests =
      double(scene.triangleCount()) * scene.camera.width() * scene.camera.height();
  for (AccelMethod a : {AccelMethod::None, AccelMethod::BoundingBox}) {
    TraceOptions o = base;
    o.accel = a;
    if (a == AccelMethod::None && bruteTests > maxBruteForceTests) {
      char why[200];
      std::snprintf(why, sizeof why,
                    "brute force (--accel none) not timed: %.2g triangle tests for primary rays "
                    "alone, over the report's limit of %.2g",
                    bruteTests, maxBruteForceTests);
      leftOut.push_back(why);
      continue;
    }
    out.push_back({"accel", configLabel(o), o, 1, 1});
  }
  return out;
}

Image renderConfig(const Scene& scene, const ReportConfig& config, int threads) {
  const SceneIntersector intersector(scene, config.trace);
  const Integrator integrator(intersector);
  const int w = scene.camera.width(), h = scene.camera.height(), step = config.step;
  Image image(w, h);
  // One traced pixel per step x step block, repeated over the block. Each
  // tile keeps its lights' last blockers, as raytrace's render does.
  const int blocksX = (w + step - 1) / step, blocksY = (h + step - 1) / step;
  forEachTile(blocksX, blocksY, 8, threads, [&](const auto& rows, const auto& cols, Counters& c) {
    LastBlockers blockers(scene);
    for (int by = rows.begin(); by < rows.end(); ++by)
      for (int bx = cols.begin(); bx < cols.end(); ++bx) {
        const int row = by * step, x = bx * step;
        Color color(0.0);
        for (int k = 0; k < config.samples; ++k) {
          double dx = 0.0, dy = 0.0;
          if (k > 0) sampleOffset(k, dx, dy);
          color += integrator.pixel(x + dx, flippedRow(row, h) + dy, c, &blockers);
        }
        color /= double(config.samples);
        for (int r = row; r < std::min(h, row + step); ++r)
          for (int xx = x; xx < std::min(w, x + step); ++xx) image.at(xx, r) = color;
      }
  });
  return image;
}

std::filesystem::path findReferenceImage(const Scene& scene) {
  const std::optional<std::filesystem::path> found = findReference(scene.file);
  if (!found) return {};
  const Image8 ref = readImage(*found);
  if (ref.width != scene.camera.width() || ref.height != scene.camera.height()) return {};
  return *found;
}

SceneReport measureScene(const Scene& scene, int threads, const ReportProgress& progress) {
  SceneReport report;
  report.scene = scene.file;
  report.leftOut = leftOut(scene);
  const SceneIntersector defaultIntersector(scene, TraceOptions{});
  if (const SceneBvhStats* bvh = defaultIntersector.bvhStats())
    for (const std::string& item : bvh->leftOut) report.leftOut.push_back(item);
  const std::vector<ReportConfig> configs = reportConfigs(scene, report.leftOut);

  // The reference image, and how its JPEG noise is measured.
  const std::filesystem::path refFile = findReferenceImage(scene);
  Image8 reference;
  bool jpegReference = false;
  if (!refFile.empty()) {
    reference = readImage(refFile);
    jpegReference = refFile.extension() == ".jpg";
    report.reference = refFile.string() + (jpegReference ? " (a stored JPEG: the seed's reference)"
                                                         : " (a stored render)");
    // The conformance test's bound: our render, JPEG-encoded, within 0.6.
    report.jpegNoiseRmse =
        jpegReference ? 0.6 : compareImages(reference, jpegRoundTrip(reference, 95)).rmse;
  } else {
    ReportConfig high{"reference", "64 samples/pixel", TraceOptions{}, 1, 64};
    reference = quantize(renderConfig(scene, high, threads));
    report.reference =
        "our render with 64 samples/pixel (no stored image of the scene's size in an "
        "expected_results/ folder beside the scene's folders)";
    report.jpegNoiseRmse = compareImages(reference, jpegRoundTrip(reference, 95)).rmse;
  }

  // Primary hits of a double-precision brute-force trace (the BVH where brute
  // force was left out: it returns the same hits, as the BVH tests assert).
  bool bruteCheap = false;
  for (const ReportConfig& c : configs) bruteCheap |= c.trace.accel == AccelMethod::None;
  TraceOptions refTrace;
  refTrace.triangle.precision = Precision::Double;
  if (bruteCheap) refTrace.accel = AccelMethod::None;
  const std::vector<PixelHit> refHits = primaryHits(scene, refTrace, 1, threads);

  // The samples sweep's reference: the same scene, converged.
  Image8 converged;
  const ReportConfig convergedConfig{"reference",
                                     std::to_string(kConvergedSamples) + " samples/pixel",
                                     TraceOptions{}, 1, kConvergedSamples};
  for (const ReportConfig& c : configs) {
    if (c.group != "samples" || !converged.rgb.empty()) continue;
    if (progress) progress(0, configs.size(), "the converged render");
    converged = quantize(renderConfig(scene, convergedConfig, threads));
    report.converged = "our render with " + convergedConfig.name;
  }

  for (const ReportConfig& c : configs) {
    if (progress) progress(report.rows.size(), configs.size(), c.group + " " + c.name);
    ReportRow row{c};
    const auto start = std::chrono::steady_clock::now();
    const Image image = renderConfig(scene, c, threads);
    row.seconds = secondsSince(start);
    const bool sweep = c.group == "samples";
    row.against = sweep ? "converged" : "reference";
    const Image8 ours =
        jpegReference && !sweep ? jpegRoundTrip(quantize(image), 95) : quantize(image);
    const ImageDifference d = compareImages(ours, sweep ? converged : reference);
    row.rmse = d.rmse;
    row.psnr = d.psnr;
    const std::vector<PixelHit> hits = primaryHits(scene, c.trace, c.step, threads);
    std::size_t differ = 0;
    for (std::size_t i = 0; i < hits.size(); ++i) {
      const PixelHit &a = hits[i], &b = refHits[i];
      if (a.found != b.found || (a.found && !sameRef(a.ref, b.ref))) {
        ++differ;
        continue;
      }
      if (!a.found) continue;
      const double angle =
          std::atan2(glm::length(glm::cross(a.normal, b.normal)), glm::dot(a.normal, b.normal));
      row.maxNormalDegrees = std::max(row.maxNormalDegrees, glm::degrees(angle));
    }
    row.hitDiffers = hits.empty() ? 0.0 : double(differ) / double(hits.size());
    report.rows.push_back(row);
  }
  report.samplesSlope = samplesSlope(report.rows);
  return report;
}

void writeReport(const std::filesystem::path& dir, const std::vector<SceneReport>& measured,
                 const std::string& stability, const ReportShare& share) {
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec)
    throw std::runtime_error(dir.string() + ": cannot create the report folder (" + ec.message() +
                             ")");
  // Every file goes to a temporary first; none replaces an earlier report's
  // until all are written (the plots first, report.md last).
  std::vector<OutputFile> files;
  // The data first; the markdown and the plots are made from it as read
  // back, so that a report merged from shares' files is this one.
  const std::string csv = report_files::rowsCsv(measured);
  const std::string scenesCsv = report_files::scenesCsv(measured);
  const std::vector<SceneReport> scenes = report_files::parseScenes(scenesCsv, csv, dir);
  std::ostringstream md;
  md << "# Error against run time\n\n"
     << "Each configuration renders the whole image once on all cores; the time is wall time "
        "(including the BVH build), so it varies with machine load. RMSE and PSNR are against "
        "the reference named per scene (8-bit units; our image JPEG-encoded first when the "
        "reference is a JPEG, as the conformance test does). *Hit differs* is the share of "
        "pixels whose primary ray hits another primitive than a double-precision brute-force "
        "trace; *normal* the worst angle between shading normals where the primitive is the "
        "same. Coarse passes trace one pixel per block and repeat it over the block, as the "
        "viewer's first passes do.\n\n"
     << "Plots (gnuplot, from report.csv; plot_SCENE.gp redraws them): RMSE against run "
        "time per configuration group with the JPEG-noise threshold, and the samples sweep's "
        "RMSE against samples per pixel with its power-law fit, both on log axes.\n\n";
  if (share.shard.count > 1)
    md << "This folder holds share " << share.shard.text() << " of a run of " << share.scenes.size()
       << " scenes; `raytrace --report-merge` joins the shares' folders into one report.\n\n";
  if (!scenes.empty()) {
    md << "| scene | scored against | samples sweep against |\n|---|---|---|\n";
    for (const SceneReport& s : scenes)
      md << "| " << report_files::sceneName(s) << " | " << s.reference << " | "
         << (s.converged.empty() ? "-" : s.converged) << " |\n";
    md << "\n";
  }
  char buf[512];
  for (const SceneReport& s : scenes) {
    const std::string name = report_files::sceneName(s);
    md << "## " << name << "\n\nScored against: " << s.reference
       << "; within JPEG noise means RMSE <= "
       << (std::snprintf(buf, sizeof buf, "%.3f", s.jpegNoiseRmse), buf) << ".\n\n"
       << "| configuration | group | seconds | RMSE | PSNR dB | hit differs | normal deg |\n"
       << "|---|---|---|---|---|---|---|\n";
    const ReportRow* cheapest = nullptr;
    for (const ReportRow& r : s.rows) {
      const ReportConfig& c = r.config;
      std::snprintf(buf, sizeof buf, "| %s | %s | %.3f | %.3f | %.1f | %.4f%% | %.3g |\n",
                    c.name.c_str(), c.group.c_str(), r.seconds, r.rmse, r.psnr,
                    100.0 * r.hitDiffers, r.maxNormalDegrees);
      md << buf;
      if (r.against == "reference" && r.rmse <= s.jpegNoiseRmse &&
          (!cheapest || r.seconds < cheapest->seconds))
        cheapest = &r;
    }
    md << "\n**Conclusion:** "
       << (cheapest ? "the cheapest configuration within JPEG noise of the reference is *" +
                          cheapest->config.name + "* (" +
                          (std::snprintf(buf, sizeof buf, "%.3f s, RMSE %.3f", cheapest->seconds,
                                         cheapest->rmse),
                           buf) +
                          ")."
                    : std::string("no configuration is within JPEG noise of the reference."))
       << "\n\n";
    if (!s.converged.empty())
      md << "The samples-per-pixel rows are measured against " << s.converged
         << " instead: on log-log axes their RMSE falls with slope "
         << (std::snprintf(buf, sizeof buf, "%.2f", s.samplesSlope), buf)
         << " (least squares; -0.5 for independent random samples).\n\n";
    md << "![error against run time, and convergence](plot_" << name << ".png)\n\n";
    if (!s.leftOut.empty()) {
      md << "Left out, and why:\n\n";
      for (const std::string& l : s.leftOut) md << "- " << l << "\n";
      md << "\n";
    }
  }
  // The plots, drawn by gnuplot from the finished CSV; their scripts are
  // kept beside it to redraw or edit them.
  for (const SceneReport& s : scenes) {
    const std::string name = report_files::sceneName(s);
    files.emplace_back(dir / ("plot_" + name + ".gp")).write(plotScript(s));
    files.back().finish();  // closed now: a report of many scenes holds no descriptors open
    files.emplace_back(dir / ("plot_" + name + ".png")).write(plotPng(s, csv));
    files.back().finish();
  }
  md << "## Stability suite\n\n"
     << "Per triangle test and precision (tests/core/report/stability_*_test.cpp): leaks = rays "
        "from "
        "inside a closed 16x16-gridded box aimed exactly at its vertices and edges that hit "
        "nothing; multiple hits = rays that more than one triangle accepts; self re-hits = "
        "spawned shadow and reflection rays hitting the triangle they left (sizes 1e-4 to 1e4 "
        "at offsets 0 to 1e6); wrong hit/miss and the error columns are against a "
        "quad-precision reference on grazing, sliver, huge and tiny triangles. Mrays/s is the "
        "speed of `raytrace --triangle T --precision P` where it counts: closest hits of the "
        "primary rays on scenes/knot's knot (106,496 triangles as make_scenes generates it, "
        "filling a view of 256x256 rays from that scene's eye) through the BVH, one ray at a "
        "time on one core.\n\n"
     << stability << "\n";
  ReportShare whole = share;
  if (whole.scenes.empty())
    for (const SceneReport& s : scenes) whole.scenes.push_back(s.scene);
  files.emplace_back(dir / report_files::kStability).write(stability);
  files.emplace_back(dir / report_files::kShare).write(report_files::shareText(whole));
  files.emplace_back(dir / report_files::kScenes).write(scenesCsv);
  files.emplace_back(dir / report_files::kRows).write(csv);
  files.emplace_back(dir / "report.md").write(md.str());
  commitTogether(files);
}

}  // namespace meshtrace
