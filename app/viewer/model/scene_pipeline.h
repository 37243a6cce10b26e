#pragma once
// Opening scenes and making their render scenes on a background thread
// (background_task.h), so that a frame never waits for a parser, vertex
// normals or a BVH. Opening a scene reads its geometry (every mesh FLAT,
// geometry_load.h), makes a preview when the scene is large, then the
// render scene with the file's modes; a later request (a mode switched, a
// mesh hidden, another triangle test) makes another render scene. Each
// action cancels the one before.
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "viewer/model/background_task.h"
#include "viewer/model/geometry_load.h"
#include "viewer/model/render_scene.h"

namespace meshtrace::viewer {

// What the background work hands back, in this order for an opening.
struct Arrival {
  std::optional<LoadedScene> loaded;
  std::shared_ptr<RenderScene> preview;
  std::shared_ptr<RenderScene> render;
  std::string error;  // the opening failed: the scene did not load
};

class ScenePipeline {
 public:
  explicit ScenePipeline(std::function<void()> wake = {});

  // `request` is made for the loaded scene: its id, and the trace options.
  void open(const std::filesystem::path& file, const TraceOptions& trace, std::uint64_t requestId);
  void prepare(const RenderRequest& request);
  void cancel() { task_.cancel(); }

  std::vector<Arrival> take();
  bool busy() const { return task_.busy(); }
  std::string phase() const { return task_.phase(); }
  double phaseMs() const { return task_.phaseMs(); }
  // Why the current work ended early (e.g. out of memory), else empty.
  std::string error() const { return task_.error(); }

 private:
  BackgroundTask<Arrival> task_;
};

}  // namespace meshtrace::viewer
