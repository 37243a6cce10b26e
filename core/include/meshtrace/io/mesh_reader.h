#pragma once
// Mesh files by their extension. The core reads OFF itself; readers of
// other formats live outside it (the OpenMesh-based ones in app/formats, so
// that the core never depends on OpenMesh) and are registered here by the
// programs that link them, before any scene loads.
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "meshtrace/geometry/mesh.h"
#include "meshtrace/io/memory_budget.h"

namespace meshtrace {

// Reads a whole mesh, throwing InputError naming the file and the element
// on bad input and reserving its arrays in `budget` before allocating them.
using MeshReader = std::function<MeshData(const std::filesystem::path&, MemoryBudget&)>;

// Reads files whose extension is `extension` (".ply"; compared without
// regard to case) with `reader` from now on. Not to be called while scenes
// load.
void registerMeshReader(std::string_view extension, MeshReader reader);

// The extensions with a registered reader, sorted, ".off" among them.
std::vector<std::string> meshExtensions();

// Whether `file`'s extension has a registered reader.
bool isMeshFile(const std::filesystem::path& file);

// Reads `file` with the reader of its extension; a file of any other
// extension is read as OFF.
MeshData readMesh(const std::filesystem::path& file, MemoryBudget& budget);

// A reader's last step, once `mesh` is read with its polygons recorded by
// appendPolygonTriangles: reserves the records' room in `budget` (they
// stay with the mesh, 12 bytes a polygon) and cuts again the faces that
// are not convex (tileNonConvexPolygons), counting in
// mesh.untiledPolygons those no triangles cover exactly.
void finishPolygons(MeshData& mesh, MemoryBudget& budget, const std::filesystem::path& file);

}  // namespace meshtrace
