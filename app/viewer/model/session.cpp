#include "viewer/model/session.h"

#include <map>
#include <utility>

#include "viewer/model/camera_control.h"
#include "viewer/model/scene_writer.h"

namespace meshtrace::viewer {

std::shared_ptr<const Scene> SceneSession::beginOpening(const std::filesystem::path& file) {
  std::shared_ptr<const Scene> old = std::move(base_);
  clear();
  file_ = file;
  opening_ = true;
  return old;
}

void SceneSession::adopt(const LoadedScene& loaded) {
  opening_ = false;
  error_.clear();
  reloadError_.clear();
  base_ = loaded.scene;
  warnings_ = base_->warnings;
  loadMs_ = loaded.ms;
  generatedText_ = loaded.generatedText;
  meshes_.clear();
  std::map<std::string, int> seen;
  for (std::size_t i = 0; i < base_->meshes.size(); ++i) {
    const Mesh& m = base_->meshes[i];
    MeshState s;
    s.name = m.file().stem().string();
    if (const int n = ++seen[s.name]; n > 1) s.name += " #" + std::to_string(n);
    s.fileShading = s.shading = loaded.fileModes[i];
    s.triangles = m.triangles().size();
    s.vertices = m.vertices().size();
    meshes_.push_back(s);
  }
  camera_ = base_->camera.spec();
  ++meshRevision_;
}

void SceneSession::adoptReload(const LoadedScene& loaded) {
  const std::vector<MeshState> before = meshes_;
  const CameraSpec camera = camera_;
  const bool moved = base_ && !sameCamera(camera_, base_->camera.spec());
  adopt(loaded);
  if (moved) {
    const CameraSpec file = camera_;
    camera_ = camera;
    camera_.width = file.width;
    camera_.height = file.height;
  }
  for (std::size_t i = 0; i < meshes_.size(); ++i) {
    for (const MeshState& b : before) {
      if (b.name != meshes_[i].name) continue;
      if (b.shading != b.fileShading) meshes_[i].shading = b.shading;
      meshes_[i].visible = b.visible;
    }
  }
  ++meshRevision_;
}

void SceneSession::fail(const std::string& error) {
  opening_ = false;
  base_.reset();
  meshes_.clear();
  warnings_.clear();
  error_ = error;
  ++meshRevision_;
}

void SceneSession::clear() {
  error_.clear();
  reloadError_.clear();
  opening_ = false;
  base_.reset();
  meshes_.clear();
  warnings_.clear();
  generatedText_.clear();
  loadMs_ = 0.0;
  ++meshRevision_;
}

void SceneSession::setShading(std::size_t mesh, Shading shading) {
  if (meshes_[mesh].shading == shading) return;
  meshes_[mesh].shading = shading;
  ++meshRevision_;
}

void SceneSession::setVisible(std::size_t mesh, bool visible) {
  if (meshes_[mesh].visible == visible) return;
  meshes_[mesh].visible = visible;
  ++meshRevision_;
}

void SceneSession::resetMeshes() {
  for (std::size_t i = 0; i < meshes_.size(); ++i) {
    setShading(i, meshes_[i].fileShading);
    setVisible(i, true);
  }
}

std::vector<Shading> SceneSession::shadingModes() const {
  std::vector<Shading> modes;
  for (const MeshState& m : meshes_) modes.push_back(m.shading);
  return modes;
}

bool SceneSession::meshesChanged() const {
  for (const MeshState& m : meshes_)
    if (m.shading != m.fileShading || !m.visible) return true;
  return false;
}

void SceneSession::saveMeshes(const std::filesystem::path& out, Existing existing) const {
  std::vector<bool> visible;
  for (const MeshState& m : meshes_) visible.push_back(m.visible);
  if (generated())
    saveSceneTextWithMeshes(generatedText_, "the scene made for " + file_.string(),
                            file_.parent_path(), out, shadingModes(), visible, existing);
  else
    saveSceneWithMeshes(file_, out, shadingModes(), visible, existing);
}

void SceneSession::resetCamera() {
  if (base_) camera_ = base_->camera.spec();
}

RenderRequest SceneSession::request(const TraceOptions& trace, std::uint64_t id) const {
  RenderRequest r;
  r.id = id;
  r.base = base_;
  r.trace = trace;
  for (const MeshState& m : meshes_) {
    r.modes.push_back(m.shading);
    r.visible.push_back(m.visible);
  }
  return r;
}

std::shared_ptr<const Scene> SceneSession::adoptBase(const RenderScene& scene) {
  if (scene.preview || !scene.allVisible || !base_ ||
      scene.prepared->scene().meshes.size() != base_->meshes.size())
    return nullptr;
  return std::exchange(base_, scene.prepared->sharedScene());
}

}  // namespace meshtrace::viewer
