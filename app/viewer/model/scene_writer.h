#pragma once
// Saving a scene with changed mesh shading modes: the file's text is kept,
// comments and layout included, and only each mesh's FLAT/PHONG word changes.
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "meshtrace/geometry/mesh.h"

namespace meshtrace::viewer {

// Returns `text` with the shading word of the i-th `mesh` entity replaced by
// modes[i]. Throws std::runtime_error if the text has a different number of
// meshes (the file changed since it was loaded).
std::string rewriteMeshModes(std::string_view text, const std::vector<Shading>& modes);

// The shading word of each `mesh` entity, in order. Throws
// std::runtime_error for text the scene reader would refuse in a way that
// changes the count (an unknown keyword) and for a word other than FLAT or
// PHONG.
std::vector<Shading> meshModes(std::string_view text);

// Reads `scene`, rewrites its modes and writes `out` (which may be `scene`)
// through a temporary file. Throws std::runtime_error naming the file.
void saveSceneWithModes(const std::filesystem::path& scene, const std::filesystem::path& out,
                        const std::vector<Shading>& modes);

}  // namespace meshtrace::viewer
