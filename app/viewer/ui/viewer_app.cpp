#include "viewer/ui/viewer_app.h"

#include <imgui.h>

#include <algorithm>

#include "viewer/ui/panels.h"

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

double msSince(ViewerApp::Clock::time_point t) {
  return std::chrono::duration<double, std::milli>(ViewerApp::Clock::now() - t).count();
}
}  // namespace

ViewerApp::ViewerApp(const ViewerOptions& options, const std::filesystem::path& executable,
                     std::function<void()> wake)
    : display_(options.threads, options.workerNice, std::move(wake)) {
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
      state_.session.setShading(*i, mode);
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
  TimingStats& t = state_.timing;
  // The render of a scene just opened was asked for when it was opened,
  // before its load; any other render, by this frame's input.
  const Clock::time_point requestedAt = t.openedAt.value_or(t.actionTime());
  const bool started = display_.sync(state_.session, wish(), requestedAt);
  if (started) openingJobAt_.reset();
  if (started && t.openedAt) openingJobAt_ = t.openedAt;
  if (started || !state_.session.loaded()) t.openedAt.reset();
}

void ViewerApp::frame(Clock::time_point inputAt) {
  state_.timing.frameInputAt = inputAt;
  renderingAtFrameStart_ = display_.status().running;
  const ImGuiIO& io = ImGui::GetIO();
  if (io.MouseDelta.x != 0 || io.MouseDelta.y != 0 || io.MouseWheel != 0 ||
      ImGui::IsAnyMouseDown() || io.InputQueueCharacters.Size > 0 || ImGui::IsAnyItemActive())
    framesSinceInput_ = 0;
  else
    ++framesSinceInput_;
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
  state_.timing.frameInputAt.reset();
}

bool ViewerApp::waitingForOpeningImage() const {
  return openingJobAt_ && display_.awaitingFirstImage() && msSince(*openingJobAt_) < kOpeningWaitMs;
}

bool ViewerApp::shouldPresent() const { return !waitingForOpeningImage(); }

bool ViewerApp::frameDone(double ms) {
  TimingStats& t = state_.timing;
  ++t.frames;
  // A frame counts as drawn while rendering when a render ran at its start
  // or at its end (one it started: opening a scene, moving the camera).
  const bool rendering = renderingAtFrameStart_ || display_.status().running;
  if (rendering) t.renderingFrames.add(ms);
  return rendering;
}

void ViewerApp::drop(const std::vector<std::string>& paths) {
  for (const std::string& p : paths) openPath(state_, p);
}

bool ViewerApp::idle() const {
  if (!state_.session.loaded()) return true;
  const ProgressiveStatus s = display_.status();
  return s.finished && display_.frame().job == s.job;
}

double ViewerApp::waitBeforeNextFrameMs(Clock::time_point lastFrameInput) const {
  if (display_.imageWaiting()) return 0.0;
  if (waitingForOpeningImage()) return std::max(0.0, kOpeningWaitMs - msSince(*openingJobAt_));
  double ms = 1000.0 / 10.0;
  // Input itself ends the wait; these frames serve what follows input
  // without more of it (a button's release, a menu closing): a few suffice.
  if (framesSinceInput_ < kFramesAfterInput)
    ms = 1000.0 / 60.0;
  else if (idle())
    ms = 250.0;
  return std::max(0.0, ms - msSince(lastFrameInput));
}

std::string ViewerApp::takeScreenshotRequest() {
  std::string r;
  std::swap(r, state_.screenshotRequest);
  return r;
}

void ViewerApp::printStats() const {
  const ProgressiveStatus s = display_.status();
  const ShownTimes& shown = display_.shownTimes();
  const FrameStats& frames = state_.timing.renderingFrames;
  std::printf(
      "load %.1f ms; from opening the scene (or the last change) to the texture: first image "
      "%.1f ms, exact image %.1f ms; the render's own first pass %.1f ms, exact %.1f ms, finished "
      "%.1f ms; %d threads\n",
      state_.timing.loadMs, shown.firstImageMs, shown.exactImageMs, s.firstCoarseMs, s.exactMs,
      s.finishedMs, display_.threads());
  std::printf("frames %d, while rendering %zu: longest %s, 99th percentile %s\n",
              state_.timing.frames, frames.count(), formatMs(frames.longest()).c_str(),
              formatMs(frames.percentile(99.0)).c_str());
}

}  // namespace meshtrace::viewer
