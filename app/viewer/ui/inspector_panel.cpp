// The pixel inspector: everything inspectPixel records about the hovered
// pixel (or the pinned one when the mouse is elsewhere), through the main
// camera, in a scrolling pane of its own height (pane_heights.h) with its
// long lines broken at spaces. The words come from inspector_report.h; --describe
// gets them whole.
#include <imgui.h>

#include "viewer/model/inspector_report.h"
#include "viewer/model/line_breaks.h"
#include "viewer/model/pane_heights.h"
#include "viewer/ui/panels.h"

namespace meshtrace::viewer {

namespace {
constexpr const char* kHint = "Hover over the image to inspect a pixel; click to pin it.";

ImVec4 colorOf(LineTone tone) {
  switch (tone) {
    case LineTone::Dim: return ImGui::GetStyle().Colors[ImGuiCol_TextDisabled];
    case LineTone::Alert: return ImVec4(1, 0.6f, 0.3f, 1);
    case LineTone::Plain: break;
  }
  return ImGui::GetStyle().Colors[ImGuiCol_Text];
}

// `text` from the cursor, which may follow other text on its line (begun
// at `lineStart`), broken at spaces to the pane's width; the lines after
// the first indented.
void drawBroken(const std::string& text, float lineStart, LineTone tone = LineTone::Plain) {
  const float indent = 2.0f * ImGui::GetFontSize();
  const float left = ImGui::GetCursorPosX(), right = left + ImGui::GetContentRegionAvail().x;
  const std::vector<std::string> pieces =
      breakAtSpaces(text, right - left, right - lineStart - indent,
                    [](const std::string& s) { return ImGui::CalcTextSize(s.c_str()).x; });
  ImGui::PushStyleColor(ImGuiCol_Text, colorOf(tone));
  ImGui::TextUnformatted(pieces[0].c_str());
  ImGui::Indent(indent);
  for (std::size_t i = 1; i < pieces.size(); ++i) ImGui::TextUnformatted(pieces[i].c_str());
  ImGui::Unindent(indent);
  ImGui::PopStyleColor();
}

void drawLine(const InspectorLine& line) {
  const float start = ImGui::GetCursorPosX();
  if (line.bullet) ImGui::Bullet();
  if (!line.lead.empty()) {
    ImGui::TextUnformatted(line.lead.c_str());
    ImGui::SameLine(0, 0);
  }
  drawBroken(line.text, start, line.tone);
}

void drawReport(ViewerState& state, const InspectorReport& report) {
  const float start = ImGui::GetCursorPosX();
  drawBroken(report.pixel, start);
  const Color c = glm::min(report.color, Color(1.0));
  ImGui::ColorButton("##colour", ImVec4(float(c.r), float(c.g), float(c.b), 1.0f),
                     ImGuiColorEditFlags_NoTooltip, ImVec2(14, 14));
  ImGui::SameLine();
  drawBroken(report.summary, start);
  if (state.pinned && ImGui::SmallButton("Unpin")) state.pinned.reset();
  for (std::size_t i = 0; i < report.bounces.size(); ++i) {
    const InspectorBounce& b = report.bounces[i];
    ImGui::PushID(static_cast<int>(i));
    if (ImGui::TreeNodeEx(b.title.c_str(), ImGuiTreeNodeFlags_DefaultOpen)) {
      for (const InspectorLine& line : b.lines) drawLine(line);
      ImGui::TreePop();
    }
    ImGui::PopID();
  }
}
}  // namespace

void drawInspectorPanel(ViewerState& state, RenderDisplay& display, float keepBelow) {
  // From the observer camera the mouse is over another image: the pinned
  // pixel only.
  const std::optional<PixelRef> pixel =
      state.hover && !state.observer.active ? state.hover : state.pinned;
  const PixelInspection* inspection = pixel ? inspectionOf(state, display, *pixel) : nullptr;
  std::optional<InspectorReport> report;
  if (inspection)
    report = inspectorReport(
        *inspection, pixel->x, pixel->y, state.pinned && *state.pinned == *pixel,
        [&](const PrimitiveRef& ref) { return describeObject(state, display, ref); });

  // The room is measured from the pane's place in the panel's content, not
  // on screen: scrolling the panel leaves the pane's height alone.
  const float splitter = kPaneSplitterHeight + ImGui::GetStyle().ItemSpacing.y;
  const float room = ImGui::GetWindowHeight() - ImGui::GetStyle().WindowPadding.y -
                     ImGui::GetCursorPosY() - splitter - keepBelow;
  float& chosen = state.settings.panes.inspector;
  const float height = paneHeight(chosen, room);
  const ImVec2 top = ImGui::GetCursorScreenPos();
  drawCapturedAs(state, report ? reportText(*report) : std::string(kHint) + "\n", [&] {
    ImGui::BeginChild("inspector", ImVec2(0, height), true);
    if (report)
      drawReport(state, *report);
    else
      drawBroken(kHint, ImGui::GetCursorPosX(), LineTone::Dim);
    ImGui::EndChild();
  });
  state.regions["inspector"] = {top.x, top.y, top.x + ImGui::GetItemRectSize().x, top.y + height};
  paneSplitter(state, "##inspector-height", height, chosen);
}

}  // namespace meshtrace::viewer
