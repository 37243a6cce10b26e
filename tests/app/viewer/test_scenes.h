#pragma once
// The viewer tests' own scenes (tests/app/viewer/scenes), and fresh copies
// of them for tests that edit or save beside them.
#include <filesystem>
#include <string>

namespace meshtrace::test {

std::filesystem::path viewerTestScenes();

// A fresh copy of the test scenes in the scratch folder `name` (emptied
// first); returns that folder.
std::filesystem::path copyOfViewerTestScenes(const std::string& name);

}  // namespace meshtrace::test
