// Comparison with a reference image: loading it, the difference image, RMSE
// and PSNR, and the error against time while the render progresses.
#include <imgui.h>
#include <imgui_stdlib.h>

#include "viewer/ui/panels.h"

namespace meshtrace::viewer {

namespace {
constexpr double kSampleEveryMs = 100.0;
constexpr int kDifferenceGain = 4;

void loadReference(ViewerState& state) {
  ReferenceState& ref = state.reference;
  ref.error.clear();
  ref.image = Image8{};
  if (ref.path.empty()) return;
  try {
    ref.image = readImage(ref.path);
  } catch (const std::exception& e) {
    ref.error = e.what();
    return;
  }
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(ref.image.width) * ref.image.height * 4,
                                 255);
  for (std::size_t i = 0; i < rgba.size() / 4; ++i)
    for (int k = 0; k < 3; ++k) rgba[i * 4 + k] = ref.image.rgb[i * 3 + k];
  ref.texture.resize(ref.image.width, ref.image.height);
  ref.texture.uploadAll(rgba.data());
  ref.differenceFor = ~0ull;
}

std::uint64_t frameStamp(const ProgressiveFrame& f) {
  std::uint64_t s = f.job << 32;
  for (std::uint32_t v : f.tileVersion) s += v;
  return s;
}
}  // namespace

void updateReference(ViewerState& state, RenderDisplay& display) {
  ReferenceState& ref = state.reference;
  // Comparing costs a pass over both images: only while someone looks.
  const bool shown =
      ref.panelOpen || state.view == View::SideBySide || state.view == View::Difference;
  if (!shown) return;
  if (!ref.path.empty() && ref.image.width == 0 && ref.error.empty()) loadReference(state);
  const ProgressiveFrame& frame = display.frame();
  if (ref.image.width == 0 || frame.width != ref.image.width || frame.height != ref.image.height ||
      frame.rgba.empty())
    return;
  const ProgressiveStatus status = display.status();
  if (ref.historyJob != status.job) {
    ref.historyJob = status.job;
    ref.errorHistory.clear();
    ref.lastSampleMs = -1.0;
  }
  const std::uint64_t stamp = frameStamp(frame);
  const bool due = ref.lastSampleMs < 0 || status.elapsedMs - ref.lastSampleMs >= kSampleEveryMs ||
                   status.finished;
  if (stamp == ref.differenceFor || !due) return;
  ref.differenceFor = stamp;
  const Image8 ours = display.colorImage();
  ref.current = compareImages(ours, ref.image);
  if (ref.lastSampleMs < 0 || status.elapsedMs - ref.lastSampleMs >= kSampleEveryMs) {
    ref.errorHistory.push_back(static_cast<float>(ref.current->rmse));
    ref.lastSampleMs = status.elapsedMs;
  }
  ref.differenceRgba.assign(static_cast<std::size_t>(ours.width) * ours.height * 4, 255);
  for (std::size_t i = 0; i < ref.differenceRgba.size() / 4; ++i)
    for (int k = 0; k < 3; ++k) {
      const int d = std::abs(int(ours.rgb[i * 3 + k]) - int(ref.image.rgb[i * 3 + k]));
      ref.differenceRgba[i * 4 + k] = static_cast<std::uint8_t>(std::min(255, d * kDifferenceGain));
    }
  ref.difference.resize(ours.width, ours.height);
  ref.difference.uploadAll(ref.differenceRgba.data());
}

void drawComparePanel(ViewerState& state, RenderDisplay& display) {
  ReferenceState& ref = state.reference;
  ImGui::SetNextItemWidth(-60);
  ImGui::InputTextWithHint("##ref", "reference image", &ref.pathField);
  ImGui::SameLine();
  if (ImGui::Button("Load")) {
    ref.path = ref.pathField;
    ref.image = Image8{};
    ref.error.clear();
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
  if (ref.image.width != frame.width || ref.image.height != frame.height) {
    ImGui::TextColored(ImVec4(1, 0.7f, 0.3f, 1), "reference is %dx%d, the render %dx%d",
                       ref.image.width, ref.image.height, frame.width, frame.height);
    return;
  }
  if (ref.current)
    ImGui::Text("RMSE %.3f  PSNR %.2f dB  max %d  (8-bit units)", ref.current->rmse,
                ref.current->psnr, ref.current->maxDifference);
  ImGui::TextDisabled("Difference view: |render - reference| x %d.", kDifferenceGain);
  if (!ref.errorHistory.empty()) {
    char label[64];
    std::snprintf(label, sizeof label, "RMSE every %.0f ms", kSampleEveryMs);
    ImGui::PlotLines("##error", ref.errorHistory.data(), static_cast<int>(ref.errorHistory.size()),
                     0, label, 0.0f, FLT_MAX, ImVec2(-1, 70));
  }
}

}  // namespace meshtrace::viewer
