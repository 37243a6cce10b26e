#pragma once
// The viewer's panels, each drawn by one function into the current ImGui
// window, and the actions they share.
#include <imgui.h>

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "viewer/gl/texture.h"
#include "viewer/model/projection.h"
#include "viewer/model/shortcuts.h"
#include "viewer/ui/render_display.h"
#include "viewer/ui/state.h"

struct ImDrawList;
struct ImVec2;

namespace meshtrace::viewer {

// How ImGui names a texture of ours.
inline ImTextureID textureId(const gl::Texture& t) {
  return reinterpret_cast<ImTextureID>(static_cast<std::intptr_t>(t.id()));
}

// Actions (actions.cpp).
void openScene(ViewerState& state, const std::filesystem::path& file);
void addFolder(ViewerState& state, const std::filesystem::path& dir, const std::string& title);
// A path typed or dropped: a .sce opens, a folder joins the list.
void openPath(ViewerState& state, const std::filesystem::path& path);
void setMessage(ViewerState& state, const std::string& message, bool error);
// Puts the open scene first among the recent ones and saves the settings
// (when the app keeps any).
void rememberScene(ViewerState& state);
// Has the settings written to state.settingsPath, if the app keeps them
// (in the background: SettingsWriter; a failure shows on a later frame).
void saveSettingsIfKept(ViewerState& state);
// The message line: `before` (if any) and the scene's warnings, shown as a
// warning; just `before` when there are none.
void showSceneWarnings(ViewerState& state, const std::string& before = {});
// Puts the camera's .sce line on the clipboard (the system's, through ImGui
// in a window) and says so in the message line.
void copyCameraLine(ViewerState& state);
// Sets the camera from a `camera` line on the clipboard, or says why not.
void pasteCameraLine(ViewerState& state);
// A mesh named by the command line: its name (file stem) or index.
std::optional<std::size_t> findMesh(const SceneSession& session, const std::string& name);
// " (its meshes: ball, box)", for a message about a mesh name not found.
std::string meshNames(const SceneSession& session);
// "mesh 'ring1' #0", "sphere #3": what a primitive is, for people.
std::string describeObject(const ViewerState& state, const RenderDisplay& display,
                           const PrimitiveRef& ref);

// The text a frame shows, kept in state.frameText when state.captureText
// is set (text_capture.cpp): ImGui's log records what the panels draw
// between beginCapture and endCapture (End finishes it too).
// drawCapturedAs runs `draw` with the log paused and records `text` in its
// place: for a scrolling pane, whose lines ImGui logs out of order (its first
// line joins the line before the pane).
void beginCapture(ViewerState& state);
void endCapture(ViewerState& state);
void drawCapturedAs(ViewerState& state, const std::string& text, const std::function<void()>& draw);

// Fields of one line of text (a label and its value each), joined by `separator`,
// broken between fields where the panel is too narrow for all of them,
// never inside one (field_lines.cpp).
void textFields(const std::vector<std::string>& fields, const std::string& separator = "  ");

// A bar under a scrolling pane `shown` pixels high that drags its height
// into `chosen`, marking the settings changed (pane_splitter.cpp); a double
// click sets `chosen` to 0: the automatic height (pane_heights.h).
void paneSplitter(ViewerState& state, const char* id, float shown, float& chosen);
inline constexpr float kPaneSplitterHeight = 6.0f;

// Saving (saving.cpp): saves the render, the window or the scene to its
// path, made absolute; a file there is replaced only with Existing::Replace,
// else the user is asked (drawOverwriteQuestion, once a frame).
void save(ViewerState& state, RenderDisplay& display, SaveKind kind, Existing existing);
// Shows the outcome of a layers save that has finished in the background.
void collectLayersSave(ViewerState& state);
void drawOverwriteQuestion(ViewerState& state, RenderDisplay& display);
// New absolute paths for the saves of `scene`, in folders the user may
// write to outside the course's data (save_target.h).
void proposeSavePaths(ViewerState& state, const std::filesystem::path& scene);

// Live reload (live_reload.cpp). Watches the open scene's file and meshes
// (after an opening, successful or not); reloads the scene when one of them
// changed (checkWatchedFiles) or when asked (reloadScene); the background
// opening's answer to a reload goes to reloaded or reloadFailed.
void watchOpenScene(ViewerState& state);
void checkWatchedFiles(ViewerState& state);
void reloadScene(ViewerState& state);
void reloaded(ViewerState& state, const LoadedScene& loaded);
void reloadFailed(ViewerState& state, const std::string& error);

// The menu bar, the keys and the help overlay (commands.cpp), from the
// shortcut table (shortcuts.h). runCommand returns false for a command it
// does not know.
bool runCommand(ViewerState& state, RenderDisplay& display, const Shortcut& shortcut);
void handleShortcuts(ViewerState& state, RenderDisplay& display);
void drawMenuBar(ViewerState& state, RenderDisplay& display);
void drawHelpOverlay(ViewerState& state);

void drawObjectsPanel(ViewerState& state, RenderDisplay& display);  // objects_panel.cpp
void drawRenderPanel(ViewerState& state, RenderDisplay& display);   // render_panel.cpp
void drawImageView(ViewerState& state, RenderDisplay& display);     // image_view.cpp
// The scene list scrolls in a pane above `keepBelow` pixels of the panel
// (for the Objects list), unless dragged (scene_panel.cpp).
void drawScenePanel(ViewerState& state, float keepBelow);
// The inspector draws in a scrolling pane that fills the panel but for
// `keepBelow` pixels (for the sections drawn after it), unless dragged.
void drawInspectorPanel(ViewerState& state, RenderDisplay& display,
                        float keepBelow);                           // inspector_panel.cpp
void drawCameraPanel(ViewerState& state);                           // camera_panel.cpp
void drawNormalsPanel(ViewerState& state, RenderDisplay& display);  // normals_panel.cpp
void drawComparePanel(ViewerState& state, RenderDisplay& display);  // compare_panel.cpp
void drawSavePanel(ViewerState& state, RenderDisplay& display);     // save_panel.cpp
void drawDrawPanel(ViewerState& state, RenderDisplay& display);     // draw_panel.cpp
void drawAbPanel(ViewerState& state, RenderDisplay& display);       // ab_panel.cpp

// A/B (ab_panel.cpp): keeps the current colour image as B (false if there
// is none); compares each finished render with B in the background.
bool keepAsB(ViewerState& state, RenderDisplay& display);
void updateAb(ViewerState& state, RenderDisplay& display);

// The debugger's findings over the image, through the shown image's camera
// (findings.cpp); `toScreen` places an image position in the window.
void drawFindings(ViewerState& state, RenderDisplay& display, ImDrawList* draw,
                  const std::function<ImVec2(const ImagePoint&)>& toScreen);
// The inspection of `pixel` through the main camera, kept while the scene
// and the camera stay; null while the render scene is not built.
const PixelInspection* inspectionOf(ViewerState& state, const RenderDisplay& display,
                                    const PixelRef& pixel);

// Legends (legend.cpp): a colour bar over [0, 1] and numbers at places on it.
struct LegendTick {
  double position;  // 0..1 along the bar
  std::string label;
};
void drawLegend(ViewerState& state, const char* title, const std::function<Color(double)>& colorAt,
                const std::vector<LegendTick>& ticks);
// A heat map's scale, 0 to `maxValue`; a count's shows each whole number
// when there are few.
void drawHeatLegend(ViewerState& state, const char* title, double maxValue, const char* unit,
                    bool counts = false);
// The depth view's scale: the depths at a quarter, half ... of the hits.
void drawDepthLegend(ViewerState& state, const FalseColorScales& scales);
// The compare panel's plot of each pass's error (error_plot.cpp).
void drawErrorPlot(ViewerState& state, const std::vector<PassError>& points);

// Starts the cross-check of every mesh of the scene against OpenMesh in
// the background (normals_panel.cpp); deviationScales hands its results to
// the display's scales.
void startCrossCheck(ViewerState& state);
FalseColorScales deviationScales(const ViewerState& state, const RenderDisplay& display);

// Reads the reference image at state.reference.path (an error goes to
// state.reference.error) and makes its texture (compare_panel.cpp).
void loadReference(ViewerState& state);
// Keeps the reference image, its texture, the difference image and the
// error of each pass current, comparing in the background.
void updateReference(ViewerState& state, RenderDisplay& display);

}  // namespace meshtrace::viewer
