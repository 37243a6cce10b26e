#include "bench/mesh_load.h"

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "formats/openmesh_reader.h"
#include "meshtrace/io/mesh_reader.h"
#include "meshtrace/io/mesh_writer.h"
#include "meshtrace/io/off_reader.h"

namespace meshtrace::bench {

namespace {
constexpr int kRounds = 5;

// The time `read` takes to load `file`, checked for the triangles expected.
double loadMs(const std::filesystem::path& file, std::size_t expectedTriangles,
              const MeshReader& read = readMesh) {
  MemoryBudget budget(defaultMemoryLimit());
  const auto start = std::chrono::steady_clock::now();
  const MeshData mesh = read(file, budget);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (mesh.triangles.size() != expectedTriangles)
    throw std::runtime_error(file.string() + " loaded " + std::to_string(mesh.triangles.size()) +
                             " triangles, not " + std::to_string(expectedTriangles));
  return ms;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}
}  // namespace

void printMeshLoadTimes(const std::filesystem::path& off) {
  formats::registerOpenMeshFormats();
  const MeshData mesh = readOff(off);
  const auto sibling = [&](const std::string& suffix) {
    return off.parent_path() / (off.stem().string() + suffix);
  };
  // Float coordinates, as scanners and exporters write them.
  const auto ply = sibling(".ply");
  if (!std::filesystem::exists(ply)) writeBinaryPly(mesh, ply, PlyCoordinates::Float);
  // OFF's numbers, as ASCII PLY and ASCII STL.
  const auto asciiPly = sibling("-ascii.ply");
  if (!std::filesystem::exists(asciiPly)) writeAsciiPly(mesh, asciiPly);
  const auto asciiStl = sibling("-ascii.stl");
  if (!std::filesystem::exists(asciiStl)) writeAsciiStl(mesh, asciiStl);
  // Binary STL: each facet's corners as floats.
  const auto stl = sibling(".stl");
  if (!std::filesystem::exists(stl)) writeMesh(mesh, stl);

  struct Row {
    const char* name;
    std::filesystem::path file;
    MeshReader read;  // OpenMesh's: the reader PLY and STL had before the core read them
    std::vector<double> ms;
  };
  const MeshReader ours = readMesh;
  const MeshReader openMesh = formats::readOpenMeshFile;
  std::vector<Row> rows = {{"OFF (ours)", off, ours, {}},
                           {"binary PLY (ours)", ply, ours, {}},
                           {"binary PLY (OpenMesh)", ply, openMesh, {}},
                           {"ASCII PLY (ours)", asciiPly, ours, {}},
                           {"ASCII PLY (OpenMesh)", asciiPly, openMesh, {}},
                           {"binary STL (ours)", stl, ours, {}},
                           {"binary STL (OpenMesh)", stl, openMesh, {}},
                           {"ASCII STL (ours)", asciiStl, ours, {}},
                           {"ASCII STL (OpenMesh)", asciiStl, openMesh, {}}};
  const std::size_t n = mesh.triangles.size();
  for (int round = 0; round < kRounds; ++round)  // interleaved: all see the same load
    for (Row& row : rows) row.ms.push_back(loadMs(row.file, n, row.read));
  std::printf("\n### Loading %s: %zu triangles, median of %d loads\n\n", off.stem().c_str(), n,
              kRounds);
  std::printf("| file | bytes | load ms | GB/s | against OFF |\n|---|---|---|---|---|\n");
  const double offMs = median(rows.front().ms);
  for (const Row& row : rows) {
    const auto bytes = static_cast<std::uintmax_t>(std::filesystem::file_size(row.file));
    const double ms = median(row.ms);
    std::printf("| %s | %ju | %.1f | %.2f | %.2f |\n", row.name, bytes, ms,
                static_cast<double>(bytes) / ms * 1e-6, ms / offMs);
  }
}

}  // namespace meshtrace::bench
