#include "meshtrace/render/render.h"

#include <algorithm>

#include "meshtrace/render/integrator.h"
#include "util/parallel_tiles.h"

namespace meshtrace {

Image render(const Scene& scene, const RenderOptions& options, Counters* counters) {
  return render(SceneIntersector(scene, options.trace), options.threads, counters);
}

Image render(const SceneIntersector& intersector, int threads, Counters* counters) {
  return render(intersector, intersector.scene().camera, threads, counters);
}

Image render(const SceneIntersector& intersector, const Camera& camera, int threads,
             Counters* counters) {
  const Integrator integrator(intersector);
  Image image(camera.width(), camera.height());
  const int width = image.width, height = image.height;
  // Pixels go in 2x2 quads whose primary rays are traced together
  // (Integrator::quad), in fixed tiles of kTileQuads x kTileQuads quads,
  // each with LastBlockers of its own: what the quads of a tile carry from
  // one to the next, and so the work done, does not depend on the thread
  // count. The quads sit on even storage rows and columns; a quad cut by
  // the image's edge goes pixel by pixel.
  constexpr int kTileQuads = 8;
  const int quadsX = (width + 1) / 2, quadsY = (height + 1) / 2;
  const auto quadsOfTile = [&](int tileRow, int tileCol, Counters& c) {
    LastBlockers blockers(intersector.scene());
    for (int qr = tileRow * kTileQuads; qr < std::min((tileRow + 1) * kTileQuads, quadsY); ++qr)
      for (int qc = tileCol * kTileQuads; qc < std::min((tileCol + 1) * kTileQuads, quadsX); ++qc) {
        const int row = 2 * qr, x = 2 * qc;
        if (row + 1 < height && x + 1 < width) {
          Color quad[kPacketSize];
          integrator.quad(camera, x, flippedRow(row + 1, height), quad, c, &blockers);
          image.at(x, row + 1) = quad[0];
          image.at(x + 1, row + 1) = quad[1];
          image.at(x, row) = quad[2];
          image.at(x + 1, row) = quad[3];
          continue;
        }
        for (int r = row; r < std::min(row + 2, height); ++r)
          for (int px = x; px < std::min(x + 2, width); ++px)
            image.at(px, r) = integrator.pixel(camera, px, flippedRow(r, height), c, &blockers);
      }
  };
  const Counters total = forEachTile((quadsX + kTileQuads - 1) / kTileQuads,
                                     (quadsY + kTileQuads - 1) / kTileQuads, 1, threads,
                                     [&](const tbb::blocked_range<int>& tileRows,
                                         const tbb::blocked_range<int>& tileCols, Counters& c) {
                                       for (int tr = tileRows.begin(); tr < tileRows.end(); ++tr)
                                         for (int tc = tileCols.begin(); tc < tileCols.end(); ++tc)
                                           quadsOfTile(tr, tc, c);
                                     });
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
  forEachTile(
      out.width, out.height, 16, threads,
      [&](const tbb::blocked_range<int>& rows, const tbb::blocked_range<int>& cols, Counters&) {
        for (int row = rows.begin(); row < rows.end(); ++row)
          for (int x = cols.begin(); x < cols.end(); ++x)
            out.counts[static_cast<std::size_t>(row) * out.width + x] =
                boxHitCount(scene, scene.camera.primaryRay(x, flippedRow(row, out.height)));
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
