// The legends of the false-colour views: a colour bar with numbers under it.
#include <imgui.h>

#include "meshtrace/render/inspect_colors.h"
#include "viewer/ui/panels.h"

namespace meshtrace::viewer {

namespace {
ImU32 toImColor(const Color& c) {
  return IM_COL32(int(255 * c.r), int(255 * c.g), int(255 * c.b), 255);
}

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", v);
  return text;
}
}  // namespace

void drawLegend(ViewerState& state, const char* title, const std::function<Color(double)>& colorAt,
                const std::vector<LegendTick>& ticks) {
  ImGui::TextUnformatted(title);
  const ImVec2 p0 = ImGui::GetCursorScreenPos();
  const float width = ImGui::GetContentRegionAvail().x, height = 14.0f;
  ImDrawList* draw = ImGui::GetWindowDrawList();
  constexpr int kSegments = 32;
  for (int i = 0; i < kSegments; ++i) {
    const float x0 = p0.x + width * i / kSegments, x1 = p0.x + width * (i + 1) / kSegments;
    const ImU32 a = toImColor(colorAt(double(i) / kSegments));
    const ImU32 b = toImColor(colorAt(double(i + 1) / kSegments));
    draw->AddRectFilledMultiColor(ImVec2(x0, p0.y), ImVec2(x1, p0.y + height), a, b, b, a);
  }
  ImGui::Dummy(ImVec2(width, height));
  state.regions["legend"] = {p0.x, p0.y, p0.x + width, p0.y + height};
  // Each number under its place on the bar, kept inside it, left to right.
  float taken = p0.x;
  const float y = ImGui::GetCursorScreenPos().y;
  for (const LegendTick& t : ticks) {
    const float w = ImGui::CalcTextSize(t.label.c_str()).x;
    const float x = std::clamp(p0.x + float(t.position) * width - w / 2, taken, p0.x + width - w);
    ImGui::SetCursorScreenPos(ImVec2(x, y));
    ImGui::TextUnformatted(t.label.c_str());
    taken = x + w + 6.0f;
  }
}

void drawHeatLegend(ViewerState& state, const char* title, double maxValue, const char* unit,
                    bool counts) {
  std::vector<LegendTick> ticks;
  if (counts && maxValue <= 8) {
    for (int k = 0; k <= int(maxValue); ++k) ticks.push_back({k / maxValue, std::to_string(k)});
  } else {
    for (double f : {0.0, 0.5, 1.0}) ticks.push_back({f, number(f * maxValue)});
  }
  ticks.back().label += std::string(" ") + unit;
  drawLegend(state, title, heatColor, ticks);
}

void drawDepthLegend(ViewerState& state, const FalseColorScales& scales) {
  const std::vector<double>& q = scales.depthQuantiles;
  if (q.size() < 2) return;
  std::vector<LegendTick> ticks;
  for (int k = 0; k <= 4; ++k) {
    const std::size_t i = (q.size() - 1) * k / 4;
    ticks.push_back({double(i) / double(q.size() - 1), number(q[i])});
  }
  drawLegend(
      state, "depth (t of the primary hit), by share of the hits nearer",
      [](double u) { return depthColor(u, 0.0, 1.0); }, ticks);
}

}  // namespace meshtrace::viewer
