// The meshes OpenMesh reads (ASCII STL here) show the same load line as those
// the core reads: on a terminal (a pseudo-terminal made by script(1)),
// how much of the file is read, rising as it is, then "computing normals"
// once the whole file counts as read.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "meshtrace/geometry/mesh_generators.h"
#include "mesh_files.h"
#include "support/cli.h"
#include "support/paths.h"

namespace meshtrace {
namespace {

TEST(OpenMeshReadProgress, AnAsciiStlFileShowsHowMuchIsRead) {
  const auto dir = test::scratchDir();
  // 150k triangles, over 8 MB of ASCII STL (above the 8 MB from which a
  // load shows a line) and more than twice the 64k facets the reader
  // reports progress by.
  const auto stl = dir / "knot.stl";
  test::writeMeshFile(makeTorusKnot(Vec3(0.0), 1.0, 2, 3, 0.3, 750, 100),
                      test::MeshFormat::StlAscii, stl);
  ASSERT_GT(std::filesystem::file_size(stl), 8u << 20);
  const auto r = test::runOnTerminal(
      test::raytraceTool().string() + " " + stl.string() + " " + (dir / "out.png").string(), dir);
  ASSERT_TRUE(r.exited && r.exitCode == 0) << test::describe(r);
  std::set<std::string> shares;
  const std::string line = "loading knot.stl: ";
  for (std::size_t at = r.out.find(line); at != std::string::npos; at = r.out.find(line, at + 1)) {
    const std::size_t start = at + line.size();
    const std::size_t percent = r.out.find('%', start);
    if (percent != std::string::npos && percent - start <= 3)
      shares.insert(r.out.substr(start, percent - start));
  }
  EXPECT_GE(shares.size(), 2u) << r.out;
  EXPECT_NE(r.out.find(line + "computing normals"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("\rloaded "), std::string::npos) << r.out;
}

}  // namespace
}  // namespace meshtrace
