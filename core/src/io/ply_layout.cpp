#include "io/ply_layout.h"

namespace meshtrace {

bool readablePlyLayout(const PlyHeader& header) {
  int vertexElements = 0;
  for (const PlyElement& e : header.elements) {
    if (e.name == "vertex") ++vertexElements;
    if (e.name == "face") {
      // Faces may come first: their indices are checked against the
      // header's vertex count, and the polygons cut once all is read.
      int cornerLists = 0;
      for (const PlyProperty& p : e.properties) {
        if (!isPlyCornerList(e, p)) continue;
        ++cornerLists;
        if (p.isFloat) return false;
      }
      if (cornerLists != 1) return false;
    }
  }
  return vertexElements == 1;
}

}  // namespace meshtrace
