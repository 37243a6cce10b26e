#pragma once
// The viewer's views and overlays, and the false colour of a pixel in each.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "meshtrace/render/inspect.h"

namespace meshtrace::viewer {

enum class View {
  Color,
  Normals,
  Depth,
  ObjectId,
  TriangleId,
  BoxHits,
  BvhCost,
  NormalDeviation,
  SideBySide,
  Difference
};
inline constexpr int kViewCount = 10;

enum class Overlay { None, BoxHits, BvhCost };
inline constexpr int kOverlayCount = 3;

const char* name(View view);   // command-line name, e.g. "normals"
const char* label(View view);  // for the UI
const char* name(Overlay overlay);
std::optional<View> parseView(std::string_view name);
std::optional<Overlay> parseOverlay(std::string_view name);

// Views drawn from PixelProbes rather than colours.
bool needsProbes(View view);
bool needsProbes(Overlay overlay);

struct FalseColorScales {
  double depthNear = 0.0, depthFar = 1.0;
  double boxMax = 1.0;        // the number of meshes
  double costMax = 1.0;       // the largest traversal cost seen
  double deviationMax = 1.0;  // degrees at the top of the scale
  // Per mesh of the rendered scene, the deviation of each vertex normal from
  // OpenMesh's, in degrees (-1: not compared); null when not computed.
  std::vector<const std::vector<float>*> meshDeviation;
  const Scene* scene = nullptr;  // the rendered scene, for the deviation view
};

inline constexpr double kMissGrey = 0.12;

// The colour of a pixel in a probe view; misses are dark grey.
Color falseColor(View view, const PixelProbe& probe, const FalseColorScales& scales);
// The heat colour of an overlay, and its value on [0, 1].
double overlayValue(Overlay overlay, const PixelProbe& probe, const FalseColorScales& scales);

// The deviation at a hit, interpolated over the triangle's corners; negative
// when unknown.
double deviationAt(const PixelProbe& probe, const FalseColorScales& scales);

}  // namespace meshtrace::viewer
