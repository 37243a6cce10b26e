#pragma once
// The scene being viewed and what the user changed about it: per-mesh
// shading and visibility, and the camera. The scene arrives from a
// background load (geometry_load.h) and the renderer's scenes are made in
// the background too (render_scene.h): the session only says what they
// should be.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "viewer/model/geometry_load.h"
#include "viewer/model/render_scene.h"
#include "viewer/model/save_target.h"

namespace meshtrace::viewer {

struct MeshState {
  std::string name;  // file stem, "#2" etc. for repeats
  Shading fileShading = Shading::Flat;
  Shading shading = Shading::Flat;
  bool visible = true;
  std::size_t triangles = 0, vertices = 0;
};

class SceneSession {
 public:
  // Forgets the current scene: `file` is being opened. Returns the scene
  // it forgets (for the caller to let go of off the UI thread).
  std::shared_ptr<const Scene> beginOpening(const std::filesystem::path& file);
  // The opening ended: with the loaded scene, or with an error (file:line
  // for bad input).
  void adopt(const LoadedScene& loaded);
  void fail(const std::string& error);
  // The same file read again after it or a mesh changed: the scene is
  // replaced, and what the user changed is kept where it still applies: a
  // moved camera (the file's new one if it was not moved, the file's image
  // size either way), and each mesh's switched mode and visibility, by name.
  void adoptReload(const LoadedScene& loaded);
  // The reload failed: the last good scene stays, with the reload's error
  // (file:line for bad input) beside it until a reload succeeds.
  void failReload(const std::string& error) { reloadError_ = error; }
  const std::string& reloadError() const { return reloadError_; }
  // What the scene reader warned of for the scene shown (scene.h), e.g. an
  // up vector parallel to the view: each names the file and line.
  const std::vector<std::string>& warnings() const { return warnings_; }
  void clear();

  bool opening() const { return opening_; }
  bool loaded() const { return base_ != nullptr; }
  const std::string& error() const { return error_; }
  const std::filesystem::path& file() const { return file_; }
  // Whether the file is a bare mesh shown in the scene made for it
  // (geometry_load.h), which saveMeshes writes out.
  bool generated() const { return !generatedText_.empty(); }
  double loadMs() const { return loadMs_; }
  // The scene as loaded: geometry, materials, lights. Its meshes' modes are
  // not the current ones (see meshes()).
  const Scene& scene() const { return *base_; }
  const std::shared_ptr<const Scene>& sharedScene() const { return base_; }

  const std::vector<MeshState>& meshes() const { return meshes_; }
  void setShading(std::size_t mesh, Shading shading);
  void setVisible(std::size_t mesh, bool visible);
  void resetMeshes();
  std::vector<Shading> shadingModes() const;
  bool meshesChanged() const;
  // Saves the scene file (for a bare mesh, the scene made for it) with the
  // current shading modes, hidden meshes commented out (scene_writer.h);
  // throws FileExists, std::runtime_error.
  void saveMeshes(const std::filesystem::path& out, Existing existing) const;

  const CameraSpec& camera() const { return camera_; }
  void setCamera(const CameraSpec& camera) { camera_ = camera; }
  void resetCamera();

  // What the renderer's scene should be now.
  RenderRequest request(const TraceOptions& trace, std::uint64_t id) const;
  // A render scene of every mesh: its scene (which holds the vertex
  // normals of its PHONG meshes) becomes the base later requests start
  // from, so that switching a mode back costs no copy.
  // Returns the base it replaces (for the caller to let go of).
  std::shared_ptr<const Scene> adoptBase(const RenderScene& scene);
  // Counts changes of the meshes' modes and visibility.
  std::uint64_t meshRevision() const { return meshRevision_; }

 private:
  std::filesystem::path file_;
  std::string error_, reloadError_;
  bool opening_ = false;
  double loadMs_ = 0.0;
  std::shared_ptr<const Scene> base_;
  std::vector<MeshState> meshes_;
  std::vector<std::string> warnings_;
  std::string generatedText_;
  CameraSpec camera_;
  std::uint64_t meshRevision_ = 0;
};

}  // namespace meshtrace::viewer
