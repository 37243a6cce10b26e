#include "meshtrace/io/mesh_reader.h"

#include <algorithm>
#include <cctype>
#include <map>

#include "meshtrace/geometry/polygon.h"
#include "meshtrace/io/obj_reader.h"
#include "meshtrace/io/off_reader.h"
#include "meshtrace/io/stl_reader.h"

namespace meshtrace {

namespace {
std::string lowercase(std::string_view text) {
  std::string out(text);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

std::map<std::string, MeshReader>& readers() {
  static std::map<std::string, MeshReader> byExtension = {
      {".off", [](const std::filesystem::path& file,
                  MemoryBudget& budget) { return readOff(file, budget); }},
      {".obj", [](const std::filesystem::path& file,
                  MemoryBudget& budget) { return readObj(file, budget); }},
      {".stl", [](const std::filesystem::path& file, MemoryBudget& budget) {
         return readStl(file, budget);
       }}};
  return byExtension;
}
}  // namespace

void registerMeshReader(std::string_view extension, MeshReader reader) {
  readers()[lowercase(extension)] = std::move(reader);
}

std::vector<std::string> meshExtensions() {
  std::vector<std::string> out;
  for (const auto& [extension, reader] : readers()) out.push_back(extension);
  return out;
}

bool isMeshFile(const std::filesystem::path& file) {
  return readers().count(lowercase(file.extension().string())) != 0;
}

void finishPolygons(MeshData& mesh, MemoryBudget& budget, const std::filesystem::path& file) {
  if (mesh.polygons.empty()) return;
  budget.reserve(mesh.polygons.capacity() * sizeof(PolygonFace), "load",
                 "the records of the " + std::to_string(mesh.polygons.size()) + " polygons of " +
                     file.filename().string());
  mesh.untiledPolygons =
      tileNonConvexPolygons(mesh.vertices, mesh.polygons, mesh.triangles).untiled;
}

MeshData readMesh(const std::filesystem::path& file, MemoryBudget& budget) {
  const auto found = readers().find(lowercase(file.extension().string()));
  if (found == readers().end()) return readOff(file, budget);
  return found->second(file, budget);
}

}  // namespace meshtrace
