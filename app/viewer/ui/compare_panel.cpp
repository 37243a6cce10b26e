// Comparison with a reference image: loading it, the difference image, RMSE
// and PSNR, and the error of each pass against time (pass_errors.h),
// compared in the background.
#include <imgui.h>
#include <imgui_stdlib.h>

#include "viewer/model/ab_compare.h"
#include "viewer/ui/panels.h"

namespace meshtrace::viewer {

void loadReference(ViewerState& state) {
  ReferenceState& ref = state.reference;
  ref.error.clear();
  ref.image = Image8{};
  ref.errors.clear();
  ref.current.reset();
  if (ref.path.empty()) return;
  try {
    ref.image = readImage(ref.path);
  } catch (const std::exception& e) {
    ref.error = e.what();
    return;
  }
  ref.texture.resize(ref.image.width, ref.image.height);
  ref.texture.uploadAll(toRgba(ref.image).data());
}

void updateReference(ViewerState& state, RenderDisplay& display) {
  ReferenceState& ref = state.reference;
  for (const PassErrors::Comparison& c : ref.task->take()) {
    if (c.job != ref.errors.job()) continue;
    ref.errors.merge(c);
    ref.current = c.current;
    ref.difference.resize(ref.image.width, ref.image.height);
    ref.difference.uploadAll(c.differenceRgba.data());
  }
  // Comparing costs passes over both images: only while someone looks.
  const bool shown =
      ref.panelOpen || state.view == View::SideBySide || state.view == View::Difference;
  if (!shown) return;
  if (!ref.path.empty() && ref.image.width == 0 && ref.error.empty()) loadReference(state);
  const ProgressiveFrame& frame = display.frame();
  const ProgressiveStatus& status = display.frameStatus();
  // A render without colours (a probe view) has nothing to compare: no
  // figure from an earlier render stays up as if it were this one's.
  if (status.job != ref.errors.job() && ref.current) ref.current.reset();
  if (ref.image.width == 0 || frame.width != ref.image.width || frame.height != ref.image.height ||
      frame.rgba.empty() || frame.job != status.job || !ref.errors.due(status) || ref.task->busy())
    return;
  const int firstPass = status.job == ref.errors.job() ? ref.errors.nextPass() : 0;
  ref.errors.asked(status);
  auto copy = std::make_shared<FrameCopy>();
  copy->job = status.job;
  copy->frame = frame;
  copy->status = status;
  ref.task->start(
      [copy, reference = ref.image, firstPass](TaskContext<PassErrors::Comparison>& task) {
        task.publish(PassErrors::compare(*copy, reference, firstPass));
      },
      "comparing with the reference");
}

void drawComparePanel(ViewerState& state, RenderDisplay& display) {
  ReferenceState& ref = state.reference;
  ImGui::SetNextItemWidth(-60);
  ImGui::InputTextWithHint("##ref", "reference image", &ref.pathField);
  ImGui::SameLine();
  if (ImGui::Button("Load")) {
    ref.path = ref.pathField;
    loadReference(state);
  }
  if (ref.path.empty()) {
    ImGui::TextDisabled("No reference found beside the scene; type a path.");
    return;
  }
  if (!ref.error.empty()) {
    ImGui::TextColored(ImVec4(1, 0.4f, 0.4f, 1), "%s", ref.error.c_str());
    return;
  }
  const ProgressiveFrame& frame = display.frame();
  if (frame.width > 0 && frame.rgba.empty()) {
    ImGui::TextColored(ImVec4(1, 0.7f, 0.3f, 1),
                       "The %s view renders no colours: nothing to compare.", label(state.view));
    return;
  }
  if (ref.image.width != frame.width || ref.image.height != frame.height) {
    ImGui::TextColored(ImVec4(1, 0.7f, 0.3f, 1), "reference is %dx%d, the render %dx%d",
                       ref.image.width, ref.image.height, frame.width, frame.height);
    return;
  }
  if (ref.current)
    ImGui::Text("RMSE %.3f  PSNR %.2f dB  max %d  (8-bit units)", ref.current->rmse,
                ref.current->psnr, ref.current->maxDifference);
  ImGui::TextDisabled("Difference view: |render - reference| x %d.", PassErrors::kDifferenceGain);
  drawErrorPlot(state, ref.errors.points());
}

}  // namespace meshtrace::viewer
