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

// Our scenes/ and ../shared/seed/scenes, looked for from the working folder
// and from the executable's folder (build/bin/ in a checkout); only those
// that exist.
std::vector<std::pair<std::filesystem::path, std::string>> defaultSceneRoots(
    const std::filesystem::path& executable);

// A scene's label in the list: its path below the folder's root.
std::string sceneLabel(const SceneFolder& folder, const std::filesystem::path& scene);

// The subfolders of `dir`, sorted, for the folder browser; empty on error.
std::vector<std::filesystem::path> subfolders(const std::filesystem::path& dir);

}  // namespace meshtrace::viewer
