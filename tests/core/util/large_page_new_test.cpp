// Our programs and this test binary link meshtrace::large_page_new (not in
// the sanitizer build, where this file is not built either).
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "meshtrace/geometry/mesh_generators.h"
#include "meshtrace/io/mesh_writer.h"
#include "meshtrace/io/off_reader.h"
#include "support/paths.h"
#include "util/build_vector.h"

namespace meshtrace {
namespace {

bool startsOnHugePage(const void* p) {
  return reinterpret_cast<std::uintptr_t>(p) % kLargePageBytes == 0;
}

TEST(LargePageNew, ImageSizedVectorsStartOnAHugePageBoundary) {
  const std::vector<std::uint8_t> rgba(800 * 600 * 4, 7);
  EXPECT_TRUE(startsOnHugePage(rgba.data()));
  EXPECT_EQ(rgba.back(), 7);
}

TEST(LargePageNew, ArraysOfALoadedMeshStartOnAHugePageBoundary) {
  // 2 x 250 x 250 triangles: 1.5 MB of vertices and of triangles.
  const MeshData grid = makeGrid(Vec3(0.0), 1.0, 250);
  ASSERT_GE(grid.triangles.size() * sizeof(TriangleIndices), kLargePageBytes / 2);
  ASSERT_GE(grid.vertices.size() * sizeof(Vec3), kLargePageBytes / 2);
  const auto file = test::scratchDir() / "grid.off";
  writeMesh(grid, file);
  const MeshData loaded = readOff(file);
  EXPECT_TRUE(startsOnHugePage(loaded.vertices.data()));
  EXPECT_TRUE(startsOnHugePage(loaded.triangles.data()));
  EXPECT_EQ(loaded.triangles.size(), grid.triangles.size());
}

TEST(LargePageNew, SmallAndLargeAllocationsAreFreedTheSameWay) {
  for (int round = 0; round < 3; ++round) {
    std::vector<std::string> mixed;
    for (std::size_t bytes :
         {std::size_t{24}, kLargePageBytes / 2, std::size_t{4096}, 3 * kLargePageBytes + 5})
      mixed.emplace_back(bytes, 'x');
    for (const std::string& s : mixed) EXPECT_EQ(s.back(), 'x');
    EXPECT_TRUE(startsOnHugePage(mixed[3].data()));
  }
}

}  // namespace
}  // namespace meshtrace
