// A heat map's colour scale with its numbers.
#include <imgui.h>

#include "meshtrace/render/inspect_colors.h"
#include "viewer/ui/panels.h"

namespace meshtrace::viewer {

namespace {
ImU32 toImColor(const Color& c) {
  return IM_COL32(int(255 * c.r), int(255 * c.g), int(255 * c.b), 255);
}
}  // namespace

void drawHeatLegend(const char* title, double maxValue, const char* unit) {
  ImGui::TextUnformatted(title);
  const ImVec2 p0 = ImGui::GetCursorScreenPos();
  const float width = ImGui::GetContentRegionAvail().x, height = 14.0f;
  ImDrawList* draw = ImGui::GetWindowDrawList();
  constexpr int kSegments = 32;
  for (int i = 0; i < kSegments; ++i) {
    const float x0 = p0.x + width * i / kSegments, x1 = p0.x + width * (i + 1) / kSegments;
    const ImU32 a = toImColor(heatColor(double(i) / kSegments));
    const ImU32 b = toImColor(heatColor(double(i + 1) / kSegments));
    draw->AddRectFilledMultiColor(ImVec2(x0, p0.y), ImVec2(x1, p0.y + height), a, b, b, a);
  }
  ImGui::Dummy(ImVec2(width, height));
  ImGui::Text("0");
  char mid[32], top[48];
  std::snprintf(mid, sizeof mid, "%.3g", maxValue / 2);
  std::snprintf(top, sizeof top, "%.3g %s", maxValue, unit);
  ImGui::SameLine(width / 2 - ImGui::CalcTextSize(mid).x / 2);
  ImGui::TextUnformatted(mid);
  ImGui::SameLine(width - ImGui::CalcTextSize(top).x);
  ImGui::TextUnformatted(top);
}

}  // namespace meshtrace::viewer
