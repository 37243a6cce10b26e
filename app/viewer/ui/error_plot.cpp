// The compare panel's plot: the error of each pass against the reference,
// over the time each pass was complete (or over the pass number when
// timings are hidden), with labelled axes. Drawn by hand: ImGui's
// PlotLines has no axes, and in Debian's 1.86 a width of -1 draws nothing.
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "viewer/ui/panels.h"

namespace meshtrace::viewer {

namespace {
constexpr float kPlotHeight = 120.0f;
constexpr float kLeftMargin = 46.0f, kBottomMargin = 34.0f, kTopMargin = 4.0f, kRightMargin = 10.0f;

// The smallest of 1, 2, 5 x 10^k at or above `v` (> 0).
double niceCeiling(double v) {
  if (!(v > 0.0)) return 1.0;
  const double p = std::pow(10.0, std::floor(std::log10(v)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= v * (1.0 - 1e-12)) return m * p;
  return 10.0 * p;
}

std::string tick(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}
}  // namespace

void drawErrorPlot(ViewerState& state, const std::vector<PassError>& points) {
  const bool byPass = state.options.hideTimings;
  ImGui::TextUnformatted("RMSE of each pass against the reference");
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float width = std::max(120.0f, ImGui::GetContentRegionAvail().x);
  ImGui::Dummy(ImVec2(width, kPlotHeight));
  const ImVec2 lo(origin.x + kLeftMargin, origin.y + kTopMargin);
  const ImVec2 hi(origin.x + width - kRightMargin, origin.y + kPlotHeight - kBottomMargin);
  state.regions["plot"] = {lo.x, lo.y, hi.x, hi.y};
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddRectFilled(lo, hi, IM_COL32(30, 32, 38, 255));
  const ImU32 axis = IM_COL32(170, 170, 180, 255), text = IM_COL32(210, 210, 215, 255);
  draw->AddLine(ImVec2(lo.x, hi.y), hi, axis);
  draw->AddLine(lo, ImVec2(lo.x, hi.y), axis);
  const auto xOf = [&](const PassError& p) { return byPass ? double(p.pass + 1) : p.ms; };
  double xMax = 0.0, yMax = 0.0;
  for (const PassError& p : points) {
    xMax = std::max(xMax, xOf(p));
    yMax = std::max(yMax, p.rmse);
  }
  // Whole passes end at the last; times and errors at a round number.
  xMax = byPass ? std::max(1.0, xMax) : niceCeiling(xMax);
  yMax = niceCeiling(yMax);
  const auto at = [&](double x, double y) {
    return ImVec2(lo.x + float(x / xMax) * (hi.x - lo.x), hi.y - float(y / yMax) * (hi.y - lo.y));
  };
  // Ticks and their numbers at 0, the middle and the end of each axis.
  for (double f : {0.0, 0.5, 1.0}) {
    const ImVec2 xt = at(f * xMax, 0.0), yt = at(0.0, f * yMax);
    draw->AddLine(xt, ImVec2(xt.x, xt.y + 4), axis);
    draw->AddLine(ImVec2(yt.x - 4, yt.y), yt, axis);
    const std::string xs = tick(f * xMax), ys = tick(f * yMax);
    const ImVec2 xsz = ImGui::CalcTextSize(xs.c_str()), ysz = ImGui::CalcTextSize(ys.c_str());
    draw->AddText(ImVec2(std::min(xt.x - xsz.x / 2, hi.x + kRightMargin - xsz.x), xt.y + 5), text,
                  xs.c_str());
    draw->AddText(ImVec2(yt.x - 6 - ysz.x, std::max(origin.y, yt.y - ysz.y / 2)), text, ys.c_str());
  }
  const char* xLabel = byPass ? "pass" : "ms since the render started";
  const ImVec2 xl = ImGui::CalcTextSize(xLabel);
  draw->AddText(ImVec2((lo.x + hi.x - xl.x) / 2, hi.y + 18), text, xLabel);
  if (points.empty()) {
    const char* wait = "waiting for the first pass";
    const ImVec2 ws = ImGui::CalcTextSize(wait);
    draw->AddText(ImVec2((lo.x + hi.x - ws.x) / 2, (lo.y + hi.y - ws.y) / 2), axis, wait);
    return;
  }
  const ImU32 line = IM_COL32(255, 150, 40, 255), aa = IM_COL32(80, 210, 255, 255);
  for (std::size_t i = 1; i < points.size(); ++i)
    draw->AddLine(at(xOf(points[i - 1]), points[i - 1].rmse), at(xOf(points[i]), points[i].rmse),
                  line, 2.0f);
  for (const PassError& p : points)
    draw->AddCircleFilled(at(xOf(p), p.rmse), 3.5f, p.antiAliasing ? aa : line);
  ImGui::TextDisabled("orange: coarse-to-exact passes; blue: anti-aliasing passes");
}

}  // namespace meshtrace::viewer
