#include "viewer_app.h"

#include <imgui.h>

#include <algorithm>

#include "panels.h"

namespace meshtrace::viewer {

namespace {
constexpr ImGuiWindowFlags kPanelFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                         ImGuiWindowFlags_NoCollapse |
                                         ImGuiWindowFlags_NoSavedSettings;

bool wanted(const ViewerOptions& o, const char* panel) {
  for (const std::string& p : o.open)
    if (p == panel) return true;
  return false;
}

void placeWindow(float x, float width) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(x, 0), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(width, display.y), ImGuiCond_Always);
}

bool section(const char* title, bool open) {
  ImGui::SetNextItemOpen(open, ImGuiCond_Once);
  return ImGui::CollapsingHeader(title);
}
}  // namespace

ViewerApp::ViewerApp(const ViewerOptions& options, const std::filesystem::path& executable)
    : display_(options.threads, options.workerNice) {
  state_.options = options;
  state_.executable = executable;
  applyOptions();
  sync();  // start rendering now, not after the first frame's GL set-up
}

void ViewerApp::applyOptions() {
  const ViewerOptions& o = state_.options;
  state_.view = o.view;
  state_.overlay = o.overlay;
  state_.opacity = static_cast<float>(o.overlayOpacity);
  state_.extraSamples = o.extraSamples;
  try {
    state_.trace.accel = parseAccelMethod(o.accel);
  } catch (const std::invalid_argument& e) {
    setMessage(state_, e.what(), true);
  }
  if (!o.noDefaultDirs)
    for (const auto& [root, title] : defaultSceneRoots(state_.executable))
      addFolder(state_, root, title);
  for (const std::string& dir : o.sceneDirs)
    addFolder(state_, dir, std::filesystem::path(dir).filename().string());
  if (o.scene.empty()) return;
  if (o.noDefaultDirs)
    addFolder(state_, std::filesystem::path(o.scene).parent_path(), "this scene's folder");
  openScene(state_, o.scene);
  for (const auto& [mesh, mode] : o.shading) {
    if (const auto i = findMesh(state_.session, mesh))
      state_.session.setShading(*i, mode == "PHONG" ? Shading::Phong : Shading::Flat);
    else
      setMessage(state_, "--shading: no mesh '" + mesh + "'", true);
  }
  for (const std::string& mesh : o.hide) {
    if (const auto i = findMesh(state_.session, mesh))
      state_.session.setVisible(*i, false);
    else
      setMessage(state_, "--hide: no mesh '" + mesh + "'", true);
  }
  if (o.pin) state_.pinned = PixelRef{o.pin->first, o.pin->second};
  if (!o.reference.empty()) {
    state_.reference.path = o.reference;
    state_.reference.pathField = o.reference;
  }
}

RenderWish ViewerApp::wish() const {
  RenderWish w;
  w.view = state_.view;
  w.overlay = state_.overlay;
  w.extraSamples = state_.extraSamples;
  w.trace = state_.trace;
  return w;
}

void ViewerApp::sync() {
  if (!display_.sync(state_.session, wish())) return;
  jobFrames_ = 0;
  TimingStats& t = state_.timing;
  if (t.awaitingFirstJob) {
    t.awaitingFirstJob = false;
    t.openToRenderStartMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t.openedAt)
            .count();
  }
}

