// Saving the render, the window and the scene: each save refuses to replace
// a file and asks first (drawOverwriteQuestion), and says the full path it
// wrote.
#include <imgui.h>

#include "meshtrace/io/exr.h"
#include "meshtrace/render/layers.h"
#include "viewer/ui/panels.h"

namespace meshtrace::viewer {

namespace fs = std::filesystem;

namespace {
fs::path absoluteOf(const std::string& path) {
  std::error_code ec;
  const fs::path p = fs::absolute(path, ec);
  return ec ? fs::path(path) : p.lexically_normal();
}

// A saved scene shows in the list: the folders holding it are scanned again,
// and its own folder joins the list when none does.
void rescanFor(ViewerState& state, const fs::path& saved) {
  bool listed = false;
  for (SceneFolder& f : state.folders) {
    const fs::path rel = saved.lexically_relative(f.root);
    if (rel.empty() || *rel.begin() == "..") continue;
    f = scanFolder(f.root, f.title);
    listed = true;
  }
  if (!listed) addFolder(state, saved.parent_path(), saved.parent_path().filename().string());
}

// The render on screen with each layer, written as raytrace writes an EXR:
// through renderLayers, by the displayed scene's intersector, through the
// displayed camera. It is a render of its own, so it runs in the
// background (the scene and camera are kept for it); another save of
// layers cancels it, and its file is then never made (OutputFile).
void saveLayers(ViewerState& state, const RenderDisplay& display, const fs::path& target) {
  std::shared_ptr<const RenderScene> scene = display.renderScene();
  if (!scene || scene->preview)
    throw std::runtime_error("not saved: the scene is still being prepared");
  state.layersSave->start(
      [scene, camera = display.camera(), threads = display.threads(),
       target](TaskContext<std::string>& task) {
        ExrImage layers = renderLayers(scene->prepared->intersector(), camera, threads);
        if (task.cancelled()) return;
        task.setPhase("writing " + target.string());
        writeExr(layers, target);
        task.publish("saved the layers to " + target.string());
      },
      "rendering the layers for " + target.string());
  setMessage(state, "saving the layers to " + target.string() + " ...", false);
}

std::string pathOf(const ViewerState& state, SaveKind kind) {
  switch (kind) {
    case SaveKind::Render: return state.savePath;
    case SaveKind::Layers: return state.layersPath;
    case SaveKind::Window: return state.screenshotPath;
    case SaveKind::Scene: break;
  }
  return state.sceneSavePath;
}
}  // namespace

void save(ViewerState& state, RenderDisplay& display, SaveKind kind, Existing existing) {
  const fs::path target = absoluteOf(pathOf(state, kind));
  try {
    refuseExisting(target, existing);
    switch (kind) {
      case SaveKind::Render:
        if (isExrPath(target)) {
          saveLayers(state, display, target);
          break;
        }
        writeImage(display.colorImage(), target);
        setMessage(state, "saved the render to " + target.string(), false);
        break;
      case SaveKind::Layers: saveLayers(state, display, target); break;
      case SaveKind::Window:
        // Written after the frame is drawn; the frame loop says where.
        state.screenshotRequest = target.string();
        break;
      case SaveKind::Scene:
        state.session.saveMeshes(target, Existing::Replace);
        rescanFor(state, target);
        setMessage(state, "saved the scene to " + target.string(), false);
        break;
    }
  } catch (const FileExists&) {
    state.overwrite = OverwriteQuestion{kind, target};
  } catch (const std::exception& e) {
    setMessage(state, e.what(), true);
  }
}

void drawOverwriteQuestion(ViewerState& state, RenderDisplay& display) {
  if (!state.overwrite) return;
  const char* title = "Replace the file?";
  if (!ImGui::IsPopupOpen(title)) ImGui::OpenPopup(title);
  if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  ImGui::Text("%s exists.", state.overwrite->path.string().c_str());
  ImGui::TextUnformatted("Replace it, or keep it and choose another name?");
  if (ImGui::Button("Replace")) {
    const SaveKind kind = state.overwrite->kind;
    state.overwrite.reset();
    ImGui::CloseCurrentPopup();
    save(state, display, kind, Existing::Replace);
  }
  ImGui::SameLine();
  if (ImGui::Button("Keep it") || ImGui::IsKeyPressed(ImGuiKey_Escape)) {
    setMessage(state, "not saved: " + state.overwrite->path.string() + " kept", false);
    state.overwrite.reset();
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

void proposeSavePaths(ViewerState& state, const fs::path& scene) {
  const std::string stem = scene.stem().string();
  std::vector<fs::path> candidates = userFolders();
  const fs::path here = chooseSaveFolder(candidates, fs::temp_directory_path());
  state.savePath = freeName(here, stem + "-render", ".png").string();
  state.layersPath = freeName(here, stem + "-layers", ".exr").string();
  state.screenshotPath = freeName(here, stem + "-window", ".png").string();
  // The scene beside its original when that folder is the user's own, so
  // that its meshes' relative paths still hold; named there as the scene
  // was (the message after saving gives the full path). The scene made for
  // a bare mesh is proposed as <stem>.sce, the name raytrace gives it.
  candidates.insert(candidates.begin(), scene.parent_path());
  const fs::path folder = chooseSaveFolder(candidates, fs::temp_directory_path());
  const fs::path name =
      freeName(folder, isBareMesh(scene) ? stem : stem + "-modes", ".sce").filename();
  state.sceneSavePath =
      (folder == absoluteOf(scene.parent_path().string()) ? scene.parent_path() / name
                                                          : folder / name)
          .string();
}

void collectLayersSave(ViewerState& state) {
  BackgroundTask<std::string>& task = *state.layersSave;
  for (const std::string& saved : task.take()) setMessage(state, saved, false);
  if (!task.busy() && !task.error().empty()) {
    setMessage(state, "not saved: " + task.error(), true);
    task.cancel();  // reported once
  }
}

}  // namespace meshtrace::viewer
