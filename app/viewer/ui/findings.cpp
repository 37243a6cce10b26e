// The debugger's findings drawn over the image, seen through the camera of
// the image shown: the pinned pixel's ray tree (primary ray, bounces,
// shadow rays; blocked ones in red with their blocker named), the mesh
// boxes and BVH nodes its primary ray entered, a BVH level cut at a depth;
// and from the observer camera, the main camera's frustum.
#include <imgui.h>

#include <algorithm>

#include "meshtrace/render/inspect_colors.h"
#include "viewer/model/camera_control.h"
#include "viewer/model/observer.h"
#include "viewer/model/projection.h"
#include "viewer/model/ray_tree.h"
#include "viewer/ui/panels.h"

namespace meshtrace::viewer {

namespace {
// A BVH level's cut is fetched up to kMaxCutBoxes nodes; of those, the
// kMaxDrawnBoxes largest in the image are drawn: more cost a software
// rasteriser too much of a frame (12 lines each, redrawn every frame), and
// the smallest are a few pixels that add nothing to the picture.
constexpr std::size_t kMaxCutBoxes = std::size_t{1} << 16;
constexpr std::size_t kMaxDrawnBoxes = 512;

ImU32 rayColor(RayKind kind) {
  switch (kind) {
    case RayKind::Primary: return IM_COL32(255, 255, 255, 255);
    case RayKind::Reflection: return IM_COL32(255, 90, 255, 255);
    case RayKind::Lit: return IM_COL32(255, 220, 60, 230);
    case RayKind::Blocked: return IM_COL32(255, 60, 50, 255);
    case RayKind::PastBlocker: return IM_COL32(255, 60, 50, 90);
  }
  return IM_COL32_WHITE;
}

class Painter {
 public:
  Painter(ImDrawList* draw, const Camera& camera,
          const std::function<ImVec2(const ImagePoint&)>& toScreen)
      : draw_(draw), projection_(camera), toScreen_(toScreen) {}

  void line(const Vec3& a, const Vec3& b, ImU32 color, float thickness = 1.0f) {
    if (const auto s = projection_.projectSegment(a, b))
      draw_->AddLine(toScreen_(s->first), toScreen_(s->second), color, thickness);
  }
  void box(const Aabb& box, ImU32 color, float thickness = 1.0f) {
    for (const auto& [a, b] : boxEdges(box)) line(a, b, color, thickness);
  }
  const Projection& projection() const { return projection_; }
  void dot(const Vec3& p, ImU32 color) {
    if (const auto q = projection_.project(p)) draw_->AddCircleFilled(toScreen_(*q), 3.5f, color);
  }
  // Text beside a point, on a dark ground; left out where it would cover
  // an earlier label (many bounces between two mirrors land in a row).
  void label(const Vec3& p, const std::string& text, ImU32 color) {
    const auto q = projection_.project(p);
    if (!q || text.empty()) return;
    const ImVec2 at = toScreen_(*q);
    const ImVec2 size = ImGui::CalcTextSize(text.c_str());
    const ImVec4 r(at.x + 4, at.y - size.y - 3, at.x + 8 + size.x, at.y - 1);
    for (const ImVec4& o : labels_)
      if (r.x < o.z && o.x < r.z && r.y < o.w && o.y < r.w) return;
    labels_.push_back(r);
    draw_->AddRectFilled(ImVec2(r.x, r.y), ImVec2(r.z, r.w), IM_COL32(0, 0, 0, 170));
    draw_->AddText(ImVec2(r.x + 2, r.y + 1), color, text.c_str());
  }

