#pragma once
// How the viewer names the face of the mesh's file a triangle was cut
// from, after the triangle's number: a polygon's triangles are not the
// file's faces, and after the first polygon the numbers part.
#include <cstdint>
#include <string>

#include "meshtrace/geometry/mesh.h"

namespace meshtrace::viewer {

// " of face 1 (24 corners)" for a polygon's triangle, " (face 2)" for a
// triangle whose face number differs from its own, else empty.
inline std::string faceSuffix(std::uint32_t triangle, const FaceOfTriangle& face) {
  if (face.corners > 3)
    return " of face " + std::to_string(face.face) + " (" + std::to_string(face.corners) +
           " corners)";
  if (face.face != triangle) return " (face " + std::to_string(face.face) + ")";
  return {};
}

}  // namespace meshtrace::viewer
