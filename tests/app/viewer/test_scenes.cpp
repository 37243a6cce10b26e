#include "app/viewer/test_scenes.h"

#include "support/paths.h"

namespace meshtrace::test {

namespace fs = std::filesystem;

fs::path viewerTestScenes() { return sourceDir() / "tests/app/viewer/scenes"; }

fs::path copyOfViewerTestScenes(const std::string& name) {
  const fs::path dir = scratchDir() / name;
  fs::remove_all(dir);
  fs::copy(viewerTestScenes(), dir, fs::copy_options::recursive);
  return dir;
}

}  // namespace meshtrace::test
