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

namespace meshtrace {

// Whether `file` is a scene (.sce) rather than a mesh to frame.
bool isSceneFile(const std::filesystem::path& file);

// The .sce text framing `bounds` (y up: the floor lies under the box), its
// mesh line naming `meshName` (relative to where the text is saved).
std::string meshSceneText(const Aabb& bounds, const std::string& meshName);

// The .sce text for `mesh`, read (readMesh) for its box, to be saved beside
// it. Throws InputError for a bad or empty mesh.
std::string meshSceneText(const std::filesystem::path& mesh, MemoryBudget& budget);

// Where the text of meshSceneText(mesh, ...) belongs: <stem>.sce beside
// the mesh, the folder its mesh line is relative to.
std::filesystem::path meshScenePath(const std::filesystem::path& mesh);

// The scene meshSceneText makes for `mesh`, as if saved at meshScenePath.
Scene loadMeshAsScene(const std::filesystem::path& mesh, MemoryBudget& budget);

}  // namespace meshtrace