 private:
  std::vector<ImVec4> labels_;
  ImDrawList* draw_;
  Projection projection_;
  const std::function<ImVec2(const ImagePoint&)>& toScreen_;
};

ImU32 depthColor(int depth, int deepest) {
  const Color c = heatColor(0.25 + 0.75 * double(depth) / std::max(1, deepest));
  return IM_COL32(int(255 * c.r), int(255 * c.g), int(255 * c.b), 220);
}

const BvhCut& cutOf(ViewerState& state, const PreparedScene& scene) {
  CutCache& c = state.cut;
  if (c.scene != &scene || c.level != state.draw.level || c.depth != state.draw.depth) {
    c.scene = &scene;
    c.level = state.draw.level;
    c.depth = state.draw.depth;
    c.cut = bvhCut(scene.intersector(), c.level, c.depth, kMaxCutBoxes);
  }
  return c.cut;
}
}  // namespace

const PixelInspection* inspectionOf(ViewerState& state, const RenderDisplay& display,
                                    const PixelRef& pixel) {
  const PreparedScene* scene = display.prepared();
  if (!scene || !scene->built()) return nullptr;
  // Through the main camera, whichever camera the shown image has.
  const CameraSpec& camera = state.session.camera();
  auto& entries = state.inspections.entries;
  for (const auto& e : entries)
    if (e.scene == scene && e.pixel == pixel && sameCamera(e.camera, camera)) return &e.inspection;
  if (entries.size() >= 2) entries.erase(entries.begin());
  entries.push_back(
      {scene, camera, pixel, inspectPixel(scene->intersector(), Camera(camera), pixel.x, pixel.y)});
  return &entries.back().inspection;
}

void drawFindings(ViewerState& state, RenderDisplay& display, ImDrawList* draw,
                  const std::function<ImVec2(const ImagePoint&)>& toScreen) {
  const PreparedScene* scene = display.prepared();
  if (!scene || !scene->built()) return;
  Painter paint(draw, display.camera(), toScreen);
  const DrawOptions& d = state.draw;
  if (d.cut) {
    const BvhCut& cut = cutOf(state, *scene);
    std::vector<std::size_t> order(cut.boxes.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    if (order.size() > kMaxDrawnBoxes) {
      std::vector<double> extent(order.size());
      for (std::size_t i = 0; i < order.size(); ++i)
        extent[i] = imageExtent(paint.projection(), cut.boxes[i].box);
      std::nth_element(order.begin(), order.begin() + kMaxDrawnBoxes, order.end(),
                       [&](std::size_t a, std::size_t b) { return extent[a] > extent[b]; });
      order.resize(kMaxDrawnBoxes);
    }
    state.cut.drawn = order.size();
    // Plain lines: an anti-aliased line is three quads to rasterise.
    const ImDrawListFlags flags = draw->Flags;
    draw->Flags &= ~ImDrawListFlags_AntiAliasedLines;
    for (std::size_t i : order) paint.box(cut.boxes[i].box, IM_COL32(80, 200, 255, 150));
    draw->Flags = flags;
  }
  const CameraSpec& main = state.session.camera();
  const Aabb bounds = sceneBounds(scene->scene());
  const double reach =
      (bounds.empty() ? 0.0 : glm::length(bounds.extent())) + glm::length(main.center - main.eye);
  if (state.observer.active) {
    for (const auto& [a, b] : frustumLines(main, reach))
      paint.line(a, b, IM_COL32(190, 200, 255, 200));
    paint.dot(main.eye, IM_COL32(190, 200, 255, 255));
    paint.label(main.eye, "main camera", IM_COL32(190, 200, 255, 255));
  }
  if (!state.pinned) return;
  const PixelInspection* in = inspectionOf(state, display, *state.pinned);
  if (!in || in->bounces.empty()) return;
  const BounceRecord& primary = in->bounces[0];
  if (d.meshBoxes)
    for (const BoxRecord& b : primary.boxes)
      if (b.mesh < scene->scene().meshes.size())
        paint.box(scene->scene().meshes[b.mesh].bounds(), IM_COL32(90, 255, 120, 220), 1.5f);
  if (d.nodes) {
    int deepest = 0;
    for (const BvhNodeBox& n : primary.nodes) deepest = std::max(deepest, n.depth);
    for (const BvhNodeBox& n : primary.nodes)
      paint.box(n.box, depthColor(n.depth, deepest), n.leaf ? 2.0f : 1.0f);
  }
  if (!d.rays) return;
  const auto describe = [&](const PrimitiveRef& ref) {
    return describeObject(state, display, ref);
  };
  const std::vector<RaySegment> tree = rayTree(*in, scene->scene(), reach, describe);
  for (const RaySegment& s : tree)
    paint.line(s.from, s.to, rayColor(s.kind), s.kind == RayKind::PastBlocker ? 1.0f : 2.0f);
  for (const RaySegment& s : tree) {
    if (s.kind == RayKind::PastBlocker || s.kind == RayKind::Lit) {
      paint.dot(s.to, IM_COL32(255, 230, 120, 255));
      if (s.kind == RayKind::Lit || s.level == 0)
        paint.label(s.to, s.label, IM_COL32(255, 230, 120, 255));
      continue;
    }
    paint.dot(s.to, rayColor(s.kind));
    paint.label(s.to, s.label, rayColor(s.kind));
  }
}

}  // namespace meshtrace::viewer
