// The central image: the current view placed by the viewport (fit, 1:1,
// zoomed and panned apart from the camera), the heat overlay, a pixel grid
// at high zoom, the inspector's pixel marks and the debugger's findings,
// the readout of the hovered and the pinned pixel, and the mouse: the wheel
// zooms the image (with Shift it moves the camera), a middle drag pans it,
// a left drag orbits the camera, a right drag pans it, a click pins a pixel.
#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "meshtrace/io/image.h"
#include "viewer/model/camera_control.h"
#include "viewer/model/pixel_readout.h"
#include "viewer/ui/panels.h"

namespace meshtrace::viewer {

namespace {
constexpr float kZoomStep = 1.25f;  // per wheel notch

ImVec2 screen(const ImageViewport& v, double col, double row) {
  const auto [x, y] = v.toScreen(col, row);
  return ImVec2(x, y);
}

void markPixel(ImDrawList* draw, const ImageViewport& v, int height, const PixelRef& p,
               ImU32 color) {
  const ImVec2 c = screen(v, p.x + 0.5, flippedRow(p.y, height) + 0.5);
  const float r = std::max(4.0f, float(v.zoom()) * 0.5f + 1.0f);
  draw->AddRect(ImVec2(c.x - r, c.y - r), ImVec2(c.x + r, c.y + r), color, 0.0f, 0, 2.0f);
  draw->AddLine(ImVec2(c.x - r - 1.5f * std::max(4.0f, r), c.y), ImVec2(c.x - r, c.y), color, 2.0f);
  draw->AddLine(ImVec2(c.x + r, c.y), ImVec2(c.x + r + 1.5f * std::max(4.0f, r), c.y), color, 2.0f);
}

// Lines between the pixels in view, once they are large enough to see.
void drawPixelGrid(ImDrawList* draw, const ImageViewport& v, const ScreenRect& area, int width,
                   int height) {
  if (v.zoom() < ImageViewport::kGridZoom) return;
  const ImU32 line = IM_COL32(0, 0, 0, 110);
  const ScreenRect image = v.imageRect();
  const float top = std::max(area.y, image.y),
              bottom = std::min(area.y + area.height, image.y + image.height);
  const float left = std::max(area.x, image.x),
              right = std::min(area.x + area.width, image.x + image.width);
  const int c0 = std::max(0, int((left - v.originX()) / v.zoom())),
            c1 = std::min(width, int((right - v.originX()) / v.zoom()) + 1);
  const int r0 = std::max(0, int((top - v.originY()) / v.zoom())),
            r1 = std::min(height, int((bottom - v.originY()) / v.zoom()) + 1);
  for (int c = c0; c <= c1; ++c) {
    const float x = screen(v, c, 0).x;
    draw->AddLine(ImVec2(x, top), ImVec2(x, bottom), line);
  }
  for (int r = r0; r <= r1; ++r) {
    const float y = screen(v, 0, r).y;
    draw->AddLine(ImVec2(left, y), ImVec2(right, y), line);
  }
}

// B over the right of the image, from the wipe's line on, with the line
// and the names of the two sides.
void drawWipe(ImDrawList* draw, const AbState& ab, ImVec2 p0, ImVec2 p1) {
  const float split = p0.x + ab.wipe * (p1.x - p0.x);
  const float u = ab.wipe;
  draw->PushClipRect(ImVec2(split, p0.y), p1, true);
  draw->AddImage(textureId(ab.texture), ImVec2(split, p0.y), p1, ImVec2(u, 0), ImVec2(1, 1));
  draw->PopClipRect();
  const ImU32 line = IM_COL32(255, 255, 255, 230);
  draw->AddLine(ImVec2(split, p0.y), ImVec2(split, p1.y), line, 2.0f);
  const float mid = 0.5f * (p0.y + p1.y);
  draw->AddTriangleFilled(ImVec2(split - 7, mid), ImVec2(split - 1, mid - 6),
                          ImVec2(split - 1, mid + 6), line);
  draw->AddTriangleFilled(ImVec2(split + 7, mid), ImVec2(split + 1, mid - 6),
                          ImVec2(split + 1, mid + 6), line);
  draw->AddText(ImVec2(split - 18, p0.y + 4), line, "A");
  draw->AddText(ImVec2(split + 8, p0.y + 4), line, "B");
}

// Dragging the wipe's line moves it (instead of the camera).
bool dragWipe(ViewerState& state, const ImageViewport& v) {
  AbState& ab = state.ab;
  const ImGuiIO& io = ImGui::GetIO();
  const ScreenRect r = v.imageRect();
  if (!ab.b || ab.mode != AbMode::Wipe || r.width <= 0) return false;
  const float split = r.x + ab.wipe * r.width;
  if (ImGui::IsItemClicked(ImGuiMouseButton_Left) && std::abs(io.MousePos.x - split) < 8.0f)
    ab.draggingWipe = true;
  if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) ab.draggingWipe = false;
  if (ab.draggingWipe) ab.wipe = std::clamp((io.MousePos.x - r.x) / r.width, 0.0f, 1.0f);
  return ab.draggingWipe;
}

// The camera the mouse moves: the observer's while it is shown.
CameraSpec& movedCamera(ViewerState& state, CameraSpec& scratch) {
  if (state.observer.active && state.observer.camera) return *state.observer.camera;
  scratch = state.session.camera();
  return scratch;
}

void handleMouse(ViewerState& state, ImageViewport& v, int height) {
  ImGuiIO& io = ImGui::GetIO();
  CameraSpec scratch;
  CameraSpec& camera = movedCamera(state, scratch);
  const CameraSpec before = camera;
  const bool hovered = ImGui::IsItemHovered();
  state.hover.reset();
  if (hovered) {
    if (const auto p = v.pixelAt(io.MousePos.x, io.MousePos.y))
      state.hover = PixelRef{p->first, flippedRow(p->second, height)};
    if (io.MouseWheel != 0.0f) {
      if (io.KeyShift)
        camera = zoom(camera, io.MouseWheel);
      else
        v.zoomAt(std::pow(kZoomStep, io.MouseWheel), io.MousePos.x, io.MousePos.y);
    }
  }
  const bool wiping = dragWipe(state, v);
  if (ImGui::IsItemActive() && !wiping) {
    const ImVec2 d = io.MouseDelta;
    if (d.x != 0 || d.y != 0) {
      if (ImGui::IsMouseDragging(ImGuiMouseButton_Left))
        camera = orbit(camera, d.x, -d.y);
      else if (ImGui::IsMouseDragging(ImGuiMouseButton_Right))
        // Image pixels, y up.
        camera = pan(camera, d.x / v.zoom(), -d.y / v.zoom());
      else if (ImGui::IsMouseDragging(ImGuiMouseButton_Middle))
        v.panBy(d.x, d.y);
    }
  }
  if (&camera == &scratch && !sameCamera(camera, before)) state.session.setCamera(camera);
  // A pixel of the observer's image is not one of the main image's.
  if (hovered && ImGui::IsMouseReleased(ImGuiMouseButton_Left) &&
      io.MouseDragMaxDistanceSqr[0] < 9.0f && state.hover && !state.observer.active && !wiping)
    state.pinned = state.hover;
}

void drawToolbar(ViewerState& state) {
  ImageViewport& v = state.viewport;
  if (ImGui::SmallButton("Fit")) v.fit();
  ImGui::SameLine();
  if (ImGui::SmallButton("1:1")) v.actualSize();
  ImGui::SameLine();
  ImGui::Text("%s %.0f%%", v.fitted() ? "fit" : "zoom", v.zoom() * 100.0);
  ImGui::SameLine();
  ImGui::TextDisabled("wheel: zoom  middle drag: pan  shift+wheel: camera");
}

// The readout lines of the hovered and the pinned pixel, wrapped to `width`.
struct Readout {
  const char* title;
  ImVec4 color;
  std::string text;
};

std::vector<Readout> readouts(ViewerState& state, RenderDisplay& display) {
  std::vector<Readout> out;
  const PreparedScene* scene = display.prepared();
  if (!scene || !scene->built()) return out;
  const auto describe = [&](const PixelProbe& p) {
    return describeObject(state, display, PrimitiveRef{p.kind, p.index, p.triangle});
  };
  const auto add = [&](const char* title, const PixelRef& p, ImVec4 color) {
    const PixelReadout r =
        readPixel(*scene, display.camera(), display.frame(), p.x, p.y, display.scales());
    std::string text;
    for (const std::string& f : readoutFields(r, describe)) text += (text.empty() ? "" : "  ") + f;
    out.push_back({title, color, text});
  };
  if (state.hover) add("hover ", *state.hover, ImVec4(1, 1, 0, 1));
  if (state.pinned) add("pinned", *state.pinned, ImVec4(0, 1, 1, 1));
  return out;
}

float readoutHeight(const std::vector<Readout>& lines, float width) {
  float h = 0.0f;
  const float title = ImGui::CalcTextSize("pinned ").x;
  for (const Readout& r : lines)
    h += ImGui::CalcTextSize(r.text.c_str(), nullptr, false, width - title).y +
         ImGui::GetStyle().ItemSpacing.y;
  return std::max(h, ImGui::GetTextLineHeightWithSpacing());
}

void drawReadouts(const std::vector<Readout>& lines) {
  for (const Readout& r : lines) {
    ImGui::TextColored(r.color, "%s", r.title);
    ImGui::SameLine();
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(r.text.c_str());
    ImGui::PopTextWrapPos();
  }
  if (lines.empty())
    ImGui::TextDisabled("Hover over the image for a pixel's values; click to pin it.");
}

// What the background work does, while it matters to what is shown: the
// opening of a scene (in place of an image), a preview's replacement, a
// render scene being remade.
// A task's phase and, unless timings are hidden, how long it has run.
template <typename Task>
std::string phaseLine(const ViewerState& state, const Task& task) {
  char line[256];
  if (state.options.hideTimings)
    std::snprintf(line, sizeof line, "%s ...", task.phase().c_str());
  else
    std::snprintf(line, sizeof line, "%s ... %.1f s", task.phase().c_str(),
                  task.phaseMs() / 1000.0);
  return line;
}

void drawWorkStatus(ViewerState& state, RenderDisplay& display) {
  const ScenePipeline& pipeline = *state.scenes.pipeline;
  const BackgroundTask<CrossCheckState::Result>& check = *state.crosscheck.task;
  if (!pipeline.busy() && state.view == View::NormalDeviation && check.busy()) {
    ImGui::TextColored(ImVec4(1.0f, 0.85f, 0.4f, 1.0f), "Meshes grey until done: %s",
                       phaseLine(state, check).c_str());
    return;
  }
  if (!pipeline.busy()) return;
  const bool previewShown = display.renderScene() && display.renderScene()->preview;
  const std::string text = phaseLine(state, pipeline);
  const char* line = text.c_str();
  if (!display.showsImage()) {
    ImGui::Text("Opening %s", state.session.file().filename().string().c_str());
    // No fraction is known: a block sweeps along the bar while work goes on.
    const ImVec2 p0 = ImGui::GetCursorScreenPos();
    ImGui::ProgressBar(0.0f, ImVec2(-1, 0), line);
    const ImVec2 p1 = ImGui::GetItemRectMax();
    const float block = 0.2f * (p1.x - p0.x);
    const float at = state.options.hideTimings
                         ? 0.0f
                         : static_cast<float>(std::fmod(ImGui::GetTime() * 0.6, 1.0));
    const float x0 = p0.x + at * (p1.x - p0.x - block);
    ImGui::GetWindowDrawList()->AddRectFilled(ImVec2(x0, p0.y), ImVec2(x0 + block, p1.y),
                                              ImGui::GetColorU32(ImGuiCol_PlotHistogram, 0.6f));
    return;
  }
  ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.85f, 0.4f, 1.0f));
  if (previewShown)
    ImGui::Text("Preview (every mesh FLAT, a quick grid): %s", line);
  else
    ImGui::Text("Updating the scene: %s", line);
  ImGui::PopStyleColor();
}
}  // namespace

