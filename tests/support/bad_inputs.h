#pragma once
// The bad scenes and meshes of issue 2, as data, so that each command-line
// tool's tests run every one of them.
#include <string>
#include <vector>

namespace meshtrace::test {

struct BadInput {
  std::string name;                   // a test name suffix
  std::string scene;                  // text of bad.sce; empty: the scene file is not written
  std::string mesh;                   // text of mesh.off beside it; empty: not written
  std::vector<std::string> mentions;  // what stderr must name
};

// Every case: scene errors name bad.sce and its line, mesh errors name the
// scene line and mesh.off with its line or element.
const std::vector<BadInput>& badInputs();

}  // namespace meshtrace::test
