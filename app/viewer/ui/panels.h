#pragma once
// The viewer's panels, each drawn by one function into the current ImGui
// window, and the actions they share.
#include <filesystem>
#include <string>
#include <vector>

#include "viewer/ui/render_display.h"
#include "viewer/ui/state.h"

namespace meshtrace::viewer {

// Actions (actions.cpp).
void openScene(ViewerState& state, const std::filesystem::path& file);
void addFolder(ViewerState& state, const std::filesystem::path& dir, const std::string& title);
// A path typed or dropped: a .sce opens, a folder joins the list.
void openPath(ViewerState& state, const std::filesystem::path& path);
void setMessage(ViewerState& state, const std::string& message, bool error);
// Puts the camera's .sce line on the clipboard (the system's, through ImGui
// in a window) and says so in the message line.
void copyCameraLine(ViewerState& state);
// A mesh named by the command line: its name (file stem) or index.
std::optional<std::size_t> findMesh(const SceneSession& session, const std::string& name);
// "mesh 'ring1' #0", "sphere #3": what a primitive is, for people.
std::string describeObject(const ViewerState& state, const RenderDisplay& display,
                           const PrimitiveRef& ref);

void drawScenePanel(ViewerState& state);                              // scene_panel.cpp
void drawObjectsPanel(ViewerState& state);                            // objects_panel.cpp
void drawRenderPanel(ViewerState& state, RenderDisplay& display);     // render_panel.cpp
void drawImageView(ViewerState& state, RenderDisplay& display);       // image_view.cpp
void drawInspectorPanel(ViewerState& state, RenderDisplay& display);  // inspector_panel.cpp
void drawCameraPanel(ViewerState& state);                             // camera_panel.cpp
void drawNormalsPanel(ViewerState& state, RenderDisplay& display);    // normals_panel.cpp
void drawComparePanel(ViewerState& state, RenderDisplay& display);    // compare_panel.cpp
void drawSavePanel(ViewerState& state, RenderDisplay& display);       // save_panel.cpp

// The colour scale of a heat map, 0 to `maxValue` (legend.cpp).
void drawHeatLegend(const char* title, double maxValue, const char* unit);

// Cross-checks every mesh of the scene against OpenMesh (normals_panel.cpp)
// and hands the deviations to the display's scales.
void runCrossCheck(ViewerState& state);
FalseColorScales deviationScales(const ViewerState& state, const RenderDisplay& display);

// Keeps the reference image, its texture, the difference image and the
// error history current (compare_panel.cpp).
void updateReference(ViewerState& state, RenderDisplay& display);

}  // namespace meshtrace::viewer
