#pragma once
// The scene being viewed and what the user changed about it: per-mesh
// shading and visibility, and the camera. Hands the renderer an immutable
// scene with the hidden meshes left out, rebuilt only when a mesh changes
// (and shared with the session, not copied, while every mesh is shown).
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "meshtrace/geometry/scene.h"
#include "meshtrace/render/progressive.h"

namespace meshtrace::viewer {

struct MeshState {
  std::string name;  // file stem, "#2" etc. for repeats
  Shading fileShading = Shading::Flat;
  Shading shading = Shading::Flat;
  bool visible = true;
};

class SceneSession {
 public:
  // Loads `file`; on failure keeps no scene and sets error() (with file:line
  // for bad input). Never throws.
  bool load(const std::filesystem::path& file);
  void clear();

  bool loaded() const { return scene_ != nullptr; }
  const std::string& error() const { return error_; }
  const std::filesystem::path& file() const { return file_; }
  double loadMs() const { return loadMs_; }
  // Every mesh, current modes. A change of shading may replace it: do not
  // hold on to it across one.
  const Scene& scene() const { return *scene_; }

  const std::vector<MeshState>& meshes() const { return meshes_; }
  void setShading(std::size_t mesh, Shading shading);
  void setVisible(std::size_t mesh, bool visible);
  void resetMeshes();
  std::vector<Shading> shadingModes() const;
  bool meshesChanged() const;
  // Saves the scene file with the current shading modes; throws std::runtime_error.
  void saveModes(const std::filesystem::path& out) const;

  const CameraSpec& camera() const { return camera_; }
  void setCamera(const CameraSpec& camera) {
    camera_ = camera;
    ++revision_;
  }
  void resetCamera();

  // The scene to render (hidden meshes left out) with its intersector.
  std::shared_ptr<const PreparedScene> prepared(const TraceOptions& options);
  // The scene's mesh index for mesh `renderIndex` of the prepared scene.
  std::uint32_t sceneMesh(std::uint32_t renderIndex) const { return renderToScene_[renderIndex]; }
  // Counts a change that needs a new render (mesh or camera): compare to notice one.
  std::uint64_t revision() const { return revision_; }

 private:
  std::filesystem::path file_;
  std::string error_;
  double loadMs_ = 0.0;
  std::shared_ptr<Scene> scene_;
  std::vector<MeshState> meshes_;
  CameraSpec camera_;
  std::shared_ptr<const PreparedScene> prepared_;
  TraceOptions preparedOptions_;
  std::vector<std::uint32_t> renderToScene_;
  std::uint64_t revision_ = 0;
};

}  // namespace meshtrace::viewer
