// The meshes OpenMesh reads (a PLY of float corner indices here, which the
// core's reader leaves to it) show the same load line as those
// the core reads: on a terminal (a pseudo-terminal made by script(1)),
// how much of the file is read, rising as it is, then "computing normals"
// once the whole file counts as read.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "mesh_files.h"
#include "meshtrace/geometry/mesh_generators.h"
#include "support/cli.h"
#include "support/files.h"
#include "support/paths.h"

namespace meshtrace {
namespace {

TEST(OpenMeshReadProgress, APlyFileItReadsShowsHowMuchIsRead) {
  const auto dir = test::scratchDir();
  // 750k triangles, about 36 MB of ASCII PLY: above the 8 MB from which a
  // load shows a line, and long enough to read (several tenths of a second)
  // for the line to be drawn again, a tenth of a second apart. Float corner
  // indices send it to OpenMesh.
  const auto ply = dir / "knot.ply";
  test::writeMeshFile(makeTorusKnot(Vec3(0.0), 1.0, 2, 3, 0.3, 3750, 100),
                      test::MeshFormat::PlyAscii, ply);
  std::string text = test::readFileBytes(ply);
  const std::string corners = "list uchar int vertex_indices";
  text.replace(text.find(corners), corners.size(), "list uchar float vertex_indices");
  test::writeFile(ply, text);
  ASSERT_GT(std::filesystem::file_size(ply), 8u << 20);
  const auto r = test::runOnTerminal(
      test::raytraceTool().string() + " " + ply.string() + " " + (dir / "out.png").string(), dir);
  ASSERT_TRUE(r.exited && r.exitCode == 0) << test::describe(r);
  std::set<std::string> shares;
  const std::string line = "loading knot.ply: ";
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
