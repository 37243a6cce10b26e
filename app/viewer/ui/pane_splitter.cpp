// The bar under a scrolling pane that drags the pane's height.
#include <imgui.h>

#include <algorithm>

#include "viewer/ui/panels.h"

namespace meshtrace::viewer {

void paneSplitter(ViewerState& state, const char* id, float shown, float& chosen) {
  const float thickness = kPaneSplitterHeight;
  const ImVec2 at = ImGui::GetCursorScreenPos();
  const float width = ImGui::GetContentRegionAvail().x;
  ImGui::InvisibleButton(id, ImVec2(width, thickness));
  const bool active = ImGui::IsItemActive(), hovered = ImGui::IsItemHovered();
  if (active || hovered) ImGui::SetMouseCursor(ImGuiMouseCursor_ResizeNS);
  const ImU32 color = ImGui::GetColorU32(active    ? ImGuiCol_SeparatorActive
                                         : hovered ? ImGuiCol_SeparatorHovered
                                                   : ImGuiCol_Separator);
  const float y = at.y + thickness / 2;
  ImGui::GetWindowDrawList()->AddLine(ImVec2(at.x, y), ImVec2(at.x + width, y), color,
                                      active || hovered ? 3.0f : 1.0f);
  if (hovered && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
    chosen = 0.0f;
    state.settingsChanged = true;
  } else if (active && ImGui::GetIO().MouseDelta.y != 0.0f) {
    chosen = std::max(1.0f, (chosen > 0 ? chosen : shown) + ImGui::GetIO().MouseDelta.y);
    state.settingsChanged = true;
  }
  if (hovered) ImGui::SetTooltip("Drag to resize; double-click for the automatic height.");
}

}  // namespace meshtrace::viewer
