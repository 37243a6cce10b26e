#include "viewer/model/scene_catalog.h"

#include <algorithm>
#include <system_error>

#include "common/batch.h"

namespace meshtrace::viewer {

namespace fs = std::filesystem;

SceneFolder scanFolder(const fs::path& root, const std::string& title) {
  SceneFolder folder{root, title, {}, {}};
  std::error_code ec;
  if (!fs::is_directory(root, ec)) {
    folder.error = "not a folder: " + root.string();
    return folder;
  }
  folder.scenes = app::findScenes(root, ec);
  if (ec) folder.error = "could not read " + root.string() + ": " + ec.message();
  return folder;
}

std::vector<std::pair<fs::path, std::string>> defaultSceneRoots(const fs::path& executable,
                                                                const fs::path& cwd) {
  std::vector<fs::path> bases;
  std::error_code ec;
  const fs::path exe = fs::weakly_canonical(executable, ec);
  // build/bin/viewer: the checkout is two folders up.
  if (!ec && exe.has_parent_path()) bases.push_back(exe.parent_path().parent_path().parent_path());
  bases.push_back(cwd);
  std::vector<std::pair<fs::path, std::string>> roots;
  const auto add = [&](const fs::path& p) {
    if (!fs::is_directory(p, ec)) return;
    const fs::path canonical = fs::weakly_canonical(p, ec);
    for (const auto& r : roots)
      if (r.first == canonical) return;
    roots.emplace_back(canonical,
                       (canonical.parent_path().filename() / canonical.filename()).string());
  };
  for (const fs::path& base : bases) {
    add(base / "scenes");
    add(base.parent_path() / "shared" / "seed" / "scenes");
  }
  return roots;
}

std::string sceneLabel(const SceneFolder& folder, const fs::path& scene) {
  std::error_code ec;
  const fs::path rel = fs::relative(scene, folder.root, ec);
  return ec || rel.empty() ? scene.filename().string() : rel.string();
}

std::vector<fs::path> subfolders(const fs::path& dir) {
  std::vector<fs::path> out;
  std::error_code ec;
  for (fs::directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec);
       !ec && it != fs::directory_iterator(); it.increment(ec)) {
    if (it->is_directory(ec) && it->path().filename().string().rfind('.', 0) != 0)
      out.push_back(it->path());
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace meshtrace::viewer
