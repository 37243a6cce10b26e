#pragma once
// What a pixel holds in every view, for the readout under the image: its
// colour, and the primary ray's depth, normal, object, triangle and face, box
// count, traversal cost and normal deviation, whichever view is shown.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "meshtrace/render/progressive.h"
#include "viewer/model/views.h"

namespace meshtrace::viewer {

struct PixelReadout {
  int x = 0, y = 0;                         // image pixel, y = 0 the bottom row
  std::optional<std::array<int, 3>> color;  // as rendered (8-bit), where the render has it
  PixelProbe probe;                         // the primary ray, as the probe views see it
  FaceOfTriangle face;                      // of the mesh's file, for a mesh's triangle
  double deviationDegrees = -1.0;           // -1: not known (no cross-check, or not a mesh)
};

// Probes pixel (x, y) through `scene` and `camera` (a cheap query: one
// primary ray) and takes the rendered colour from `frame`.
PixelReadout readPixel(const PreparedScene& scene, const Camera& camera,
                       const ProgressiveFrame& frame, int x, int y, const FalseColorScales& scales);

// The readout as short "name value" fields; `describe` names a hit object
// (e.g. "mesh 'ball' #0").
std::vector<std::string> readoutFields(
    const PixelReadout& r, const std::function<std::string(const PixelProbe&)>& describe);

}  // namespace meshtrace::viewer
