// The central image: the current view fitted to the window, the heat
// overlay, the inspector's pixel marks, and mouse camera control (left drag
// orbits, right drag pans, the wheel zooms, a click pins a pixel).
#include <imgui.h>

#include "meshtrace/io/image.h"
#include "viewer/model/camera_control.h"
#include "viewer/ui/panels.h"

namespace meshtrace::viewer {

namespace {
ImTextureID textureId(const gl::Texture& t) {
  return reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(t.id()));
}

void markPixel(ImDrawList* draw, ImVec2 origin, float scale, int height, const PixelRef& p,
               ImU32 color) {
  const float x = origin.x + (p.x + 0.5f) * scale,
              y = origin.y + (flippedRow(p.y, height) + 0.5f) * scale;
  const float r = std::max(4.0f, scale);
  draw->AddRect(ImVec2(x - r, y - r), ImVec2(x + r, y + r), color, 0.0f, 0, 2.0f);
  draw->AddLine(ImVec2(x - 2.5f * r, y), ImVec2(x - r, y), color, 2.0f);
  draw->AddLine(ImVec2(x + r, y), ImVec2(x + 2.5f * r, y), color, 2.0f);
}

void handleMouse(ViewerState& state, ImVec2 origin, float scale, int width, int height) {
  ImGuiIO& io = ImGui::GetIO();
  SceneSession& session = state.session;
  const bool hovered = ImGui::IsItemHovered();
  state.hover.reset();
  if (hovered) {
    const int col = int((io.MousePos.x - origin.x) / scale),
              row = int((io.MousePos.y - origin.y) / scale);
    if (col >= 0 && row >= 0 && col < width && row < height)
      state.hover = PixelRef{col, flippedRow(row, height)};
    if (io.MouseWheel != 0.0f) session.setCamera(zoom(session.camera(), io.MouseWheel));
  }
  if (ImGui::IsItemActive()) {
    const ImVec2 d = io.MouseDelta;
    if (d.x != 0 || d.y != 0) {
      // Image pixels, y up.
      const double dx = d.x / scale, dy = -d.y / scale;
      if (ImGui::IsMouseDragging(ImGuiMouseButton_Left))
        session.setCamera(orbit(session.camera(), d.x, -d.y));
      else if (ImGui::IsMouseDragging(ImGuiMouseButton_Right) ||
               ImGui::IsMouseDragging(ImGuiMouseButton_Middle))
        session.setCamera(pan(session.camera(), dx, dy));
    }
  }
  if (hovered && ImGui::IsMouseReleased(ImGuiMouseButton_Left) &&
      io.MouseDragMaxDistanceSqr[0] < 9.0f && state.hover)
    state.pinned = state.hover;
}
}  // namespace

void drawImageView(ViewerState& state, RenderDisplay& display) {
  if (!state.session.loaded()) {
    if (!state.session.error().empty()) {
      ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.35f, 1.0f), "Could not load the scene:");
      ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.6f, 0.6f, 1.0f));
      ImGui::TextWrapped("%s", state.session.error().c_str());
      ImGui::PopStyleColor();
    } else {
      ImGui::TextDisabled("Open a scene from the list, type a path, or drop a .sce file here.");
    }
    return;
  }
  const gl::Texture& image = display.image();
  if (!image.valid()) return;
  const int w = image.width(), h = image.height();
  const bool sideBySide = state.view == View::SideBySide && state.reference.texture.valid();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const float columns = sideBySide ? 2.0f : 1.0f;
  const float scale =
      std::max(0.05f, std::min((avail.x - (columns - 1) * 8) / (columns * w), avail.y / h));
  const ImVec2 size(w * scale, h * scale);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton("image", size,
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                             ImGuiButtonFlags_MouseButtonMiddle);
  handleMouse(state, origin, scale, w, h);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 end(origin.x + size.x, origin.y + size.y);
  const bool difference = state.view == View::Difference && state.reference.difference.valid();
  draw->AddImage(textureId(difference ? state.reference.difference : image), origin, end);
  if (state.overlay != Overlay::None && display.overlay().valid())
    draw->AddImage(textureId(display.overlay()), origin, end, ImVec2(0, 0), ImVec2(1, 1),
                   IM_COL32(255, 255, 255, int(255 * state.opacity)));
  if (state.pinned) markPixel(draw, origin, scale, h, *state.pinned, IM_COL32(0, 255, 255, 255));
  if (state.hover && !(state.hover == state.pinned))
    markPixel(draw, origin, scale, h, *state.hover, IM_COL32(255, 255, 0, 200));
  if (sideBySide) {
    ImGui::SameLine(0, 8);
    ImGui::Image(textureId(state.reference.texture), size);
  }
  if ((state.view == View::SideBySide || state.view == View::Difference) &&
      !state.reference.texture.valid())
    ImGui::TextDisabled("No reference image for this scene (see Compare).");
}

}  // namespace meshtrace::viewer
