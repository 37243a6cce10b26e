#pragma once
// The coordinates of a vertex line of a text mesh (OFF, OBJ), read and
// refused in the same words whatever the format.
#include <cstddef>
#include <cstdint>
#include <filesystem>

#include "io/text.h"
#include "meshtrace/util/math.h"

namespace meshtrace::text {

// The next three values of `tokens` as the coordinates of vertex `index`
// (values after them are left unread). Throws InputError naming `file`,
// `line` and the vertex for fewer than three values, a word among them or
// a coordinate that is not finite.
Vec3 readVertexCoordinates(TokenReader& tokens, const std::filesystem::path& file, std::size_t line,
                           std::int64_t index);

}  // namespace meshtrace::text
