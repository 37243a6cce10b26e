#include "viewer/model/scene_pipeline.h"

namespace meshtrace::viewer {

namespace {
void makeAndPublish(TaskContext<Arrival>& task, const RenderRequest& request) {
  auto render = makeRenderScene(
      request, [&](std::string phase) { task.setPhase(std::move(phase)); },
      [&] { return task.cancelled(); });
  if (!render) return;
  Arrival a;
  a.render = std::move(render);
  task.publish(std::move(a));
}
}  // namespace

ScenePipeline::ScenePipeline(std::function<void()> wake) : task_(std::move(wake)) {}

void ScenePipeline::open(const std::filesystem::path& file, const TraceOptions& trace,
                         std::uint64_t requestId) {
  task_.start(
      [file, trace, requestId](TaskContext<Arrival>& task) {
        LoadedScene loaded;
        try {
          loaded = loadGeometry(file);
        } catch (const std::exception& e) {
          Arrival failed;
          failed.error = e.what();
          task.publish(std::move(failed));
          return;
        }
        const std::shared_ptr<const Scene> scene = loaded.scene;
        {
          Arrival a;
          a.loaded = loaded;
          task.publish(std::move(a));
        }
        if (task.cancelled()) return;
        if (scene->triangleCount() >= kPreviewTriangles) {
          task.setPhase("a quick grid for a first look");
          Arrival a;
          a.preview = std::make_shared<RenderScene>(makePreview(scene, trace));
          task.publish(std::move(a));
        }
        if (task.cancelled()) return;
        RenderRequest request;
        request.id = requestId;
        request.base = scene;
        request.modes = loaded.fileModes;
        request.visible.assign(loaded.fileModes.size(), true);
        request.trace = trace;
        makeAndPublish(task, request);
      },
      "reading the scene and its meshes");
}

void ScenePipeline::prepare(const RenderRequest& request) {
  task_.start([request](TaskContext<Arrival>& task) { makeAndPublish(task, request); },
              "applying the changes");
}

std::vector<Arrival> ScenePipeline::take() { return task_.take(); }

}  // namespace meshtrace::viewer
