#include "support/cli.h"

#include <gtest/gtest.h>

#include <system_error>

#include "support/files.h"
#include "support/paths.h"
#include "support/scene_snippets.h"

namespace meshtrace::test {

ToolResult expectRefusal(const std::filesystem::path& tool, const std::vector<std::string>& args,
                         const std::filesystem::path& dir, const std::vector<std::string>& mentions,
                         const std::filesystem::path& output) {
  std::error_code ec;  // a name too long to exist is no error here
  const bool outputExisted = std::filesystem::is_regular_file(output, ec);
  const std::string before = readFileBytes(output);
  const std::vector<std::string> filesBefore = listFolder(dir);
  const ToolResult result = runTool(tool, args, dir);
  EXPECT_TRUE(result.exited) << "the tool must exit, not crash or hang: " << describe(result);
  EXPECT_EQ(result.exitCode, 1) << describe(result);
  EXPECT_NE(result.err.find("error"), std::string::npos) << describe(result);
  for (const std::string& m : mentions)
    EXPECT_NE(result.err.find(m), std::string::npos) << "stderr should mention '" << m << "'\n"
                                                     << describe(result);
  if (outputExisted) {
    EXPECT_TRUE(readFileBytes(output) == before) << "the old output must be left as it was";
  }
  EXPECT_EQ(listFolder(dir), filesBefore) << "no partial or temporary file may be left";
  return result;
}

void expectRefusesBadInput(const std::filesystem::path& tool, const BadInput& input) {
  const auto dir = scratchDir();
  if (!input.scene.empty()) writeFile(dir / "bad.sce", input.scene);
  if (!input.mesh.empty()) writeFile(dir / "mesh.off", input.mesh);
  std::filesystem::create_directory(dir / "folder.off");
  writeFile(dir / "out.png", kOldOutput);
  expectRefusal(tool, {(dir / "bad.sce").string(), (dir / "out.png").string()}, dir, input.mentions,
                dir / "out.png");
}

std::filesystem::path folderWithGoodScene() {
  const auto dir = scratchDir();
  writeFile(dir / "tri.off", kTriangleOff);
  writeFile(dir / "good.sce", kCameraLine + "light 0 0 10 1 1 1\n" + kSphereLine +
                                  "mesh tri.off PHONG " + kMaterial + "\n");
  return dir;
}

std::vector<std::string> renderArgs(const std::filesystem::path& dir, const std::string& out) {
  return {(dir / "good.sce").string(), (dir / out).string()};
}

void expectRefusedBeforeRendering(const ToolResult& r) {
  EXPECT_EQ(r.out.find("loaded"), std::string::npos) << describe(r);
  EXPECT_EQ(r.out.find("rendered"), std::string::npos) << describe(r);
}

ToolResult expectSuccess(const std::filesystem::path& tool, const std::vector<std::string>& args,
                         const std::filesystem::path& dir) {
  const ToolResult result = runTool(tool, args, dir);
  EXPECT_TRUE(result.exited && result.exitCode == 0) << describe(result);
  EXPECT_EQ(result.err.find("error"), std::string::npos) << describe(result);
  return result;
}

ToolResult runOnTerminal(const std::string& command, const std::filesystem::path& dir) {
  return runTool("/usr/bin/script", {"-qec", command, "/dev/null"}, dir);
}

}  // namespace meshtrace::test
