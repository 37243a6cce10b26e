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
  double depthNear = 0.0, depthFar = 1.0;  // robust percentiles of the hits (heat_scales.h)
  // Depths at evenly spaced shares of the hits, from depthNear to depthFar:
  // a depth is drawn by its share of hits nearer (an equalised scale, so
  // that objects stand out of a floor that runs to the horizon).
  std::vector<double> depthQuantiles;
  double boxMax = 1.0;        // the most mesh boxes a primary ray meets
  double costMax = 1.0;       // the largest traversal cost
  double deviationMax = 1.0;  // degrees at the top of the scale
  // Per mesh of the rendered scene, the deviation of each vertex normal from
  // OpenMesh's, in degrees (-1: not compared); null when not computed.
  std::vector<const std::vector<float>*> meshDeviation;
  const Scene* scene = nullptr;  // the rendered scene, for the deviation view
};

inline constexpr double kMissGrey = 0.12;

// The colour of a pixel in a probe view; misses are dark grey (in the
// views of counts, a miss has its count like any ray).
Color falseColor(View view, const PixelProbe& probe, const FalseColorScales& scales);
// An overlay's value on [0, 1] (its heat colour's position), and whether it
// covers the pixel at all: a count of zero leaves the image beneath clear.
double overlayValue(Overlay overlay, const PixelProbe& probe, const FalseColorScales& scales);
bool overlayCovers(Overlay overlay, const PixelProbe& probe);
// Whether the view or the overlay is coloured by the measured ranges.
bool usesScales(View view, Overlay overlay);

// Where `depth` lies on the depth scale, 0 (near) to 1 (far).
double depthPosition(double depth, const FalseColorScales& scales);

// The deviation at a hit, interpolated over the triangle's corners; negative
// when unknown.
double deviationAt(const PixelProbe& probe, const FalseColorScales& scales);

}  // namespace meshtrace::viewer
