// Render progress and timings, the view, overlay and anti-aliasing controls,
// and the legend of the heat maps shown.
#include <imgui.h>

#include "meshtrace/render/inspect.h"
#include "viewer/model/render_progress.h"
#include "viewer/ui/panels.h"

namespace meshtrace::viewer {

namespace {
std::string ms(const ViewerState& state, double v) {
  if (state.options.hideTimings) return "-";
  return v < 0 ? "..." : formatMs(v);
}

std::string ms(const ViewerState& state, std::optional<double> v) {
  return state.options.hideTimings ? "-" : formatMs(v);
}

// A combo of an option's values, named as the command line names them.
template <typename Value>
void choose(const char* title, Value& value, std::initializer_list<Value> values) {
  ImGui::SetNextItemWidth(200);
  if (!ImGui::BeginCombo(title, toString(value))) return;
  for (Value v : values)
    if (ImGui::Selectable(toString(v), v == value)) value = v;
  ImGui::EndCombo();
}
}  // namespace

void drawRenderPanel(ViewerState& state, RenderDisplay& display) {
  const ProgressiveStatus s = display.status();
  if (display.active()) {
    char overlayText[96];
    const bool preview = display.renderScene() && display.renderScene()->preview;
    if (preview)
      std::snprintf(
          overlayText, sizeof overlayText, "%s",
          s.finished ? "preview: first pass, while the scene is made" : "preview: first pass");
    else if (s.exactDone && s.finished)
      std::snprintf(overlayText, sizeof overlayText, "exact, %d sample%s per pixel",
                    s.samplesPerPixel, s.samplesPerPixel == 1 ? "" : "s");
    else if (s.exactDone) {
      const std::optional<double> left = aaTimeLeftMs(s);
      std::snprintf(overlayText, sizeof overlayText, "AA: %d of %d samples%s%s", s.samplesPerPixel,
                    1 + state.extraSamples, left ? ", " : "",
                    left ? (ms(state, *left) + " left").c_str() : "");
    } else
      std::snprintf(overlayText, sizeof overlayText, "pass %d of %d, %.0f%%", s.passesDone + 1,
                    s.passCount, 100.0 * s.exactFraction);
    const float fraction = s.passCount > 0 ? float(s.passesDone) / float(s.passCount) : 0.0f;
    const std::string barText =
        display.paused() ? std::string("paused, ") + overlayText : std::string(overlayText);
    ImGui::ProgressBar(s.finished ? 1.0f : std::max(fraction, float(s.exactFraction) * 0.999f),
                       ImVec2(-1, 0), barText.c_str());
    const std::uint64_t rays =
        s.counters.primaryRays + s.counters.shadowRays + s.counters.reflectionRays;
    const double seconds = s.elapsedMs / 1000.0;
    char raysPerSecond[64] = "rays/s -";
    if (!state.options.hideTimings)
      std::snprintf(raysPerSecond, sizeof raysPerSecond, "%.2f M rays/s",
                    seconds > 0 ? rays / seconds / 1e6 : 0.0);
    textFields({"elapsed " + ms(state, s.elapsedMs), raysPerSecond});
    // Shown times count from the user's action (opening the scene, a
    // change), not from the render's start: what the user waits.
    const ShownTimes& shown = display.shownTimes();
    textFields({"load " + ms(state, state.timing.loadMs),
                "first image " + ms(state, shown.firstImageMs),
                "exact " + ms(state, shown.exactImageMs)});
    const FrameStats& frames = state.timing.renderingFrames;
    textFields({std::to_string(display.threads()) + " threads", std::to_string(rays) + " rays"});
    textFields({"frames while rendering:", "longest " + ms(state, frames.longest()),
                "99% " + ms(state, frames.percentile(99.0))});
  }
  ImGui::SetNextItemWidth(200);
  if (ImGui::BeginCombo("view", label(state.view))) {
    for (int i = 0; i < kViewCount; ++i) {
      const View v = static_cast<View>(i);
      if (ImGui::Selectable(label(v), v == state.view)) state.view = v;
    }
    ImGui::EndCombo();
  }
  ImGui::SetNextItemWidth(200);
  static const char* overlayLabels[kOverlayCount] = {"none", "box hits", "traversal cost"};
  int overlay = static_cast<int>(state.overlay);
  if (ImGui::Combo("overlay", &overlay, overlayLabels, kOverlayCount))
    state.overlay = static_cast<Overlay>(overlay);
  if (state.overlay != Overlay::None) {
    ImGui::SetNextItemWidth(200);
    ImGui::SliderFloat("opacity", &state.opacity, 0.0f, 1.0f, "%.2f");
  }
  ImGui::SetNextItemWidth(200);
  ImGui::SliderInt("AA samples", &state.extraSamples, 0, 16);
  // As raytrace's --triangle, --precision and --accel: each makes a new
  // render scene in the background.
  TraceOptions& trace = state.trace;
  choose("triangle test", trace.triangle.test,
         {TriangleTest::Watertight, TriangleTest::Cramer, TriangleTest::MollerTrumbore});
  choose("precision", trace.triangle.precision, {Precision::Double, Precision::Single});
  choose("acceleration", trace.accel,
         {AccelMethod::Bvh, AccelMethod::BoundingBox, AccelMethod::None});
  const FalseColorScales& scales = display.scales();
  const bool boxes = state.view == View::BoxHits || state.overlay == Overlay::BoxHits;
  const bool cost = state.view == View::BvhCost || state.overlay == Overlay::BvhCost;
  if (boxes)
    drawHeatLegend(state, "mesh boxes the primary ray meets (most in the image)", scales.boxMax,
                   "boxes", true);
  if (cost)
    drawHeatLegend(state, "nodes + boxes + primitives tested (primary ray)", scales.costMax,
                   "tests");
  if (state.overlay != Overlay::None)
    ImGui::TextDisabled("The overlay leaves pixels with a count of 0 clear.");
  if (state.view == View::NormalDeviation)
    drawHeatLegend(state, "vertex normal vs OpenMesh, interpolated", scales.deviationMax, "deg");
  if (state.view == View::Depth) drawDepthLegend(state, scales);
}

}  // namespace meshtrace::viewer
