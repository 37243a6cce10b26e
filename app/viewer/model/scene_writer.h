#pragma once
// Saving a scene with changed mesh shading modes and hidden meshes: the
// file's text is kept, comments and layout included; each mesh's FLAT/PHONG
// word changes, and a hidden mesh's entity becomes comment lines, so that
// the choice survives and is undone by deleting a `#`.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "meshtrace/geometry/mesh.h"
#include "viewer/model/save_target.h"

namespace meshtrace::viewer {

// Returns `text` with the shading word of the i-th `mesh` entity replaced by
// modes[i], and the entity commented out where visible[i] is false; for a
// scene moved from folder `from` to `to`, relative mesh paths lead to the
// same files from `to`. Throws std::runtime_error if the text has a
// different number of meshes (the file changed since it was loaded).
std::string rewriteMeshes(std::string_view text, const std::vector<Shading>& modes,
                          const std::vector<bool>& visible, const std::filesystem::path& from,
                          const std::filesystem::path& to);

// The shading word of each `mesh` entity, in order. Throws
// std::runtime_error for text the scene reader would refuse in a way that
// changes the count (an unknown keyword) and for a word other than FLAT or
// PHONG.
std::vector<Shading> meshModes(std::string_view text);

// Reads `scene`, rewrites its meshes and writes `out` whole or not at all
// (output_file.h). Throws FileExists if `out` exists (`scene` itself
// included) unless `existing` says to replace it, std::runtime_error naming
// the file for other failures.
void saveSceneWithMeshes(const std::filesystem::path& scene, const std::filesystem::path& out,
                         const std::vector<Shading>& modes, const std::vector<bool>& visible,
                         Existing existing);

// The same for scene text not read from a file (the scene made for a bare
// mesh): its relative mesh paths lead from folder `from`, and its errors
// are said to be of `source`.
void saveSceneTextWithMeshes(std::string_view text, const std::string& source,
                             const std::filesystem::path& from, const std::filesystem::path& out,
                             const std::vector<Shading>& modes, const std::vector<bool>& visible,
                             Existing existing);

}  // namespace meshtrace::viewer