void ViewerApp::frame() {
  const ImGuiIO& io = ImGui::GetIO();
  if (io.MouseDelta.x != 0 || io.MouseDelta.y != 0 || io.MouseWheel != 0 ||
      ImGui::IsAnyMouseDown() || io.InputQueueCharacters.Size > 0 || ImGui::IsAnyItemActive())
    lastInteraction_ = std::chrono::steady_clock::now();
  sync();
  if (state_.view == View::NormalDeviation && state_.session.loaded() &&
      !state_.session.meshes().empty() && (state_.crosschecks.empty() || !state_.crosschecks[0])) {
    runCrossCheck(state_);
    display_.invalidate();
  }
  display_.update(deviationScales(state_, display_));
  updateReference(state_, display_);

  const ImVec2 size = ImGui::GetIO().DisplaySize;
  const float leftWidth = std::clamp(0.22f * size.x, 230.0f, 320.0f);
  const float rightWidth = std::clamp(0.32f * size.x, 330.0f, 440.0f);
  placeWindow(0, leftWidth);
  ImGui::Begin("Scenes", nullptr, kPanelFlags);
  drawScenePanel(state_);
  ImGui::Separator();
  ImGui::TextUnformatted("Objects");
  drawObjectsPanel(state_);
  ImGui::End();

  placeWindow(leftWidth, size.x - leftWidth - rightWidth);
  const std::string title =
      (state_.session.file().empty() ? std::string("No scene")
                                     : state_.session.file().filename().string()) +
      "###image";
  ImGui::Begin(title.c_str(), nullptr, kPanelFlags | ImGuiWindowFlags_NoScrollbar);
  if (!state_.message.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, state_.messageIsError ? ImVec4(1, 0.45f, 0.45f, 1)
                                                               : ImVec4(0.6f, 1, 0.6f, 1));
    ImGui::TextWrapped("%s", state_.message.c_str());
    ImGui::PopStyleColor();
  }
  drawImageView(state_, display_);
  ImGui::End();

  placeWindow(size.x - rightWidth, rightWidth);
  ImGui::Begin("Details", nullptr, kPanelFlags);
  const ViewerOptions& o = state_.options;
  if (section("Render", true)) drawRenderPanel(state_, display_);
  if (section("Inspector", true)) drawInspectorPanel(state_, display_);
  if (section("Camera", wanted(o, "camera"))) drawCameraPanel(state_);
  if (section("Normals vs OpenMesh", wanted(o, "normals"))) drawNormalsPanel(state_, display_);
  state_.reference.panelOpen = section("Compare with a reference", wanted(o, "compare"));
  if (state_.reference.panelOpen) drawComparePanel(state_, display_);
  if (section("Save", wanted(o, "save"))) drawSavePanel(state_, display_);
  ImGui::End();
  // A change made in this frame restarts the render now, not next frame.
  sync();
}

void ViewerApp::frameDrawn(double ms) {
  TimingStats& t = state_.timing;
  t.lastFrameMs = ms;
  ++t.frames;
  t.frameHistory.push_back(static_cast<float>(ms));
  if (t.frameHistory.size() > 240) t.frameHistory.erase(t.frameHistory.begin());
  const ProgressiveStatus s = display_.status();
  if (s.job != timedJob_) {
    timedJob_ = s.job;
    jobFrames_ = 0;
  }
  // The frame that loaded a scene pays for the load; it is timed apart (load).
  if (s.running && ++jobFrames_ > 1) t.maxFrameMs = std::max(t.maxFrameMs, ms);
}

void ViewerApp::drop(const std::vector<std::string>& paths) {
  for (const std::string& p : paths) openPath(state_, p);
}

bool ViewerApp::idle() const {
  if (!state_.session.loaded()) return true;
  const ProgressiveStatus s = display_.status();
  return s.finished && display_.frame().job == s.job;
}

double ViewerApp::framePeriodMs() const {
  const double sinceInput =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - lastInteraction_)
          .count();
  return sinceInput < 1000.0 ? 1000.0 / 60.0 : 1000.0 / 15.0;
}

std::string ViewerApp::takeScreenshotRequest() {
  std::string r;
  std::swap(r, state_.screenshotRequest);
  return r;
}

void ViewerApp::printStats() const {
  const ProgressiveStatus s = display_.status();
  std::printf(
      "load %.1f ms, first coarse image %.1f ms after the render started (%.1f ms after opening), "
      "exact image %.1f ms, finished %.1f ms, %d threads\n",
      state_.timing.loadMs, s.firstCoarseMs, state_.timing.openToRenderStartMs + s.firstCoarseMs,
      s.exactMs, s.finishedMs, display_.threads());
  std::printf("frames %d, longest frame while rendering %.1f ms\n", state_.timing.frames,
              state_.timing.maxFrameMs);
}

}  // namespace meshtrace::viewer
