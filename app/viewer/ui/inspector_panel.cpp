// The pixel inspector: everything inspectPixel records about the hovered
// pixel (or the pinned one when the mouse is elsewhere), through the main
// camera.
#include <imgui.h>

#include "meshtrace/render/inspect.h"
#include "viewer/ui/panels.h"

namespace meshtrace::viewer {

namespace {
void vec(const char* label, const Vec3& v) {
  ImGui::Text("%-14s (%.5f, %.5f, %.5f)", label, v.x, v.y, v.z);
}

void color(const char* label, const Color& c) {
  ImGui::Text("%-14s (%.4f, %.4f, %.4f)", label, c.r, c.g, c.b);
}

void drawSurface(const ViewerState& state, const RenderDisplay& display, const SurfaceRecord& s) {
  ImGui::Text("hit           %s", describeObject(state, display, s.ref).c_str());
  if (s.ref.kind == ObjectKind::Mesh) ImGui::Text("triangle      %u", s.ref.triangle);
  ImGui::Text("t             %.6f", s.t);
  vec("point", s.point);
  if (s.ref.kind == ObjectKind::Mesh) {
    ImGui::Text("barycentrics  a %.5f  b %.5f  g %.5f", s.alpha, s.beta, s.gamma);
    vec("flat normal", s.geometricNormal);
    if (s.hasVertexNormals) {
      for (int k = 0; k < 3; ++k) {
        char label[24];
        std::snprintf(label, sizeof label, "vertex n%d", k);
        vec(label, s.vertexNormals[k]);
      }
    }
    if (s.phong) {
      vec("interpolated", s.shadingNormal);
      ImGui::Text("flat vs interpolated: %.4f deg", s.normalAngleDegrees);
    } else {
      ImGui::TextDisabled("FLAT: shading uses the flat normal");
    }
  } else {
    vec("normal", s.shadingNormal);
  }
}

void drawLights(const ViewerState& state, const RenderDisplay& display, const BounceRecord& b) {
  color("ambient", b.ambient);
  for (const LightRecord& l : b.lights) {
    ImGui::Text("light %zu  n.l %.3f", l.light, l.nDotL);
    ImGui::SameLine();
    if (!l.facing)
      ImGui::TextDisabled("behind the surface: no shadow ray");
    else if (l.shadowed && l.blocker)
      ImGui::TextColored(ImVec4(1, 0.6f, 0.3f, 1), "shadowed by %s at t %.4g",
                         describeObject(state, display, *l.blocker).c_str(), l.blockerT);
    else if (l.shadowed)
      ImGui::TextColored(ImVec4(1, 0.6f, 0.3f, 1), "shadowed");
    else
      ImGui::TextUnformatted("lit");
    if (l.facing && !l.shadowed) {
      ImGui::Text("   diffuse (%.4f, %.4f, %.4f)", l.diffuse.r, l.diffuse.g, l.diffuse.b);
      ImGui::Text("   specular (%.4f, %.4f, %.4f)", l.specular.r, l.specular.g, l.specular.b);
    }
  }
}

void drawBounce(const ViewerState& state, const RenderDisplay& display, const BounceRecord& b) {
  vec("ray origin", b.ray.origin);
  vec("ray direction", b.ray.direction);
  if (!b.hit) {
    ImGui::Text("miss: background");
  } else {
    drawSurface(state, display, b.surface);
    drawLights(state, display, b);
    color("local", b.local);
    if (b.reflects)
      ImGui::Text("mirror %.3f: (1 - m) local + m reflected; carries %.3f of the pixel", b.mirror,
                  b.weight);
    else if (b.mirror > 0)
      ImGui::TextDisabled("mirror %.3f, but the depth limit is reached", b.mirror);
  }
  color("returns", b.color);
  if (b.boxes.empty()) {
    ImGui::TextDisabled("entered no mesh box");
  } else {
    ImGui::Text("mesh boxes entered:");
    for (const BoxRecord& box : b.boxes)
      ImGui::BulletText(
          "%s  t %.4g .. %.4g",
          describeObject(state, display, PrimitiveRef{ObjectKind::Mesh, box.mesh, 0}).c_str(),
          box.tEnter, box.tExit);
  }
}
}  // namespace

void drawInspectorPanel(ViewerState& state, RenderDisplay& display) {
  // From the observer camera the mouse is over another image: the pinned
  // pixel only.
  const std::optional<PixelRef> pixel =
      state.hover && !state.observer.active ? state.hover : state.pinned;
  const PixelInspection* inspection = pixel ? inspectionOf(state, display, *pixel) : nullptr;
  if (!inspection) {
    ImGui::TextDisabled("Hover over the image to inspect a pixel; click to pin it.");
    return;
  }
  const PixelInspection& in = *inspection;
  const bool pinned = state.pinned && *state.pinned == *pixel;
  ImGui::Text("pixel (%d, %d)%s  y = 0 is the bottom row", pixel->x, pixel->y,
              pinned ? " pinned" : "");
  const Color c = glm::min(in.color, Color(1.0));
  ImGui::ColorButton("##colour", ImVec4(float(c.r), float(c.g), float(c.b), 1.0f),
                     ImGuiColorEditFlags_NoTooltip, ImVec2(14, 14));
  ImGui::SameLine();
  ImGui::Text("colour (%.4f, %.4f, %.4f)  rays: %llu shadow, %llu reflection", in.color.r,
              in.color.g, in.color.b, static_cast<unsigned long long>(in.counters.shadowRays),
              static_cast<unsigned long long>(in.counters.reflectionRays));
  if (state.pinned && ImGui::SmallButton("Unpin")) state.pinned.reset();
  for (const BounceRecord& b : in.bounces) {
    ImGui::PushID(b.level);
    char title[96];
    if (b.level == 0)
      std::snprintf(title, sizeof title, "primary ray");
    else
      std::snprintf(title, sizeof title, "reflection %d (weight %.3f)", b.level, b.weight);
    if (ImGui::TreeNodeEx(title, ImGuiTreeNodeFlags_DefaultOpen)) {
      drawBounce(state, display, b);
      ImGui::TreePop();
    }
    ImGui::PopID();
  }
}

}  // namespace meshtrace::viewer
