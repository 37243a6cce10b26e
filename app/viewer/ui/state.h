#pragma once
// What the viewer's panels share: the options, the scene session and the
// work in the background for it, the scene list, the view settings, the
// inspector's pixel, the cross-check results, the reference image and the
// messages to show.
#include <array>
#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "crosscheck/normals_crosscheck.h"
#include "meshtrace/report/image_compare.h"
#include "viewer/gl/texture.h"
#include "viewer/model/ab_compare.h"
#include "viewer/model/background_task.h"
#include "viewer/model/file_watch.h"
#include "viewer/model/folder_browser.h"
#include "viewer/model/frame_stats.h"
#include "viewer/model/image_viewport.h"
#include "viewer/model/options.h"
#include "viewer/model/pass_errors.h"
#include "viewer/model/scene_catalog.h"
#include "viewer/model/scene_pipeline.h"
#include "viewer/model/session.h"
#include "viewer/model/settings.h"
#include "viewer/model/settings_writer.h"
#include "viewer/model/views.h"
#include "viewer/ui/render_display.h"

namespace meshtrace::viewer {

struct PixelRef {
  int x = 0, y = 0;  // image pixel, y = 0 the bottom row
  bool operator==(const PixelRef&) const = default;
};

// The renderer's scenes, made in the background (scene_pipeline.h): the
// latest request, and what arrived for it.
struct SceneRequests {
  std::unique_ptr<ScenePipeline> pipeline;
  std::uint64_t lastId = 0;            // the request whose answer is shown
  std::uint64_t meshRevision = ~0ull;  // the session's when it was asked
  TraceOptions trace;                  // and the trace options
  std::shared_ptr<const RenderScene> preview, render;
  std::string failure;  // why the latest render scene could not be made
};

// The OpenMesh cross-check of every mesh, made in the background.
struct CrossCheckState {
  using Reports = std::vector<std::optional<crosscheck::NormalsReport>>;
  struct Result {
    Reports reports;  // per scene mesh
    double ms = 0.0;
  };
  std::unique_ptr<BackgroundTask<Result>> task;
  Reports reports;
  double ms = 0.0;
  bool done() const { return !reports.empty() && reports[0].has_value(); }
};

struct ReferenceState {
  std::filesystem::path path;  // empty: none
  std::string pathField;
  float sceneListContent = 0.0f;  // the scene list's height as drawn last frame
  std::string error;
  Image8 image;
  gl::Texture texture, difference;
  PassErrors errors;  // the current render's, per pass (pass_errors.h)
  std::unique_ptr<BackgroundTask<PassErrors::Comparison>> task;
  std::optional<ImageDifference> current;
  bool panelOpen = false;  // the compare panel was drawn last frame
};

// The BVH cut drawn over the image, kept while its scene, level and depth
// stay (findings.cpp).
struct CutCache {
  const PreparedScene* scene = nullptr;
  BvhLevel level = BvhLevel::Triangles;
  int depth = -1;
  BvhCut cut;
  std::size_t drawn = 0;  // of its boxes, the largest in the image (findings.cpp)
};

// Inspections of pixels through the main camera, kept while the render
// scene and the camera stay: the hovered and the pinned pixel's.
struct InspectionCache {
  struct Entry {
    const PreparedScene* scene = nullptr;
    CameraSpec camera;
    PixelRef pixel;
    PixelInspection inspection;
  };
  std::vector<Entry> entries;
};

// The observer camera (observer.h): shown instead of the main one while
// active; placed when first shown for a scene.
struct ObserverState {
  bool active = false;
  std::optional<CameraSpec> camera;
};

// A/B (ab_compare.h): the render kept as B and its comparison with the
// current one, made in the background.
struct AbState {
  std::optional<KeptImage> b;
  gl::Texture texture, difference;
  AbMode mode = AbMode::A;
  float wipe = 0.5f;  // the share of the image's width, from the left, that shows A
  bool draggingWipe = false;
  std::unique_ptr<BackgroundTask<AbComparison>> task;
  std::optional<ImageDifference> stats;  // A against B, for the job below
  std::uint64_t comparedJob = 0;         // the A render compared, or being compared
};

// Live reload (live_reload.cpp): the open scene's files, watched, and a
// reload under way.
struct LiveReload {
  FileWatch watch;
  bool pending = false;
  std::string changed;  // the file whose change started the reload
  std::chrono::steady_clock::time_point nextCheck;
};

struct TimingStats {
  using Clock = std::chrono::steady_clock;
  // When the input of the frame being built was taken: what the user does in
  // it was asked for then. Unset between frames (a drop arrives there).
  std::optional<Clock::time_point> frameInputAt;
  // A scene was opened, its (full, not preview) render not started yet.
  std::optional<Clock::time_point> openedAt;
  double loadMs = 0.0;
  FrameStats renderingFrames;  // frames drawn while a render ran, since the scene was opened
  int frames = 0;

