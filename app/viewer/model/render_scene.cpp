#include "viewer/model/render_scene.h"

namespace meshtrace::viewer {

namespace {
// Everything of `s` but its meshes, without copying them.
Scene withoutMeshes(const Scene& s) {
  Scene out;
  out.file = s.file;
  out.camera = s.camera;
  out.depth = s.depth;
  out.background = s.background;
  out.ambience = s.ambience;
  out.lights = s.lights;
  out.spheres = s.spheres;
  out.planes = s.planes;
  out.cylinders = s.cylinders;
  out.warnings = s.warnings;
  return out;
}

// "1,000,192"
std::string withCommas(std::size_t n) {
  std::string digits = std::to_string(n), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}
}  // namespace

bool sameTrace(const TraceOptions& a, const TraceOptions& b) {
  return a.accel == b.accel && a.triangle.test == b.triangle.test &&
         a.triangle.precision == b.triangle.precision;
}

std::shared_ptr<RenderScene> makeRenderScene(const RenderRequest& request,
                                             const std::function<void(std::string)>& phase,
                                             const std::function<bool()>& cancelled) {
  const Scene& base = *request.base;
  auto out = std::make_shared<RenderScene>();
  out->request = request.id;
  bool same = true;
  std::size_t normals = 0;
  for (std::uint32_t i = 0; i < base.meshes.size(); ++i) {
    const Mesh& mesh = base.meshes[i];
    if (request.visible[i]) out->sceneMesh.push_back(i);
    same = same && request.visible[i] && mesh.shading() == request.modes[i];
    if (request.modes[i] == Shading::Phong && mesh.vertexNormals().empty())
      normals += mesh.triangles().size();
  }
  out->allVisible = out->sceneMesh.size() == base.meshes.size();
  std::shared_ptr<const Scene> scene = request.base;
  if (!same) {
    phase(normals > 0 ? "vertex normals of " + withCommas(normals) + " triangles"
                      : "applying the shading modes");
    auto changed = std::make_shared<Scene>(withoutMeshes(base));
    for (std::uint32_t i : out->sceneMesh) {
      if (cancelled()) return nullptr;
      changed->meshes.push_back(base.meshes[i]);
      changed->meshes.back().setShading(request.modes[i]);
    }
    scene = std::move(changed);
  }
  if (cancelled()) return nullptr;
  phase(request.trace.accel == AccelMethod::Bvh
            ? "building the BVH over " + withCommas(scene->triangleCount()) + " triangles"
            : "preparing the scene");
  auto prepared = std::make_shared<PreparedScene>(std::move(scene), request.trace);
  prepared->intersector();
  out->prepared = std::move(prepared);
  return out;
}

RenderScene makePreview(std::shared_ptr<const Scene> scene, const TraceOptions& trace) {
  RenderScene out;
  out.preview = true;
  for (std::uint32_t i = 0; i < scene->meshes.size(); ++i) out.sceneMesh.push_back(i);
  auto prepared = std::make_shared<PreparedScene>(std::move(scene), trace, SceneStructure::Preview);
  prepared->intersector();
  out.prepared = std::move(prepared);
  return out;
}

}  // namespace meshtrace::viewer
