#include "meshtrace/render.h"

#include <tbb/blocked_range2d.h>
#include <tbb/combinable.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include "meshtrace/integrator.h"

namespace meshtrace {

namespace {
// Runs body(x, y, row, counters) for every pixel, in 16x16 tiles spread over
// `threads` workers (0: all cores), where y = 0 is the bottom row and `row`
// the storage row (0 at the top).
template <typename Body>
Counters forEachPixel(int width, int height, int threads, const Body& body) {
  tbb::combinable<Counters> perThread;
  const auto run = [&] {
    tbb::parallel_for(tbb::blocked_range2d<int>(0, height, 16, 0, width, 16),
                      [&](const tbb::blocked_range2d<int>& r) {
                        Counters& counters = perThread.local();
                        for (int row = r.rows().begin(); row < r.rows().end(); ++row)
                          for (int x = r.cols().begin(); x < r.cols().end(); ++x)
                            body(x, height - 1 - row, row, counters);
                      });
  };
  if (threads > 0) {
    tbb::task_arena arena(threads);
    arena.execute(run);
  } else {
    run();
  }
  Counters total;
  perThread.combine_each([&](const Counters& c) { total += c; });
  return total;
}
}  // namespace

Image render(const Scene& scene, const RenderOptions& options, Counters* counters) {
  return render(SceneIntersector(scene, options.trace), options.threads, counters);
}

Image render(const SceneIntersector& intersector, int threads, Counters* counters) {
  const Scene& scene = intersector.scene();
  const Integrator integrator(intersector);
  Image image(scene.camera.width(), scene.camera.height());
  const Counters total = forEachPixel(
      image.width, image.height, threads,
      [&](int x, int y, int row, Counters& c) { image.at(x, row) = integrator.pixel(x, y, c); });
  if (counters) *counters += total;
  return image;
}

int boxHitCount(const Scene& scene, const Ray& ray) {
  const RayInverse inverse(ray);
  int n = 0;
  for (const Mesh& mesh : scene.meshes) {
    double tEnter, tExit;
    n += intersectSlabs(mesh.bounds(), inverse, 0.0, kInfinity, tEnter, tExit);
  }
  return n;
}

BoxHitCounts countBoxHits(const Scene& scene, int threads) {
  BoxHitCounts out;
  out.width = scene.camera.width();
  out.height = scene.camera.height();
  out.counts.assign(static_cast<std::size_t>(out.width) * out.height, 0);
  forEachPixel(out.width, out.height, threads, [&](int x, int y, int row, Counters&) {
    out.counts[static_cast<std::size_t>(row) * out.width + x] =
        boxHitCount(scene, scene.camera.primaryRay(x, y));
  });
  for (int n : out.counts) out.maxCount = std::max(out.maxCount, n);
  return out;
}

Image debugAabbImage(const BoxHitCounts& counts) {
  Image image(counts.width, counts.height);
  if (counts.maxCount == 0) return image;
  for (std::size_t i = 0; i < counts.counts.size(); ++i)
    image.pixels[i] = Color(double(counts.counts[i]) / counts.maxCount, 0.0, 0.0);
  return image;
}

}  // namespace meshtrace
