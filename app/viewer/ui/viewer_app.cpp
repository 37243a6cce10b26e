#include "viewer/ui/viewer_app.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "viewer/model/observer.h"
#include "viewer/ui/message_colors.h"
#include "viewer/ui/panels.h"

namespace meshtrace::viewer {

namespace {
constexpr ImGuiWindowFlags kPanelFlags = ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                                         ImGuiWindowFlags_NoCollapse |
                                         ImGuiWindowFlags_NoSavedSettings;

// The side panels: their width is dragged at their inner edge (and kept in
// the settings); placed each frame below the menu bar.
constexpr ImGuiWindowFlags kSidePanelFlags = kPanelFlags & ~ImGuiWindowFlags_NoResize;

// A width the user dragged the current window to, kept for the next frames.
void keepWidth(ViewerState& state, SidePanel& panel, float placed) {
  const float now = ImGui::GetWindowWidth();
  if (std::abs(now - placed) < 0.5f) return;
  panel.width = now;
  state.settingsChanged = true;
}

bool wanted(const ViewerOptions& o, const char* panel) {
  for (const std::string& p : o.open)
    if (p == panel) return true;
  return false;
}

// Below the menu bar, `top` pixels high.
void placeWindow(float x, float width, float top) {
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  ImGui::SetNextWindowPos(ImVec2(x, top), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(width, display.y - top), ImGuiCond_Always);
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
    : display_(options.threads, options.workerNice, wake) {
  state_.options = options;
  state_.executable = executable;
  state_.scenes.pipeline = std::make_unique<ScenePipeline>(wake);
  state_.crosscheck.task = std::make_unique<BackgroundTask<CrossCheckState::Result>>(wake);
  state_.reference.task = std::make_unique<BackgroundTask<PassErrors::Comparison>>(wake);
  state_.ab.task = std::make_unique<BackgroundTask<AbComparison>>(wake);
  state_.layersSave = std::make_unique<BackgroundTask<std::string>>(wake);
  applyOptions();
  sync();  // start loading now, not after the first frame's GL set-up
}

void ViewerApp::useSettings(const std::filesystem::path& file) {
  state_.settingsPath = file;
  state_.settings = loadSettings(file);
  if (state_.session.loaded()) rememberScene(state_);
}

void ViewerApp::applyOptions() {
  const ViewerOptions& o = state_.options;
  state_.view = o.view;
  state_.overlay = o.overlay;
  state_.opacity = static_cast<float>(o.overlayOpacity);
  state_.extraSamples = o.extraSamples;
  state_.trace = o.trace;
  state_.draw = o.draw;
  if (!o.noDefaultDirs)
    for (const auto& [root, title] : defaultSceneRoots(state_.executable))
      addFolder(state_, root, title);
  for (const std::string& dir : o.sceneDirs)
    addFolder(state_, dir, std::filesystem::path(dir).filename().string());
  if (o.scene.empty()) return;
  if (o.noDefaultDirs) {
    // A scene named without a folder is in the current one ("" is none).
    std::filesystem::path folder = std::filesystem::path(o.scene).parent_path();
    if (folder.empty()) folder = ".";
    addFolder(state_, folder, "this scene's folder");
  }
  openScene(state_, o.scene);
  state_.sceneOptionsPending = true;
  state_.depthCheckPending = o.draw.cut && o.depthGiven;
}

void ViewerApp::applySceneOptions() {
  state_.sceneOptionsPending = false;
  const ViewerOptions& o = state_.options;
  // With A/B from the command line, B's settings come first (advanceAbSetup).
  applyShading("--shading", o.shading);
  if (o.keepB()) {
    applyShading("--b-shading", o.bShading);
    if (o.bTrace) state_.trace = *o.bTrace;
    abStage_ = AbStage::RenderingB;
  }
  for (const std::string& mesh : o.hide) {
    if (const auto i = findMesh(state_.session, mesh))
      state_.session.setVisible(*i, false);
    else
      refuse("--hide: the scene has no mesh '" + mesh + "'" + meshNames(state_.session));
  }
  if (o.pin) {
    const CameraSpec& c = state_.session.camera();
    const auto [x, y] = *o.pin;
    if (x < 0 || y < 0 || x >= c.width || y >= c.height)
      refuse("--pin " + std::to_string(x) + "," + std::to_string(y) + ": the image is " +
             std::to_string(c.width) + "x" + std::to_string(c.height) + " (x 0.." +
             std::to_string(c.width - 1) + ", y 0.." + std::to_string(c.height - 1) + ")");
    else
      state_.pinned = PixelRef{x, y};
  }
  if (o.observer) {
    state_.observer.active = true;
    state_.observer.camera = observerCamera(state_.session.camera(), state_.session.scene());
  }
  if (o.zoom) {
    const CameraSpec& c = state_.session.camera();
    // About the pinned pixel's centre (storage rows count from the top).
    const double col = state_.pinned ? state_.pinned->x + 0.5 : c.width / 2.0;
    const double row =
        state_.pinned ? flippedRow(state_.pinned->y, c.height) + 0.5 : c.height / 2.0;
    state_.viewport.zoomTo(*o.zoom, col, row);
  }
  if (!o.reference.empty()) {
    state_.reference.path = o.reference;
    state_.reference.pathField = o.reference;
    loadReference(state_);
    if (!state_.reference.error.empty()) refuse("--reference: " + state_.reference.error);
  }
}

void ViewerApp::applyShading(const char* option,
                             const std::vector<std::pair<std::string, Shading>>& modes) {
  for (const auto& [mesh, mode] : modes) {
    if (const auto i = findMesh(state_.session, mesh))
      state_.session.setShading(*i, mode);
    else
      refuse(std::string(option) + ": the scene has no mesh '" + mesh + "'" +
             meshNames(state_.session));
  }
}

void ViewerApp::advanceAbSetup() {
  if (abStage_ != AbStage::RenderingB || !state_.session.loaded()) return;
  if (!showsLatestRequest()) return;
  abStage_ = AbStage::Done;
  if (!keepAsB(state_, display_)) {
    refuse("--b-*: the colour image is not rendered in the " + std::string(label(state_.view)) +
           " view: nothing to keep as B");
    return;
  }
  // Now A: the command line's own settings.
  const ViewerOptions& o = state_.options;
  for (std::size_t i = 0; i < state_.session.meshes().size(); ++i)
    state_.session.setShading(i, state_.session.meshes()[i].fileShading);
  applyShading("--shading", o.shading);
  state_.trace = o.trace;
  state_.ab.mode = o.abMode;
  state_.ab.wipe = o.wipe;
}

void ViewerApp::checkBvhDepth() {
  state_.depthCheckPending = false;
  const DrawOptions& d = state_.options.draw;
  const BvhCut root = bvhCut(state_.scenes.render->prepared->intersector(), d.level, 0, 1);
  std::string problem;
  if (root.boxes.empty())
    problem = std::string("--draw cut: the scene has no ") + toString(d.level) + " BVH";
  else if (d.depth > root.levelDepth)
    problem = "--bvh-depth " + std::to_string(d.depth) + ": the " + toString(d.level) +
              " BVH's deepest nodes are at depth " + std::to_string(root.levelDepth);
  if (!problem.empty()) refuse(problem);
}

void ViewerApp::refuse(const std::string& problem) {
  state_.optionErrors.push_back(problem);
  state_.message = problem;
  state_.messageIsError = true;
  // Headless, failures() reports these once at the end.
  if (!state_.options.headless) std::fprintf(stderr, "%s\n", problem.c_str());
}

RenderWish ViewerApp::wish() const {
  RenderWish w;
  w.view = state_.view;
  w.overlay = state_.overlay;
  w.extraSamples = state_.extraSamples;
  return w;
}

void ViewerApp::receive() {
  SceneRequests& scenes = state_.scenes;
  for (auto& object : state_.retired) display_.dispose(std::move(object));
  state_.retired.clear();
  for (Arrival& a : scenes.pipeline->take()) {
    if (state_.reload.pending && !a.error.empty()) {
      reloadFailed(state_, a.error);
      continue;
    }
    if (state_.reload.pending && a.loaded) {
      reloaded(state_, *a.loaded);
      // The opening's render scene has the file's modes: kept only when the
      // user's switches are those (else requestRenderScene asks for theirs).
      if (!state_.session.meshesChanged()) scenes.meshRevision = state_.session.meshRevision();
      state_.timing.loadMs = a.loaded->ms;
    } else if (!a.error.empty()) {
      state_.session.fail(a.error);
      if (!state_.options.headless) std::fprintf(stderr, "error: %s\n", a.error.c_str());
      display_.dispose(std::exchange(scenes.preview, nullptr));
      display_.dispose(std::exchange(scenes.render, nullptr));
      display_.stop();
      state_.sceneOptionsPending = false;
      watchOpenScene(state_);
      continue;
    } else if (a.loaded) {
      state_.session.adopt(*a.loaded);
      rememberScene(state_);
      showSceneWarnings(state_);
      watchOpenScene(state_);
      scenes.meshRevision = state_.session.meshRevision();
      state_.timing.loadMs = a.loaded->ms;
      state_.crosscheck.reports.assign(state_.session.meshes().size(), std::nullopt);
      if (state_.sceneOptionsPending) applySceneOptions();
    }
    if (a.preview && !scenes.render) scenes.preview = a.preview;
    if (a.render && a.render->request == scenes.lastId) {
      display_.dispose(std::exchange(scenes.render, a.render));
      display_.dispose(std::exchange(scenes.preview, nullptr));
      display_.dispose(state_.session.adoptBase(*a.render));
      if (state_.depthCheckPending) checkBvhDepth();
    }
    // What was not kept (an answer to an older request) goes too.
    display_.dispose(std::move(a.preview));
    display_.dispose(std::move(a.render));
  }
  const std::string failed = scenes.pipeline->error();
  if (!failed.empty() && failed != scenes.failure) {
    scenes.failure = failed;
    setMessage(state_, "could not prepare the scene: " + failed, true);
  }
}

void ViewerApp::requestRenderScene() {
  SceneRequests& scenes = state_.scenes;
  const SceneSession& session = state_.session;
  if (!session.loaded()) return;
  if (session.meshRevision() == scenes.meshRevision && sameTrace(state_.trace, scenes.trace))
    return;
  scenes.meshRevision = session.meshRevision();
  scenes.trace = state_.trace;
  scenes.failure.clear();
  scenes.pipeline->prepare(session.request(state_.trace, ++scenes.lastId));
}

void ViewerApp::runBackgroundWork() {
  CrossCheckState& check = state_.crosscheck;
  for (CrossCheckState::Result& r : check.task->take()) {
    check.reports = std::move(r.reports);
    check.ms = r.ms;
    display_.invalidate();
  }
  if (state_.view == View::NormalDeviation && state_.session.loaded() &&
      !state_.session.meshes().empty() && !check.done() && !check.task->busy())
    startCrossCheck(state_);
  updateReference(state_, display_);
  updateAb(state_, display_);
  collectLayersSave(state_);
  if (const std::string error = state_.settingsWriter.takeError(); !error.empty())
    setMessage(state_, "settings not saved: " + error, true);
}

void ViewerApp::sync() {
  receive();
  requestRenderScene();
  TimingStats& t = state_.timing;
  const SceneRequests& scenes = state_.scenes;
  // The render of a scene just opened was asked for when it was opened,
  // before its load; any other render, by this frame's input.
  const Clock::time_point requestedAt = t.openedAt.value_or(t.actionTime());
  const std::shared_ptr<const RenderScene> scene = scenes.render ? scenes.render : scenes.preview;
  const ObserverState& observer = state_.observer;
  const CameraSpec& camera =
      observer.active && observer.camera ? *observer.camera : state_.session.camera();
  const bool started =
      display_.sync(state_.session.loaded() ? scene : nullptr, camera, wish(), requestedAt);
  if (started) {
    const auto ms = [](double v) {
      return std::chrono::duration_cast<Clock::duration>(
          std::chrono::duration<double, std::milli>(v));
    };
    firstImageDeadline_ =
        t.openedAt ? *t.openedAt + ms(kOpeningWaitMs) : Clock::now() + ms(kRestartWaitMs);
  }
  // The opening ends with the full render's start (a preview's is not it).
  if ((started && scene && !scene->preview) ||
      (!state_.session.loaded() && !state_.session.opening()))
    t.openedAt.reset();
}

void ViewerApp::frame(Clock::time_point inputAt) {
  state_.timing.frameInputAt = inputAt;
  // The watched files are looked at a few times a second: an edit shows
  // soon after it is saved, and the stat calls cost the frames nothing.
  if (inputAt >= state_.reload.nextCheck) {
    state_.reload.nextCheck = inputAt + std::chrono::milliseconds(kWatchIntervalMs);
    checkWatchedFiles(state_);
  }
  renderingAtFrameStart_ = display_.status().running;
  const ImGuiIO& io = ImGui::GetIO();
  if (io.MouseDelta.x != 0 || io.MouseDelta.y != 0 || io.MouseWheel != 0 ||
      ImGui::IsAnyMouseDown() || io.InputQueueCharacters.Size > 0 || ImGui::IsAnyItemActive())
    framesSinceInput_ = 0;
  else
    ++framesSinceInput_;
  sync();
  display_.update(deviationScales(state_, display_));
  runBackgroundWork();
  advanceAbSetup();
  state_.regions.clear();
  state_.frameText.clear();

  handleShortcuts(state_, display_);
  drawMenuBar(state_, display_);
  const float top = ImGui::GetFrameHeight();
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  const PanelWidths widths = panelWidths(size.x, state_.settings);
  const float leftWidth = widths.left, rightWidth = widths.right;
  if (leftWidth > 0) {
    placeWindow(0, leftWidth, top);
    ImGui::Begin("Scenes", nullptr, kSidePanelFlags);
    keepWidth(state_, state_.settings.left, leftWidth);
    beginCapture(state_);
    drawScenePanel(state_, belowSceneList_);
    const float afterSceneList = ImGui::GetCursorPosY();
    ImGui::Separator();
    ImGui::TextUnformatted("Objects");
    drawObjectsPanel(state_, display_);
    belowSceneList_ = ImGui::GetCursorPosY() - afterSceneList;
    endCapture(state_);
    ImGui::End();
  }

  placeWindow(leftWidth, size.x - leftWidth - rightWidth, top);
  const std::string title =
      (state_.session.file().empty() ? std::string("No scene")
                                     : state_.session.file().filename().string()) +
      "###image";
  ImGui::Begin(title.c_str(), nullptr, kPanelFlags | ImGuiWindowFlags_NoScrollbar);
  beginCapture(state_);
  if (!state_.message.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, state_.messageIsError     ? kErrorColor
                                         : state_.messageIsWarning ? kWarningColor
                                                                   : ImVec4(0.6f, 1, 0.6f, 1));
    ImGui::TextWrapped("%s", state_.message.c_str());
    ImGui::PopStyleColor();
  }
  drawImageView(state_, display_);
  endCapture(state_);
  ImGui::End();

  if (rightWidth > 0) {
    placeWindow(size.x - rightWidth, rightWidth, top);
    ImGui::Begin("Details", nullptr, kSidePanelFlags);
    keepWidth(state_, state_.settings.right, rightWidth);
    beginCapture(state_);
    const ViewerOptions& o = state_.options;
    if (section("Render", true)) drawRenderPanel(state_, display_);
    if (section("Draw over the image", wanted(o, "draw"))) drawDrawPanel(state_, display_);
    // The inspector's pane fills the panel down to what the sections after
    // it drew last frame.
    if (section("Inspector", true)) drawInspectorPanel(state_, display_, belowInspector_);
    const float afterInspector = ImGui::GetCursorPosY();
    if (section("A/B", wanted(o, "ab"))) drawAbPanel(state_, display_);
    if (section("Camera", wanted(o, "camera"))) drawCameraPanel(state_);
    if (section("Normals vs OpenMesh", wanted(o, "normals"))) drawNormalsPanel(state_, display_);
    state_.reference.panelOpen = section("Compare with a reference", wanted(o, "compare"));
    if (state_.reference.panelOpen) drawComparePanel(state_, display_);
    if (section("Save", wanted(o, "save"))) drawSavePanel(state_, display_);
    belowInspector_ = ImGui::GetCursorPosY() - afterInspector;
    endCapture(state_);
    ImGui::End();
  }
  drawOverwriteQuestion(state_, display_);
  drawHelpOverlay(state_);
  // A panel's new width is written once the drag that set it ends.
  if (state_.settingsChanged && !ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
    state_.settingsChanged = false;
    saveSettingsIfKept(state_);
  }
  // A change made in this frame restarts the render now, not next frame.
  sync();
  state_.timing.frameInputAt.reset();
}

bool ViewerApp::waitingForFirstImage() const {
  return firstImageDeadline_ && display_.awaitingFirstImage() &&
         Clock::now() < *firstImageDeadline_;
}

bool ViewerApp::shouldPresent() const { return !waitingForFirstImage(); }

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
  const SceneRequests& scenes = state_.scenes;
  if (abStage_ == AbStage::RenderingB && state_.session.loaded() && scenes.failure.empty())
    return false;
  if (state_.session.opening() || scenes.pipeline->busy() || state_.crosscheck.task->busy() ||
      state_.reference.task->busy() || state_.ab.task->busy() || state_.layersSave->busy())
    return false;
  if (!state_.session.loaded() || !scenes.failure.empty()) return true;
  return showsLatestRequest();
}

bool ViewerApp::showsLatestRequest() const {
  // A render scene made for an older request is not it, even when the
  // newer one's answer waits to be received.
  const SceneRequests& scenes = state_.scenes;
  return scenes.render && scenes.render->request == scenes.lastId &&
         display_.renderScene() == scenes.render && display_.showsFinishedRender();
}

std::vector<std::string> ViewerApp::failures() const {
  std::vector<std::string> out;
  if (!state_.session.error().empty()) out.push_back(state_.session.error());
  if (!state_.scenes.failure.empty())
    out.push_back("could not prepare the scene: " + state_.scenes.failure);
  out.insert(out.end(), state_.optionErrors.begin(), state_.optionErrors.end());
  return out;
}

double ViewerApp::waitBeforeNextFrameMs(Clock::time_point lastFrameInput) const {
  if (display_.imageWaiting()) return 0.0;
  if (waitingForFirstImage()) return std::max(0.0, -msSince(*firstImageDeadline_));
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
