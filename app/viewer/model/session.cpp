#include "viewer/model/session.h"

#include <chrono>
#include <map>

#include "meshtrace/io/scene_parser.h"
#include "viewer/model/scene_writer.h"

namespace meshtrace::viewer {

bool SceneSession::load(const std::filesystem::path& file) {
  clear();
  file_ = file;
  const auto start = std::chrono::steady_clock::now();
  try {
    scene_ = std::make_shared<Scene>(loadScene(file));
  } catch (const std::exception& e) {
    error_ = e.what();
    return false;
  }
  loadMs_ =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  std::map<std::string, int> seen;
  for (const Mesh& m : scene_->meshes) {
    MeshState s;
    s.name = m.file().stem().string();
    if (const int n = ++seen[s.name]; n > 1) s.name += " #" + std::to_string(n);
    s.fileShading = s.shading = m.shading();
    meshes_.push_back(s);
  }
  camera_ = scene_->camera.spec();
  return true;
}

void SceneSession::clear() {
  error_.clear();
  scene_.reset();
  meshes_.clear();
  prepared_.reset();
  renderToScene_.clear();
  loadMs_ = 0.0;
  ++revision_;
}

void SceneSession::setShading(std::size_t mesh, Shading shading) {
  if (meshes_[mesh].shading == shading) return;
  meshes_[mesh].shading = shading;
  // The renderer may hold this very scene (see prepared()): change a copy.
  if (scene_.use_count() > 1) scene_ = std::make_shared<Scene>(*scene_);
  scene_->meshes[mesh].setShading(shading);
  prepared_.reset();
  ++revision_;
}

void SceneSession::setVisible(std::size_t mesh, bool visible) {
  if (meshes_[mesh].visible == visible) return;
  meshes_[mesh].visible = visible;
  prepared_.reset();
  ++revision_;
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

void SceneSession::saveModes(const std::filesystem::path& out) const {
  saveSceneWithModes(file_, out, shadingModes());
}

void SceneSession::resetCamera() {
  if (!scene_) return;
  camera_ = scene_->camera.spec();
  ++revision_;
}

std::shared_ptr<const PreparedScene> SceneSession::prepared(const TraceOptions& options) {
  if (!scene_) return nullptr;
  if (prepared_ && preparedOptions_.accel == options.accel) return prepared_;
  renderToScene_.clear();
  for (std::uint32_t i = 0; i < scene_->meshes.size(); ++i)
    if (meshes_[i].visible) renderToScene_.push_back(i);
  // With every mesh shown, the renderer shares our scene (setShading copies
  // it before changing it); else it gets a copy without the hidden meshes.
  std::shared_ptr<const Scene> render = scene_;
  if (renderToScene_.size() < scene_->meshes.size()) {
    auto some = std::make_shared<Scene>(*scene_);
    some->meshes.clear();
    for (std::uint32_t i : renderToScene_) some->meshes.push_back(scene_->meshes[i]);
    render = std::move(some);
  }
  prepared_ = std::make_shared<PreparedScene>(std::move(render), options);
  preparedOptions_ = options;
  return prepared_;
}

}  // namespace meshtrace::viewer
