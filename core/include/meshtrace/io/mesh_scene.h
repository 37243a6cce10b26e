#pragma once
// A bare mesh file as a scene: its bounding box framed by a camera, lit by
// a light above and in front, standing on a floor, shaded PHONG. The scene
// is made as .sce text and parsed, so that the text a user saves renders
// what the bare mesh rendered.
#include <filesystem>
#include <string>

#include "meshtrace/geometry/aabb.h"
#include "meshtrace/geometry/scene.h"
#include "meshtrace/io/memory_budget.h"
#include "meshtrace/io/scene_parser.h"

namespace meshtrace {

// Whether `file` is a scene (.sce) rather than a mesh to frame.
bool isSceneFile(const std::filesystem::path& file);

// The .sce text framing `bounds` (y up: the floor lies under the box), its
// mesh line naming `meshName` (relative to where the text is saved).
std::string meshSceneText(const Aabb& bounds, const std::string& meshName);

// A bare mesh read once (readMesh, within `budget`): the .sce text that
// frames its box, and a source that hands its arrays to that text's mesh
// line (parseScene), so that the file is not read a second time. Throws
// InputError for a bad or empty mesh, or a name a scene cannot hold.
struct FramedMesh {
  std::string text;
  MeshSource meshes;
};
FramedMesh frameMesh(const std::filesystem::path& mesh, MemoryBudget& budget);

// The .sce text for `mesh`, read for its box, to be saved beside it
// (frameMesh's text; the arrays are freed).
std::string meshSceneText(const std::filesystem::path& mesh, MemoryBudget& budget);

// Where the text of meshSceneText(mesh, ...) belongs: <stem>.sce beside
// the mesh, the folder its mesh line is relative to.
std::filesystem::path meshScenePath(const std::filesystem::path& mesh);

// The scene meshSceneText makes for `mesh`, as if saved at meshScenePath.
Scene loadMeshAsScene(const std::filesystem::path& mesh, MemoryBudget& budget);

}  // namespace meshtrace
