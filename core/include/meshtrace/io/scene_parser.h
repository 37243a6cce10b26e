#pragma once
// Reader for the `.sce` scene format (see SCENE_FORMAT in the README).
#include <filesystem>
#include <functional>
#include <string_view>

#include "meshtrace/geometry/scene.h"
#include "meshtrace/io/memory_budget.h"

namespace meshtrace {

// Throws InputError naming the file and line on bad input. Mesh paths are
// resolved against the scene file's folder; the meshes are read, side by
// side, once the whole scene file has parsed, and of several bad meshes the
// first in the file is the one reported. The meshes' arrays are reserved
// in `budget` before they are allocated (MemoryLimitError beyond its limit).
Scene loadScene(const std::filesystem::path& file, MemoryBudget& budget);
// With a budget of defaultMemoryLimit().
Scene loadScene(const std::filesystem::path& file);

// Where the mesh lines of a scene get their arrays: readMesh(file, budget)
// unless a caller already holds a mesh's arrays (a bare mesh read once to
// frame it, mesh_scene.h).
using MeshSource = std::function<MeshData(const std::filesystem::path&, MemoryBudget&)>;

// Parses scene text that claims to come from `file` (used for messages and
// for resolving mesh paths).
Scene parseScene(std::string_view text, const std::filesystem::path& file, MemoryBudget& budget);
// The same, the meshes' arrays taken from `meshes`.
Scene parseScene(std::string_view text, const std::filesystem::path& file, MemoryBudget& budget,
                 const MeshSource& meshes);
// With a budget of defaultMemoryLimit().
Scene parseScene(std::string_view text, const std::filesystem::path& file);

// Whether `text` can be written as one word of a scene file, as a mesh
// line's file name must be: not empty, no white space (which separates
// words) and no '#' (which starts a comment). Scene files have no quoting.
bool isSceneWord(std::string_view text);

}  // namespace meshtrace