  Clock::time_point actionTime() const { return frameInputAt.value_or(Clock::now()); }
};

// A save that would replace a file waits for the user's answer (saving.cpp).
// Layers: the render's EXR of every layer (render/layers.h), as raytrace
// writes it; a Render save to a .exr path is one too.
enum class SaveKind { Render, Layers, Window, Scene };
struct OverwriteQuestion {
  SaveKind kind;
  std::filesystem::path path;
};

// A key pressed in the window, with its modifiers: `code` is GLFW's.
struct KeyPress {
  int code;
  bool ctrl, shift, alt;
};

struct ViewerState {
  ViewerOptions options;
  std::filesystem::path executable;
  SceneSession session;
  SceneRequests scenes;
  std::vector<SceneFolder> folders;
  std::string pathField;
  float sceneListContent = 0.0f;         // the scene list's height as drawn last frame
  std::optional<FolderBrowser> browser;  // open while shown

  View view = View::Color;
  Overlay overlay = Overlay::None;
  float opacity = 0.6f;
  int extraSamples = 0;
  TraceOptions trace;

  std::optional<PixelRef> hover, pinned;
  ImageViewport viewport;
  DrawOptions draw;
  CutCache cut;
  InspectionCache inspections;
  ObserverState observer;

  CrossCheckState crosscheck;
  ReferenceState reference;
  AbState ab;
  TimingStats timing;
  LiveReload reload;
  std::string savePath, layersPath, screenshotPath, sceneSavePath;  // absolute, proposed new
  // The EXR layers being rendered and written (saving.cpp): a render of
  // every layer of the image, too long for a frame. Its result is the
  // message to show.
  std::unique_ptr<BackgroundTask<std::string>> layersSave;
  std::optional<OverwriteQuestion> overwrite;
  std::string screenshotRequest;  // set by the UI, served after the frame is drawn
  std::string message;            // last action's result
  bool messageIsError = false;
  bool messageIsWarning = false;
  // The menu bar and keys (commands.cpp).
  bool helpOpen = false, aboutOpen = false;
  bool quitRequested = false;
  bool focusPathField = false;       // the next frame puts the keyboard in the path field
  std::vector<KeyPress> keyPresses;  // since the last frame, for the shortcuts
  // Remembered between runs in settingsPath; empty (tests, headless): not
  // read or written.
  ViewerSettings settings;
  std::filesystem::path settingsPath;
  SettingsWriter settingsWriter;  // writes `settings` to settingsPath
  bool settingsChanged = false;   // and not yet written
  std::string bookmarkName;       // the camera panel's field
  // The command line's settings that apply to the scene (meshes, pixel,
  // reference) wait for it to load; what they name that it lacks is listed
  // here (a headless run then fails).
  bool sceneOptionsPending = false;
  bool depthCheckPending = false;
  std::vector<std::string> optionErrors;
  // Where this frame drew its image, plot, legends and panes (x0, y0, x1,
  // y1 in window pixels), and the text it showed, kept when captureText is
  // set: what --describe writes.
  std::map<std::string, std::array<float, 4>> regions;
  std::string frameText;
  bool captureText = false;
  // Large objects let go of by an action, for the display's disposer to
  // free off the UI thread (viewer_app.cpp hands them over each frame).
  std::vector<std::shared_ptr<const void>> retired;
};

}  // namespace meshtrace::viewer
