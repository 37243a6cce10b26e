// Our vertex normals against OpenMesh's: per mesh the max and mean angle and
// the worst vertices; the data behind the deviation view.
#include <imgui.h>

#include <chrono>

#include "viewer/ui/panels.h"

namespace meshtrace::viewer {

void runCrossCheck(ViewerState& state) {
  if (!state.session.loaded()) return;
  const auto start = std::chrono::steady_clock::now();
  const auto& meshes = state.session.scene().meshes;
  state.crosschecks.assign(meshes.size(), std::nullopt);
  for (std::size_t i = 0; i < meshes.size(); ++i)
    state.crosschecks[i] = crosscheck::crossCheckNormals(meshes[i], 5);
  state.crosscheckMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

FalseColorScales deviationScales(const ViewerState& state, const RenderDisplay& display) {
  FalseColorScales s;
  s.deviationMax = 0.0;
  if (!display.prepared()) return s;
  const std::size_t renderMeshes = display.prepared()->scene().meshes.size();
  s.meshDeviation.assign(renderMeshes, nullptr);
  for (std::uint32_t i = 0; i < renderMeshes; ++i) {
    const std::uint32_t m = state.session.sceneMesh(i);
    if (m < state.crosschecks.size() && state.crosschecks[m]) {
      s.meshDeviation[i] = &state.crosschecks[m]->perVertexDegrees;
      s.deviationMax = std::max(s.deviationMax, state.crosschecks[m]->maxDegrees);
    }
  }
  // A scale that starts at a visible size: agreement to 1e-12 degrees should look uniform.
  s.deviationMax = std::max(s.deviationMax, 1e-6);
  return s;
}

void drawNormalsPanel(ViewerState& state, RenderDisplay& display) {
  if (!state.session.loaded()) return;
  if (state.session.meshes().empty()) {
    ImGui::TextDisabled("No meshes.");
    return;
  }
  const bool have = !state.crosschecks.empty() && state.crosschecks[0].has_value();
  if (ImGui::Button(have ? "Run again" : "Cross-check normals")) {
    runCrossCheck(state);
    display.invalidate();
  }
  if (!have) return;
  if (!state.options.hideTimings) {
    ImGui::SameLine();
    ImGui::Text("%.1f ms", state.crosscheckMs);
  }
  ImGui::TextDisabled("Angle-weighted normals through OpenMesh's half-edges.");
  for (std::size_t i = 0; i < state.crosschecks.size(); ++i) {
    const auto& r = state.crosschecks[i];
    if (!r) continue;
    ImGui::PushID(static_cast<int>(i));
    ImGui::Text("%s: max %.3g deg, mean %.3g deg over %zu vertices",
                state.session.meshes()[i].name.c_str(), r->maxDegrees, r->meanDegrees, r->compared);
    if (r->facesRejected || r->verticesSkipped)
      ImGui::TextColored(ImVec4(1, 0.7f, 0.3f, 1),
                         "  %zu faces OpenMesh refused, %zu vertices not compared",
                         r->facesRejected, r->verticesSkipped);
    if (ImGui::TreeNode("worst vertices")) {
      for (const auto& w : r->worst) ImGui::Text("vertex %u: %.3g deg", w.vertex, w.degrees);
      ImGui::TreePop();
    }
    ImGui::PopID();
  }
}

}  // namespace meshtrace::viewer
