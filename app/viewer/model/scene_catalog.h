#pragma once
// The scene list: folders of .sce files the viewer offers, and where the
// default folders are.
#include <filesystem>
#include <string>
#include <vector>

namespace meshtrace::viewer {

struct SceneFolder {
  std::filesystem::path root;
  std::string title;
  std::vector<std::filesystem::path> scenes;  // every .sce below root, sorted
  std::string error;                          // why the folder could not be read
};

// Never throws: an unreadable folder comes back with `error` set.
SceneFolder scanFolder(const std::filesystem::path& root, const std::string& title);

// scenes/ and ../shared/seed/scenes, looked for from the checkout the
// executable is in (build/bin/ in a checkout) and then from the working
// folder `cwd`; only those that exist, each once. The order does not
// depend on where the viewer starts, and each is titled by its folder
// ("seed/scenes"), since a scenes/ folder in the working folder need not
// be this project's.
std::vector<std::pair<std::filesystem::path, std::string>> defaultSceneRoots(
    const std::filesystem::path& executable,
    const std::filesystem::path& cwd = std::filesystem::current_path());

// A scene's label in the list: its path below the folder's root.
std::string sceneLabel(const SceneFolder& folder, const std::filesystem::path& scene);

// The subfolders of `dir`, sorted, for the folder browser; empty on error.
std::vector<std::filesystem::path> subfolders(const std::filesystem::path& dir);

}  // namespace meshtrace::viewer
