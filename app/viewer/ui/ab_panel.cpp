// A/B: keep the current render as B, change something (a mesh's mode, the
// triangle test, the precision, a mesh hidden), then flip or wipe between
// the new render A and B, or look at their difference, with RMSE, PSNR and
// the largest difference; compared in the background.
#include <imgui.h>

#include "viewer/model/camera_control.h"
#include "viewer/model/pass_errors.h"
#include "viewer/ui/panels.h"

namespace meshtrace::viewer {

namespace {
// What the current render is made with, in a line.
std::string settingsLabel(const ViewerState& state) {
  std::string meshes;
  for (const MeshState& m : state.session.meshes()) {
    if (!m.visible)
      meshes += (meshes.empty() ? "" : ", ") + m.name + " hidden";
    else if (m.shading != m.fileShading)
      meshes += (meshes.empty() ? "" : ", ") + m.name + " " + toString(m.shading);
  }
  if (meshes.empty()) meshes = "the file's meshes";
  return meshes + "; " + toString(state.trace.triangle.test) + " " +
         toString(state.trace.triangle.precision) + ", " + toString(state.trace.accel) +
         (state.extraSamples ? ", AA " + std::to_string(state.extraSamples) : "");
}
}  // namespace

bool keepAsB(ViewerState& state, RenderDisplay& display) {
  const ProgressiveFrame& frame = display.frame();
  if (frame.rgba.empty() || !display.showsImage()) return false;
  AbState& ab = state.ab;
  KeptImage kept;
  kept.image = display.colorImage();
  kept.label = settingsLabel(state);
  kept.camera = state.session.camera();
  kept.exact = display.frameStatus().exactDone && display.frameStatus().job == frame.job;
  ab.texture.resize(kept.image.width, kept.image.height);
  ab.texture.uploadAll(toRgba(kept.image).data());
  ab.b = std::move(kept);
  ab.stats.reset();
  ab.comparedJob = 0;
  ab.task->cancel();
  return true;
}

void updateAb(ViewerState& state, RenderDisplay& display) {
  AbState& ab = state.ab;
  for (AbComparison& c : ab.task->take()) {
    if (c.job != ab.comparedJob) continue;
    ab.stats = c.difference;
    ab.difference.resize(ab.b->image.width, ab.b->image.height);
    ab.difference.uploadAll(c.differenceRgba.data());
  }
  if (!ab.b) return;
  // A is compared once its render has finished: a figure of a half-done
  // render would move with every pass.
  const ProgressiveFrame& frame = display.frame();
  const ProgressiveStatus& status = display.frameStatus();
  if (status.job != ab.comparedJob && ab.stats) ab.stats.reset();
  if (!status.finished || status.job != frame.job || status.job == ab.comparedJob ||
      frame.rgba.empty() || frame.width != ab.b->image.width || frame.height != ab.b->image.height)
    return;
  ab.comparedJob = status.job;
  auto copy = std::make_shared<FrameCopy>();
  copy->job = status.job;
  copy->frame = frame;
  ab.task->start(
      [copy, b = ab.b->image](TaskContext<AbComparison>& task) {
        task.publish(compareWithB(copy->job, currentImage(copy->frame), b));
      },
      "comparing A with B");
}

void drawAbPanel(ViewerState& state, RenderDisplay& display) {
  AbState& ab = state.ab;
  if (ImGui::Button("Keep as B") && !keepAsB(state, display))
    setMessage(state, "nothing to keep: the colour image is not rendered in this view", true);
  if (!ab.b) {
    ImGui::SameLine();
    ImGui::TextDisabled("then change something, and flip or wipe.");
    return;
  }
  ImGui::SameLine();
  ImGui::TextWrapped("B: %s%s", ab.b->label.c_str(), ab.b->exact ? "" : " (kept mid-render)");
  ImGui::Text("A: %s", settingsLabel(state).c_str());
  for (int i = 0; i < kAbModeCount; ++i) {
    if (i) ImGui::SameLine();
    int mode = static_cast<int>(ab.mode);
    if (ImGui::RadioButton(label(static_cast<AbMode>(i)), &mode, i))
      ab.mode = static_cast<AbMode>(mode);
  }
  ImGui::SameLine();
  if (ImGui::SmallButton("Flip")) ab.mode = ab.mode == AbMode::B ? AbMode::A : AbMode::B;
  if (ab.mode == AbMode::Wipe) {
    ImGui::SetNextItemWidth(200);
    ImGui::SliderFloat("wipe", &ab.wipe, 0.0f, 1.0f, "%.2f");
    ImGui::TextDisabled("A left of the line, B right; drag the line over the image.");
  }
  const ProgressiveFrame& frame = display.frame();
  if (frame.width > 0 && (frame.width != ab.b->image.width || frame.height != ab.b->image.height))
    ImGui::TextColored(ImVec4(1, 0.7f, 0.3f, 1), "A is %dx%d, B %dx%d", frame.width, frame.height,
                       ab.b->image.width, ab.b->image.height);
  else if (frame.width > 0 && frame.rgba.empty())
    ImGui::TextColored(ImVec4(1, 0.7f, 0.3f, 1), "The %s view renders no colours to compare.",
                       label(state.view));
  else if (ab.stats)
    ImGui::Text("A vs B: RMSE %.3f  PSNR %.2f dB  max %d  (8-bit units)", ab.stats->rmse,
                ab.stats->psnr, ab.stats->maxDifference);
  else
    ImGui::TextDisabled("A vs B: once A's render has finished");
  if (!sameCamera(ab.b->camera, state.session.camera()))
    ImGui::TextColored(ImVec4(1, 0.7f, 0.3f, 1),
                       "The camera moved since B was kept: they show different views.");
}

}  // namespace meshtrace::viewer
