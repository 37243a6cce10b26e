#pragma once
// The scenes the viewer's renderer traces, made off the UI thread: the
// loaded scene with the user's shading modes and without the hidden
// meshes, its intersector built; and, while that is made for a large
// scene, a preview (the scene as loaded, every mesh FLAT, through the
// quick grid of progressive.h).
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "meshtrace/render/progressive.h"

namespace meshtrace::viewer {

struct RenderRequest {
  std::uint64_t id = 0;               // to match the answer to the latest request
  std::shared_ptr<const Scene> base;  // the loaded scene (its meshes' modes may differ)
  std::vector<Shading> modes;         // per mesh of `base`
  std::vector<bool> visible;          // per mesh of `base`
  TraceOptions trace;
};

struct RenderScene {
  std::uint64_t request = 0;
  std::shared_ptr<const PreparedScene> prepared;  // built
  std::vector<std::uint32_t> sceneMesh;           // per mesh rendered, its index in the base
  bool preview = false;
  bool allVisible = true;  // the scene is the base with the modes applied, nothing left out
};

// Whether two sets of options make the same render scene (those the
// viewer lets the user change: the method, the triangle test, the precision).
bool sameTrace(const TraceOptions& a, const TraceOptions& b);

// From this many triangles on, a preview is worth making: below, the BVH
// builds in about the time the preview would take.
inline constexpr std::size_t kPreviewTriangles = 200'000;

// Applies the request (a mesh switched to another mode shares its arrays
// with the base, mesh.h) and builds the intersector; says what it does
// through `phase`. Returns null if `cancelled` turns true between its steps.
std::shared_ptr<RenderScene> makeRenderScene(const RenderRequest& request,
                                             const std::function<void(std::string)>& phase,
                                             const std::function<bool()>& cancelled);

// The preview of a loaded scene, its grid built.
RenderScene makePreview(std::shared_ptr<const Scene> scene, const TraceOptions& trace);

}  // namespace meshtrace::viewer
