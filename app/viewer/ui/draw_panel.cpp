// What is drawn over the image: the pinned pixel's ray tree, the boxes and
// BVH nodes its primary ray entered, a BVH level cut; and the observer
// camera, which shows all of it from outside.
#include <imgui.h>

#include "viewer/model/observer.h"
#include "viewer/ui/panels.h"

namespace meshtrace::viewer {

namespace {
void swatch(ImU32 color, const char* text) {
  const ImVec2 p = ImGui::GetCursorScreenPos();
  const float h = ImGui::GetTextLineHeight();
  ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(p.x, p.y + h * 0.4f),
                                            ImVec2(p.x + 14, p.y + h * 0.6f), color);
  ImGui::Dummy(ImVec2(16, h));
  ImGui::SameLine();
  ImGui::TextUnformatted(text);
}
}  // namespace

void drawDrawPanel(ViewerState& state, RenderDisplay& display) {
  DrawOptions& d = state.draw;
  ImGui::Checkbox("ray tree of the pinned pixel", &d.rays);
  if (d.rays) {
    ImGui::Indent();
    swatch(IM_COL32(255, 255, 255, 255), "primary ray and its hit");
    ImGui::SameLine(0, 16);
    swatch(IM_COL32(255, 90, 255, 255), "reflections");
    swatch(IM_COL32(255, 220, 60, 230), "shadow ray to a light");
    ImGui::SameLine(0, 16);
    swatch(IM_COL32(255, 60, 50, 255), "blocked, with its blocker");
    ImGui::Unindent();
  }
  ImGui::Checkbox("mesh boxes its primary ray entered", &d.meshBoxes);
  ImGui::Checkbox("BVH nodes its primary ray entered (by depth)", &d.nodes);
  if ((d.rays || d.meshBoxes || d.nodes) && !state.pinned)
    ImGui::TextDisabled("Click a pixel to pin it.");
  ImGui::Checkbox("every BVH node at a depth", &d.cut);
  const PreparedScene* scene = display.prepared();
  if (d.cut && scene && scene->built()) {
    int level = static_cast<int>(d.level);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(110);
    ImGui::Combo("##level", &level, "objects\0triangles\0");
    d.level = static_cast<BvhLevel>(level);
    const BvhCut probe = bvhCut(scene->intersector(), d.level, 0, 1);
    if (probe.boxes.empty()) {
      ImGui::TextDisabled("This scene has no %s BVH.", toString(d.level));
    } else {
      ImGui::SetNextItemWidth(200);
      ImGui::SliderInt("depth", &d.depth, 0, probe.levelDepth);
      d.depth = std::clamp(d.depth, 0, probe.levelDepth);
      const CutCache& c = state.cut;
      if (c.scene == scene && c.depth == d.depth && c.level == d.level) {
        ImGui::Text("%zu%s boxes: nodes at depth %d, and leaves above it", c.cut.boxes.size(),
                    c.cut.truncated ? "+" : "", d.depth);
        if (c.drawn < c.cut.boxes.size())
          ImGui::TextDisabled("the %zu largest in the image drawn", c.drawn);
      }
    }
  }
  ImGui::Separator();
  ObserverState& o = state.observer;
  if (ImGui::Checkbox("look from the observer camera", &o.active) && o.active && !o.camera &&
      state.session.loaded())
    o.camera = observerCamera(state.session.camera(), state.session.scene());
  if (o.active) {
    ImGui::SameLine();
    if (ImGui::SmallButton("place again") && state.session.loaded())
      o.camera = observerCamera(state.session.camera(), state.session.scene());
    ImGui::TextDisabled("The mouse moves the observer; the main camera stays.");
  }
}

}  // namespace meshtrace::viewer
