#include "viewer/model/pixel_readout.h"

#include <cstdio>

#include "meshtrace/io/image.h"
#include "viewer/model/face_label.h"

namespace meshtrace::viewer {

PixelReadout readPixel(const PreparedScene& scene, const Camera& camera,
                       const ProgressiveFrame& frame, int x, int y,
                       const FalseColorScales& scales) {
  PixelReadout r;
  r.x = x;
  r.y = y;
  r.probe = probePixel(scene.intersector(), camera, x, y);
  if (r.probe.hit() && r.probe.kind == ObjectKind::Mesh)
    r.face = scene.scene().meshes[r.probe.index].faceOf(r.probe.triangle);
  if (const std::uint8_t* rgba = frame.rgbaAt(x, flippedRow(y, frame.height)))
    r.color = std::array<int, 3>{rgba[0], rgba[1], rgba[2]};
  r.deviationDegrees = deviationAt(r.probe, scales);
  return r;
}

std::vector<std::string> readoutFields(
    const PixelReadout& r, const std::function<std::string(const PixelProbe&)>& describe) {
  std::vector<std::string> out;
  char text[160];
  std::snprintf(text, sizeof text, "(%d, %d)", r.x, r.y);
  out.push_back(text);
  if (r.color) {
    std::snprintf(text, sizeof text, "rgb %d %d %d", (*r.color)[0], (*r.color)[1], (*r.color)[2]);
    out.push_back(text);
  }
  const PixelProbe& p = r.probe;
  if (p.hit()) {
    std::snprintf(text, sizeof text, "depth %.4g", p.depth);
    out.push_back(text);
    std::snprintf(text, sizeof text, "normal (%.3f, %.3f, %.3f)", p.normal[0], p.normal[1],
                  p.normal[2]);
    out.push_back(text);
    std::snprintf(text, sizeof text, "object %d: %s", p.object, describe(p).c_str());
    out.push_back(text);
    if (p.kind == ObjectKind::Mesh)
      out.push_back("triangle " + std::to_string(p.triangle) + faceSuffix(p.triangle, r.face));
  } else {
    out.push_back("miss (background)");
  }
  out.push_back("boxes " + std::to_string(p.boxHits));
  out.push_back("cost " + std::to_string(p.cost));
  if (r.deviationDegrees >= 0.0) {
    std::snprintf(text, sizeof text, "deviation %.3g deg", r.deviationDegrees);
    out.push_back(text);
  }
  return out;
}

}  // namespace meshtrace::viewer