void drawImageView(ViewerState& state, RenderDisplay& display) {
  if (!state.session.loaded() && !state.session.opening()) {
    if (!state.session.error().empty()) {
      ImGui::TextColored(ImVec4(1.0f, 0.35f, 0.35f, 1.0f), "Could not load the scene:");
      ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.6f, 0.6f, 1.0f));
      ImGui::TextWrapped("%s", state.session.error().c_str());
      ImGui::PopStyleColor();
    } else {
      ImGui::TextDisabled(
          "Open a scene from the list, type a path, or drop a .sce or mesh file here.");
    }
    return;
  }
  drawWorkStatus(state, display);
  const gl::Texture& image = display.image();
  if (!display.showsImage() || !image.valid()) return;
  drawToolbar(state);
  const int w = image.width(), h = image.height();
  const bool sideBySide = state.view == View::SideBySide && state.reference.texture.valid();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  // The readouts of the pixels hovered and pinned last frame: the mouse
  // handling below may change them.
  const std::vector<Readout> lines = readouts(state, display);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float gap = 8.0f;
  const float columnWidth = sideBySide ? (avail.x - gap) / 2.0f : avail.x;
  const ScreenRect area{origin.x, origin.y, columnWidth,
                        std::max(16.0f, avail.y - readoutHeight(lines, avail.x))};
  ImageViewport& v = state.viewport;
  v.layout(area, w, h);
  ImGui::InvisibleButton("image", ImVec2(avail.x, area.height),
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                             ImGuiButtonFlags_MouseButtonMiddle);
  handleMouse(state, v, h);
  const ScreenRect shown = v.imageRect();
  state.regions["image"] = {shown.x, shown.y, shown.x + shown.width, shown.y + shown.height};
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 areaEnd(area.x + area.width, area.y + area.height);
  draw->PushClipRect(ImVec2(area.x, area.y), areaEnd, true);
  const ImVec2 p0(shown.x, shown.y), p1(shown.x + shown.width, shown.y + shown.height);
  const bool difference = state.view == View::Difference && state.reference.difference.valid();
  const AbState& ab = state.ab;
  const bool abShown = ab.b && ab.texture.valid() && ab.texture.width() == w &&
                       ab.texture.height() == h && ab.mode != AbMode::A;
  const gl::Texture* shownTexture = difference ? &state.reference.difference : &image;
  if (abShown && ab.mode == AbMode::B) shownTexture = &ab.texture;
  if (abShown && ab.mode == AbMode::Difference && ab.difference.valid())
    shownTexture = &ab.difference;
  draw->AddImage(textureId(*shownTexture), p0, p1);
  if (abShown && ab.mode == AbMode::Wipe) drawWipe(draw, ab, p0, p1);
  if (state.overlay != Overlay::None && display.overlay().valid())
    draw->AddImage(textureId(display.overlay()), p0, p1, ImVec2(0, 0), ImVec2(1, 1),
                   IM_COL32(255, 255, 255, int(255 * state.opacity)));
  drawPixelGrid(draw, v, area, w, h);
  // An image position (y up, pixel i traced at i) sits at its pixel's centre.
  // The findings belong to the image: a ray that leaves it stops at its edge.
  draw->PushClipRect(p0, p1, true);
  drawFindings(state, display, draw, [&](const ImagePoint& p) {
    return screen(v, p.x + 0.5, flippedRow(0, h) - p.y + 0.5);
  });
  draw->PopClipRect();
  if (state.observer.active) {
    ImGui::GetWindowDrawList()->AddText(ImVec2(area.x + 6, area.y + 4),
                                        IM_COL32(190, 200, 255, 255), "observer camera");
  } else if (state.pinned) {
    markPixel(draw, v, h, *state.pinned, IM_COL32(0, 255, 255, 255));
  }
  if (state.hover && !(state.hover == state.pinned))
    markPixel(draw, v, h, *state.hover, IM_COL32(255, 255, 0, 200));
  draw->PopClipRect();
  if (sideBySide) {
    // The reference beside, placed the same way in its own column.
    const float dx = columnWidth + gap;
    draw->PushClipRect(ImVec2(area.x + dx, area.y), ImVec2(areaEnd.x + dx, areaEnd.y), true);
    draw->AddImage(textureId(state.reference.texture), ImVec2(p0.x + dx, p0.y),
                   ImVec2(p1.x + dx, p1.y));
    draw->PopClipRect();
  }
  if ((state.view == View::SideBySide || state.view == View::Difference) &&
      !state.reference.texture.valid())
    ImGui::TextDisabled("No reference image for this scene (see Compare).");
  drawReadouts(lines);
}

}  // namespace meshtrace::viewer
