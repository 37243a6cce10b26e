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
  auto ply = off;
  ply.replace_extension(".ply");
  // Float coordinates, as scanners and exporters write them.
  if (!std::filesystem::exists(ply)) writeBinaryPly(mesh, ply, PlyCoordinates::Float);
  // OFF's numbers, as ASCII PLY.
  auto asciiPly = off;
  asciiPly.replace_filename(off.stem().string() + "-ascii.ply");
  if (!std::filesystem::exists(asciiPly)) writeAsciiPly(mesh, asciiPly);
  // Binary STL: each facet's corners as floats.
  auto stl = off;
  stl.replace_extension(".stl");
  if (!std::filesystem::exists(stl)) writeMesh(mesh, stl);
  std::vector<double> offMs, plyMs, openMeshMs, asciiMs, asciiOpenMeshMs, stlMs, stlOpenMeshMs;
  const std::size_t n = mesh.triangles.size();
  for (int round = 0; round < kRounds; ++round) {  // interleaved: all see the same load
    offMs.push_back(loadMs(off, n));
    plyMs.push_back(loadMs(ply, n));
    asciiMs.push_back(loadMs(asciiPly, n));
    // The reader PLY and STL had before the core read them.
    openMeshMs.push_back(loadMs(ply, n, formats::readOpenMeshFile));
    asciiOpenMeshMs.push_back(loadMs(asciiPly, n, formats::readOpenMeshFile));
    stlMs.push_back(loadMs(stl, n));
    stlOpenMeshMs.push_back(loadMs(stl, n, formats::readOpenMeshFile));
  }
  const double a = median(offMs), b = median(plyMs), c = median(openMeshMs);
  const double d = median(asciiMs), e = median(asciiOpenMeshMs);
  std::printf("\n### Loading %s: %zu triangles, median of %d loads\n\n", off.stem().c_str(),
              mesh.triangles.size(), kRounds);
  std::printf("| file | bytes | load ms | against OFF |\n|---|---|---|---|\n");
  std::printf("| OFF (ours) | %ju | %.1f | 1.00 |\n",
              static_cast<std::uintmax_t>(std::filesystem::file_size(off)), a);
  const auto plyBytes = static_cast<std::uintmax_t>(std::filesystem::file_size(ply));
  std::printf("| binary PLY (ours) | %ju | %.1f | %.2f |\n", plyBytes, b, b / a);
  std::printf("| binary PLY (OpenMesh) | %ju | %.1f | %.2f |\n", plyBytes, c, c / a);
  const auto asciiBytes = static_cast<std::uintmax_t>(std::filesystem::file_size(asciiPly));
  std::printf("| ASCII PLY (ours) | %ju | %.1f | %.2f |\n", asciiBytes, d, d / a);
  std::printf("| ASCII PLY (OpenMesh) | %ju | %.1f | %.2f |\n", asciiBytes, e, e / a);
  const double g = median(stlMs), h = median(stlOpenMeshMs);
  const auto stlBytes = static_cast<std::uintmax_t>(std::filesystem::file_size(stl));
  std::printf("| binary STL (ours) | %ju | %.1f | %.2f |\n", stlBytes, g, g / a);
  std::printf("| binary STL (OpenMesh) | %ju | %.1f | %.2f |\n", stlBytes, h, h / a);
}

}  // namespace meshtrace::bench
