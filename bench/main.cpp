// bench: our BVH against Embree 3 on the same scenes and rays, in one run.
// Every speed figure is also given as a ratio to Embree measured in the same
// run, since only ratios hold on a shared, noisy machine.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "bench/crossover.h"
#include "bench/embree_intersector.h"
#include "bench/full_run.h"
#include "bench/mesh_load.h"
#include "bench/mesh_scenes.h"
#include "bench/rays.h"
#include "meshtrace/accel/intersector.h"
#include "meshtrace/io/scene_parser.h"

using namespace meshtrace;
using namespace meshtrace::bench;

namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Brute force gets about this many seconds per measurement (a strided
// subset of the rays), and a full render only when it would end within
// kSlowRenderLimit.
constexpr double kSubsetSeconds = 0.5;
constexpr double kSlowRenderLimit = 30.0;
// Whole runs of each engine, alternating, for the full-run figure: single
// runs of a ~70 ms scene spread over half their time, so fewer runs let a
// scene's median move by a tenth between benches of the same code. The
// runs of a scene are spread over rounds through all scenes, seconds
// apart, so that one slow spell of the shared machine cannot cover all of
// a scene's runs.
constexpr int kFullRunRounds = 3;
constexpr int kFullRunsPerRound = 7;

double median(std::vector<double> v) {
  std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
  return v[v.size() / 2];
}

// Mrays/s on 1 thread, on all.
struct Throughput {
  double primary[2] = {0, 0};        // ray by ray (Embree: rtcIntersect1)
  double primaryPacket[2] = {0, 0};  // 2x2 quads (Embree: rtcIntersect4)
  double shadow[2] = {0, 0};
  // Bounces off the primary hits (rays.h), ray by ray on 1 thread.
  double mirror = 0, hemisphere = 0;
};

struct EngineFigures {
  std::optional<double> buildMs, bytesPerTriangle, renderMs;
  std::optional<double> structureBytesPerTriangle;  // without the mesh's own arrays
  Throughput rays;
  bool measured = false;
};

struct SceneFigures {
  std::filesystem::path file;
  std::string name;
  std::size_t triangles = 0;
  double loadMs = 0;
  EngineFigures ours, embree, embreeHq, aabb, none;
  std::size_t verifiedRays = 0, differences = 0;
  // The median of the full runs' ratios, ours / Embree-backed, run by run:
  // a run and the one after it share the machine's spell.
  std::optional<double> fullRunPairedRatio;
};

// Mrays/s for `trace` over the whole set (or every stride-th ray).
template <typename Trace>
double mrays(std::size_t n, std::size_t stride, int threads, const Trace& trace) {
  const double s = timeRays(n, stride, threads, 3, trace);
  return double((n + stride - 1) / stride) / s * 1e-6;
}

std::size_t meshBytes(const Scene& scene) {
  std::size_t b = 0;
  for (const Mesh& m : scene.meshes)
    b += m.vertices().size() * sizeof(Vec3) + m.triangles().size() * sizeof(TriangleIndices);
  return b;
}

TraceOptions withAccel(AccelMethod m) {
  TraceOptions o;
  o.accel = m;
  return o;
}

// One ray of each set through our intersector, as the timers call it.
auto oursPrimary(const SceneIntersector& is, const RaySet& primary) {
  return [&is, &primary](std::size_t i) {
    Hit hit;
    Counters c;
    is.closestHit(primary.rays[i], 0.0, hit, c);
  };
}
// Call k: packet k, or past the packets one leftover ray (RaySet::packets).
auto oursPrimaryPackets(const SceneIntersector& is, const RaySet& primary) {
  return [&is, &primary](std::size_t k) {
    Counters c;
    if (k < primary.packets) {
      Hit hits[kPacketSize];
      bool found[kPacketSize];
      is.closestHitPacket(&primary.rays[kPacketSize * k], 0.0, hits, found, c);
    } else {
      Hit hit;
      is.closestHit(primary.rays[k + (kPacketSize - 1) * primary.packets], 0.0, hit, c);
    }
  };
}
// A spawned closest-hit ray (a bounce), leaving its primitive.
auto oursBounce(const SceneIntersector& is, const RaySet& bounce) {
  return [&is, &bounce](std::size_t i) {
    Hit hit;
    Counters c;
    is.closestHit(bounce.rays[i], 0.0, hit, c, bounce.startOf(i));
  };
}
auto oursShadow(const SceneIntersector& is, const RaySet& shadow) {
  return [&is, &shadow](std::size_t i) {
    Counters c;
    is.occluded(shadow.rays[i], 0.0, shadow.tMax[i], c, shadow.startOf(i));
  };
}

// The slow methods alone, on every stride-th ray.
void measureSlow(const SceneIntersector& is, const RaySet& primary, const RaySet& shadow,
                 std::size_t stride, int threads, Throughput& out) {
  for (int k = 0; k < 2; ++k) {
    const int t = k == 0 ? 1 : threads;
    out.primary[k] = mrays(primary.rays.size(), stride, t, oursPrimary(is, primary));
    out.shadow[k] = mrays(shadow.rays.size(), stride, t, oursShadow(is, shadow));
  }
}

// A way of tracing a ray set: trace(k) for every k < calls.
template <typename Trace>
struct Tracer {
  std::size_t calls;
  Trace trace;
};
template <typename Trace>
Tracer(std::size_t, Trace) -> Tracer<Trace>;

// Mrays/s of each tracer over the same n rays, best of kSideBySidePasses
// passes taken in turn (the first engine, the second, ..., the first
// again), so that a slow spell of this shared machine falls on every engine
// alike.
constexpr int kSideBySidePasses = 5;
template <typename... Trace>
std::array<double, sizeof...(Trace)> interleavedMrays(std::size_t n, int threads,
                                                      const Tracer<Trace>&... tracer) {
  std::array<double, sizeof...(Trace)> best;
  best.fill(1e300);
  for (int pass = 0; pass < kSideBySidePasses; ++pass) {
    std::size_t k = 0;
    ((best[k] = std::min(best[k], timeRays(tracer.calls, 1, threads, 1, tracer.trace)), ++k), ...);
  }
  for (double& s : best) s = double(n) / s * 1e-6;
  return best;
}

std::vector<RTCRayHit> embreeRays(const RaySet& set) {
  std::vector<RTCRayHit> out;
  out.reserve(set.rays.size());
  for (std::size_t i = 0; i < set.rays.size(); ++i)
    out.push_back(EmbreeIntersector::prepare(set.rays[i], 0.0, set.tMax[i]));
  return out;
}

// Each engine's closest hits, ray by ray (Embree: rtcIntersect1), on one
// thread: Mrays/s of ours, Embree robust and Embree HQ.
std::array<double, 3> measureClosestHits(const SceneIntersector& ours,
                                         const EmbreeIntersector& robust,
                                         const EmbreeIntersector& hq, const RaySet& set) {
  const std::vector<RTCRayHit> rays = embreeRays(set);
  const auto embree = [&rays](const EmbreeIntersector& e) {
    return [&rays, engine = &e](std::size_t i) {
      RTCRayHit rh = rays[i];
      engine->intersect1(rh);
    };
  };
  const std::size_t n = rays.size();
  return interleavedMrays(n, 1, Tracer{n, oursBounce(ours, set)}, Tracer{n, embree(robust)},
                          Tracer{n, embree(hq)});
}

// Our BVH and both Embree builds on the same rays, side by side.
void measureSideBySide(const SceneIntersector& ours, const EmbreeIntersector& robust,
                       const EmbreeIntersector& hq, const RaySet& primary, const RaySet& shadow,
                       int threads, SceneFigures& f) {
  const std::vector<RTCRayHit> p = embreeRays(primary), s = embreeRays(shadow);
  const auto embreePrimary = [&p](const EmbreeIntersector& e) {
    return [&p, engine = &e](std::size_t i) {
      RTCRayHit rh = p[i];
      engine->intersect1(rh);
    };
  };
  // Packet k as one rtcIntersect4 call, the leftover rays one by one.
  std::vector<RTCRayHit4> p4;
  for (std::size_t k = 0; k < primary.packets; ++k)
    p4.push_back(EmbreeIntersector::pack(&p[kPacketSize * k]));
  const auto embreePackets = [&p, &p4, &primary](const EmbreeIntersector& e) {
    return [&p, &p4, &primary, engine = &e](std::size_t k) {
      alignas(16) static constexpr int kValid[4] = {-1, -1, -1, -1};
      if (k < p4.size()) {
        RTCRayHit4 rh = p4[k];
        engine->intersect4(kValid, rh);
      } else {
        RTCRayHit rh = p[k + (kPacketSize - 1) * primary.packets];
        engine->intersect1(rh);
      }
    };
  };
  const auto embreeShadow = [&s](const EmbreeIntersector& e) {
    return [&s, engine = &e](std::size_t i) {
      RTCRay r = s[i].ray;
      engine->occluded1(r);
    };
  };
  const std::size_t calls = primary.packetCalls();
  for (int k = 0; k < 2; ++k) {
    const int t = k == 0 ? 1 : threads;
    const auto pr = interleavedMrays(
        p.size(), t, Tracer{p.size(), oursPrimary(ours, primary)},
        Tracer{p.size(), embreePrimary(robust)}, Tracer{p.size(), embreePrimary(hq)},
        Tracer{calls, oursPrimaryPackets(ours, primary)}, Tracer{calls, embreePackets(robust)},
        Tracer{calls, embreePackets(hq)});
    const auto sh = interleavedMrays(s.size(), t, Tracer{s.size(), oursShadow(ours, shadow)},
                                     Tracer{s.size(), embreeShadow(robust)},
                                     Tracer{s.size(), embreeShadow(hq)});
    f.ours.rays.primary[k] = pr[0];
    f.embree.rays.primary[k] = pr[1];
    f.embreeHq.rays.primary[k] = pr[2];
    f.ours.rays.primaryPacket[k] = pr[3];
    f.embree.rays.primaryPacket[k] = pr[4];
    f.embreeHq.rays.primaryPacket[k] = pr[5];
    f.ours.rays.shadow[k] = sh[0];
    f.embree.rays.shadow[k] = sh[1];
    f.embreeHq.rays.shadow[k] = sh[2];
  }
}

// aabb and none on a strided subset sized to take about kSubsetSeconds.
std::size_t subsetStride(const SceneIntersector& is, const RaySet& primary) {
  const std::size_t n = primary.rays.size();
  const std::size_t probe = std::max<std::size_t>(1, n / 64);
  const double s = timeRays(n, probe, 1, 1, oursPrimary(is, primary));
  const double perRay = s / double((n + probe - 1) / probe);
  const auto wanted = static_cast<std::size_t>(kSubsetSeconds / std::max(perRay, 1e-9));
  return std::max<std::size_t>(1, n / std::max<std::size_t>(wanted, 1));
}

// BVH hits against brute force on every stride-th ray of both sets.
void verify(const SceneIntersector& bvh, const SceneIntersector& none, const RaySet& primary,
            const RaySet& shadow, std::size_t stride, SceneFigures& f) {
  Counters c;
  for (std::size_t i = 0; i < primary.rays.size(); i += stride) {
    Hit a, b;
    const bool fa = bvh.closestHit(primary.rays[i], 0.0, a, c);
    const bool fb = none.closestHit(primary.rays[i], 0.0, b, c);
    ++f.verifiedRays;
    f.differences +=
        fa != fb ||
        (fa && (a.t != b.t || a.ref.object != b.ref.object || a.ref.triangle != b.ref.triangle));
  }
  for (std::size_t i = 0; i < shadow.rays.size(); i += stride) {
    ++f.verifiedRays;
    f.differences += bvh.occluded(shadow.rays[i], 0.0, shadow.tMax[i], c, shadow.startOf(i)) !=
                     none.occluded(shadow.rays[i], 0.0, shadow.tMax[i], c, shadow.startOf(i));
  }
}

// Nothing for a scene the Embree side cannot trace.
std::optional<SceneFigures> measure(const std::filesystem::path& file,
                                    const std::filesystem::path& outDir, int threads, bool slow) {
  SceneFigures f;
  f.file = file;
  f.name = file.stem().string();
  auto start = Clock::now();
  const Scene scene = loadScene(file);
  f.loadMs = secondsSince(start) * 1e3;
  if (!EmbreeIntersector::supports(scene)) return std::nullopt;
  f.triangles = scene.triangleCount();
  const double tris = double(std::max<std::size_t>(f.triangles, 1));

  start = Clock::now();
  const SceneIntersector ours(scene, TraceOptions{});
  f.ours.buildMs = secondsSince(start) * 1e3;
  const SceneBvhStats& st = *ours.bvhStats();
  f.ours.structureBytesPerTriangle = (st.meshBvhBytes + st.topLevelBytes) / tris;
  f.ours.bytesPerTriangle = *f.ours.structureBytesPerTriangle + meshBytes(scene) / tris;
  const EmbreeIntersector embree(scene, RTC_BUILD_QUALITY_MEDIUM);
  const EmbreeIntersector embreeHq(scene, RTC_BUILD_QUALITY_HIGH);
  f.embree.buildMs = embree.buildSeconds() * 1e3;
  f.embreeHq.buildMs = embreeHq.buildSeconds() * 1e3;
  f.embree.bytesPerTriangle = embree.bytes() / tris;
  f.embreeHq.bytesPerTriangle = embreeHq.bytes() / tris;
  f.embree.structureBytesPerTriangle = embree.builtBytes() / tris;
  f.embreeHq.structureBytesPerTriangle = embreeHq.builtBytes() / tris;

  const RaySet primary = primaryRays(scene);
  const RaySet shadow = shadowRays(scene, ours, primary);
  measureSideBySide(ours, embree, embreeHq, primary, shadow, threads, f);
  for (const Bounce b : {Bounce::Mirror, Bounce::Hemisphere}) {
    const auto mr = measureClosestHits(ours, embree, embreeHq, bounceRays(scene, ours, primary, b));
    double Throughput::*figure =
        b == Bounce::Mirror ? &Throughput::mirror : &Throughput::hemisphere;
    f.ours.rays.*figure = mr[0];
    f.embree.rays.*figure = mr[1];
    f.embreeHq.rays.*figure = mr[2];
  }
  f.ours.measured = f.embree.measured = f.embreeHq.measured = true;

  if (slow) {
    for (AccelMethod m : {AccelMethod::BoundingBox, AccelMethod::None}) {
      EngineFigures& e = m == AccelMethod::None ? f.none : f.aabb;
      const SceneIntersector is(scene, withAccel(m));
      const std::size_t stride = subsetStride(is, primary);
      measureSlow(is, primary, shadow, stride, threads, e.rays);
      e.measured = true;
      if (m == AccelMethod::None) verify(ours, is, primary, shadow, stride, f);
      // A render casts about as many rays as primary plus shadow here.
      const double estimate = primary.rays.size() / (e.rays.primary[1] * 1e6) +
                              shadow.rays.size() / (e.rays.shadow[1] * 1e6);
      if (estimate < kSlowRenderLimit)
        e.renderMs =
            fullRunMs(toString(m), file, outDir / (f.name + "-" + toString(m) + ".png"), threads);
    }
  }
  return f;
}

// The whole runs of ours and the Embree-backed renderer, alternating, in
// rounds through all the scenes (see kFullRunRounds): each engine's median,
// and the median of the ratios of each of our runs to the Embree-backed run
// just after it (the two share the machine's spell).
void measureFullRuns(const std::filesystem::path& outDir, int threads,
                     std::vector<SceneFigures>& all) {
  std::vector<std::vector<double>> ours(all.size()), embree(all.size());
  for (int round = 0; round < kFullRunRounds; ++round)
    for (std::size_t i = 0; i < all.size(); ++i)
      for (int k = 0; k < kFullRunsPerRound; ++k) {
        ours[i].push_back(fullRunMs("bvh", all[i].file, outDir / (all[i].name + ".png"), threads));
        embree[i].push_back(
            fullRunMs("embree", all[i].file, outDir / (all[i].name + "-embree.png"), threads));
      }
  for (std::size_t i = 0; i < all.size(); ++i) {
    std::vector<double> pairRatios;
    for (std::size_t k = 0; k < ours[i].size(); ++k)
      pairRatios.push_back(ours[i][k] / embree[i][k]);
    all[i].ours.renderMs = median(ours[i]);
    all[i].embree.renderMs = median(embree[i]);
    all[i].fullRunPairedRatio = median(pairRatios);
  }
}

std::string cell(std::optional<double> v, const char* format = "%.1f") {
  if (!v) return "–";
  char buf[64];
  std::snprintf(buf, sizeof buf, format, *v);
  return buf;
}
std::string ratio(std::optional<double> a, std::optional<double> b) {
  if (!a || !b || *b == 0.0) return "–";
  return cell(*a / *b, *a / *b < 0.01 ? "%.2g×" : "%.2f×");
}

void printScene(const SceneFigures& f, int threads) {
  std::printf("\n### %s: %zu triangles, loaded in %.1f ms\n\n", f.name.c_str(), f.triangles,
              f.loadMs);
  std::printf(
      "| figure | ours | Embree robust | Embree HQ | ours / robust | ours / HQ | aabb "
      "(/ robust) | none (/ robust) |\n|---|---:|---:|---:|---:|---:|---:|---:|\n");
  const auto row = [&](const char* label, auto get, const char* format) {
    const auto v = [&](const EngineFigures& e) { return get(e); };
    const auto slowCell = [&](const EngineFigures& e) {
      const auto x = v(e);
      return x ? cell(x, format) + " (" + ratio(x, v(f.embree)) + ")" : std::string("–");
    };
    std::printf("| %s | %s | %s | %s | %s | %s | %s | %s |\n", label,
                cell(v(f.ours), format).c_str(), cell(v(f.embree), format).c_str(),
                cell(v(f.embreeHq), format).c_str(), ratio(v(f.ours), v(f.embree)).c_str(),
                ratio(v(f.ours), v(f.embreeHq)).c_str(), slowCell(f.aabb).c_str(),
                slowCell(f.none).c_str());
  };
  using E = EngineFigures;
  using O = std::optional<double>;
  row(
      "build ms", [](const E& e) { return e.buildMs; }, "%.1f");
  row(
      "bytes / triangle, structure", [](const E& e) { return e.structureBytesPerTriangle; },
      "%.1f");
  row(
      "bytes / triangle, with the mesh", [](const E& e) { return e.bytesPerTriangle; }, "%.1f");
  const std::string all = std::to_string(threads) + " threads";
  const auto mr = [](const E& e, double v) { return e.measured ? O(v) : O(); };
  row(
      "primary Mrays/s, 1 thread, ray by ray", [&](const E& e) { return mr(e, e.rays.primary[0]); },
      "%.3g");
  row(("primary Mrays/s, " + all + ", ray by ray").c_str(),
      [&](const E& e) { return mr(e, e.rays.primary[1]); }, "%.3g");
  const auto packets = [](const E& e) { return e.rays.primaryPacket[0] > 0; };
  row(
      "primary Mrays/s, 1 thread, 2x2 packets",
      [&](const E& e) { return packets(e) ? O(e.rays.primaryPacket[0]) : O(); }, "%.3g");
  row(("primary Mrays/s, " + all + ", 2x2 packets").c_str(),
      [&](const E& e) { return packets(e) ? O(e.rays.primaryPacket[1]) : O(); }, "%.3g");
  row(
      "shadow Mrays/s, 1 thread", [&](const E& e) { return mr(e, e.rays.shadow[0]); }, "%.3g");
  row(("shadow Mrays/s, " + all).c_str(), [&](const E& e) { return mr(e, e.rays.shadow[1]); },
      "%.3g");
  const auto bounce = [](double v) { return v > 0 ? O(v) : O(); };
  row(
      "mirror bounce Mrays/s, 1 thread, ray by ray",
      [&](const E& e) { return bounce(e.rays.mirror); }, "%.3g");
  row(
      "hemisphere bounce Mrays/s, 1 thread, ray by ray",
      [&](const E& e) { return bounce(e.rays.hemisphere); }, "%.3g");
  row(
      "full run ms (load, build, render, write)", [](const E& e) { return e.renderMs; }, "%.0f");
  if (f.verifiedRays)
    std::printf("\nBVH against brute force on %zu of these rays: %zu differ.\n", f.verifiedRays,
                f.differences);
}

void printSummary(const std::vector<SceneFigures>& all) {
  std::printf(
      "\n### Summary: ours / Embree robust (build, memory, time: lower is better; "
      "Mrays/s: higher is better)\n\n"
      "Primary rays: ours in 2x2 packets, as the renderer traces them, against "
      "rtcIntersect1; then ours ray by ray against rtcIntersect1, and both engines' "
      "packets (ours against rtcIntersect4).\n\n"
      "| scene | triangles | load ms | build | B/tri structure | B/tri with mesh | "
      "primary 1T | primary all | primary 1T ray by ray | primary 1T packets, both | "
      "shadow 1T | shadow all | full run | full run, paired | primary 1T vs HQ | "
      "aabb→bvh primary 1T |\n"
      "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const SceneFigures& f : all) {
    const auto& o = f.ours;
    const auto& e = f.embree;
    std::printf(
        "| %s | %zu | %.0f | %s | %s (%s) | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s | %s "
        "|\n",
        f.name.c_str(), f.triangles, f.loadMs, ratio(o.buildMs, e.buildMs).c_str(),
        cell(o.structureBytesPerTriangle).c_str(),
        ratio(o.structureBytesPerTriangle, e.structureBytesPerTriangle).c_str(),
        ratio(o.bytesPerTriangle, e.bytesPerTriangle).c_str(),
        ratio(o.rays.primaryPacket[0], e.rays.primary[0]).c_str(),
        ratio(o.rays.primaryPacket[1], e.rays.primary[1]).c_str(),
        ratio(o.rays.primary[0], e.rays.primary[0]).c_str(),
        ratio(o.rays.primaryPacket[0], e.rays.primaryPacket[0]).c_str(),
        ratio(o.rays.shadow[0], e.rays.shadow[0]).c_str(),
        ratio(o.rays.shadow[1], e.rays.shadow[1]).c_str(), ratio(o.renderMs, e.renderMs).c_str(),
        cell(f.fullRunPairedRatio, "%.2f×").c_str(),
        ratio(o.rays.primaryPacket[0], f.embreeHq.rays.primary[0]).c_str(),
        f.aabb.measured ? ratio(o.rays.primary[0], f.aabb.rays.primary[0]).c_str() : "–");
  }
  std::printf(
      "\nBounces off the primary hits, ray by ray on 1 thread (ours against rtcIntersect1): "
      "the mirror direction, and a direction uniform over the hemisphere.\n\n"
      "| scene | mirror / robust | mirror / HQ | hemisphere / robust | hemisphere / HQ |\n"
      "|---|---:|---:|---:|---:|\n");
  for (const SceneFigures& f : all) {
    const Throughput &o = f.ours.rays, &e = f.embree.rays, &hq = f.embreeHq.rays;
    std::printf("| %s | %s | %s | %s | %s |\n", f.name.c_str(), ratio(o.mirror, e.mirror).c_str(),
                ratio(o.mirror, hq.mirror).c_str(), ratio(o.hemisphere, e.hemisphere).c_str(),
                ratio(o.hemisphere, hq.hemisphere).c_str());
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App cli{"Benchmark our BVH against Embree 3 (see BENCHMARKS.md)."};
  std::vector<std::string> scenes;
  std::string makeScene, makeKnot, meshLoad, outDir = "bench-data/out";
  std::size_t knotTriangles = 1'000'000;
  int threads = static_cast<int>(std::thread::hardware_concurrency());
  bool fast = false, crossover = false;
  cli.add_option("scenes", scenes, "Scene files to measure");
  cli.add_option("--threads", threads, "Threads for the 'all threads' figures")
      ->capture_default_str();
  cli.add_flag("--fast", fast, "Skip the aabb and none measurements");
  cli.add_option("--out", outDir, "Folder for the rendered images")->capture_default_str();
  cli.add_option("--make-scene", makeScene, "Write MESH.sce framing MESH.off, and exit");
  cli.add_option("--make-knot", makeKnot, "Write a generated torus knot OFF, and exit");
  cli.add_option("--triangles", knotTriangles, "Triangles of --make-knot")->capture_default_str();
  cli.add_option("--mesh-load", meshLoad,
                 "Time loading MESH.off and the same mesh as PLY and STL, and exit");
  cli.add_flag("--crossover", crossover, "Measure the mesh size at which a BVH pays, and exit");
  // The child process of a whole-run measurement (full_run.h).
  std::string fullRun, image;
  cli.add_option("--full-run", fullRun)->group("");
  cli.add_option("--image", image)->group("");
  CLI11_PARSE(cli, argc, argv);

  try {
    if (!fullRun.empty()) {
      if (scenes.size() != 1 || image.empty())
        throw std::runtime_error("--full-run takes one scene and --image");
      std::printf("%.3f\n", fullRunHereMs(fullRun, scenes[0], image, threads));
      return 0;
    }
    if (!makeKnot.empty()) {
      writeKnot(makeKnot, knotTriangles);
      return 0;
    }
    if (!makeScene.empty()) {
      writeMeshScene(makeScene, std::filesystem::path(makeScene).replace_extension(".sce"));
      return 0;
    }
    if (!meshLoad.empty()) {
      printMeshLoadTimes(meshLoad);
      return 0;
    }
    if (crossover) {
      printCrossover();
      return 0;
    }
    std::filesystem::create_directories(outDir);
    std::vector<SceneFigures> all;
    for (const std::string& s : scenes) {
      std::fprintf(stderr, "bench: measuring %s\n", s.c_str());
      if (std::optional<SceneFigures> f = measure(s, outDir, threads, !fast))
        all.push_back(std::move(*f));
      else
        std::printf("\n(skipping %s: spheres or cylinders, which the Embree side lacks)\n",
                    s.c_str());
    }
    std::fprintf(stderr, "bench: whole runs, %d rounds through the scenes\n", kFullRunRounds);
    measureFullRuns(outDir, threads, all);
    for (const SceneFigures& f : all) printScene(f, threads);
    printSummary(all);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 1;
  }
  return 0;
}
