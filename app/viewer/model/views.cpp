#include "viewer/model/views.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "meshtrace/render/inspect_colors.h"
#include "meshtrace/util/enum_names.h"

namespace meshtrace::viewer {

namespace {
// An EnumName with a label for the UI.
struct ViewInfo {
  View value;
  const char* name;
  const char* label;
};
constexpr std::array<ViewInfo, kViewCount> kViews{{
    {View::Color, "color", "Colour"},
    {View::Normals, "normals", "Normals"},
    {View::Depth, "depth", "Depth"},
    {View::ObjectId, "object", "Object id"},
    {View::TriangleId, "triangle", "Triangle id"},
    {View::BoxHits, "boxes", "Box hits (heat)"},
    {View::BvhCost, "cost", "Traversal cost (heat)"},
    {View::NormalDeviation, "deviation", "Normal deviation vs OpenMesh"},
    {View::SideBySide, "side-by-side", "Reference side by side"},
    {View::Difference, "difference", "Difference to reference"},
}};
constexpr std::array<EnumName<Overlay>, kOverlayCount> kOverlays{
    {{Overlay::None, "none"}, {Overlay::BoxHits, "boxes"}, {Overlay::BvhCost, "cost"}}};
}  // namespace

const char* name(View view) { return nameIn(kViews, view); }
const char* label(View view) { return kViews[static_cast<int>(view)].label; }
const char* name(Overlay overlay) { return nameIn(kOverlays, overlay); }

std::optional<View> parseView(std::string_view n) { return valueNamed(kViews, n); }
std::optional<Overlay> parseOverlay(std::string_view n) { return valueNamed(kOverlays, n); }

bool needsProbes(View view) {
  return view != View::Color && view != View::SideBySide && view != View::Difference;
}
bool needsProbes(Overlay overlay) { return overlay != Overlay::None; }

double overlayValue(Overlay overlay, const PixelProbe& probe, const FalseColorScales& scales) {
  switch (overlay) {
    case Overlay::BoxHits: return scales.boxMax > 0 ? probe.boxHits / scales.boxMax : 0.0;
    case Overlay::BvhCost: return scales.costMax > 0 ? probe.cost / scales.costMax : 0.0;
    case Overlay::None: break;
  }
  return 0.0;
}

bool overlayCovers(Overlay overlay, const PixelProbe& probe) {
  switch (overlay) {
    case Overlay::BoxHits: return probe.boxHits > 0;
    case Overlay::BvhCost: return probe.cost > 0;
    case Overlay::None: break;
  }
  return false;
}

bool usesScales(View view, Overlay overlay) {
  return view == View::Depth || view == View::BoxHits || view == View::BvhCost ||
         overlay != Overlay::None;
}

double depthPosition(double depth, const FalseColorScales& s) {
  const std::vector<double>& q = s.depthQuantiles;
  if (q.size() < 2) {
    const double span = s.depthFar - s.depthNear;
    return span > 0.0 ? std::clamp((depth - s.depthNear) / span, 0.0, 1.0) : 0.0;
  }
  if (depth <= q.front()) return 0.0;
  if (depth >= q.back()) return 1.0;
  const std::size_t i =
      std::upper_bound(q.begin(), q.end(), depth) - q.begin();  // q[i-1] <= d < q[i]
  const double within = q[i] > q[i - 1] ? (depth - q[i - 1]) / (q[i] - q[i - 1]) : 0.0;
  return (double(i - 1) + within) / double(q.size() - 1);
}

double deviationAt(const PixelProbe& probe, const FalseColorScales& scales) {
  if (!scales.scene || !probe.hit() || probe.kind != ObjectKind::Mesh ||
      probe.index >= scales.meshDeviation.size())
    return -1.0;
  const std::vector<float>* dev = scales.meshDeviation[probe.index];
  if (!dev) return -1.0;
  const auto& tri = scales.scene->meshes[probe.index].triangles()[probe.triangle];
  const double w[3] = {1.0 - probe.beta - probe.gamma, probe.beta, probe.gamma};
  double d = 0.0;
  for (int k = 0; k < 3; ++k) {
    const float v = (*dev)[tri[k]];
    if (v < 0.0f) return -1.0;
    d += w[k] * v;
  }
  return d;
}

Color falseColor(View view, const PixelProbe& p, const FalseColorScales& s) {
  switch (view) {
    case View::BoxHits: return heatColor(overlayValue(Overlay::BoxHits, p, s));
    case View::BvhCost: return heatColor(overlayValue(Overlay::BvhCost, p, s));
    default: break;
  }
  if (!p.hit()) return Color(kMissGrey);
  switch (view) {
    case View::Normals: return normalColor(Vec3(p.normal[0], p.normal[1], p.normal[2]));
    case View::Depth: return depthColor(depthPosition(p.depth, s), 0.0, 1.0);
    case View::ObjectId: return idColor(static_cast<std::uint32_t>(p.object));
    case View::TriangleId:
      return p.kind == ObjectKind::Mesh ? idColor(p.triangle * 7919u + p.index) : Color(0.35);
    case View::NormalDeviation: {
      const double d = deviationAt(p, s);
      return d < 0.0 ? Color(0.35) : heatColor(s.deviationMax > 0.0 ? d / s.deviationMax : 0.0);
    }
    default: break;
  }
  return Color(kMissGrey);
}

}  // namespace meshtrace::viewer
