#include "meshtrace/render/layers.h"

#include "meshtrace/render/inspect.h"
#include "meshtrace/render/render.h"
#include "util/parallel_tiles.h"

namespace meshtrace {

ExrImage renderLayers(const SceneIntersector& intersector, int threads) {
  return renderLayers(intersector, intersector.scene().camera, threads);
}

ExrImage renderLayers(const SceneIntersector& intersector, const Camera& camera, int threads) {
  const Image color = render(intersector, camera, threads);
  const int w = color.width, h = color.height;
  const std::size_t pixels = static_cast<std::size_t>(w) * h;
  ExrImage out{w, h, {}};
  const auto floats = [&](const char* name) -> std::vector<float>& {
    out.channels.push_back({name, std::vector<float>(pixels), {}});
    return out.channels.back().floats;
  };
  const auto uints = [&](const char* name) -> std::vector<std::uint32_t>& {
    out.channels.push_back({name, {}, std::vector<std::uint32_t>(pixels)});
    return out.channels.back().uints;
  };
  out.channels.reserve(15);
  std::vector<float>* rgb[3] = {&floats("R"), &floats("G"), &floats("B")};
  std::vector<float>& z = floats("Z");
  std::vector<float>* n[3] = {&floats("N.X"), &floats("N.Y"), &floats("N.Z")};
  std::vector<float>* p[3] = {&floats("P.X"), &floats("P.Y"), &floats("P.Z")};
  std::vector<std::uint32_t>& object = uints("objectId");
  std::vector<std::uint32_t>& triangle = uints("triangleId");
  std::vector<float>& beta = floats("barycentric.B");
  std::vector<float>& gamma = floats("barycentric.C");
  std::vector<std::uint32_t>& cost = uints("traversalCost");
  // Probes go over the image as the render does: in tiles, on `threads`.
  forEachTile(w, h, 16, threads, [&](auto rows, auto cols, Counters&) {
    for (int row = rows.begin(); row < rows.end(); ++row)
      for (int x = cols.begin(); x < cols.end(); ++x) {
        const std::size_t i = static_cast<std::size_t>(row) * w + x;
        const int y = flippedRow(row, h);
        for (int c = 0; c < 3; ++c) (*rgb[c])[i] = static_cast<float>(color.pixels[i][c]);
        const PixelProbe probe = probePixel(intersector, camera, x, y);
        cost[i] = probe.cost;
        if (!probe.hit()) {
          z[i] = std::numeric_limits<float>::infinity();
          object[i] = triangle[i] = kNoHitId;
          continue;
        }
        z[i] = probe.depth;
        const Vec3 point = camera.primaryRay(x, y).at(probe.depth);
        for (int c = 0; c < 3; ++c) {
          (*n[c])[i] = probe.normal[c];
          (*p[c])[i] = static_cast<float>(point[c]);
        }
        object[i] = static_cast<std::uint32_t>(probe.object);
        triangle[i] = probe.kind == ObjectKind::Mesh ? probe.triangle : kNoHitId;
        beta[i] = probe.beta;
        gamma[i] = probe.gamma;
      }
  });
  return out;
}

}  // namespace meshtrace
