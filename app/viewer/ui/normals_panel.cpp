// Our vertex normals against OpenMesh's: per mesh the max and mean angle and
// the worst vertices; the data behind the deviation view.
#include <imgui.h>

#include <chrono>

#include "viewer/ui/panels.h"

namespace meshtrace::viewer {

void startCrossCheck(ViewerState& state) {
  if (!state.session.loaded()) return;
  // The scene as loaded: its meshes' own normals are computed where they
  // lack them (crossCheckNormals), off the UI thread.
  const std::shared_ptr<const Scene> scene = state.session.sharedScene();
  state.crosscheck.task->start(
      [scene](TaskContext<CrossCheckState::Result>& task) {
        const auto start = std::chrono::steady_clock::now();
        CrossCheckState::Result r;
        r.reports.assign(scene->meshes.size(), std::nullopt);
        for (std::size_t i = 0; i < scene->meshes.size(); ++i) {
          if (task.cancelled()) return;
          task.setPhase("checking " + scene->meshes[i].file().filename().string());
          r.reports[i] = crosscheck::crossCheckNormals(scene->meshes[i], 5);
        }
        r.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                   .count();
        task.publish(std::move(r));
      },
      "checking the normals against OpenMesh");
}

FalseColorScales deviationScales(const ViewerState& state, const RenderDisplay& display) {
  FalseColorScales s;
  s.deviationMax = 0.0;
  const auto& scene = display.renderScene();
  if (!scene) return s;
  const auto& reports = state.crosscheck.reports;
  s.meshDeviation.assign(scene->sceneMesh.size(), nullptr);
  for (std::size_t i = 0; i < scene->sceneMesh.size(); ++i) {
    const std::uint32_t m = scene->sceneMesh[i];
    if (m < reports.size() && reports[m]) {
      s.meshDeviation[i] = &reports[m]->perVertexDegrees;
      s.deviationMax = std::max(s.deviationMax, reports[m]->maxDegrees);
    }
  }
  // A scale that starts at a visible size: agreement to 1e-12 degrees should look uniform.
  s.deviationMax = std::max(s.deviationMax, 1e-6);
  return s;
}

void drawNormalsPanel(ViewerState& state, RenderDisplay&) {
  if (!state.session.loaded()) return;
  if (state.session.meshes().empty()) {
    ImGui::TextDisabled("No meshes.");
    return;
  }
  CrossCheckState& check = state.crosscheck;
  if (check.task->busy()) {
    ImGui::Text("%s ...", check.task->phase().c_str());
    return;
  }
  if (ImGui::Button(check.done() ? "Run again" : "Cross-check normals")) startCrossCheck(state);
  if (!check.done()) return;
  if (!state.options.hideTimings) {
    ImGui::SameLine();
    ImGui::Text("%.1f ms", check.ms);
  }
  ImGui::TextDisabled("Angle-weighted normals through OpenMesh's half-edges.");
  // The figures' lines, as a region for --describe: their last digits are
  // rounding noise that moves with any change to either side's arithmetic,
  // so the snapshot tests read them as text, not as pixels.
  const ImVec2 top = ImGui::GetCursorScreenPos();
  // To the window's edge: a long line runs past the content region, clipped.
  const float right = ImGui::GetWindowPos().x + ImGui::GetWindowSize().x;
  for (std::size_t i = 0; i < check.reports.size(); ++i) {
    const auto& r = check.reports[i];
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
  state.regions["normals_figures"] = {top.x, top.y, right, ImGui::GetCursorScreenPos().y};
}

}  // namespace meshtrace::viewer
